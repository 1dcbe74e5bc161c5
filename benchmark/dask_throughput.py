#!/usr/bin/env python3
# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Maps per second through expmap.dask on a LocalCluster against one process.

    PYTHONPATH=build/python python3 benchmark/dask_throughput.py \
        [--workers 2] [--fraction 0.01] [--chunk-size 256] MESH [MESH ...]

Maps every vertex of every mesh with the heat method, three ways, each
timed from the mesh files to all arrays in memory (reading and
precomputation included; the cluster's start-up excluded):
  one process, one thread:  compute_many(threads=1), mesh after mesh
  one process, all threads: compute_many(threads=0)
  LocalCluster:             map_meshes() on --workers processes of 1 thread,
                            and on 1 process of --workers threads
"""

import argparse
import logging
import time

import dask

import expmap
import expmap.dask


def one_process(meshes, patch, threads):
    maps = 0
    start = time.perf_counter()
    for mesh in meshes:
        V, F = expmap.read_mesh(mesh)
        heat = expmap.HeatExponentialMap(V, F)
        maps += len(heat.compute_many(range(len(V)), threads=threads, **patch))
    return maps, time.perf_counter() - start


def through_cluster(meshes, patch, workers, threads, chunk_size):
    from distributed import Client, LocalCluster

    with dask.config.set({"distributed.scheduler.work-stealing": False}):  # as the manual says
        cluster = LocalCluster(n_workers=workers, threads_per_worker=threads, processes=True,
                               host="127.0.0.1", dashboard_address=None, silence_logs=logging.ERROR)
    with cluster, Client(cluster) as client:
        client.wait_for_workers(workers)
        start = time.perf_counter()
        results = expmap.dask.map_meshes(client, meshes, fraction=patch["fraction"], chunk_size=chunk_size)
        seconds = time.perf_counter() - start
    return sum(len(r["sources"]) for r in results.values()), seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--fraction", type=float, default=0.01)
    parser.add_argument("--chunk-size", type=int, default=256)
    args = parser.parse_args()
    patch = {"fraction": args.fraction}
    for name, run in (("one process, 1 thread", lambda: one_process(args.meshes, patch, 1)),
                      ("one process, all threads", lambda: one_process(args.meshes, patch, 0)),
                      ("LocalCluster, %d x 1 thread" % args.workers,
                       lambda: through_cluster(args.meshes, patch, args.workers, 1, args.chunk_size)),
                      ("LocalCluster, 1 x %d threads" % args.workers,
                       lambda: through_cluster(args.meshes, patch, 1, args.workers, args.chunk_size))):
        maps, seconds = run()
        print("%-28s %8d maps %8.2f s %10.0f maps/s" % (name, maps, seconds, maps / seconds), flush=True)


if __name__ == "__main__":
    main()
