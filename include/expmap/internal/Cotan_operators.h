// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_COTAN_OPERATORS_H
#define EXPMAP_INTERNAL_COTAN_OPERATORS_H

#include <expmap/internal/Intrinsic_triangulation.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

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

#endif  // EXPMAP_INTERNAL_COTAN_OPERATORS_H
