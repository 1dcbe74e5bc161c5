// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PRECOMPUTATION_PROGRESS_H
#define EXPMAP_PRECOMPUTATION_PROGRESS_H

/// \file Precomputation_progress.h
/// Progress reports of a long precomputation (the heat method's takes a
/// minute on millions of vertices), for a progress bar or a status page.

#include <functional>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Called by a precomputation at the start of each of its steps with the
/// step's name (e.g. "Poisson factorization") and the estimated fraction
/// of the precomputation's time done before it, in [0, 1); and once at the
/// end with "done" and 1. Called on the thread that runs the
/// precomputation; the name is a string literal, valid for the program's
/// lifetime. An exception the callback throws ends the precomputation and
/// leaves the constructor that runs it (a way to cancel it).
using Precomputation_callback = std::function<void(const char* step, double fraction)>;

}  // namespace expmap

#endif  // EXPMAP_PRECOMPUTATION_PROGRESS_H
