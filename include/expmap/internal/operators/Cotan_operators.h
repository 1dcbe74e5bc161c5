// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_OPERATORS_COTAN_OPERATORS_H
#define EXPMAP_INTERNAL_OPERATORS_COTAN_OPERATORS_H

#include <expmap/internal/operators/Intrinsic_triangulation.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace expmap {
namespace internal {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Area and corner cotangents of every face of `tri`.
inline std::vector<Triangle_shape> triangle_shapes(const Intrinsic_triangulation& tri) {
  std::vector<Triangle_shape> shapes(tri.number_of_faces());
  for (std::size_t f = 0; f < shapes.size(); ++f) shapes[f] = triangle_shape(tri.length[f]);
  return shapes;
}

/// The positive semi-definite cotan Laplacian L (L = -B of the paper's
/// section 3): L_ij = -(cot a_ij + cot b_ij) / 2, L_ii = -sum_j L_ij.
/// Boundary edges get their single cotangent, which is the natural (zero
/// Neumann) boundary condition. `corner_regularization` is added to the
/// diagonal once per incident face corner (CGAL's Heat_method_3 adds 1e-8).
inline Sparse_matrix cotan_laplacian(const Intrinsic_triangulation& tri,
                                     const std::vector<Triangle_shape>& shapes,
                                     double corner_regularization = 0.0) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(12 * tri.number_of_faces());
  for (std::size_t f = 0; f < tri.number_of_faces(); ++f) {
    const auto& c = tri.face[f];
    for (int k = 0; k < 3; ++k) {
      // The cotangent at corner k weighs the opposite edge (k+1, k+2).
      const int i = c[(k + 1) % 3], j = c[(k + 2) % 3];
      const double w = 0.5 * shapes[f].cotangent[k];
      t.emplace_back(i, j, -w);
      t.emplace_back(j, i, -w);
      t.emplace_back(i, i, w);
      t.emplace_back(j, j, w);
      if (corner_regularization != 0.0) t.emplace_back(c[k], c[k], corner_regularization);
    }
  }
  const int n = static_cast<int>(tri.number_of_vertices);
  Sparse_matrix L(n, n);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

/// Lumped (barycentric) mass: a third of the area of every incident face.
inline Eigen::VectorXd lumped_mass(const Intrinsic_triangulation& tri,
                                   const std::vector<Triangle_shape>& shapes) {
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(static_cast<int>(tri.number_of_vertices));
  for (std::size_t f = 0; f < tri.number_of_faces(); ++f)
    for (int v : tri.face[f]) mass[v] += shapes[f].area / 3.0;
  return mass;
}

/// Lumped mixed Voronoi mass (Meyer, Desbrun, Schroeder and Barr, "Discrete
/// differential-geometry operators for triangulated 2-manifolds", VisMath
/// 2002): in a non-obtuse triangle each corner gets the part of the
/// triangle nearer to it than to the other corners, (|e1|^2 cot b + |e2|^2
/// cot a) / 8 over its two edges e1, e2 and their opposite angles b, a; an
/// obtuse triangle gives half its area to the obtuse corner and a quarter
/// to each other one (its circumcentre lies outside it). Every triangle's
/// area is shared out exactly, as in `lumped_mass`.
inline Eigen::VectorXd mixed_voronoi_mass(const Intrinsic_triangulation& tri,
                                          const std::vector<Triangle_shape>& shapes) {
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(static_cast<int>(tri.number_of_vertices));
  for (std::size_t f = 0; f < tri.number_of_faces(); ++f) {
    const Triangle_shape& shape = shapes[f];
    const std::array<double, 3>& l = tri.length[f];  // l[k] = |c_k c_k+1|
    const auto& cot = shape.cotangent;
    const bool obtuse = cot[0] < 0 || cot[1] < 0 || cot[2] < 0;
    for (int k = 0; k < 3; ++k) {
      const int v = tri.face[f][k];
      if (obtuse) {
        mass[v] += cot[k] < 0 ? shape.area / 2 : shape.area / 4;
        continue;
      }
      // Edge (k, k+1) faces corner k+2; edge (k+2, k) faces corner k+1.
      const double next = l[k], previous = l[(k + 2) % 3];
      mass[v] += (next * next * cot[(k + 2) % 3] + previous * previous * cot[(k + 1) % 3]) / 8;
    }
  }
  return mass;
}

/// Sets row and column `v` of a symmetric matrix to those of the identity.
/// Used for isolated vertices (no face: nothing diffuses there) and for the
/// vertex pinned in each component of the Poisson system.
inline void make_identity_row(Sparse_matrix& A, const std::vector<int>& vertices) {
  if (vertices.empty()) return;
  std::vector<char> is_pinned(static_cast<std::size_t>(A.rows()), 0);
  for (int v : vertices) is_pinned[v] = 1;
  A.prune([&](int row, int col, double) { return !is_pinned[row] && !is_pinned[col]; });
  for (int v : vertices) A.coeffRef(v, v) = 1.0;
  A.makeCompressed();
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_OPERATORS_COTAN_OPERATORS_H
