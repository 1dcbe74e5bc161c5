// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_STREAM_FLOOR_H
#define EXPMAP_BENCHMARK_STREAM_FLOOR_H

/// \file Stream_floor.h
/// The "stream floor" of a localized solve: the time one pass over as many
/// (row index, value) pairs as the solve read from the Cholesky factors
/// takes, stored as a factor stores them (an int array and a double array,
/// as in `Cholesky_factor_view`).
///
/// A localized triangular solve must read every factor entry of the
/// columns it visits at least once, so no implementation of it can beat
/// this loop on the same machine; `query_ms / floor_ms` says how far a
/// query is from that bound. Protocol:
///
/// 1. `prepare(max_entries)` allocates the two arrays for the largest
///    measurement to come and fills them once (untimed: this faults the
///    pages in, so no measurement pays for first touch);
/// 2. each `measure_ms(entries)` times one pass over the first `entries`
///    pairs (row indices summed, values summed), with no warm-up pass of
///    its own. Whatever part of the buffer still sits in a cache from the
///    fill or an earlier pass is read from there, as the upper levels of a
///    factor's elimination tree are after earlier queries; this can only
///    lower the floor, i.e. make `query_ms / floor_ms` larger.
///
/// The buffers are separate from the factors (the public API does not show
/// which columns a query touched) and freed by `release()`.

#include "Timing.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace expmap_bench {

class Stream_floor {
 public:
  /// Allocates and fills the buffers for passes of up to `max_entries`.
  void prepare(std::size_t max_entries) {
    if (max_entries <= m_row.size()) return;
    release();
    m_row.resize(max_entries);
    m_value.resize(max_entries);
    for (std::size_t k = 0; k < max_entries; ++k) {
      m_row[k] = static_cast<int>(k & 0xfffff);
      m_value[k] = 1.0 + 1e-9 * static_cast<double>(k & 0xffff);
    }
  }

  /// Milliseconds for one streaming pass over `entries` (int, double) pairs.
  double measure_ms(std::size_t entries) {
    if (entries == 0) return 0.0;
    prepare(entries);
    const int* row = m_row.data();
    const double* value = m_value.data();
    Stopwatch watch;
    // Four independent sums each, so neither the adds' latency nor the
    // order of floating-point additions (which the compiler must keep)
    // limits the loop below the memory's speed.
    std::int64_t r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    double v0 = 0, v1 = 0, v2 = 0, v3 = 0;
    std::size_t k = 0;
    for (; k + 4 <= entries; k += 4) {
      r0 += row[k];
      r1 += row[k + 1];
      r2 += row[k + 2];
      r3 += row[k + 3];
      v0 += value[k];
      v1 += value[k + 1];
      v2 += value[k + 2];
      v3 += value[k + 3];
    }
    for (; k < entries; ++k) {
      r0 += row[k];
      v0 += value[k];
    }
    const double ms = watch.milliseconds();
    m_sink = m_sink + (v0 + v1) + (v2 + v3) + static_cast<double>((r0 + r1) + (r2 + r3));
    return ms;
  }

  /// Frees the buffers.
  void release() {
    std::vector<int>().swap(m_row);
    std::vector<double>().swap(m_value);
  }

 private:
  std::vector<int> m_row;
  std::vector<double> m_value;
  volatile double m_sink = 0;
};

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_STREAM_FLOOR_H
