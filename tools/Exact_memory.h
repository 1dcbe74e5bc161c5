// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_EXACT_MEMORY_H
#define EXPMAP_TOOLS_EXACT_MEMORY_H

/// \file Exact_memory.h
/// What one map of the exact method costs in memory, estimated from its
/// patch size before it is computed, and what the machine has to give:
/// `expmap compute` and `expmap batch` refuse an exact map beyond the
/// machine's memory (unless forced), and `expmap view` caps its requests.
///
/// The exact method's sequence tree grows faster than its patch (the
/// windows of Mitchell, Mount & Papadimitriou's algorithm): a patch of 16,000
/// vertices takes 0.6 to 1.0 GB, one of 32,000 vertices 2.0 to 2.5 GB.

#include "Command_line.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include <sys/resource.h>

namespace expmap_cli {

/// An upper estimate, in MiB, of the memory one exact map of
/// `patch_vertices` vertices takes on top of the method object:
/// 60 + 1000 (k / 16,000)^1.7. It is the envelope of 89 maps measured
/// with `expmap-exact-memory` (the rise of the resident set during the
/// query) on armadillo, bunny00, refined_elephant, the Loop subdivisions of
/// bunny00 and refined_elephant and elephant_loop2 (26k to 711k vertices),
/// patches of 1,000 to 32,000 vertices: 1.05 to 6.9 times what they took,
/// closest on the finely subdivided meshes (doc/viewer.md).
inline double exact_query_mib(double patch_vertices) {
  return 60 + 1000 * std::pow(patch_vertices / 16000, 1.7);
}

/// The largest patch (in vertices) whose `exact_query_mib()` is at most
/// `mib`; 0 if none is.
inline std::size_t exact_patch_vertices_within(double mib) {
  if (!(mib > 60)) return 0;
  const double k = 16000 * std::pow((mib - 60) / 1000, 1 / 1.7);
  return static_cast<std::size_t>(std::floor(k + 1e-9));
}

/// A field of /proc/meminfo or /proc/self/status ("MemAvailable",
/// "VmSize", ...) in MiB; negative if it cannot be read (not Linux).
inline double proc_field_mib(const char* file, const std::string& field) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.compare(0, field.size() + 1, field + ":") == 0) {
      try {
        return std::stod(line.substr(field.size() + 1)) / 1024;  // the value is in kB
      } catch (...) {
        return -1;
      }
    }
  return -1;
}

/// The memory this program can still take, in MiB: what the system can
/// give without swapping (`MemAvailable` of /proc/meminfo), or less under
/// an address-space limit (`ulimit -v`); negative where neither is known.
inline double available_memory_mib() {
  double available = proc_field_mib("/proc/meminfo", "MemAvailable");
  rlimit limit{};
  const double used = proc_field_mib("/proc/self/status", "VmSize");
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && used >= 0) {
    const double headroom = static_cast<double>(limit.rlim_cur) / (1024 * 1024) - used;
    available = available < 0 ? headroom : std::min(available, headroom);
  }
  return available;
}

/// `k` with its thousands grouped: "16,000".
inline std::string grouped(std::size_t k) {
  std::string digits = std::to_string(k);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
    digits.insert(static_cast<std::size_t>(i), ",");
  return digits;
}

/// `mib` in words: "850 MB" or "4.2 GB" (decimal units, as people read them).
inline std::string memory_text(double mib) {
  const double bytes = mib * 1024 * 1024;
  char text[32];
  if (bytes < 1e9)
    std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
  else
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  return text;
}

/// Refuses an exact run of `maps_at_once` maps at a time, each of
/// `patch_vertices` vertices, whose `exact_query_mib()` estimate exceeds
/// `available_memory_mib()`, unless `force`: then it only warns on stderr.
/// \throws Runtime_error naming the estimate, the memory available and
///         the ways out (a smaller patch, fewer threads, --force).
inline void check_exact_memory(std::size_t patch_vertices, unsigned maps_at_once, bool force) {
  const double available = available_memory_mib();
  const double needed = maps_at_once * exact_query_mib(static_cast<double>(patch_vertices));
  if (available < 0 || needed <= available) return;
  std::string message = "an exact map of about " + grouped(patch_vertices) +
                        " patch vertices takes up to " +
                        memory_text(exact_query_mib(static_cast<double>(patch_vertices)));
  if (maps_at_once > 1)
    message += ", " + std::to_string(maps_at_once) + " at once (one per thread) up to " +
               memory_text(needed) + ",";
  message += " by the measured estimate (doc/viewer.md), more than the " + memory_text(available) +
             " this machine has available";
  if (!force)
    throw Runtime_error(message + "; choose a smaller patch" +
                        (maps_at_once > 1 ? std::string(" or fewer --threads") : std::string()) +
                        ", or give --force to try anyway");
  std::fflush(stdout);
  std::cerr << "expmap: warning: " << message << "; trying anyway (--force)\n";
}

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_EXACT_MEMORY_H
