// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_CHOLMOD_SOLVER_H
#define EXPMAP_CHOLMOD_SOLVER_H

/// \file Cholmod_solver.h
/// CHOLMOD (SuiteSparse) model of the `SparseCholeskySolver` concept.

#include <expmap/Cholesky_factor_view.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cholmod.h>

#include <stdexcept>
#include <string>

namespace expmap {

/// \ingroup PkgExpmapSolvers
/// Factors a symmetric positive definite matrix with CHOLMOD, ordered by
/// METIS nested dissection, and exposes the factor for localized solves.
///
/// The factorization itself is supernodal (fast, BLAS based); the factor is
/// then converted once to a simplicial LL^T in compressed columns, the form
/// the localized triangular solves traverse column by column.
///
/// \cgalModels `SparseCholeskySolver`
class Cholmod_solver {
 public:
  /// Column-major sparse matrix type accepted by `factor()`.
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  Cholmod_solver() { cholmod_start(&m_common); configure(); }
  ~Cholmod_solver() { release(); cholmod_finish(&m_common); }
  Cholmod_solver(const Cholmod_solver&) = delete;
  Cholmod_solver& operator=(const Cholmod_solver&) = delete;

  /// Factors `A` (only its lower triangle is read).
  /// \throws std::runtime_error if `A` is not square or not positive definite.
  void factor(const Matrix& A) {
    if (A.rows() != A.cols())
      throw std::runtime_error("Cholmod_solver: the matrix is not square");
    release();
    Matrix lower = A.triangularView<Eigen::Lower>();
    lower.makeCompressed();
    cholmod_sparse view = sparse_view(lower);
    m_factor = cholmod_analyze(&view, &m_common);
    if (m_factor == nullptr) throw_status("symbolic analysis");
    cholmod_factorize(&view, m_factor, &m_common);
    if (m_common.status != CHOLMOD_OK || m_factor->minor < m_factor->n)
      throw std::runtime_error(
          "Cholmod_solver: the matrix is not positive definite (pivot " +
          std::to_string(m_factor->minor) + " of " + std::to_string(m_factor->n) +
          " failed); the mesh may have degenerate or disconnected parts");
    if (!cholmod_change_factor(CHOLMOD_REAL, /*to_ll=*/1, /*to_super=*/0,
                               /*to_packed=*/1, /*to_monotonic=*/1, m_factor, &m_common))
      throw_status("conversion to a simplicial factor");
  }

  /// The factor, for localized solves. \pre `factor()` succeeded.
  Cholesky_factor_view factor_view() const {
    Cholesky_factor_view v;
    if (m_factor == nullptr) return v;
    v.size = static_cast<int>(m_factor->n);
    v.permutation = static_cast<const int*>(m_factor->Perm);
    v.column_start = static_cast<const int*>(m_factor->p);
    v.row_index = static_cast<const int*>(m_factor->i);
    v.value = static_cast<const double*>(m_factor->x);
    v.unit_diagonal = false;
    return v;
  }

  /// Full solve of A x = b with CHOLMOD's own triangular solves (an
  /// independent oracle for the localized kernel). \pre `factor()` succeeded.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd rhs = b;
    cholmod_dense dense{};
    dense.nrow = dense.d = static_cast<size_t>(rhs.size());
    dense.ncol = 1;
    dense.nzmax = dense.nrow;
    dense.x = rhs.data();
    dense.xtype = CHOLMOD_REAL;
    dense.dtype = CHOLMOD_DOUBLE;
    cholmod_common* common = const_cast<cholmod_common*>(&m_common);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, m_factor, &dense, common);
    if (x == nullptr) throw std::runtime_error("Cholmod_solver: solve failed");
    Eigen::VectorXd result =
        Eigen::Map<Eigen::VectorXd>(static_cast<double*>(x->x), rhs.size());
    cholmod_free_dense(&x, common);
    return result;
  }

  /// Number of stored entries of the factor (its memory is about 12 bytes each).
  std::size_t factor_nonzeros() const {
    return m_factor == nullptr ? 0 : static_cast<const int*>(m_factor->p)[m_factor->n];
  }

 private:
  void configure() {
    // METIS nested dissection only: its balanced separators keep the
    // elimination tree shallow, which is what makes localized solves cheap.
    m_common.nmethods = 1;
    m_common.method[0].ordering = CHOLMOD_METIS;
    m_common.postorder = 1;
    m_common.supernodal = CHOLMOD_SUPERNODAL;
    m_common.print = 0;  // errors are reported by exceptions, not on stderr
  }

  static cholmod_sparse sparse_view(Matrix& lower) {
    cholmod_sparse s{};
    s.nrow = static_cast<size_t>(lower.rows());
    s.ncol = static_cast<size_t>(lower.cols());
    s.nzmax = static_cast<size_t>(lower.nonZeros());
    s.p = lower.outerIndexPtr();
    s.i = lower.innerIndexPtr();
    s.x = lower.valuePtr();
    s.stype = -1;  // symmetric, lower triangle stored
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
  }

  void throw_status(const char* step) {
    throw std::runtime_error(std::string("Cholmod_solver: ") + step +
                             " failed (CHOLMOD status " + std::to_string(m_common.status) + ")");
  }

  void release() {
    if (m_factor != nullptr) cholmod_free_factor(&m_factor, &m_common);
  }

  cholmod_common m_common;
  cholmod_factor* m_factor = nullptr;
};

}  // namespace expmap

#endif  // EXPMAP_CHOLMOD_SOLVER_H
