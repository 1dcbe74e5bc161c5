// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_MAP_REQUEST_H
#define EXPMAP_TOOLS_VIEWER_MAP_REQUEST_H

/// \file Map_request.h
/// The parameters of `GET /api/map`, checked: everything a request can say
/// is parsed here, before any work, so that a bad request costs nothing and
/// gets one clear message (HTTP 400).

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

namespace expmap_view {

/// A request that asks for something impossible: HTTP 400 with its message.
class Bad_request : public std::runtime_error {
 public:
  explicit Bad_request(const std::string& message) : std::runtime_error(message) {}
};

/// What the server allows a request to ask for, so that no request holds
/// the server for long or makes it hold much memory.
struct Request_limits {
  /// The largest patch fraction: a map of the whole mesh from the exact
  /// method would take minutes.
  double max_fraction = 0.25;
  /// The largest patch radius, in mesh units (the server sets it to the
  /// diagonal of the mesh's bounding box, beyond which a radius adds nothing).
  double max_radius = 1;
  /// Heat's time factors from this range only (each new one is a
  /// precomputation of its own).
  double min_time_factor = 0.1, max_time_factor = 1000;
};

/// One map query: the point of space whose nearest surface point is the
/// source, the method, the patch (exactly one of fraction and radius) and
/// the heat method's time factor.
struct Map_request {
  std::array<double, 3> point{};
  std::string method;
  std::optional<double> fraction, radius;
  std::optional<double> time_factor;  ///< `m`; only with method "heat"
};

/// `text` (a value from a request) as an error message may echo it: its
/// first 40 bytes, each one outside printable ASCII replaced by '?', and
/// "..." if cut. A request can carry any bytes at any length; the message
/// stays short, readable and valid UTF-8.
inline std::string shown(const std::string& text) {
  constexpr std::size_t max_length = 40;
  std::string s = text.substr(0, max_length);
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  if (text.size() > max_length) s += "...";
  return s;
}

/// A finite number filling the whole of `text`; `name` for the message.
inline double parse_number(const std::string& name, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || errno == ERANGE || !std::isfinite(value))
    throw Bad_request(name + " must be a finite number (got '" + shown(text) + "')");
  return value;
}

/// Three finite numbers "X,Y,Z".
inline std::array<double, 3> parse_point(const std::string& name, const std::string& text) {
  std::array<double, 3> p{};
  std::string::size_type start = 0;
  for (int k = 0; k < 3; ++k) {
    const std::string::size_type comma = text.find(',', start);
    if ((k < 2) != (comma != std::string::npos))
      throw Bad_request(name + " must be three comma-separated numbers X,Y,Z (got '" + shown(text) + "')");
    p[k] = parse_number(name, text.substr(start, k < 2 ? comma - start : std::string::npos));
    start = comma + 1;
  }
  return p;
}

/// The request that the query parameters `params` (name to value, as an
/// HTTP library hands them over; a name may come more than once) state.
/// \throws Bad_request naming the parameter for unknown or repeated
///         parameters, a missing point, method or patch, both a fraction
///         and a radius, values out of range, and `m` with a method other
///         than heat. The method's name is checked by the caller, which
///         knows the methods.
inline Map_request parse_map_request(const std::multimap<std::string, std::string>& params,
                                     const Request_limits& limits) {
  static const char* const known[] = {"point", "method", "fraction", "radius", "m"};
  for (auto it = params.begin(); it != params.end(); it = params.upper_bound(it->first)) {
    bool is_known = false;
    for (const char* k : known) is_known = is_known || it->first == k;
    if (!is_known)
      throw Bad_request("unknown parameter '" + shown(it->first) +
                        "' (known: point, method, fraction, radius, m)");
    if (params.count(it->first) > 1)
      throw Bad_request("parameter '" + shown(it->first) + "' is given more than once");
  }
  const auto value = [&](const char* name) -> std::optional<std::string> {
    const auto it = params.find(name);
    if (it == params.end()) return std::nullopt;
    return it->second;
  };

  Map_request r;
  const auto point = value("point");
  if (!point) throw Bad_request("point=X,Y,Z is required (a point on or near the surface)");
  r.point = parse_point("point", *point);
  const auto method = value("method");
  if (!method || method->empty()) throw Bad_request("method is required (e.g. method=dgpc)");
  r.method = *method;

  if (const auto f = value("fraction")) {
    r.fraction = parse_number("fraction", *f);
    if (!(*r.fraction > 0 && *r.fraction <= limits.max_fraction))
      throw Bad_request("fraction must be in (0, " + std::to_string(limits.max_fraction) +
                        "] (got " + shown(*f) + ")");
  }
  if (const auto radius = value("radius")) {
    r.radius = parse_number("radius", *radius);
    if (!(*r.radius > 0 && *r.radius <= limits.max_radius))
      throw Bad_request("radius must be in (0, " + std::to_string(limits.max_radius) +
                        "], the mesh's bounding-box diagonal (got " + shown(*radius) + ")");
  }
  if (r.fraction.has_value() == r.radius.has_value())
    throw Bad_request("give exactly one of fraction=F and radius=R");

  if (const auto m = value("m")) {
    if (r.method != "heat") throw Bad_request("m (the time factor) applies only to method=heat");
    r.time_factor = parse_number("m", *m);
    if (!(*r.time_factor >= limits.min_time_factor && *r.time_factor <= limits.max_time_factor))
      throw Bad_request("m must be in [" + std::to_string(limits.min_time_factor) + ", " +
                        std::to_string(limits.max_time_factor) + "] (got " + shown(*m) + ")");
  }
  return r;
}

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_MAP_REQUEST_H
