// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_TIMING_H
#define EXPMAP_BENCHMARK_TIMING_H

/// \file Timing.h
/// Wall-clock timing with std::chrono::steady_clock.

#include <chrono>
#include <utility>

namespace expmap_bench {

/// Seconds since construction (or the last restart()), on the steady clock.
class Stopwatch {
 public:
  Stopwatch() : m_start(std::chrono::steady_clock::now()) {}
  void restart() { m_start = std::chrono::steady_clock::now(); }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }
  double milliseconds() const { return 1e3 * seconds(); }

 private:
  std::chrono::steady_clock::time_point m_start;
};

/// Runs `f()` once and returns its wall time in milliseconds; the result of
/// `f()` goes to `out`.
template <class F, class R>
double time_ms(F&& f, R& out) {
  Stopwatch watch;
  out = std::forward<F>(f)();
  return watch.milliseconds();
}

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_TIMING_H
