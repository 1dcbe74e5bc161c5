// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_PEAK_MEMORY_H
#define EXPMAP_BENCHMARK_PEAK_MEMORY_H

/// \file Peak_memory.h
/// Resident memory of this process from Linux's /proc/self/status: the
/// current resident set (VmRSS) and its high-water mark (VmHWM).
///
/// VmHWM only grows, so to measure the peak of one mesh's precomputation
/// after an earlier, larger one, `reset_peak_rss()` writes "5" to
/// /proc/self/clear_refs, which (Linux >= 4.0) resets the high-water mark
/// to the current resident set. Where that is refused, the mark cannot be
/// reset and a peak read later is the peak of the whole process so far.

#include <fstream>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace expmap_bench {

/// A field of /proc/self/status in MiB (e.g. "VmHWM", "VmRSS"); a negative
/// value if it cannot be read (not Linux).
inline double proc_status_mib(const std::string& field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, field.size() + 1, field + ":") != 0) continue;
    try {
      return std::stod(line.substr(field.size() + 1)) / 1024.0;  // the value is in kB
    } catch (...) {
      return -1;
    }
  }
  return -1;
}

/// Current resident set size in MiB.
inline double current_rss_mib() { return proc_status_mib("VmRSS"); }

/// Peak resident set size in MiB since start or since the last successful
/// `reset_peak_rss()`.
inline double peak_rss_mib() { return proc_status_mib("VmHWM"); }

/// Resets the peak resident set size to the current one; false if the
/// kernel refused (then `peak_rss_mib()` keeps the whole process's peak).
inline bool reset_peak_rss() {
  std::ofstream out("/proc/self/clear_refs");
  if (!out) return false;
  out << "5" << std::flush;
  return static_cast<bool>(out);
}

/// Returns the free memory of the heap to the system where the allocator
/// can (glibc's malloc_trim), so the resident set of a new mesh does not
/// carry freed pages of the previous one.
inline void release_free_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace expmap_bench

#endif  // EXPMAP_BENCHMARK_PEAK_MEMORY_H
