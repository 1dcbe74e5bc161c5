"""The .npz of `expmap batch`, loaded by NumPy itself, holds the same maps
as the .csv the same run writes (run by ctest when NumPy is installed).

usage: python3 npz_matches_csv.py EXPMAP MESH WORK_DIR
"""
import csv
import os
import subprocess
import sys

import numpy


def main():
    expmap, mesh, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    npz_path = os.path.join(work, "maps.npz")
    csv_path = os.path.join(work, "maps.csv")
    sources = [0, 17, 5, 17, 2000]
    subprocess.run([expmap, "batch", mesh, "--sources", ",".join(map(str, sources)),
                    "--fraction", "0.02", "--threads", "2", "-o", npz_path, "-o", csv_path],
                   check=True, stdout=subprocess.DEVNULL)

    data = numpy.load(npz_path)
    assert sorted(data.files) == sorted(["sources", "offsets", "vertex", "r", "theta", "u", "v",
                                         "fold_free_radius"]), data.files
    assert data["sources"].tolist() == sources
    offsets = data["offsets"]
    assert offsets.shape == (len(sources) + 1,) and offsets[0] == 0
    assert numpy.all(numpy.diff(offsets) > 0)
    rows = offsets[-1]
    for name, dtype in [("vertex", numpy.int64), ("r", numpy.float64), ("theta", numpy.float64),
                        ("u", numpy.float64), ("v", numpy.float64)]:
        assert data[name].dtype == dtype and data[name].shape == (rows,), (name, data[name].dtype)

    with open(csv_path, newline="") as f:
        table = list(csv.DictReader(f))
    assert len(table) == rows, (len(table), rows)
    expected_source = numpy.repeat(data["sources"], numpy.diff(offsets))
    assert [int(row["source"]) for row in table] == expected_source.tolist()
    assert [int(row["vertex"]) for row in table] == data["vertex"].tolist()
    for name in ["r", "theta", "u", "v"]:
        # 17 significant digits in the CSV: the same doubles, bit for bit.
        assert numpy.array_equal(numpy.array([float(row[name]) for row in table]), data[name]), name
    # The fold-free radius: one per map, on each of its CSV rows, within its patch.
    radius = data["fold_free_radius"]
    assert radius.dtype == numpy.float64 and radius.shape == (len(sources),)
    expected_radius = numpy.repeat(radius, numpy.diff(offsets))
    assert numpy.array_equal(numpy.array([float(row["fold_free_radius"]) for row in table]),
                             expected_radius)
    for i in range(len(sources)):
        assert 0 < radius[i] <= data["r"][offsets[i]:offsets[i + 1]].max(), i
    # Each map starts at its source, at distance 0.
    assert numpy.array_equal(data["vertex"][offsets[:-1]], data["sources"])
    assert numpy.all(data["r"][offsets[:-1]] == 0)
    print("npz and csv agree: %d maps, %d rows" % (len(sources), rows))


if __name__ == "__main__":
    main()
