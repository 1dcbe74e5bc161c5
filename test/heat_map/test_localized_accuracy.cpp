// The localized query integrates the distance on a region around the patch
// only; against the whole-mesh heat distances (the same method with the
// Poisson problem solved on the whole mesh) the cut-off error must stay
// small. Over seeded random sources of real meshes its percentiles are gated
// at today's values plus a margin; on hand-picked sources of special cases
// (widened candidates, radius patches, a margin retry, analytic meshes) its
// mean in the inner 90% of the patch stays below 1% of the patch radius.
#include <expmap/Heat_exponential_map.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../../benchmark/Sample_statistics.h"
#include "Analytic_surfaces.h"
#include "test_support.h"

using namespace expmap_test;
using Inspection = expmap::internal::heat::Factor_inspection;

namespace {

struct Cutoff_error {
  double mean_inner = 0, max_inner = 0, mean_all = 0, max_all = 0;  // relative to the radius
};

// The heat's own distances (the geodesic front's fallback would replace
// them where its map folds or meets the boundary).
expmap::Heat_query_options heat_only() {
  expmap::Heat_query_options query;
  query.fallback = expmap::Heat_fallback::none;
  return query;
}

// The whole-mesh heat distances of `source`, by vertex index.
template <class Heat>
std::unordered_map<std::size_t, double> whole_mesh_distances(const Heat& heat,
                                                             std::size_t source) {
  const auto whole = heat.compute_by_index(source, expmap::Patch::fraction(1.0), heat_only());
  std::unordered_map<std::size_t, double> reference;
  for (std::size_t i = 0; i < whole.size(); ++i) reference[whole.indices[i]] = whole.distance[i];
  return reference;
}

// The localized query's distances against the whole-mesh ones.
template <class Heat>
Cutoff_error cutoff_error(const Heat& heat, std::size_t source, const expmap::Patch& patch,
                          const std::unordered_map<std::size_t, double>& reference) {
  const auto local = heat.compute_by_index(source, patch, heat_only());
  const double radius = local.distance.back();
  const std::size_t inner = static_cast<std::size_t>(0.9 * static_cast<double>(local.size()));
  Cutoff_error e;
  for (std::size_t i = 0; i < local.size(); ++i) {
    const double error = std::abs(local.distance[i] - reference.at(local.indices[i])) / radius;
    e.mean_all += error;
    e.max_all = std::max(e.max_all, error);
    if (i < inner) {
      e.mean_inner += error;
      e.max_inner = std::max(e.max_inner, error);
    }
  }
  e.mean_all /= static_cast<double>(local.size());
  e.mean_inner /= static_cast<double>(inner);
  return e;
}

template <class Heat>
Cutoff_error cutoff_error(const Heat& heat, std::size_t source, const expmap::Patch& patch) {
  return cutoff_error(heat, source, patch, whole_mesh_distances(heat, source));
}

template <class Heat>
void check_cutoff(const Heat& heat, const char* name, std::initializer_list<std::size_t> sources,
                  std::initializer_list<double> fractions = {0.05, 0.25}) {
  for (double fraction : fractions)
    for (std::size_t source : sources) {
      const Cutoff_error e = cutoff_error(heat, source, expmap::Patch::fraction(fraction));
      BOOST_TEST_MESSAGE(name << " source " << source << ", " << fraction * 100
                              << "% patch: inner 90% mean " << e.mean_inner << " max "
                              << e.max_inner << "; whole patch mean " << e.mean_all << " max "
                              << e.max_all << " (relative to the radius)");
      BOOST_TEST(e.mean_inner < 0.01);
    }
}

// Seeded random sources: `count` vertices from std::mt19937(seed)'s raw
// output modulo the vertex count (portable, unlike the standard library's
// distributions; the bias is below 1e-5 for these meshes).
std::vector<std::size_t> random_sources(std::size_t vertex_count, std::size_t count,
                                        unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<std::size_t> sources;
  while (sources.size() < count) sources.push_back(static_cast<std::size_t>(rng()) % vertex_count);
  return sources;
}

// Today's percentiles over the sources of one patch size's cut-off error:
// of the mean in the inner 90% of the patch (the measure the hand-picked
// checks bound) and of the largest over the whole patch, both relative to
// the patch radius.
struct Cutoff_today {
  double fraction;
  double mean_inner_median, mean_inner_p90, mean_inner_max;
  double max_all_median, max_all_p90;
};

// The limit of a percentile: today's value plus a margin of 25% and 2e-4 of
// the radius.
double cutoff_limit(double today) { return 1.25 * today + 2e-4; }

// The heat with its defaults on `mesh_name`, the cut-off errors of
// `sources_count` random sources (seed 1) at each of `today`'s patch
// fractions, one whole-mesh solve per source; the percentiles checked
// against today's plus the margin.
void check_cutoff_percentiles(const char* mesh_name, std::size_t sources_count,
                              const std::vector<Cutoff_today>& today) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>(mesh_name);
  const expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  const std::vector<std::size_t> sources = random_sources(num_vertices(mesh), sources_count, 1);
  std::vector<std::vector<double>> mean_inner(today.size()), max_all(today.size());
  for (std::size_t s : sources) {
    const auto reference = whole_mesh_distances(heat, s);
    for (std::size_t k = 0; k < today.size(); ++k) {
      const Cutoff_error e =
          cutoff_error(heat, s, expmap::Patch::fraction(today[k].fraction), reference);
      mean_inner[k].push_back(e.mean_inner);
      max_all[k].push_back(e.max_all);
    }
  }
  using expmap_bench::median;
  using expmap_bench::percentile;
  for (std::size_t k = 0; k < today.size(); ++k) {
    const Cutoff_today& t = today[k];
    const std::vector<double>& m = mean_inner[k];
    const std::vector<double>& x = max_all[k];
    const auto above_one_percent =
        std::count_if(m.begin(), m.end(), [](double e) { return e >= 0.01; });
    BOOST_TEST_MESSAGE(mesh_name << ", " << t.fraction * 100 << "% patches, " << sources.size()
                                 << " random sources: inner 90% mean median " << median(m)
                                 << ", p90 " << percentile(m, 90) << ", max " << percentile(m, 100)
                                 << " (" << above_one_percent
                                 << " at 1% or more); whole patch max median " << median(x)
                                 << ", p90 " << percentile(x, 90) << " (relative to the radius)");
    BOOST_TEST_CONTEXT(mesh_name << ", " << t.fraction * 100 << "% patches") {
      BOOST_TEST(median(m) <= cutoff_limit(t.mean_inner_median));
      BOOST_TEST(percentile(m, 90) <= cutoff_limit(t.mean_inner_p90));
      BOOST_TEST(percentile(m, 100) <= cutoff_limit(t.mean_inner_max));
      BOOST_TEST(median(x) <= cutoff_limit(t.max_all_median));
      BOOST_TEST(percentile(x, 90) <= cutoff_limit(t.max_all_p90));
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(localized_accuracy)

// The factors kept in floats: on armadillo every supernode fits a float, so
// the bytes halve, and the maps move by float round-off only
// (doc/performance.md).
BOOST_AUTO_TEST_CASE(single_precision_factors_change_distances_by_round_off) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("armadillo.off");
  expmap::Heat_options options;
  options.factor_precision = expmap::Factor_precision::single_precision;
  const expmap::Heat_exponential_map<Surface_mesh> exact(mesh), single(mesh, options);
  BOOST_TEST(exact.factor_bytes() == 8 * Inspection::factor_entries(exact));
  BOOST_TEST(2 * single.factor_bytes() == exact.factor_bytes());
  double largest = 0;
  for (std::size_t s : {2000u, 9000u, 15000u}) {
    const auto a = exact.compute_by_index(s, expmap::Patch::fraction(0.05));
    const auto b = single.compute_by_index(s, expmap::Patch::fraction(0.05));
    BOOST_TEST_REQUIRE(a.indices == b.indices, "source " << s);
    const double radius = a.distance.back();
    for (std::size_t i = 0; i < a.size(); ++i)
      largest = std::max(largest, std::abs(a.distance[i] - b.distance[i]) / radius);
  }
  BOOST_TEST_MESSAGE("largest distance change " << largest << " of the radius");
  BOOST_TEST(largest < 1e-5);
  BOOST_TEST(largest > 0);  // the factor was rounded
}

// The cut-off error at 100 random sources (std::mt19937 seed 1) of three
// meshes, as percentiles over the sources, at 1%, 5% and 25% patches. The
// numbers are today's (2026-11-28, Release build, GCC 12, x86-64): the
// median, 90th percentile and largest of the inner 90% mean, then the
// median and 90th percentile of the whole patch's largest error, relative
// to the patch radius; cutoff_limit adds the margin. At 1% the error is
// largest: on armadillo 46 of the 100 sources reach 1% of the radius (22 on
// bunny00, 37 on refined_elephant); at 5% and 25% none does.
BOOST_AUTO_TEST_CASE(cutoff_error_percentiles_over_random_sources) {
  check_cutoff_percentiles("armadillo.off", 100,
                           {{0.01, 0.00938, 0.0209, 0.0279, 0.0316, 0.0630},
                            {0.05, 0.00313, 0.00717, 0.00872, 0.0150, 0.0271},
                            {0.25, 0.00109, 0.00178, 0.00216, 0.00652, 0.0101}});
  check_cutoff_percentiles("bunny00.off", 100,
                           {{0.01, 0.00628, 0.0135, 0.0282, 0.0224, 0.0493},
                            {0.05, 0.00325, 0.00632, 0.00964, 0.0129, 0.0231},
                            {0.25, 0.000827, 0.00176, 0.00264, 0.00401, 0.00698}});
  check_cutoff_percentiles("refined_elephant.off", 100,
                           {{0.01, 0.00842, 0.0166, 0.0307, 0.0269, 0.0494},
                            {0.05, 0.00208, 0.00565, 0.00875, 0.00935, 0.0222},
                            {0.25, 0.000303, 0.000844, 0.00224, 0.00248, 0.00584}});
}

// With the input mesh's cotan weights the heat matrix is not an M-matrix
// (as on meshes with obtuse angles opposite boundary edges, by default), so
// count patches solve the heat on breadth-first candidates. Edge lengths
// vary on this mesh, and the candidates of these sources cut the heat's
// level sets short at 5%: their queries grow the candidates around the
// cut-short vertices and extend the source heat to them (manual, section 2,
// step 2).
BOOST_AUTO_TEST_CASE(refined_elephant_cutoff_error_with_widened_candidates) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("refined_elephant.off");
  expmap::Heat_options options;
  options.laplacian = expmap::Laplacian_mode::direct;
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh, options);
  for (const std::size_t source : {44339u, 21024u, 9731u})
    BOOST_TEST(heat.compute_by_index(source, expmap::Patch::fraction(0.05))
                       .statistics.candidate_widenings > 0u,
               "source " << source);
  check_cutoff(heat, "refined_elephant", {44339, 21024, 9731});
}

// A radius patch finds its region largest first down to the heat a plane
// carries to its region's radius (manual, section 2, step 2). On this mesh
// the vertex density varies by an order of magnitude, so the region's size
// follows the heat, not a count: the cut-off error stays as small as a
// count patch's, and the patch holds every vertex the whole-mesh map puts
// well inside the radius.
BOOST_AUTO_TEST_CASE(refined_elephant_radius_patches_down_to_a_heat) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("refined_elephant.off");
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  for (const std::size_t source : {5u, 17246u, 29776u, 41461u}) {
    for (const double fraction : {0.05, 0.25}) {
      const double radius =
          heat.compute_by_index(source, expmap::Patch::fraction(fraction)).distance.back();
      const expmap::Patch patch = expmap::Patch::geodesic_radius(radius);
      const Cutoff_error e = cutoff_error(heat, source, patch);
      BOOST_TEST_MESSAGE("source " << source << ", radius of a " << fraction * 100
                                   << "% patch: inner 90% mean " << e.mean_inner << " max "
                                   << e.max_inner);
      BOOST_TEST(e.mean_inner < 0.01);
      const auto local = heat.compute_by_index(source, patch);
      const auto whole = heat.compute_by_index(source, expmap::Patch::geodesic_radius(0.9 * radius));
      std::unordered_map<std::size_t, bool> in_patch;
      for (const std::size_t v : local.indices) in_patch[v] = true;
      std::size_t missing = 0;
      for (const std::size_t v : whole.indices) missing += in_patch.count(v) == 0;
      BOOST_TEST(missing == 0u, "source " << source << ": " << missing << " vertices within 0.9 R missing");
      BOOST_TEST(local.distance.back() <= radius);
    }
  }
}

// The patches of these sources come closer to their region's edge than the
// margin at the first attempt (measured: by 0.9% for 2 at 1%, by 0.3% for
// 11480 at 5%; the edge taken at the middle of the edges leaving the
// region, manual section 2, step 5), and the query retries on a region
// twice as large. The retry is not what keeps a cut-off error below 1%:
// of 150 random sources at 1% on this mesh, 60 exceed it when 45 of them
// retry and 63 when one does (measured with expmap-bench; the percentiles
// over random sources are gated in cutoff_error_percentiles_over_random_sources).
// A retry continues the first attempt's heat solve, so its map is the one a
// first attempt on the doubled region computes (`region_growth` 4, whose
// wider margin, 1.7 radii, source 2's doubled region holds too).
BOOST_AUTO_TEST_CASE(armadillo_cutoff_error_after_a_margin_retry) {
  const Surface_mesh mesh = load_mesh<Surface_mesh>("armadillo.off");
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  check_cutoff(heat, "armadillo", {2}, {0.01});
  check_cutoff(heat, "armadillo", {11480}, {0.05});
  BOOST_TEST(
      heat.compute_by_index(11480, expmap::Patch::fraction(0.05)).statistics.region_retries == 1u);
  expmap::Heat_query_options doubled;
  doubled.region_growth = 4;
  const auto retried = heat.compute_by_index(2, expmap::Patch::fraction(0.01));
  const auto direct = heat.compute_by_index(2, expmap::Patch::fraction(0.01), doubled);
  BOOST_TEST(retried.statistics.region_retries == 1u);
  BOOST_TEST(direct.statistics.region_retries == 0u);
  BOOST_TEST_REQUIRE(retried.indices == direct.indices);
  double largest = 0;
  for (std::size_t i = 0; i < retried.size(); ++i)
    largest = std::max({largest, std::abs(retried.distance[i] - direct.distance[i]),
                        std::abs(retried.angle[i] - direct.angle[i])});
  BOOST_TEST(largest < 1e-12, "largest difference " << largest);
  // A source whose first region holds the margin does not retry.
  BOOST_TEST(heat.compute_by_index(2000, expmap::Patch::fraction(0.05)).statistics.region_retries ==
             0u);
}

// A grid ten times finer across than along: the breadth-first candidates
// are far too short across, the rings grown around the cut-short vertices
// do not catch up within their rounds, and the candidates are widened
// everywhere (then the margin retry follows). The targeted rings on the
// meshes above never reach that fallback.
BOOST_AUTO_TEST_CASE(anisotropic_grid_cutoff_error_after_widening_everywhere) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(60, 600, 1.0, 1.0), mesh);
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  const std::size_t n = num_vertices(mesh);
  check_cutoff(heat, "anisotropic grid", {n / 2 + 3, n / 3 + 7}, {0.05});
}

BOOST_AUTO_TEST_CASE(sphere_cutoff_error) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_icosphere(5, 1.0), mesh);
  expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  check_cutoff(heat, "sphere (10,242 vertices)", {0, 5000});
}

namespace {

// A torus of 480 x 480 vertices moved at random by up to 0.3 of the spacing.
void make_jittered_torus(Surface_mesh& mesh) {
  const int around = 480, along = 480;
  const double major = 3.0, minor = 1.0, step = 2 * M_PI / around;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> offset(-0.3 * step, 0.3 * step);
  expmap_analytic::Triangle_soup torus;
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      const double u = i * step + offset(rng), v = j * step + offset(rng);
      torus.points.push_back({(major + minor * std::cos(v)) * std::cos(u),
                              (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v)});
    }
  auto at = [&](int i, int j) { return (j % along) * around + (i % around); };
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      torus.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      torus.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  expmap_analytic::soup_to_mesh(torus, mesh);
}

// The largest change between two maps of the same patch, in distance
// relative to the patch radius and in angle (rad).
template <class Map>
std::pair<double, double> largest_changes(const Map& a, const Map& b) {
  const double radius = b.distance.back();
  double distance_change = 0, angle_change = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    distance_change = std::max(distance_change, std::abs(a.distance[i] - b.distance[i]) / radius);
    angle_change =
        std::max(angle_change, std::abs(std::remainder(a.angle[i] - b.angle[i], 2 * M_PI)));
  }
  return {distance_change, angle_change};
}

}  // namespace

// Small count and radius patches of a large mesh prune their heat solves
// (Heat_query_options::pruning_tolerance): the map must equal the unpruned one to 1e-10 of the
// radius in distance and 1e-10 rad in angle, and the solves must read fewer
// factor entries. A torus of 230k vertices, large enough that the query
// prunes, closed (pruning needs nonnegative cotan weights, which boundary
// edges opposite obtuse angles break), its vertices moved at random by up
// to 0.3 of the spacing (regular vertices give exactly tied distances,
// which round-off may order either way).
// The whole mesh's factors, where pruning and the Poisson factor's
// compression act; meshes this large answer small patches on subdomains
// by default.
expmap::Heat_options whole_mesh_factors() {
  expmap::Heat_options options;
  options.subdomain_min_vertices = std::numeric_limits<std::size_t>::max();
  return options;
}

BOOST_AUTO_TEST_CASE(pruned_heat_solves_change_nothing_but_the_work) {
  Surface_mesh mesh;
  make_jittered_torus(mesh);
  const std::size_t vertex_count = num_vertices(mesh);
  expmap::Heat_query_options unpruned;
  unpruned.pruning_tolerance = 0;
  const expmap::Heat_exponential_map<Surface_mesh> heat(mesh, whole_mesh_factors());
  for (const std::size_t source : {std::size_t{1000}, vertex_count / 2 + 77})
    for (const double fraction : {0.001, 0.004, 0.02}) {
      // A count patch, and a radius patch of its radius (its region found
      // down to a heat, which also sets its pruning threshold).
      const double patch_radius =
          heat.compute_by_index(source, expmap::Patch::fraction(fraction), unpruned)
              .distance.back();
      for (const expmap::Patch& patch :
           {expmap::Patch::fraction(fraction), expmap::Patch::geodesic_radius(patch_radius)}) {
        const auto a = heat.compute_by_index(source, patch);
        const auto b = heat.compute_by_index(source, patch, unpruned);
        BOOST_TEST_REQUIRE(a.indices == b.indices);
        const auto [distance_error, angle_error] = largest_changes(a, b);
        BOOST_TEST_MESSAGE("source " << source << ", " << fraction * 100 << "%, "
                                     << (patch.kind() == expmap::Patch::Kind::fraction ? "count" : "radius")
                                     << " patch: pruned solves read "
                                     << a.statistics.factor_entries << " of "
                                     << b.statistics.factor_entries << " factor entries; distance "
                                     << distance_error << " of the radius, angle " << angle_error
                                     << " rad");
        BOOST_TEST(distance_error <= 1e-10);
        BOOST_TEST(angle_error <= 1e-10);
        BOOST_TEST(a.statistics.factor_entries < b.statistics.factor_entries);
      }
    }
}

// A long thin tube (8 vertices around, 240k in all, moved at random by up
// to 0.2 of the spacing): the region of a 0.4% patch (found largest first)
// reaches much farther along it than the disk the pruning threshold is
// guessed from, the guess is too bold, and the query must catch that and
// solve the heat again (measured: 170k and 188k factor entries against 135k
// and 153k unpruned).
// The map must still equal the unpruned one.
BOOST_AUTO_TEST_CASE(pruned_heat_solves_catch_a_too_bold_threshold) {
  const int around = 8, along = 30000;
  const double spacing = 2 * M_PI / around;
  expmap_analytic::Triangle_soup tube =
      expmap_analytic::make_cylinder(around, along, 1.0, spacing * along);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> offset(-0.2 * spacing, 0.2 * spacing);
  for (auto& p : tube.points)
    for (double& x : p) x += offset(rng);
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(tube, mesh);
  expmap::Heat_query_options unpruned;
  unpruned.pruning_tolerance = 0;
  const expmap::Heat_exponential_map<Surface_mesh> heat(mesh, whole_mesh_factors());
  for (const std::size_t source :
       {std::size_t{around * 50 + 1}, static_cast<std::size_t>(num_vertices(mesh) / 2 + 3)}) {
    const auto a = heat.compute_by_index(source, expmap::Patch::fraction(0.004));
    const auto b = heat.compute_by_index(source, expmap::Patch::fraction(0.004), unpruned);
    BOOST_TEST_REQUIRE(a.indices == b.indices);
    const auto [distance_error, angle_error] = largest_changes(a, b);
    BOOST_TEST_MESSAGE("tube, source " << source << ": " << a.statistics.factor_entries
                                       << " factor entries pruned and solved again, "
                                       << b.statistics.factor_entries << " unpruned; distance "
                                       << distance_error << ", angle " << angle_error);
    BOOST_TEST(distance_error <= 1e-10);
    BOOST_TEST(angle_error <= 1e-10);
    // The second solve is what this test is about: it shows in the work.
    BOOST_TEST(a.statistics.factor_entries > b.statistics.factor_entries);
  }
}

// The rows below the Poisson factor's large separators in low-rank form
// (Heat_options::poisson_compression_tolerance, on by default): the torus's
// factor has such blocks, and the maps must equal those of the dense factor
// to 1e-10 of the radius in distance and 1e-10 rad in angle (measured:
// about 1e-14), with fewer factor entries read.
BOOST_AUTO_TEST_CASE(compressed_poisson_rows_change_nothing_but_the_work) {
  Surface_mesh mesh;
  make_jittered_torus(mesh);
  expmap::Heat_options dense_options = whole_mesh_factors();
  dense_options.poisson_compression_tolerance = 0;
  const expmap::Heat_exponential_map<Surface_mesh> compressed(mesh, whole_mesh_factors()),
      dense(mesh, dense_options);
  BOOST_TEST_MESSAGE(Inspection::poisson_compressed_supernodes(compressed)
                     << " Poisson supernodes with rows below in low-rank form");
  BOOST_TEST_REQUIRE(Inspection::poisson_compressed_supernodes(compressed) > 0u);
  BOOST_TEST(Inspection::poisson_compressed_supernodes(dense) == 0u);
  for (const std::size_t source : {std::size_t{1000}, std::size_t{num_vertices(mesh) / 2 + 77}})
    for (const double fraction : {0.001, 0.02}) {
      const auto a = compressed.compute_by_index(source, expmap::Patch::fraction(fraction));
      const auto b = dense.compute_by_index(source, expmap::Patch::fraction(fraction));
      BOOST_TEST_REQUIRE(a.indices == b.indices);
      const auto [distance_change, angle_change] = largest_changes(a, b);
      BOOST_TEST_MESSAGE("source " << source << ", " << fraction * 100 << "%: "
                                   << a.statistics.factor_entries << " factor entries against "
                                   << b.statistics.factor_entries << "; distance "
                                   << distance_change << " of the radius, angle " << angle_change
                                   << " rad");
      BOOST_TEST(distance_change <= 1e-10);
      BOOST_TEST(angle_change <= 1e-10);
      BOOST_TEST(a.statistics.factor_entries < b.statistics.factor_entries);
    }
}

// query_threads 2 solves the star beside the distance, on the whole region,
// and reads the patch's rows from it: the same maps as one thread, for
// pruned and unpruned solves, count and radius patches, and the angle
// estimators of two, three and one-per-star-vertex columns. Small regions
// stay on one thread (the same work); larger ones read more entries.
BOOST_AUTO_TEST_CASE(a_second_thread_changes_nothing_but_the_work) {
  Surface_mesh torus, sphere;
  make_jittered_torus(torus);
  expmap_analytic::soup_to_mesh(expmap_analytic::make_icosphere(5), sphere);
  auto compare = [](const auto& heat, const expmap::Heat_query_options& one, std::size_t source,
                    const expmap::Patch& patch, const char* what) {
    expmap::Heat_query_options two = one;
    two.query_threads = 2;
    const auto a = heat.compute_by_index(source, patch, one);
    const auto b = heat.compute_by_index(source, patch, two);
    BOOST_TEST_REQUIRE(a.indices == b.indices);
    const auto [distance_change, angle_change] = largest_changes(b, a);
    BOOST_TEST_MESSAGE(what << ", source " << source << ", " << a.size() << " vertices: "
                            << a.statistics.factor_entries << " factor entries on one thread, "
                            << b.statistics.factor_entries << " on two; distance "
                            << distance_change << " of the radius, angle " << angle_change
                            << " rad");
    BOOST_TEST(distance_change <= 1e-12);
    BOOST_TEST(angle_change <= 1e-12);
    if (2 * a.size() < 1000)
      BOOST_TEST(a.statistics.factor_entries == b.statistics.factor_entries);
    if (2 * a.size() > 2000)
      BOOST_TEST(a.statistics.factor_entries < b.statistics.factor_entries);
  };
  {
    const expmap::Heat_exponential_map<Surface_mesh> heat(torus);
    for (const double fraction : {0.001, 0.004, 0.02, 0.1}) {
      const double radius =
          heat.compute_by_index(1000, expmap::Patch::fraction(fraction)).distance.back();
      compare(heat, {}, 1000, expmap::Patch::fraction(fraction), "torus, count patch");
      compare(heat, {}, 1000, expmap::Patch::geodesic_radius(radius), "torus, radius patch");
    }
  }
  expmap::Heat_query_options logarithmic, gradient;
  logarithmic.angle_estimator = expmap::Angle_estimator::log_heat_quadratic_fit;
  gradient.angle_estimator = expmap::Angle_estimator::heat_gradient;
  const expmap::Heat_exponential_map<Surface_mesh> heat(sphere);
  for (const expmap::Heat_query_options& options : {logarithmic, gradient})
    compare(heat, options, 17, expmap::Patch::fraction(0.3), "icosphere");
}

BOOST_AUTO_TEST_CASE(query_threads_other_than_one_or_two_are_rejected) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(4, 4, 1.0, 1.0), mesh);
  const expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  for (const int threads : {0, 3, -1}) {
    expmap::Heat_query_options query;
    query.query_threads = threads;
    BOOST_CHECK_THROW(heat.compute_by_index(0, expmap::Patch::fraction(0.5), query),
                      expmap::Invalid_input);
  }
}

BOOST_AUTO_TEST_CASE(solve_tolerances_out_of_range_are_rejected) {
  Surface_mesh mesh;
  expmap_analytic::soup_to_mesh(expmap_analytic::make_grid(4, 4, 1.0, 1.0), mesh);
  const expmap::Heat_exponential_map<Surface_mesh> heat(mesh);
  for (const double tolerance : {-1e-14, 1e-6, std::nan("")}) {
    expmap::Heat_query_options pruning;
    pruning.pruning_tolerance = tolerance;
    BOOST_CHECK_THROW(heat.compute_by_index(0, expmap::Patch::fraction(0.5), pruning),
                      expmap::Invalid_input);
    expmap::Heat_options compression;
    compression.poisson_compression_tolerance = tolerance;
    BOOST_CHECK_THROW((expmap::Heat_exponential_map<Surface_mesh>(mesh, compression)),
                      expmap::Invalid_input);
  }
}

BOOST_AUTO_TEST_SUITE_END()
