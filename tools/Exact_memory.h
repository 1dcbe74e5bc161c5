// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_EXACT_MEMORY_H
#define EXPMAP_TOOLS_EXACT_MEMORY_H

/// \file Exact_memory.h
/// What one map of the exact method costs in memory, estimated before it is
/// computed from the size of the submesh it builds its sequence tree on
/// (`Exact_exponential_map::region_faces()`), and what the machine has to
/// give: `expmap compute` and `expmap batch` refuse an exact map beyond the
/// machine's memory (unless forced), and `expmap view` caps its requests.
///
/// The sequence tree (the windows of Mitchell, Mount & Papadimitriou's
/// algorithm) grows faster than its submesh: 37,000 to 50,000 faces took
/// 0.3 to 1.0 GB, 83,000 faces 2.6 GB. The submesh has 2.2 to 4 times as many faces as the
/// patch has vertices, more where the surface folds back within the patch's
/// reach, so the patch's size alone does not tell the memory.

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

/// An upper estimate, in MiB, of the memory one exact map takes on top of
/// the method object when its submesh has `region_faces` faces:
/// 40 + 1000 (F / 40,000)^1.5. It is the envelope of 92 maps measured with
/// `expmap-exact-memory` (the rise of the resident set during the query) on
/// armadillo, bunny00, refined_elephant, the Loop subdivisions of bunny00
/// and refined_elephant and elephant_loop2 (26k to 711k vertices), patches
/// of 1,000 to 32,000 vertices: 1.03 to 5.5 times what they took, closest
/// on the finely subdivided meshes (doc/viewer.md).
inline double exact_query_mib(double region_faces) {
  return 40 + 1000 * std::pow(region_faces / 40000, 1.5);
}

/// The most faces of a submesh whose `exact_query_mib()` is at most `mib`;
/// 0 if none is.
inline std::size_t exact_region_faces_within(double mib) {
  if (!(mib > 40)) return 0;
  return static_cast<std::size_t>(std::floor(40000 * std::pow((mib - 40) / 1000, 1 / 1.5) + 1e-9));
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

/// The faces worth counting (`Exact_exponential_map::region_faces()`)
/// before `check_exact_memory()` for `maps_at_once` maps at a time: past
/// the first count whose estimate exceeds `available_memory_mib()` the
/// answer is the same. 0 where the memory available is not known.
inline std::size_t exact_region_faces_to_count(unsigned maps_at_once) {
  const double available = available_memory_mib();
  if (available < 0) return 0;
  return exact_region_faces_within(available / std::max(1u, maps_at_once)) + 1;
}

/// Refuses an exact run of `maps_at_once` maps at a time, the largest of
/// them on a submesh of `region_faces` faces (counted up to
/// `exact_region_faces_to_count()`), whose `exact_query_mib()` estimate
/// exceeds `available_memory_mib()`, unless `force`: then it only warns on
/// stderr.
/// \throws Runtime_error naming the estimate, the memory available and
///         the ways out (a smaller patch, fewer threads, --force).
inline void check_exact_memory(std::size_t region_faces, unsigned maps_at_once, bool force) {
  const double available = available_memory_mib();
  const double one = exact_query_mib(static_cast<double>(region_faces));
  const double needed = maps_at_once * one;
  if (available < 0 || needed <= available) return;
  // A count stopped past `exact_region_faces_to_count()` says only "more
  // than the faces before it".
  const bool stopped = region_faces > exact_region_faces_to_count(maps_at_once);
  std::string message =
      "an exact map of this patch builds its sequence tree on " +
      (stopped ? "more than " + grouped(region_faces - 1) + " faces (its submesh) and may take more than "
               : grouped(region_faces) + " faces (its submesh) and takes up to ") +
      memory_text(one);
  if (maps_at_once > 1)
    message += ", " + std::to_string(maps_at_once) + " at once (one per thread) " + memory_text(needed) + ",";
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
