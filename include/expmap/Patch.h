// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PATCH_H
#define EXPMAP_PATCH_H

/// \file Patch.h
/// Which vertices an exponential map is computed for.

#include <expmap/Errors.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapRef
/// The region of a query, shared by all methods of the package:
/// every vertex within a geodesic radius, the k vertices nearest to the
/// source, a fraction of the mesh's vertices (nearest first), or an explicit
/// set of vertices given by their indices (0-based, in the order of
/// `vertices(tm)`). Patches never leave the source's connected component.
class Patch {
 public:
  /// Which of the four factory functions made the patch.
  enum class Kind {
    geodesic_radius,  ///< `geodesic_radius()`: `radius()` is set
    vertex_count,     ///< `vertex_count()`: `count()` is set
    fraction,         ///< `fraction()`: `fraction_of_mesh()` is set
    vertex_set        ///< `vertex_set()`: `vertices()` is set
  };

  /// All vertices whose distance to the source is at most `radius`.
  /// \throws Invalid_input unless `radius` is positive and finite.
  static Patch geodesic_radius(double radius) {
    if (!(radius > 0) || !std::isfinite(radius))
      throw Invalid_input("the patch radius must be positive and finite (got " +
                          std::to_string(radius) + ")");
    Patch p(Kind::geodesic_radius);
    p.m_radius = radius;
    return p;
  }

  /// The `count` vertices nearest to the source (the source included).
  /// \throws Invalid_input if `count` is 0.
  static Patch vertex_count(std::size_t count) {
    if (count == 0) throw Invalid_input("the patch must have at least one vertex (got 0)");
    Patch p(Kind::vertex_count);
    p.m_count = count;
    return p;
  }

  /// The nearest `fraction` of all vertices of the mesh (rounded up);
  /// `fraction(1)` maps the whole connected component of the source.
  /// \throws Invalid_input unless 0 < fraction <= 1.
  static Patch fraction(double fraction) {
    if (!(fraction > 0 && fraction <= 1))
      throw Invalid_input("the patch fraction must be in (0, 1] (got " + std::to_string(fraction) +
                          ")");
    Patch p(Kind::fraction);
    p.m_fraction = fraction;
    return p;
  }

  /// Exactly these vertices (indices into `vertices(tm)`; the source is
  /// always added). Distances and angles are those of the surrounding mesh.
  static Patch vertex_set(std::vector<std::size_t> vertex_indices) {
    if (vertex_indices.empty()) throw Invalid_input("the patch vertex set is empty");
    Patch p(Kind::vertex_set);
    p.m_vertices = std::move(vertex_indices);
    return p;
  }

  /// The kind of patch; the accessor of that kind holds its parameter,
  /// the others return 0 or an empty set.
  Kind kind() const { return m_kind; }
  /// The radius of a `geodesic_radius()` patch.
  double radius() const { return m_radius; }
  /// The count of a `vertex_count()` patch.
  std::size_t count() const { return m_count; }
  /// The fraction of a `fraction()` patch.
  double fraction_of_mesh() const { return m_fraction; }
  /// The vertex indices of a `vertex_set()` patch, as given.
  const std::vector<std::size_t>& vertices() const { return m_vertices; }

  /// The number of vertices a count or fraction patch asks for on a mesh of
  /// `mesh_vertices` vertices (0 for the other kinds).
  std::size_t target_count(std::size_t mesh_vertices) const {
    if (m_kind == Kind::vertex_count) return m_count;
    if (m_kind == Kind::fraction)
      return static_cast<std::size_t>(std::ceil(m_fraction * static_cast<double>(mesh_vertices)));
    return 0;
  }

 private:
  explicit Patch(Kind kind) : m_kind(kind) {}
  Kind m_kind;
  double m_radius = 0;
  std::size_t m_count = 0;
  double m_fraction = 0;
  std::vector<std::size_t> m_vertices;
};

/// \ingroup PkgExpmapRef
/// Per-query settings shared by all methods.
struct Query_options {
  /// Direction of angle zero at the source, projected onto its tangent
  /// plane. Default: the world x axis (the y axis where the source normal is
  /// within 30 degrees of x).
  std::optional<std::array<double, 3>> reference_direction;
  /// Cut the map to its fold-free disk: keep only the vertices nearer than
  /// `Local_map::fold_free_radius` (the source always), so that no triangle
  /// of the result is flipped; a map without a fold stays whole. See
  /// `trim_to_fold_free_disk()`.
  bool trim_folds = false;
  /// Fill `Local_map::fold_free_radius` (one more pass over the patch's
  /// triangles; `trim_folds` fills it too).
  bool find_fold_free_radius = false;
};

}  // namespace expmap

#endif  // EXPMAP_PATCH_H
