// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HEAT_REGION_H
#define EXPMAP_INTERNAL_HEAT_REGION_H

// Step 2 (manual, section 2), its end: the region the distance is
// integrated on, the vertices with the most heat from the source.

#include <expmap/internal/Kth_largest.h>
#include <expmap/internal/Radix_sort.h>
#include <expmap/internal/heat/Query_workspace.h>

#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace expmap {
namespace internal {
namespace heat {

// Candidates solved for heat per region vertex: the heat's level sets need
// room beyond the region inside the candidates (1.0 or 1.6: 1-2% more
// factor entries on lion-head and holes; 1.6 also retries more).
constexpr double candidate_excess = 1.3;

// Vertices every region search reaches beyond its share, for small patches
// whose few rings a proportional budget leaves no room (0: 2-6x the
// retried 1% queries on lion-head, holes and mech-holes-shark).
constexpr std::size_t breadth_first_extra = 16;

// Vertices a region search reaches for a patch of `target` vertices on a
// region `growth` times larger, `excess` times as many.
inline std::size_t breadth_first_budget(std::size_t target, double growth, double excess) {
  return static_cast<std::size_t>(std::ceil(growth * excess * static_cast<double>(target))) +
         breadth_first_extra;
}

// The `count` rows of `rows` (ascending) with the most heat from the
// source, ties to the lower row, into `out` in ascending order: by the
// count-th largest heat value and one pass, a selection on the values
// themselves rather than on rows compared through the heat array.
inline void hottest_rows(const std::vector<std::size_t>& rows, std::size_t count,
                         std::vector<std::size_t>& out, Workspace& ws) {
  out.clear();
  if (count >= rows.size()) {
    out.assign(rows.begin(), rows.end());
    return;
  }
  if (count == 0) return;
  std::size_t hotter = 0;
  const double threshold = kth_largest(
      rows.size(), count, [&](std::size_t i) { return ws.heat[rows[i]]; }, ws.heat_values, hotter);
  // Rows hotter than the threshold all belong; of those at it, the lowest.
  std::size_t at_threshold = count - hotter;
  for (const std::size_t row : rows) {
    const double h = ws.heat[row];
    if (h > threshold || (h == threshold && at_threshold > 0 && at_threshold--)) out.push_back(row);
  }
}

// Sets ws.heat_row to the `kept` hottest candidates, the source first, in
// candidate order. Heat level sets are near-geodesic circles, so the
// cut-off of the Poisson right-hand side is nearly rotationally symmetric
// and shifts distances by a nearly constant amount, which the normalization
// at the source removes (a graph-distance region's polygonal edge would
// bend the distance field instead).
inline void choose_region(std::size_t kept, Workspace& ws) {
  ws.rows.resize(ws.candidates.size());
  std::iota(ws.rows.begin(), ws.rows.end(), std::size_t{0});
  hottest_rows(ws.rows, kept, ws.heat_row, ws);
  // The source leads the region (its heat is the largest, but a poor mesh
  // could break that tie; keep it regardless).
  if (!ws.heat_row.empty() && ws.heat_row.front() != 0) {
    ws.heat_row.pop_back();
    ws.heat_row.insert(ws.heat_row.begin(), 0);
  }
}

// Marks the chosen region and fills ws.region, ws.region_heat and
// ws.region_by_index.
inline void mark_region(Workspace& ws) {
  const std::size_t kept = ws.heat_row.size();
  ws.region.resize(kept);
  ws.region_heat.resize(kept);
  ws.in_region.next_query();
  for (std::size_t i = 0; i < kept; ++i) {
    ws.region[i] = ws.candidates[ws.heat_row[i]];
    ws.region_heat[i] = ws.heat[ws.heat_row[i]];
    ws.in_region.mark(ws.region[i], static_cast<int>(i));
  }
  // The loops over the region's faces and neighbours read per-vertex arrays;
  // in vertex order (which follows the surface, see locality_order) they
  // stream through memory instead of jumping between breadth-first rings.
  ws.region_by_index.assign(ws.region.begin(), ws.region.end());
  radix_sort_indices(ws.region_by_index, ws.sort_scratch);
}

}  // namespace heat
}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HEAT_REGION_H
