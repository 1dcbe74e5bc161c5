// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_BATCH_QUERIES_H
#define EXPMAP_PYTHON_BATCH_QUERIES_H

// Stopgap until the library's own compute_many() (include/expmap/Batch.h)
// is merged: the queries of a batch spread over a few std::threads, each
// failure kept with its source instead of ending the batch. Same layout as
// expmap::Batch_result, so switching to the library is a one-line change.

#include <expmap/Local_map.h>
#include <expmap/Patch.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <new>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace expmap_python {

template <class VertexDescriptor>
struct Batch_maps {
  std::vector<expmap::Local_map<VertexDescriptor>> maps;  // in source order; empty where failed
  std::vector<std::string> errors;                        // "" where the query succeeded
};

/// `method.compute_by_index()` for every source, on `threads` threads
/// (0: one per core). Queries are const and thread safe, so the threads
/// share `method`.
template <class Method>
Batch_maps<typename Method::vertex_descriptor> compute_batch(
    const Method& method, const std::vector<std::size_t>& sources, const expmap::Patch& patch,
    const expmap::Query_options& query, unsigned threads) {
  Batch_maps<typename Method::vertex_descriptor> batch;
  batch.maps.resize(sources.size());
  batch.errors.resize(sources.size());
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < sources.size(); i = next++) {
      try {
        batch.maps[i] = method.compute_by_index(sources[i], patch, query);
      } catch (const std::bad_alloc&) {
        batch.errors[i] = "out of memory";
      } catch (const std::exception& e) {
        batch.errors[i] = e.what();
      } catch (...) {
        batch.errors[i] = "unexpected internal error";
      }
    }
  };
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, sources.size())));
  std::vector<std::thread> pool;
  try {
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  } catch (const std::system_error&) {
    // Fewer threads than asked for: the ones started share the work.
  }
  work();
  for (std::thread& t : pool) t.join();
  return batch;
}

}  // namespace expmap_python

#endif  // EXPMAP_PYTHON_BATCH_QUERIES_H
