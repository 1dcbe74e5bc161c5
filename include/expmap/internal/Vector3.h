// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_VECTOR3_H
#define EXPMAP_INTERNAL_VECTOR3_H

#include <array>
#include <cmath>

namespace expmap {
namespace internal {

/// Plain double 3-vectors for the inner loops, independent of the kernel the
/// user's mesh is built on (coordinates are converted once with to_double).
using Vector3 = std::array<double, 3>;

inline Vector3 operator+(const Vector3& a, const Vector3& b) {
  return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
}
inline Vector3 operator-(const Vector3& a, const Vector3& b) {
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
inline Vector3 operator*(double s, const Vector3& a) { return {{s * a[0], s * a[1], s * a[2]}}; }
inline Vector3& operator+=(Vector3& a, const Vector3& b) {
  a[0] += b[0];
  a[1] += b[1];
  a[2] += b[2];
  return a;
}
inline double dot(const Vector3& a, const Vector3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vector3 cross(const Vector3& a, const Vector3& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline double squared_norm(const Vector3& a) { return dot(a, a); }
inline double norm(const Vector3& a) { return std::sqrt(dot(a, a)); }

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_VECTOR3_H
