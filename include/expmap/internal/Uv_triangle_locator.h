// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_UV_TRIANGLE_LOCATOR_H
#define EXPMAP_INTERNAL_UV_TRIANGLE_LOCATOR_H

// Which triangle of a map's (u, v) plane holds a point: a bucket grid over
// the triangles' bounding boxes, about one triangle per cell, so locating
// the few dozen points of a polar grid costs about as much as listing the
// patch's triangles.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace expmap {
namespace internal {

/// A point's triangle and its barycentric coordinates (each in [0, 1],
/// summing to 1).
struct Uv_location {
  std::size_t triangle;
  std::array<double, 3> weight;
};

class Uv_triangle_locator {
 public:
  using Uv = std::array<double, 2>;
  using Corners = std::array<Uv, 3>;

  /// The counter-clockwise triangles `triangles` (clockwise and collapsed
  /// ones hold no point: they are where the map folds), in a square grid
  /// over [-extent, extent]^2.
  Uv_triangle_locator(const std::vector<Corners>& triangles, double extent)
      : m_triangles(triangles), m_extent(extent) {
    const std::size_t count = std::max<std::size_t>(1, triangles.size());
    m_cells = std::max<std::size_t>(
        1, std::min<std::size_t>(512, static_cast<std::size_t>(std::sqrt(double(count)))));
    m_cell_size = 2 * extent / double(m_cells);
    std::vector<std::size_t> count_in(m_cells * m_cells + 1, 0);
    // Two passes (count, then fill) give every cell's list in one array.
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        for (std::size_t c = 1; c < count_in.size(); ++c) count_in[c] += count_in[c - 1];
        m_start = count_in;
        m_entries.resize(count_in.back());
      }
      for (std::size_t t = 0; t < triangles.size(); ++t) {
        if (!(twice_area(triangles[t]) > 0)) continue;
        const Corners& p = triangles[t];
        const std::size_t x0 = cell(std::min({p[0][0], p[1][0], p[2][0]}));
        const std::size_t x1 = cell(std::max({p[0][0], p[1][0], p[2][0]}));
        const std::size_t y0 = cell(std::min({p[0][1], p[1][1], p[2][1]}));
        const std::size_t y1 = cell(std::max({p[0][1], p[1][1], p[2][1]}));
        for (std::size_t y = y0; y <= y1; ++y)
          for (std::size_t x = x0; x <= x1; ++x) {
            const std::size_t c = y * m_cells + x;
            if (pass == 0)
              ++count_in[c + 1];
            else
              m_entries[--count_in[c + 1]] = t;
          }
      }
    }
  }

  /// The first counter-clockwise triangle (in the order given) that holds
  /// `point`, edges included; none if no triangle does.
  std::optional<Uv_location> locate(const Uv& point) const {
    if (!(std::abs(point[0]) <= m_extent && std::abs(point[1]) <= m_extent)) return std::nullopt;
    const std::size_t c = cell(point[1]) * m_cells + cell(point[0]);
    std::optional<Uv_location> found;
    for (std::size_t e = m_start[c]; e < m_start[c + 1]; ++e) {
      const std::size_t t = m_entries[e];
      if (found && found->triangle < t) continue;
      const Corners& p = m_triangles[t];
      const double area = twice_area(p);
      const double w0 = cross(p[1], p[2], point) / area;
      const double w1 = cross(p[2], p[0], point) / area;
      const double w2 = cross(p[0], p[1], point) / area;
      // A point on an edge shared by two triangles belongs to both; the
      // tolerance keeps it from falling between them by rounding.
      constexpr double on_edge = -1e-12;
      if (w0 < on_edge || w1 < on_edge || w2 < on_edge) continue;
      std::array<double, 3> w{std::max(w0, 0.0), std::max(w1, 0.0), std::max(w2, 0.0)};
      const double sum = w[0] + w[1] + w[2];
      found = Uv_location{t, {w[0] / sum, w[1] / sum, w[2] / sum}};
    }
    return found;
  }

 private:
  static double cross(const Uv& a, const Uv& b, const Uv& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  static double twice_area(const Corners& p) { return cross(p[0], p[1], p[2]); }
  std::size_t cell(double x) const {
    const double i = std::floor((x + m_extent) / m_cell_size);
    return static_cast<std::size_t>(std::clamp(i, 0.0, double(m_cells - 1)));
  }

  const std::vector<Corners>& m_triangles;
  double m_extent;
  std::size_t m_cells = 1;
  double m_cell_size = 1;
  std::vector<std::size_t> m_start;    // cell c's triangles: m_entries[m_start[c], m_start[c + 1])
  std::vector<std::size_t> m_entries;  // triangle indices, by cell
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_UV_TRIANGLE_LOCATOR_H
