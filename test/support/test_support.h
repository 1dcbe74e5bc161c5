// Shared helpers of the test suites: meshes from Debian's libcgal-demo and
// small statistics.
#ifndef EXPMAP_TEST_SUPPORT_H
#define EXPMAP_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace expmap_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface_mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;

/// Path of a mesh fetched by scripts/fetch-cgal-meshes.sh.
inline std::string data_mesh(const std::string& name) {
  return std::string(EXPMAP_TEST_DATA_DIR) + "/" + name;
}

/// Reads a mesh of the test data; a missing file fails the test loudly
/// (run scripts/fetch-cgal-meshes.sh), it is never skipped.
template <class Mesh>
Mesh load_mesh(const std::string& name) {
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(data_mesh(name), mesh))
    throw std::runtime_error("cannot read test mesh " + data_mesh(name) +
                             " (run scripts/fetch-cgal-meshes.sh)");
  return mesh;
}

inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

inline double mean(const std::vector<double>& values) {
  double s = 0;
  for (double v : values) s += v;
  return values.empty() ? 0 : s / static_cast<double>(values.size());
}

/// The angle in (-pi, pi] equivalent to `a`.
inline double wrap_angle(double a) {
  const double two_pi = 2 * 3.14159265358979323846;
  a = std::remainder(a, two_pi);
  return a <= -two_pi / 2 ? a + two_pi : a;
}

/// Mean absolute angle error after removing the best constant rotation
/// (the circular mean of the differences), as the exact and computed maps
/// may use different reference directions.
inline double mean_angle_error_up_to_rotation(const std::vector<double>& computed,
                                              const std::vector<double>& exact) {
  double c = 0, s = 0;
  for (std::size_t i = 0; i < computed.size(); ++i) {
    c += std::cos(computed[i] - exact[i]);
    s += std::sin(computed[i] - exact[i]);
  }
  const double rotation = std::atan2(s, c);
  std::vector<double> errors;
  for (std::size_t i = 0; i < computed.size(); ++i)
    errors.push_back(std::abs(wrap_angle(computed[i] - exact[i] - rotation)));
  return mean(errors);
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_SUPPORT_H
