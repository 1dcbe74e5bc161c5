// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_ERRORS_H
#define EXPMAP_ERRORS_H

/// \file Errors.h
/// The exceptions expmap throws for input it cannot use.

#include <exception>
#include <new>
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

namespace internal {

/// The message a user is shown for `e`: the library's own exceptions as
/// they are; any other (from a dependency or the standard library, whose
/// text speaks of its own internals) in the library's words, as a failure
/// of the computation, with its text kept for a bug report. The program,
/// the batches and the Python module report every exception through this.
inline std::string user_message(const std::exception& e) {
  if (dynamic_cast<const Invalid_input*>(&e) || dynamic_cast<const Computation_error*>(&e))
    return e.what();
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
  return std::string("the computation failed unexpectedly (") + e.what() +
         "); this is a bug in expmap or a library it uses: please report it with the mesh "
         "and the command";
}

}  // namespace internal

}  // namespace expmap

#endif  // EXPMAP_ERRORS_H
