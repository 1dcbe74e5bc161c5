# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Exponential maps of many meshes on a Dask cluster (``dask.distributed``).

Each mesh is precomputed once, on one worker, and kept there in a small
per-process cache; its sources are split into chunks that are scheduled on
that worker (``workers=[address]``), so no precomputation travels over the
network. ``allow_other_workers=True`` lets the scheduler run a chunk
elsewhere when that worker is gone: the chunk task then finds no cached
precomputation on its new worker and redoes it there. Results are
collected per chunk, once, by chunk number, so a chunk that ran twice (its
first worker died after finishing it) is neither lost nor counted twice.

On a real cluster::

    from dask.distributed import Client
    import expmap.dask
    client = Client("tcp://scheduler:8786")
    expmap.dask.map_meshes(client, paths, fraction=0.01, out_dir="maps/")

Every worker needs the ``expmap`` package importable and the mesh files at
the same paths (a shared file system). Run the scheduler with work stealing
off (``DASK_DISTRIBUTED__SCHEDULER__WORK_STEALING=False``): otherwise it
moves queued chunks to idle workers, which then precompute the mesh again
(correct, but twice the precomputations and their memory).
"""

import collections
import os
import threading

import numpy as np

from . import METHODS, read_mesh

#: The arrays of one mesh's maps, as in ``expmap batch -o OUT.npz``.
ARRAY_NAMES = ("sources", "offsets", "vertex", "r", "theta", "u", "v", "fold_free_radius")

# Per worker process: (path, method, options) -> method object, the least
# recently used dropped beyond _CACHE_SIZE (precomputations are large).
_CACHE_SIZE = 2
_cache = collections.OrderedDict()
_cache_lock = threading.Lock()
_key_locks = collections.defaultdict(threading.Lock)


def _options_key(options):
    return tuple(sorted((k, repr(v)) for k, v in options.items()))


def _precomputed(path, method, options):
    """The method object for this mesh in this process, built on first use."""
    key = (path, method, _options_key(options))
    with _cache_lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
        key_lock = _key_locks[key]
    # One thread builds it; others asking for the same mesh wait for it.
    with key_lock:
        with _cache_lock:
            if key in _cache:
                return _cache[key]
        vertices, faces = read_mesh(path)
        built = METHODS[method](vertices, faces, **options)
        with _cache_lock:
            _cache[key] = built
            _precomputed_paths.append(path)
            while len(_cache) > _CACHE_SIZE:
                _cache.popitem(last=False)
        return built


_precomputed_paths = []  # every precomputation this process made, in order


def cached_meshes():
    """The mesh paths whose precomputation this process holds now (on a
    worker: its cache), e.g. ``client.run(expmap.dask.cached_meshes)``."""
    with _cache_lock:
        return sorted({key[0] for key in _cache})


def precomputed_meshes():
    """Every mesh path this process has precomputed, in order, repeats
    included: a path listed twice was evicted from the cache (or its
    options differed) and precomputed again."""
    with _cache_lock:
        return list(_precomputed_paths)


def _prepare(path, method, options):
    """Task: precompute the mesh here; the number of vertices and where."""
    from distributed import get_worker

    return _precomputed(path, method, options).number_of_vertices, get_worker().address


def _map_chunk(path, method, options, patch, sources):
    """Task: the maps of some sources of one mesh, as a dict of arrays."""
    batch = _precomputed(path, method, options).compute_many(sources, threads=1, **patch)
    arrays = batch.as_dict()
    arrays["errors"] = np.array(batch.errors, dtype=str)
    return arrays


def _patch_chunk(path, method, options, grid, sources):
    """Task: the polar patch operator of some sources of one mesh, as arrays."""
    op = _precomputed(path, method, options).patch_operator(sources, threads=1, **grid)
    data, indices, indptr = op._csr
    return {"data": data, "indices": indices, "indptr": indptr, "sampled": op.sampled,
            "sources": np.asarray(op.sources, dtype=np.int64),
            "errors": np.array(op.errors, dtype=str), "vertices": op.shape[1]}


def _concatenate_patches(chunks, grid):
    """One mesh's operator, in SciPy's CSR layout (scipy.sparse.load_npz),
    from its chunks' operators, in chunk order."""
    indptr = [np.zeros(1, dtype=np.int64)]
    entries = 0
    for c in chunks:
        indptr.append(c["indptr"][1:] + entries)
        entries += int(c["indptr"][-1])
    vertices = chunks[0]["vertices"] if chunks else 0
    out = {name: np.concatenate([c[name] for c in chunks]) for name in ("data", "indices", "sources")}
    out["indptr"] = np.concatenate(indptr)
    out["sampled"] = np.concatenate([c["sampled"] for c in chunks]).astype(np.uint8)
    out["errors"] = np.concatenate([c["errors"] for c in chunks]).astype(str)
    out["format"] = np.array("csr")
    out["shape"] = np.array([len(out["indptr"]) - 1, vertices], dtype=np.int64)
    out["radius"] = np.array(float(grid["radius"]))
    return out


def _empty_chunk():
    arrays = {name: np.zeros(0, dtype=np.int64 if name in ("sources", "vertex") else float) for name in ARRAY_NAMES}
    arrays["offsets"] = np.zeros(1, dtype=np.int64)
    arrays["errors"] = np.zeros(0, dtype=str)
    return arrays


def _concatenate(chunks):
    """One mesh's arrays from its chunks' arrays, in chunk order."""
    out = {name: np.concatenate([c[name] for c in chunks]) for name in ARRAY_NAMES if name != "offsets"}
    out["errors"] = np.concatenate([c["errors"] for c in chunks]).astype(str)
    offsets = [np.zeros(1, dtype=np.int64)]
    rows = 0
    for c in chunks:
        offsets.append(c["offsets"][1:] + rows)
        rows += int(c["offsets"][-1])
    out["offsets"] = np.concatenate(offsets)
    return out


def _patch_argument(fraction, radius, vertices):
    given = {k: v for k, v in (("fraction", fraction), ("radius", radius), ("vertices", vertices)) if v is not None}
    if len(given) != 1:
        raise ValueError("give exactly one of fraction=, radius= or vertices= (got %d)" % len(given))
    return given


def _npz_paths(meshes, out_dir):
    paths = {}
    for mesh in meshes:
        stem = os.path.splitext(os.path.basename(mesh))[0]
        path = os.path.join(out_dir, stem + ".npz")
        if path in paths.values():
            raise ValueError("two meshes would both be written to %r" % path)
        paths[mesh] = path
    return paths


def _checked_arguments(meshes, sources, method, chunk_size, options, out_dir):
    """The arguments both map_meshes and patch_operators take, checked:
    (meshes, sources, options, npz_paths); out_dir is made."""
    if isinstance(meshes, (str, bytes, os.PathLike)):
        raise ValueError("meshes must be a list of mesh paths, not one path")
    meshes = [os.fspath(m) for m in meshes]
    if len(set(meshes)) != len(meshes):
        raise ValueError("a mesh is listed twice")
    if method not in METHODS:
        raise ValueError("unknown method %r (known: %s)" % (method, ", ".join(METHODS)))
    if not (isinstance(chunk_size, int) and chunk_size > 0):
        raise ValueError("chunk_size must be a positive integer (got %r)" % (chunk_size,))
    if not (isinstance(sources, str) and sources == "all") and not isinstance(sources, dict):
        raise ValueError('sources must be "all" or a dict from mesh path to source indices')
    if isinstance(sources, dict):
        sources = {os.fspath(k): v for k, v in sources.items()}
        missing = [m for m in meshes if m not in sources]
        if missing:
            raise ValueError("no sources given for %s" % ", ".join(missing))
    options = dict(options or {})
    npz_paths = None
    if out_dir is not None:
        if os.path.exists(out_dir) and not os.path.isdir(out_dir):
            raise ValueError("out_dir %r exists and is not a folder" % (out_dir,))
        npz_paths = _npz_paths(meshes, out_dir)
        # Here, before any task: the files are written by this process, and a
        # folder that cannot be made should fail now, not after the maps.
        os.makedirs(out_dir, exist_ok=True)
    return meshes, sources, options, npz_paths


def map_meshes(client, meshes, sources="all", method="heat", fraction=None, radius=None,
               vertices=None, out_dir=None, chunk_size=256, options=None, progress=None):
    """Local maps of many sources on many meshes, computed on a Dask cluster.

    client: a ``dask.distributed.Client``.
    meshes: mesh file paths (readable by every worker under that path).
    sources: ``"all"`` (every vertex of every mesh) or a dict from mesh path
        to its source indices.
    method: ``"heat"``, ``"dem"``, ``"dgpc"`` or ``"exact"`` (expmap.METHODS).
    fraction, radius, vertices: the patch, exactly one (as in compute()).
    out_dir: if given, one ``<mesh stem>.npz`` per mesh is written there as
        soon as that mesh is done, and the dict maps each mesh to its file.
        The folder (and its parents) is made if it does not exist.
    chunk_size: sources per task; smaller chunks balance and recover
        faster, larger ones cost less scheduling.
    options: keyword arguments of the method class (e.g. ``{"time_factor": 5}``).
    progress: called as ``progress(done_chunks, total_chunks)`` on the
        client after each chunk.

    Returns a dict from mesh path to a dict of arrays ``sources``,
    ``offsets``, ``vertex``, ``r``, ``theta``, ``u``, ``v`` (rows
    offsets[i]:offsets[i+1] belong to sources[i]) and ``errors`` (per
    source, '' or why its query failed), or to the .npz path with out_dir.
    Raises ValueError for bad arguments (an out_dir that is a file), OSError
    if out_dir cannot be made; a mesh that cannot be read or
    precomputed raises the worker's exception here.
    """
    patch = _patch_argument(fraction, radius, vertices)
    meshes, sources, options, npz_paths = _checked_arguments(meshes, sources, method, chunk_size,
                                                             options, out_dir)
    return _run_meshes(client, meshes, sources, method, options, chunk_size, npz_paths, progress,
                       lambda mesh, piece, **where: client.submit(
                           _map_chunk, mesh, method, options, patch, piece, pure=False, **where),
                       _concatenate, _empty_chunk())


def patch_operators(client, meshes, radius, rings=5, rays=16, sources="all", method="dgpc",
                    out_dir=None, chunk_size=256, options=None, progress=None, reference=None):
    """The polar patch operators (``method.patch_operator()``) of many
    meshes, computed on a Dask cluster as map_meshes computes maps.

    radius, rings, rays, reference: the grid, as in patch_operator().
    meshes, sources, method, out_dir, chunk_size, options, progress: as in
    map_meshes; method defaults to "dgpc" (manual, section 15).

    Returns a dict from mesh path to a dict of arrays in SciPy's CSR layout
    (``data``, ``indices``, ``indptr``, ``format``, ``shape``: give it to
    ``scipy.sparse.csr_matrix((d["data"], d["indices"], d["indptr"]),
    d["shape"])``) with ``sources``, ``sampled`` (sources, rings, rays),
    ``radius`` and ``errors``; with out_dir, to ``<mesh stem>.npz``, which
    ``scipy.sparse.load_npz`` reads. Raises as map_meshes.
    """
    meshes, sources, options, npz_paths = _checked_arguments(meshes, sources, method, chunk_size,
                                                             options, out_dir)
    grid = {"radius": radius, "rings": rings, "rays": rays, "reference": reference}
    empty = {"data": np.zeros(0), "indices": np.zeros(0, dtype=np.int64),
             "indptr": np.zeros(1, dtype=np.int64), "sampled": np.zeros((0, rings, rays), bool),
             "sources": np.zeros(0, dtype=np.int64), "errors": np.zeros(0, dtype=str),
             "vertices": 0}
    return _run_meshes(client, meshes, sources, method, options, chunk_size, npz_paths, progress,
                       lambda mesh, piece, **where: client.submit(
                           _patch_chunk, mesh, method, options, grid, piece, pure=False, **where),
                       lambda chunks: _concatenate_patches(chunks, grid), empty)


def _run_meshes(client, meshes, sources, method, options, chunk_size, npz_paths, progress,
                submit_chunk, concatenate, empty_chunk):
    """The scheduling both map_meshes and patch_operators share: meshes
    precomputed a few at a time, their sources in chunks on that worker."""
    from distributed import as_completed

    # Meshes are precomputed a few at a time (one per worker, plus one so a
    # worker can start the next while its threads still map the last), the
    # next when one is done: all at once, a worker would precompute more
    # meshes than its cache holds before mapping any, then redo them.
    waiting = list(reversed(meshes))
    position = {mesh: i for i, mesh in enumerate(meshes)}
    in_flight = len(client.scheduler_info().get("workers", {})) + 1
    prepared_mesh = {}  # future key -> mesh
    chunk_futures = {}  # future key -> (mesh, chunk number)
    chunks_of = {}
    done = {}
    results = {}
    total_chunks = 0
    finished_chunks = 0
    work = as_completed(with_results=True)

    def prepare_next():
        if waiting:
            mesh = waiting.pop()
            # Ahead of queued chunks, so a worker that finished a mesh starts the next.
            f = client.submit(_prepare, mesh, method, options, pure=False, priority=10)
            prepared_mesh[f.key] = mesh
            work.add(f)

    def finish(mesh):
        arrays = concatenate([done[mesh][i] for i in range(chunks_of[mesh])])
        del done[mesh]
        if npz_paths is None:
            results[mesh] = arrays
        else:
            np.savez(npz_paths[mesh], **arrays)
            results[mesh] = npz_paths[mesh]
        prepare_next()

    for _ in range(in_flight):
        prepare_next()
    try:
        for future, result in work:
            if future.key in prepared_mesh:
                mesh = prepared_mesh.pop(future.key)
                n, address = result
                chosen = np.arange(n, dtype=np.int64) if isinstance(sources, str) else np.asarray(sources[mesh])
                if chosen.ndim != 1:
                    raise ValueError("the sources of %s must be a 1-D list of vertex indices" % mesh)
                pieces = [chosen[i:i + chunk_size] for i in range(0, len(chosen), chunk_size)]
                chunks_of[mesh] = len(pieces)
                done[mesh] = {}
                total_chunks += len(pieces)
                if not pieces:
                    done[mesh][0] = empty_chunk
                    chunks_of[mesh] = 1
                    finish(mesh)
                # Earlier meshes first: a worker that takes over another's chunks
                # then works through one mesh at a time instead of alternating
                # between more meshes than its cache holds.
                for number, piece in enumerate(pieces):
                    f = submit_chunk(mesh, piece, workers=[address], allow_other_workers=True,
                                     priority=-position[mesh])
                    chunk_futures[f.key] = (mesh, number)
                    work.add(f)
                continue
            mesh, number = chunk_futures.pop(future.key)
            done[mesh][number] = result
            finished_chunks += 1
            if progress is not None:
                progress(finished_chunks, total_chunks)
            if len(done[mesh]) == chunks_of[mesh]:
                finish(mesh)
    except BaseException:
        # A mesh that could not be read or mapped (or an interrupt): stop
        # what is still queued instead of leaving it to run for nobody.
        client.cancel(list(work.futures))
        raise
    return {mesh: results[mesh] for mesh in meshes}
