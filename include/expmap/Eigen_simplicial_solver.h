// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_EIGEN_SIMPLICIAL_SOLVER_H
#define EXPMAP_EIGEN_SIMPLICIAL_SOLVER_H

/// \file Eigen_simplicial_solver.h
/// Eigen `SimplicialLDLT` model of the `SparseCholeskySolver` concept.

#include <expmap/Cholesky_factor_view.h>

#include <Eigen/Core>
#include <iostream>  // Eigen/MetisSupport uses std::cerr without including it
#include <Eigen/MetisSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <stdexcept>

namespace expmap {

/// \ingroup PkgExpmapSolvers
/// Factors a symmetric positive definite matrix with Eigen's
/// `SimplicialLDLT`, ordered by METIS nested dissection (`Eigen::MetisOrdering`),
/// and exposes the unit-diagonal LDL^T factor for localized solves.
///
/// Slower to factor than `Cholmod_solver` (no supernodes), but needs nothing
/// beyond Eigen and METIS.
///
/// \cgalModels `SparseCholeskySolver`
class Eigen_simplicial_solver {
 public:
  /// Column-major sparse matrix type accepted by `factor()`.
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// Factors `A` (only its lower triangle is read).
  /// \throws std::runtime_error if `A` is not square or not positive definite.
  void factor(const Matrix& A) {
    if (A.rows() != A.cols())
      throw std::runtime_error("Eigen_simplicial_solver: the matrix is not square");
    m_ldlt.compute(A);
    m_diagonal = m_ldlt.vectorD();  // vectorD() returns a copy: keep one alive
    if (m_ldlt.info() != Eigen::Success || !(m_diagonal.array() > 0).all())
      throw std::runtime_error(
          "Eigen_simplicial_solver: the matrix is not positive definite; the mesh may "
          "have degenerate or disconnected parts");
    const auto& inverse = m_ldlt.permutationP().indices();  // row of A -> pivot
    m_permutation.resize(inverse.size());
    for (int row = 0; row < inverse.size(); ++row) m_permutation[inverse[row]] = row;
  }

  /// The factor, for localized solves. \pre `factor()` succeeded.
  Cholesky_factor_view factor_view() const {
    const auto& L = m_ldlt.matrixL().nestedExpression();
    Cholesky_factor_view v;
    v.size = static_cast<int>(L.rows());
    v.permutation = m_permutation.data();
    v.column_start = L.outerIndexPtr();
    v.row_index = L.innerIndexPtr();
    v.value = L.valuePtr();
    v.unit_diagonal = true;
    v.diagonal = m_diagonal.data();
    return v;
  }

  /// Full solve of A x = b by Eigen's own triangular solves (an oracle).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return m_ldlt.solve(b); }

  /// Number of stored entries of the factor.
  std::size_t factor_nonzeros() const {
    return static_cast<std::size_t>(m_ldlt.matrixL().nestedExpression().nonZeros()) +
           static_cast<std::size_t>(m_diagonal.size());
  }

 private:
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::MetisOrdering<int>> m_ldlt;
  Eigen::VectorXi m_permutation;
  Eigen::VectorXd m_diagonal;
};

}  // namespace expmap

#endif  // EXPMAP_EIGEN_SIMPLICIAL_SOLVER_H
