// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_COMMAND_LINE_H
#define EXPMAP_TOOLS_COMMAND_LINE_H

/// \file Command_line.h
/// Parsing of `expmap compute` and `expmap batch` arguments, by hand: the grammar is small, and
/// a dependency (Boost.Program_options needs a compiled library) would cost
/// more than it saves. Only syntax and value ranges are checked here; what
/// needs the mesh (the source index) is checked after reading it.

#include <expmap/Angle_estimator.h>
#include <expmap/Heat_options.h>
#include <expmap/Option_names.h>
#include <expmap/Setting_ranges.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace expmap_cli {

/// A command line that asks for something impossible; reported with the
/// usage exit status (2).
class Usage_error : public std::runtime_error {
 public:
  explicit Usage_error(const std::string& message) : std::runtime_error(message) {}
};

/// A failure of the run itself (files, mesh): exit status 1.
class Runtime_error : public std::runtime_error {
 public:
  explicit Runtime_error(const std::string& message) : std::runtime_error(message) {}
};

enum class Output_format { csv, obj, svg, npz };

struct Output {
  std::string path;
  Output_format format;
};

/// What `expmap compute` was asked to do (and, but for `source`, what each
/// map of `expmap batch` is). Optional fields are unset when
/// the option was not given, so the library's defaults stay in one place.
struct Compute_arguments {
  std::string mesh;
  std::size_t source = 0;
  // A point source instead of `source`: a position whose nearest surface
  // point is mapped from, or a face of the file and the barycentric
  // coordinates of its corners, in the file's order.
  std::optional<std::array<double, 3>> source_point;
  std::optional<std::size_t> source_face;
  std::optional<std::array<double, 3>> barycentric;
  std::string point_option;  // the option that gave point sources ("" for vertices), for messages
  std::optional<double> radius, fraction;
  std::optional<std::size_t> vertex_count;
  std::string method = "heat";
  std::optional<double> time_factor;
  std::optional<expmap::Laplacian_mode> laplacian;
  std::optional<expmap::Vertex_area> vertex_area;
  std::optional<expmap::Factor_precision> factor_precision;
  std::optional<int> query_threads;
  std::optional<expmap::Angle_estimator> angles;
  std::optional<expmap::Near_source_blend> near_source_blend;
  std::optional<expmap::Heat_fallback> fallback;
  std::optional<std::array<double, 3>> reference;
  bool triangulate = true;  // --no-triangulate refuses polygonal faces instead
  bool repair = false;
  bool trim_folds = false;  // --trim-folds: each map cut to its fold-free disk
  bool force = false;       // --force: an exact map beyond its memory estimate is tried anyway
  std::vector<Output> outputs;
  bool help = false;
};

/// Which vertices `expmap batch` maps.
struct Source_selection {
  enum class Kind { all, list, file };
  Kind kind = Kind::all;
  std::vector<std::size_t> list;  // Kind::list
  std::string file;               // Kind::file: read once the mesh is known
};

/// What `expmap batch` was asked to do: the maps of `expmap compute` (whose
/// `source` it does not use) from many sources.
struct Batch_arguments : Compute_arguments {
  Source_selection sources;
  std::string source_points_file;  // --source-points: one X,Y,Z per line, instead of `sources`
  unsigned threads = 0;  // 0: all cores
};

/// The format an output path asks for, by its extension (any letter case).
/// \throws Usage_error for any other extension.
inline Output_format output_format(const std::string& path) {
  const std::string::size_type dot = path.rfind('.');
  const std::string::size_type slash = path.find_last_of("/\\");
  std::string ext;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
    ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "csv") return Output_format::csv;
  if (ext == "obj") return Output_format::obj;
  if (ext == "svg") return Output_format::svg;
  if (ext == "npz") return Output_format::npz;
  throw Usage_error("cannot tell the format of output '" + path +
                    "': its extension must be .csv, .obj or .svg (compute) or .csv, .npz (batch)");
}

/// A finite real number filling the whole of `text`.
inline double parse_real(const std::string& option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || errno == ERANGE || !std::isfinite(value))
    throw Usage_error(option + " expects a finite number (got '" + text + "')");
  return value;
}

/// A non-negative integer filling the whole of `text` (no sign: strtoull
/// would silently wrap "-1" to a huge index).
inline std::size_t parse_index(const std::string& option, const std::string& text) {
  const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isdigit(c) != 0;
  });
  errno = 0;
  const unsigned long long value = digits ? std::strtoull(text.c_str(), nullptr, 10) : 0;
  if (!digits || errno == ERANGE)
    throw Usage_error(option + " expects a non-negative integer (got '" + text + "')");
  return static_cast<std::size_t>(value);
}

/// Throws if an option that may be given once comes again.
inline void check_once(const std::string& name, bool given) {
  if (given) throw Usage_error(name + " is given more than once");
}

/// Three numbers separated by commas, e.g. "1,0,0".
inline std::array<double, 3> parse_vector(const std::string& option, const std::string& text) {
  std::array<double, 3> v{};
  std::string::size_type start = 0;
  for (int k = 0; k < 3; ++k) {
    const std::string::size_type comma = text.find(',', start);
    if ((k < 2) != (comma != std::string::npos))
      throw Usage_error(option + " expects three comma-separated numbers X,Y,Z (got '" + text +
                        "')");
    v[k] = parse_real(option, text.substr(start, k < 2 ? comma - start : std::string::npos));
    start = comma + 1;
  }
  return v;
}

/// Barycentric coordinates "A,B,C", not negative and of positive sum,
/// rescaled to sum 1.
inline std::array<double, 3> parse_barycentric(const std::string& option, const std::string& text) {
  std::array<double, 3> w = parse_vector(option, text);
  const double sum = w[0] + w[1] + w[2];
  if (w[0] < 0 || w[1] < 0 || w[2] < 0 || !(sum > 0) || !std::isfinite(sum))
    throw Usage_error(option + " expects three numbers A,B,C, none negative and not all zero (got '" +
                      text + "')");
  for (double& x : w) x /= sum;
  return w;
}

/// The sources of `expmap batch`: "all", comma-separated indices "3,17,42",
/// or "@FILE" (indices in a file, read later).
inline Source_selection parse_sources(const std::string& option, const std::string& text) {
  Source_selection s;
  if (text == "all") return s;
  if (!text.empty() && text[0] == '@') {
    if (text.size() == 1) throw Usage_error(option + " @FILE needs a file name after '@'");
    s.kind = Source_selection::Kind::file;
    s.file = text.substr(1);
    return s;
  }
  s.kind = Source_selection::Kind::list;
  std::string::size_type start = 0;
  for (;;) {
    const std::string::size_type comma = text.find(',', start);
    s.list.push_back(parse_index(option, text.substr(start, comma - start)));
    if (comma == std::string::npos) return s;
    start = comma + 1;
  }
}

/// Parses the options `compute` and `batch` share and the mesh file,
/// calling `own(name, take_value)` first for the command's own options (it
/// returns false for names it does not know). `--help` stops checking: the
/// caller prints help. `args` excludes the program and command names.
/// \throws Usage_error naming the offending option or value.
template <class Own_options>
void parse_map_options(const std::vector<std::string>& args, const std::string& command,
                       Compute_arguments& a, Own_options own) {
  std::vector<std::string> positional;
  bool method_given = false, options_ended = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string name = args[i], value;
    bool inline_value = false;
    if (options_ended || name.size() < 2 || name[0] != '-') {
      positional.push_back(name);
      continue;
    }
    if (name == "--") {
      options_ended = true;
      continue;
    }
    const std::string::size_type equals = name.find('=');
    if (name.compare(0, 2, "--") == 0 && equals != std::string::npos) {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
      inline_value = true;
    }
    // The value of an option is the next argument, whatever it looks like:
    // "--radius -1" must reach the range check, not read as an option.
    auto take_value = [&]() -> std::string {
      if (inline_value) return value;
      if (i + 1 >= args.size()) throw Usage_error(name + " needs a value");
      return args[++i];
    };
    auto once = [&](bool given) { check_once(name, given); };
    // A real option that must be positive (given at most once).
    auto positive_real = [&](std::optional<double>& field) {
      once(field.has_value());
      const std::string text = take_value();
      field = parse_real(name, text);
      if (!(*field > 0)) throw Usage_error(name + " must be positive (got " + text + ")");
    };
    // A number in the range the library gives the setting (given at most once).
    auto in_range = [&](auto& field, const expmap::Setting_range& range) {
      once(field.has_value());
      const std::string text = take_value();
      using Number = typename std::decay_t<decltype(field)>::value_type;
      if constexpr (std::is_integral_v<Number>) {
        const std::size_t value = parse_index(name, text);
        if (!range.contains(static_cast<double>(value)))
          throw Usage_error(name + " must be " + range.range + " (got " + text + ")");
        field = static_cast<Number>(value);
      } else {
        field = parse_real(name, text);
        if (!range.contains(*field))
          throw Usage_error(name + " must be " + range.range + " (got " + text + ")");
      }
    };
    // A setting named as in expmap/Option_names.h (given at most once).
    auto named = [&](auto& field) {
      once(field.has_value());
      try {
        field = expmap::from_string<typename std::decay_t<decltype(field)>::value_type>(
            take_value());
      } catch (const expmap::Invalid_input& e) {
        throw Usage_error(name + ": " + e.what());
      }
    };

    if (name == "-h" || name == "--help") {
      a.help = true;
      return;
    } else if (own(name, take_value)) {
      continue;
    } else if (name == "--radius") {
      positive_real(a.radius);
    } else if (name == "--fraction") {
      once(a.fraction.has_value());
      const std::string text = take_value();
      a.fraction = parse_real(name, text);
      if (!(*a.fraction > 0 && *a.fraction <= 1))
        throw Usage_error("--fraction must be in (0, 1] (got " + text + ")");
    } else if (name == "--vertices") {
      once(a.vertex_count.has_value());
      a.vertex_count = parse_index(name, take_value());
      if (*a.vertex_count == 0) throw Usage_error("--vertices must be at least 1");
    } else if (name == "--method") {
      once(method_given);
      a.method = take_value();
      method_given = true;
    } else if (name == "--time-factor") {
      in_range(a.time_factor, expmap::setting_ranges::time_factor);
    } else if (name == "--laplacian") {
      named(a.laplacian);
    } else if (name == "--vertex-area") {
      named(a.vertex_area);
    } else if (name == "--factor-precision") {
      named(a.factor_precision);
    } else if (name == "--query-threads") {
      in_range(a.query_threads, expmap::setting_ranges::query_threads);
    } else if (name == "--angles") {
      named(a.angles);
    } else if (name == "--fallback") {
      named(a.fallback);
    } else if (name == "--near-source-blend") {
      once(a.near_source_blend.has_value());
      const std::string text = take_value();
      const std::string::size_type comma = text.find(',');
      if (comma == std::string::npos)
        throw Usage_error("--near-source-blend takes BEGIN,END in mean edge lengths (got '" +
                          text + "')");
      expmap::Near_source_blend blend;
      blend.begin = parse_real(name, text.substr(0, comma));
      blend.end = parse_real(name, text.substr(comma + 1));
      const expmap::Setting_range& range = expmap::setting_ranges::near_source_blend;
      if (!range.contains(blend.begin) || !range.contains(blend.end) || blend.begin > blend.end)
        throw Usage_error("--near-source-blend must be " + std::string(range.range) + " (got '" +
                          text + "')");
      a.near_source_blend = blend;
    } else if (name == "--reference") {
      once(a.reference.has_value());
      a.reference = parse_vector(name, take_value());
      const auto& r = *a.reference;
      if (r[0] == 0 && r[1] == 0 && r[2] == 0) throw Usage_error("--reference must not be zero");
    } else if (name == "--triangulate" || name == "--no-triangulate" || name == "--repair") {
      // --triangulate is the default; it is still accepted so that older
      // command lines keep working.
      if (inline_value) throw Usage_error(name + " takes no value");
      if (name == "--repair")
        a.repair = true;
      else
        a.triangulate = name == "--triangulate";
    } else if (name == "--trim-folds" || name == "--force") {
      if (inline_value) throw Usage_error(name + " takes no value");
      (name == "--force" ? a.force : a.trim_folds) = true;
    } else if (name == "-o" || name == "--output") {
      const std::string path = take_value();
      a.outputs.push_back({path, output_format(path)});
    } else {
      throw Usage_error("unknown option '" + name + "' (see expmap " + command + " --help)");
    }
  }

  if (positional.empty())
    throw Usage_error("no mesh file given (see expmap " + command + " --help)");
  if (positional.size() > 1)
    throw Usage_error("more than one mesh file given ('" + positional[0] + "', '" + positional[1] +
                      "')");
  a.mesh = positional[0];
}

/// Checks what both commands require once all options are read: one patch
/// and outputs in the `formats` the command writes (`names` for messages).
inline void check_patch_and_outputs(const Compute_arguments& a,
                                    const std::vector<Output_format>& formats,
                                    const std::string& names) {
  const int regions =
      int(a.radius.has_value()) + int(a.fraction.has_value()) + int(a.vertex_count.has_value());
  if (regions != 1)
    throw Usage_error("give exactly one of --radius, --fraction and --vertices (got " +
                      std::to_string(regions) + ")");
  if (a.outputs.empty()) throw Usage_error("no output given (-o FILE" + names + ")");
  for (const Output& output : a.outputs)
    if (std::find(formats.begin(), formats.end(), output.format) == formats.end())
      throw Usage_error("output '" + output.path + "': this command writes FILE" + names);
}

/// Parses the arguments that follow `compute`.
/// \throws Usage_error naming the offending option or value.
inline Compute_arguments parse_compute_arguments(const std::vector<std::string>& args) {
  Compute_arguments a;
  bool source_given = false;
  parse_map_options(args, "compute", a, [&](const std::string& name, auto take_value) {
    if (name == "--source") {
      check_once(name, source_given);
      a.source = parse_index(name, take_value());
      source_given = true;
    } else if (name == "--source-point") {
      check_once(name, a.source_point.has_value());
      a.source_point = parse_vector(name, take_value());
    } else if (name == "--source-face") {
      check_once(name, a.source_face.has_value());
      a.source_face = parse_index(name, take_value());
    } else if (name == "--barycentric") {
      check_once(name, a.barycentric.has_value());
      a.barycentric = parse_barycentric(name, take_value());
    } else {
      return false;
    }
    return true;
  });
  if (a.help) return a;
  const int sources = int(source_given) + int(a.source_point.has_value()) +
                      int(a.source_face.has_value());
  if (sources != 1)
    throw Usage_error("give exactly one of --source V (a 0-based vertex index), --source-point "
                      "X,Y,Z and --source-face F with --barycentric A,B,C (got " +
                      std::to_string(sources) + ")");
  if (a.source_face.has_value() != a.barycentric.has_value())
    throw Usage_error(a.source_face ? "--source-face needs --barycentric A,B,C"
                                    : "--barycentric is given only with --source-face");
  if (a.source_point) a.point_option = "--source-point";
  if (a.source_face) a.point_option = "--source-face";
  using F = Output_format;
  check_patch_and_outputs(a, {F::csv, F::obj, F::svg}, ".csv, .obj or .svg");
  return a;
}

namespace detail {

/// Parses the arguments of a command that maps many sources: `own` takes
/// the command's own options first (returning whether it knew the option).
template <class Arguments, class Own>
void parse_many_sources(const std::vector<std::string>& args, const std::string& command,
                        Arguments& a, bool& sources_given, Own own) {
  bool threads_given = false;
  parse_map_options(args, command, a, [&](const std::string& name, auto take_value) {
    if (own(name, take_value)) return true;
    if (name == "--sources") {
      check_once(name, sources_given);
      a.sources = parse_sources(name, take_value());
      sources_given = true;
    } else if (name == "--source-points") {
      check_once(name, !a.point_option.empty());
      a.source_points_file = take_value();
      if (a.source_points_file.empty()) throw Usage_error("--source-points needs a file name");
      a.point_option = name;
    } else if (name == "--threads") {
      check_once(name, threads_given);
      const std::size_t threads = parse_index(name, take_value());
      if (threads > 4096) throw Usage_error("--threads must be at most 4096 (0: all cores)");
      a.threads = static_cast<unsigned>(threads);
      threads_given = true;
    } else {
      return false;
    }
    return true;
  });
}

}  // namespace detail

/// Parses the arguments that follow `batch`.
/// \throws Usage_error naming the offending option or value.
inline Batch_arguments parse_batch_arguments(const std::vector<std::string>& args) {
  Batch_arguments a;
  bool sources_given = false;
  detail::parse_many_sources(args, "batch", a, sources_given,
                             [](const std::string&, auto) { return false; });
  if (a.help) return a;
  if (sources_given == !a.point_option.empty())
    throw Usage_error(sources_given ? "--sources and --source-points exclude each other"
                                    : "give --sources (all, a list I,J,K or @FILE of 0-based "
                                      "vertex indices) or --source-points FILE (X,Y,Z lines)");
  using F = Output_format;
  check_patch_and_outputs(a, {F::csv, F::npz}, ".csv or .npz");
  return a;
}

/// What `expmap patches` was asked to do: a batch's sources and method, a
/// polar grid instead of a patch.
struct Patches_arguments : Batch_arguments {
  std::size_t rings = 5, rays = 16;
};

/// Parses the arguments that follow `patches`.
/// \throws Usage_error naming the offending option or value.
inline Patches_arguments parse_patches_arguments(const std::vector<std::string>& args) {
  Patches_arguments a;
  a.method = "dgpc";
  bool sources_given = false, rings_given = false, rays_given = false;
  detail::parse_many_sources(
      args, "patches", a, sources_given, [&](const std::string& name, auto take_value) {
        if (name != "--rings" && name != "--rays") return false;
        bool& given = name == "--rings" ? rings_given : rays_given;
        check_once(name, given);
        const std::size_t count = parse_index(name, take_value());
        if (count < 1 || count > 4096)
          throw Usage_error(name + " must be in [1, 4096] (got " + std::to_string(count) + ")");
        (name == "--rings" ? a.rings : a.rays) = count;
        given = true;
        return true;
      });
  if (a.help) return a;
  if (!a.point_option.empty()) throw Usage_error("patches takes --sources, not --source-points");
  if (!a.radius) throw Usage_error("give the grid's --radius R");
  if (a.fraction || a.vertex_count)
    throw Usage_error("patches samples a disk of --radius R; --fraction and --vertices do not apply");
  if (a.trim_folds)
    throw Usage_error("patches always samples inside each map's fold-free disk; drop --trim-folds");
  if (a.outputs.size() != 1 || a.outputs[0].format != Output_format::npz)
    throw Usage_error("give one output -o OUT.npz");
  return a;
}

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_COMMAND_LINE_H
