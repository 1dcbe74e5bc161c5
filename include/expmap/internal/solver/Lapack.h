// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_SOLVER_LAPACK_H
#define EXPMAP_INTERNAL_SOLVER_LAPACK_H

#include <cstddef>

// The LAPACK routines the library calls, declared here rather than through
// an Eigen decomposition: Eigen's SVD templates would be compiled in every
// translation unit that includes the library. The target expmap::expmap
// links LAPACK (CHOLMOD depends on it already).
extern "C" {
// Singular value decomposition by divide and conquer (column-major). The
// last argument is the length of `jobz`, which gfortran-compiled LAPACK
// takes as a hidden argument.
void dgesdd_(const char* jobz, const int* m, const int* n, double* a, const int* lda, double* s,
             double* u, const int* ldu, double* vt, const int* ldvt, double* work,
             const int* lwork, int* iwork, int* info, std::size_t jobz_length);
}

#endif  // EXPMAP_INTERNAL_SOLVER_LAPACK_H
