// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_OPERATORS_INTRINSIC_TRIANGULATION_H
#define EXPMAP_INTERNAL_OPERATORS_INTRINSIC_TRIANGULATION_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// A triangle mesh described only by its connectivity and its edge lengths.
///
/// The heat method needs nothing but lengths: cotangents, areas, gradients
/// and divergences of piecewise linear functions are all intrinsic. Keeping
/// the operators on this representation lets the same code run on the input
/// mesh (lengths measured in 3D) and on its intrinsic Delaunay triangulation
/// (lengths changed by edge flips), like CGAL's Heat_method_3 modes.
///
/// `length[f][k]` is the length of the edge from `face[f][k]` to
/// `face[f][(k + 1) % 3]`. Faces are oriented consistently (counter-clockwise
/// seen from outside for an oriented input).
struct Intrinsic_triangulation {
  std::size_t number_of_vertices = 0;
  std::vector<std::array<int, 3>> face;
  std::vector<std::array<double, 3>> length;

  std::size_t number_of_faces() const { return face.size(); }
};

/// Quantities of one triangle computed from its three edge lengths.
///
/// Corner k of the triangle is vertex `face[f][k]`; `cotangent[k]` is the
/// cotangent of the interior angle at corner k, which weighs the opposite
/// edge (from corner k+1 to corner k+2) in the cotan Laplacian.
struct Triangle_shape {
  double area = 0;
  std::array<double, 3> cotangent{{0, 0, 0}};
  /// Planar layout: corner 0 at the origin, corner 1 at (x1, 0), corner 2 at
  /// (x2, y2) with y2 > 0, stored as {x1, x2, y2}.
  std::array<double, 3> layout{{0, 0, 0}};
};

/// Area and corner cotangents from edge lengths, robust for slivers.
///
/// Uses cot(angle at k) = (a^2 + b^2 - c^2) / (4 area), where c is the edge
/// opposite corner k, and Kahan's stable formula for the area. A degenerate
/// triangle returns area 0 and zero cotangents; callers reject such input
/// before building operators.
inline Triangle_shape triangle_shape(const std::array<double, 3>& l) {
  // l[0] = |c0 c1|, l[1] = |c1 c2|, l[2] = |c2 c0|; the edge opposite
  // corner k is l[(k + 1) % 3].
  std::array<double, 3> s = l;
  // Kahan: sort a >= b >= c.
  if (s[0] < s[1]) std::swap(s[0], s[1]);
  if (s[1] < s[2]) std::swap(s[1], s[2]);
  if (s[0] < s[1]) std::swap(s[0], s[1]);
  const double a = s[0], b = s[1], c = s[2];
  const double q = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  Triangle_shape shape;
  if (!(q > 0)) return shape;
  shape.area = 0.25 * std::sqrt(q);
  const double inv4A = 1.0 / (4.0 * shape.area);
  for (int k = 0; k < 3; ++k) {
    const double opposite = l[(k + 1) % 3];
    const double adjacent1 = l[k];
    const double adjacent2 = l[(k + 2) % 3];
    shape.cotangent[k] =
        (adjacent1 * adjacent1 + adjacent2 * adjacent2 - opposite * opposite) * inv4A;
  }
  // The height from the area is accurate even for slivers.
  shape.layout = {{l[0], (l[0] * l[0] + l[2] * l[2] - l[1] * l[1]) / (2.0 * l[0]),
                   2.0 * shape.area / l[0]}};
  return shape;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_OPERATORS_INTRINSIC_TRIANGULATION_H
