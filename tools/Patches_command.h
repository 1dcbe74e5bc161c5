// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_PATCHES_COMMAND_H
#define EXPMAP_TOOLS_PATCHES_COMMAND_H

// `expmap patches`: the polar patch operator of a method and its .npz in
// SciPy's sparse layout. Part of expmap_cli.cpp, which includes it after
// make_method(), query_settings(), settings_description(), seconds_since()
// and check_batch_memory(), and uses Mesh and Batch_sources from there.

#include "Command_line.h"
#include "Progress_bar.h"

#include <expmap/IO/write_npz.h>
#include <expmap/Polar_patch_operator.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Patches_run {
  std::string description;  // the method with its settings
  double precompute_seconds = 0, operator_seconds = 0;
  expmap::Polar_patch_operator op;
};

// The operator of the vertex sources `sources` (patches takes no points).
template <class Method_class>
Patches_run run_patches(const Mesh& mesh, const expmap_cli::Patches_arguments& a,
                        const Batch_sources& sources, const expmap::Query_options& query) {
  Patches_run run;
  auto start = std::chrono::steady_clock::now();
  const expmap::Patch patch = expmap::Patch::geodesic_radius(*a.radius);
  const auto method = make_method<Method_class>(mesh, a, patch);
  run.precompute_seconds = seconds_since(start);
  run.description = settings_description<Method_class>(a);
  check_batch_memory(method, a, sources, patch);

  start = std::chrono::steady_clock::now();
  expmap_cli::Progress_bar bar(sources.size());
  expmap::Batch_options options;
  options.threads = a.threads;
  options.progress = [&](std::size_t done, std::size_t) { bar.update(done); };
  run.op = expmap::polar_patch_operator(mesh, method, sources.vertices,
                                        {*a.radius, a.rings, a.rays}, options,
                                        query_settings<Method_class>(a, query));
  bar.finish();
  run.operator_seconds = seconds_since(start);
  return run;
}

// The operator as scipy.sparse.save_npz writes a CSR matrix (data,
// indices, indptr, format, shape), its columns and sources the file's
// vertices (`file_index` of each mesh vertex, `file_vertices` of them),
// and beside it sources, sampled (k, rings, rays) and radius.
inline void write_patch_operator_npz(const std::string& path, const expmap::Polar_patch_operator& op,
                                     const std::vector<std::size_t>& file_index,
                                     std::size_t file_vertices) {
  using expmap::IO::npy_array;
  const auto entries = static_cast<std::size_t>(op.weights.nonZeros());
  const std::vector<double> data(op.weights.valuePtr(), op.weights.valuePtr() + entries);
  std::vector<std::int64_t> indices(entries);
  for (std::size_t k = 0; k < entries; ++k)
    indices[k] = static_cast<std::int64_t>(file_index[op.weights.innerIndexPtr()[k]]);
  const std::vector<std::int64_t> indptr(op.weights.outerIndexPtr(),
                                         op.weights.outerIndexPtr() + op.weights.rows() + 1);
  const std::vector<std::int64_t> shape{static_cast<std::int64_t>(op.weights.rows()),
                                        static_cast<std::int64_t>(file_vertices)};
  std::vector<std::int64_t> sources;
  for (std::size_t s : op.sources) sources.push_back(static_cast<std::int64_t>(file_index[s]));
  const std::vector<double> radius{op.grid.radius};
  static const char format[] = "csr";
  expmap::IO::Npy_array format_array{"format", "|S3", {},
                                     reinterpret_cast<const unsigned char*>(format), 3};
  expmap::IO::Npy_array sampled{"sampled", "|u1", {op.sources.size(), op.grid.rings, op.grid.rays},
                                op.sampled.data(), op.sampled.size()};
  expmap::IO::Npy_array radius_array = npy_array("radius", radius);
  radius_array.shape = {};
  std::ofstream out(path, std::ios::binary);
  if (!out) throw expmap_cli::Runtime_error("cannot create output file '" + path + "'");
  expmap::IO::write_npz(out, {npy_array("data", data), npy_array("indices", indices),
                              npy_array("indptr", indptr), format_array, npy_array("shape", shape),
                              npy_array("sources", sources), sampled, radius_array});
  out.close();
  if (!out) throw expmap_cli::Runtime_error("could not write all of '" + path + "'");
}

}  // namespace

#endif  // EXPMAP_TOOLS_PATCHES_COMMAND_H
