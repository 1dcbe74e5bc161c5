// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HAS_COMPUTE_AT_POINT_H
#define EXPMAP_INTERNAL_HAS_COMPUTE_AT_POINT_H

#include <expmap/Patch.h>
#include <expmap/internal/Point_source.h>

#include <type_traits>
#include <utility>

namespace expmap {
namespace internal {

/// Whether the method class `Method` maps from points of faces, that is,
/// provides `compute_at_point()` (see `Method_front`): its
/// `compute(Surface_point, ...)` and `compute_many(std::vector<Surface_point>, ...)`
/// compile only then. The command-line program and the Python module ask
/// it to refuse point sources, with a clear message, for methods that do
/// not; once every method maps from points, this trait and those checks go.
template <class Method, class = void>
struct Has_compute_at_point : std::false_type {};

template <class Method>
struct Has_compute_at_point<
    Method, std::void_t<decltype(std::declval<const Method&>().compute_at_point(
                std::declval<const Point_source&>(), std::declval<const Patch&>(),
                std::declval<const typename Method::Query&>()))>> : std::true_type {};

template <class Method>
constexpr bool has_compute_at_point_v = Has_compute_at_point<Method>::value;

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HAS_COMPUTE_AT_POINT_H
