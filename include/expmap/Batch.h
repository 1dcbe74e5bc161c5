// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BATCH_H
#define EXPMAP_BATCH_H

/// \file Batch.h
/// Many queries at once on all cores: the options and the result of
/// `compute_many()`, which every method class has.

#include <expmap/Errors.h>
#include <expmap/Local_map.h>
#include <expmap/internal/Parallel_loop.h>

#include <cctype>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <new>
#include <string>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// How `compute_many()` runs a batch.
struct Batch_options {
  unsigned threads = 0;  ///< 0: std::thread::hardware_concurrency()
  /// Called with (maps done, total) after each map, never concurrently (serialized by the batch).
  /// If it throws, the batch starts no further query and `compute_many()`
  /// rethrows the exception once the running queries have finished: a way
  /// to cancel a batch.
  std::function<void(std::size_t, std::size_t)> progress;
};

/// \ingroup PkgExpmapRef
/// The maps of a batch, one per source, and what went wrong where a query
/// failed: a failed query costs its own map only.
///
/// A successful map always holds at least its source, so an empty map and
/// a non-empty error go together.
/// \code
/// auto batch = heat.compute_many_by_index(sources, expmap::Patch::fraction(0.01));
/// for (std::size_t i = 0; i < sources.size(); ++i)
///   if (batch.errors[i].empty()) use(batch.maps[i]);
///   else std::cerr << batch.errors[i] << "\n";  // e.g. "source vertex 7 is isolated (...)"
/// \endcode
template <class VertexDescriptor>
struct Batch_result {
  std::vector<Local_map<VertexDescriptor>> maps;  ///< in source order; empty where that query failed
  std::vector<std::string> errors;                 ///< in source order; "" where it succeeded
  /// The number of sources whose query failed.
  std::size_t failures() const {
    std::size_t count = 0;
    for (const std::string& e : errors) count += e.empty() ? 0 : 1;
    return count;
  }
};

namespace internal {

/// The message of a failed query, naming its source as `noun` and its
/// index (in the user's mesh, or in the list of points) unless the
/// library's message already does.
inline std::string batch_error_message(std::size_t source, const std::string& what,
                                       const char* noun = "source vertex") {
  const std::string name = noun + (" " + std::to_string(source));
  const std::string::size_type at = what.find(name);
  const bool named = at != std::string::npos &&
                     (at + name.size() == what.size() || !std::isdigit(static_cast<unsigned char>(
                                                             what[at + name.size()])));
  return named ? what : name + ": " + what;
}

/// Answers `query(sources[i])` for every i on the threads `batch` asks for
/// and collects the maps in source order. An exception from a query becomes
/// that source's error; one from `batch.progress` stops the batch and is
/// rethrown. `noun` names a source in the errors.
///
/// Queries run in the order `order` gives (a permutation of the positions
/// in `sources`; empty: as given), each thread on runs of it
/// (`parallel_loop`). Given along a curve through the sources (as
/// `hilbert_order`), neighbouring sources run one after another on one
/// thread: a heat method on subdomains then factors each ball once for all
/// the sources it serves (internal/heat/Subdomain_cache.h).
template <class VertexDescriptor, class Query>
Batch_result<VertexDescriptor> run_batch(const std::vector<std::size_t>& sources,
                                         const Batch_options& batch, Query query,
                                         const char* noun = "source vertex",
                                         const std::vector<std::size_t>& order = {}) {
  Batch_result<VertexDescriptor> result;
  result.maps.resize(sources.size());
  result.errors.resize(sources.size());
  std::mutex progress_mutex;
  std::size_t done = 0;
  parallel_loop(sources.size(), batch_thread_count(batch.threads, sources.size()),
                [&](std::size_t k) {
                  const std::size_t i = order.empty() ? k : order[k];
                  try {
                    result.maps[i] = query(sources[i]);
                  } catch (const std::exception& e) {
                    result.errors[i] = batch_error_message(sources[i], user_message(e), noun);
                  } catch (...) {
                    result.errors[i] = batch_error_message(sources[i], "unknown error", noun);
                  }
                  std::lock_guard<std::mutex> lock(progress_mutex);
                  ++done;
                  if (batch.progress) batch.progress(done, sources.size());
                },
                /*runs=*/!order.empty());
  return result;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_BATCH_H
