// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_ERRORS_H
#define EXPMAP_ERRORS_H

/// \file Errors.h
/// The exceptions expmap throws for input it cannot use.

#include <stdexcept>
#include <string>

namespace expmap {

/// \ingroup PkgExpmapRef
/// Thrown when the mesh or a parameter cannot be used; `what()` names the
/// offending vertex, face or parameter and says what to do about it.
class Invalid_input : public std::invalid_argument {
 public:
  /// `message` becomes `what()`.
  explicit Invalid_input(const std::string& message) : std::invalid_argument(message) {}
};

/// \ingroup PkgExpmapRef
/// Thrown when a computation cannot deliver a trustworthy result for valid
/// input (for example, heat that underflows to zero inside the patch).
class Computation_error : public std::runtime_error {
 public:
  /// `message` becomes `what()`.
  explicit Computation_error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace expmap

#endif  // EXPMAP_ERRORS_H
