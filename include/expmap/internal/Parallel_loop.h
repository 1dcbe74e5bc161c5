// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_PARALLEL_LOOP_H
#define EXPMAP_INTERNAL_PARALLEL_LOOP_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace expmap {
namespace internal {

/// The number of threads a batch runs on: `requested`, or the hardware's
/// count for 0, never more than there is work for, and at least 1.
inline unsigned batch_thread_count(unsigned requested, std::size_t work) {
  unsigned threads = requested != 0 ? requested : std::thread::hardware_concurrency();
  if (threads == 0) threads = 1;  // hardware_concurrency() may not know
  return static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, work)));
}

/// Whether the calling thread runs a parallel loop's body beside other
/// threads. Work that could start a thread of its own (a heat query's
/// second thread, `Heat_query_options::query_threads`) does not there: the loop
/// already keeps a thread per core busy.
inline bool& in_parallel_loop() {
  thread_local bool inside = false;
  return inside;
}

/// Calls `body(i)` once for every i in [0, count) on `threads` threads, the
/// calling one included. Each thread takes the next index from a shared
/// counter when it is done with the last, so uneven work (patches near a
/// boundary, failed queries) never leaves a thread idle while others still
/// have a queue of their own.
///
/// With `runs`, a thread takes a run of consecutive indices instead: half
/// its share of what is left (at least one index). Work that goes faster
/// where neighbouring indices share something (a batch in locality order,
/// whose neighbouring sources share a subdomain) then has each thread on a
/// part of its own, apart from the last, short runs that even the load.
///
/// If `body` throws, no further index is started; the running calls finish
/// and the first exception is rethrown here. If the system refuses to start
/// a thread, the loop runs on the threads it has (at worst the caller's).
template <class Body>
void parallel_loop(std::size_t count, unsigned threads, Body body, bool runs = false) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex failure_mutex;
  std::exception_ptr failure;
  auto work = [&]() {
    // Marked while it works for the loop (the calling thread lives on after).
    struct Mark {
      bool before;
      explicit Mark(bool parallel) : before(in_parallel_loop()) { in_parallel_loop() = parallel; }
      ~Mark() { in_parallel_loop() = before; }
    } mark(threads > 1);
    while (!stop.load(std::memory_order_relaxed)) {
      std::size_t first = next.load(std::memory_order_relaxed), size = 1;
      do {
        if (first >= count) return;
        if (runs) size = std::max<std::size_t>(1, (count - first) / (2 * std::size_t{threads}));
      } while (!next.compare_exchange_weak(first, first + size, std::memory_order_relaxed));
      for (std::size_t i = first; i < first + size && !stop.load(std::memory_order_relaxed); ++i) {
        try {
          body(i);
        } catch (...) {
          std::lock_guard<std::mutex> lock(failure_mutex);
          if (!failure) failure = std::current_exception();
          stop = true;
        }
      }
    }
  };
  std::vector<std::thread> helpers;
  try {
    helpers.reserve(threads);
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
  } catch (const std::exception&) {  // std::system_error, std::bad_alloc
    // Fewer threads than asked: slower, but every index is still done.
  }
  work();
  for (std::thread& helper : helpers) helper.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_PARALLEL_LOOP_H
