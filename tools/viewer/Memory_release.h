// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_MEMORY_RELEASE_H
#define EXPMAP_TOOLS_VIEWER_MEMORY_RELEASE_H

/// \file Memory_release.h
/// Giving back to the system the memory a large map leaves free. glibc's
/// malloc keeps what a thread frees in that thread's arena for its next
/// allocations, so each of the server's threads would hold on to the
/// largest query it ever ran: on bunny00, ten exact maps at 25% left the
/// server at 2.5 GB (one of them alone peaks at 0.5 GB). Trimming the heap
/// after each large map brings it back to 104 MB; fewer threads or fewer
/// arenas (MALLOC_ARENA_MAX=2) still left 0.88 GB (doc/viewer.md). Small
/// maps leave little, and trimming after each would cost the interactive
/// rates a few milliseconds a map, so they do not trim.

#include "Map_service.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstddef>
#include <string>

namespace expmap_view {

/// Maps of this many vertices or more leave a few MB free (their answer
/// alone is about 1 MB of JSON): after them the heap is trimmed.
constexpr std::size_t trimmed_map_vertices = 10000;

/// Whether the heap is trimmed after answering `r`: after every exact map
/// (its sequence tree is freed at the end) and every map of at least
/// `trimmed_map_vertices` vertices.
inline bool leaves_much_free(const Map_response& r) {
  return r.method == "exact" || r.map.size() >= trimmed_map_vertices;
}

/// Returns the free memory of every arena to the system where the allocator
/// can (glibc's malloc_trim); elsewhere nothing.
inline void release_free_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_MEMORY_RELEASE_H
