// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::rrht_orient_normals(): towards a direction or a viewpoint, and the
// consistent orientation out of closed surfaces, on RRHT's normals.

#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/rrht_orient_normals.h>
#include <CGAL/RRHT/internal/Sheets.h>
#include <CGAL/RRHT/internal/Wedge.h>
#include <CGAL/RRHT/internal/relaxed_signs.h>

#include "orientation_scores.h"
#include "shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace rrht_test;

namespace {

// A sensor beyond each point, seen from the origin.
struct Sensor
{
  typedef Sample key_type;
  typedef Point value_type;
  typedef Point reference;
  typedef boost::readable_property_map_tag category;
  friend Point get(Sensor, const Sample& s) { return CGAL::ORIGIN + 3 * (s.point - CGAL::ORIGIN); }
};

const auto maps = CGAL::RRHT::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample());

// Turns the exact normals of a shape centered on the origin whose faces
// are all seen from it (cube, cylinder, plate) out of it.
void truth_outward(Cloud& cloud)
{
  for(Sample& s : cloud)
    if(s.truth * (s.point - CGAL::ORIGIN) < 0)
      s.truth = -s.truth;
}

// The share of the points, up to `end`, whose normal points along their
// exact, outward normal, among those whose normal is within 60 degrees of
// the exact one's line: a normal farther off (at an edge, a wrong plane)
// is not that of the surface, and which way it points says nothing of
// the orientation. Only the points that `keep` keeps, if given.
template <typename Keep>
double share_outward(const Cloud& cloud, Cloud::const_iterator end, Keep keep)
{
  std::size_t outward = 0, total = 0;
  for(auto it = cloud.begin(); it != end; ++it)
  {
    const double c = cosine_to_truth(*it);
    if(keep(*it) && std::abs(c) >= 0.5)
    {
      ++total;
      outward += (c > 0);
    }
  }
  return total == 0 ? 0. : double(outward) / double(total);
}

double share_outward(const Cloud& cloud, Cloud::const_iterator end)
{
  return share_outward(cloud, end, [](const Sample&) { return true; });
}

// RRHT normals (fast setting) of the cloud, then oriented consistently.
Cloud::iterator estimate_and_orient(Cloud& cloud)
{
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    cloud, 60, CGAL::RRHT::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample())
                 .number_of_planes(300).number_of_rotations(2));
  return CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(cloud, 18, maps);
}

} // namespace

TEST_CASE("Consistent orientation of closed CAD shapes: outward across sharp edges", "[orientation]")
{
  struct Case { const char* name; Cloud cloud; double noise; };
  std::vector<Case> cases;
  for(double noise : { 0., 0.2 })
  {
    cases.push_back({ "cube", cube(20000, 1), noise });
    cases.push_back({ "closed cylinder", closed_cylinder(20000, 2), noise });
    cases.push_back({ "plate 2% thick", thin_box(20000, 0.02 * std::sqrt(8.), 3), noise });
  }
  for(Case& c : cases)
  {
    truth_outward(c.cloud);
    add_noise(c.cloud, c.noise, 7);
    const auto end = estimate_and_orient(c.cloud);
    INFO(c.name << ", noise " << c.noise << "%");
    CHECK(end == c.cloud.end());
    // CGAL::mst_orient_normals() on the noisy plate's normals flips one
    // whole side. The plate's rim, 3 neighbor spacings wide at 20k points,
    // holds the most errors here.
    CHECK(share_outward(c.cloud, end) >= (c.name == std::string("plate 2% thick") ? 0.997 : 0.999));
  }
}

TEST_CASE("Consistent orientation of a hollow box: the cavity's walls point into it", "[orientation]")
{
  Cloud cloud = hollow_box(20000, 0.15, 4);
  const auto end = estimate_and_orient(cloud);
  const auto in_cavity = [](const Sample& s) {
    return std::abs(s.point.x()) < 0.9 && std::abs(s.point.y()) < 0.9 && std::abs(s.point.z()) < 0.9;
  };
  REQUIRE(std::count_if(cloud.begin(), end, in_cavity) > 5000);
  CHECK(share_outward(cloud, end, in_cavity) >= 0.995);
  CHECK(share_outward(cloud, end) >= 0.995);
}

TEST_CASE("Consistent orientation of a noisy hollow box: walls 5 noise deviations thick", "[orientation]")
{
  // Walls 1% of the diagonal thick under 0.2% noise: 0.62% of the points
  // are carried nearer the other side of their wall than their own, and no
  // orientation from the points alone can tell them; the cavity as a whole
  // must not flip, and a point past the middle of a wall goes to the side
  // it is nearer, which leaves the others within half a point of that
  // floor. At 50k points, with the default normals: on sparser clouds,
  // whose neighborhoods reach farther than the walls are thick, patches of
  // the cavity still flip (see the user manual).
  const double wall = 0.01 * 2 * std::sqrt(3.);
  Cloud cloud = hollow_box(50000, wall, 11);
  add_noise(cloud, 0.2, 47);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, 100, maps);
  const auto end = CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(cloud, 18, maps);
  const auto in_cavity = [&](const Sample& s) { return s.truth * (s.point - CGAL::ORIGIN) < 0; };
  REQUIRE(std::count_if(cloud.begin(), end, in_cavity) > 20000);
  CHECK(share_outward(cloud, end, in_cavity) >= 0.98);
  CHECK(share_outward(cloud, end) >= 0.989);
}

TEST_CASE("Consistent orientation of thin machined parts: no flipped patch", "[orientation]")
{
  // The two faces of the spool's flanges are 3 neighbor spacings apart, and
  // RRHT gives its narrow rims the faces' normals: were each rim point
  // trusted on the plane of the next, the rim would chain the two faces of a
  // flange into one sheet and turn the shaft and the inner faces inside out.
  // The drilled block's smallest bores are a few neighborhoods across.
  for(double noise : { 0., 0.05 })
    for(const std::string name : { "spool", "drilled block" })
    {
      Cloud cloud = name == "spool" ? spool(50000, 14) : drilled_block(50000, 15);
      add_noise(cloud, noise, 16);
      CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, 100, maps);
      const auto end = CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(cloud, 18, maps);
      INFO(name << ", noise " << noise << "%");
      REQUIRE(end == cloud.end());
      CHECK(share_outward(cloud, end) >= 0.999);
      CHECK(largest_inward_patch(cloud, 18) <= 50);
    }
}

TEST_CASE("Consistent orientation of a closed blade: its knife edges do not carry their sign into its sides",
          "[orientation]")
{
  // The sides meet at 4.4 degrees: within a few neighbor spacings of an
  // edge, each point's neighbors on the other side lie within the noise of
  // its tangent plane, and only the tilt of the two sides tells them apart
  // (a wedge). Taken for one sheet, they turned over patches of the sides
  // far from the edges (6% of the normals inward, a patch of 1792 points).
  // Outliers near the blade, whose normals are the nearby faces', must not
  // pull the wedges' planes off the faces, which would turn over patches of
  // hundreds of normals.
  for(const bool outliers : { false, true })
  {
    Cloud cloud = closed_blade(50000, closed_blade_thickness, 17);
    if(outliers)
      add_outliers(cloud, 1, 0.02 * bounding_box_diagonal(cloud), 48);
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, 100, maps);
    const auto end = CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(cloud, 18, maps);
    INFO((outliers ? "with 1% outliers" : "clean"));
    REQUIRE(end == cloud.end());
    CHECK(share_outward(cloud, end) >= 0.999);
    CHECK(largest_inward_patch(cloud, 18) <= 50);
  }
}

TEST_CASE("Wedge: the two sides of a thin part that meet at a small angle, not parallel sheets or a corner",
          "[orientation]")
{
  using CGAL::RRHT::internal::Wedge;
  // Points of the unit disk about the origin, the point, on the planes
  // z = t x and z = 0.2 - t x (t = tan 3 degrees): the sides of a blade
  // whose edge is at x = 1.9; or on other surfaces through the same disk.
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  const auto sample = [](const std::function<double(double, int)>& height) {
    std::vector<Eigen::Vector3d> points(1, Eigen::Vector3d::Zero());
    for(int r = 1; r <= 3; ++r)
      for(int a = 0; a < 8; ++a)
        for(int face = 0; face < 2; ++face)
        {
          const double angle = CGAL_PI * (a + 0.5 * face) / 4;
          const double x = r / 3. * std::cos(angle), y = r / 3. * std::sin(angle);
          points.emplace_back(x, y, height(x, face));
        }
    return points;
  };
  const double t = std::tan(3 * CGAL_PI / 180);
  const Wedge wedge(sample([t](double x, int face) { return face == 0 ? t * x : 0.2 - t * x; }), axis);
  REQUIRE(wedge.found());
  CHECK(wedge.deviation() > 0.05);
  CHECK(wedge.side(Eigen::Vector3d(0.5, 0.3, t * 0.5)) == 1);
  CHECK(wedge.side(Eigen::Vector3d(0.5, -0.3, 0.2 - t * 0.5)) == -1);
  // Where the sides meet, a neighbor on either is unsure.
  CHECK(wedge.side(Eigen::Vector3d(0.1 / t, 0, 0.15)) == 0);
  // Parallel sheets (their offsets tell them apart: `Sheets`) and a ridge,
  // whose faces lie side by side, are no wedge; on a flat sheet, the
  // deviation from one plane is rounding, far below any noise.
  CHECK_FALSE(Wedge(sample([](double, int face) { return face == 0 ? 0. : 0.2; }), axis).found());
  CHECK_FALSE(Wedge(sample([t](double x, int) { return -t * std::abs(x); }), axis).found());
  const Wedge flat(sample([](double x, int) { return 1e-3 * x; }), axis);
  CHECK(flat.deviation() < 1e-12);
}

TEST_CASE("Sheets: stacked sheets told apart by their offsets, one noisy sheet kept whole", "[orientation]")
{
  using CGAL::RRHT::internal::Sheets;
  // 16 offsets spread evenly, of standard deviation `noise`, on each sheet
  // at `levels`; the point, at 0, on the first.
  const double noise = 0.01;
  const auto offsets = [noise](const std::vector<double>& levels) {
    std::vector<double> o(1, 0.);
    for(double level : levels)
      for(int t = 0; t < 16; ++t)
        o.push_back(level + noise * std::sqrt(3.) * ((t + 0.5) / 8 - 1));
    return o;
  };
  std::vector<double> one = offsets({ 0. });
  const Sheets::Splits one_splits(one);
  CHECK(std::is_sorted(one.begin(), one.end()));
  // The best split into two halves a single sheet: less than its noise.
  CHECK(one_splits.spread_within_sheets() > 0.4 * noise);
  CHECK(one_splits.spread_within_sheets() < noise);
  const Sheets single(one_splits, noise);
  CHECK_FALSE(single.several());
  CHECK(single.side(3 * noise) == 1);
  // Two sheets 6 noise deviations apart: the spread is each one's.
  std::vector<double> two = offsets({ 0., 6 * noise });
  const Sheets::Splits two_splits(two);
  CHECK(two_splits.spread_within_sheets() == Approx(noise).epsilon(0.1));
  const Sheets pair(two_splits, noise);
  CHECK(pair.several());
  CHECK(pair.side(noise) == 1);
  CHECK(pair.side(6 * noise) == -1);
  // The same offsets, where the noise over the cloud is as large as the gap:
  // one sheet.
  CHECK_FALSE(Sheets(two_splits, 6 * noise).several());
  // Three sheets, the point's the first: the third is farther than the next.
  std::vector<double> three = offsets({ 0., 6 * noise, 12 * noise });
  const Sheets stack(Sheets::Splits(three), noise);
  CHECK(stack.side(0) == 1);
  CHECK(stack.side(6 * noise) == -1);
  CHECK(stack.side(12 * noise) == 0);
}

TEST_CASE("Relaxed signs: a wrongly joined part of a cluster flips back, clusters apart stay apart", "[orientation]")
{
  using CGAL::RRHT::internal::Signed_edge;
  // A ring of 20 vertices whose edges all agree, 5 of them given the other
  // sign: 2 edges against 5 vertices' small anchor.
  std::vector<Signed_edge> edges;
  for(std::uint32_t v = 0; v < 20; ++v)
    edges.push_back({ (std::min)(v, (v + 1) % 20), (std::max)(v, (v + 1) % 20), 1. });
  std::vector<int> signs(20, 1);
  for(std::size_t v = 8; v < 13; ++v)
    signs[v] = -1;
  const std::vector<int> relaxed =
    CGAL::RRHT::internal::relaxed_signs<CGAL::Sequential_tag>(20, edges, std::vector<std::uint32_t>(20, 0), signs);
  CHECK(relaxed == std::vector<int>(20, 1));
  // The same ring as two clusters, 8 to 12 apart: each keeps its sign.
  std::vector<std::uint32_t> cluster(20, 0);
  for(std::size_t v = 8; v < 13; ++v)
    cluster[v] = 1;
  CHECK(CGAL::RRHT::internal::relaxed_signs<CGAL::Sequential_tag>(20, edges, cluster, signs) == signs);
}

TEST_CASE("Relaxed signs: the matrix's product is Eigen's sparse product, bit for bit, on any number of threads",
          "[orientation]")
{
  using CGAL::RRHT::internal::Signed_edge;
  // A random graph over three blocks of rows, some edges left out, some
  // vertices without any.
  const std::size_t size = 10000;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> weight(-1, 1);
  // Each pair once, as orientation_edges() gives them.
  std::vector<Signed_edge> edges;
  for(std::uint32_t a = 0; a < size; ++a)
    for(std::uint32_t b = a + 1 + std::uint32_t(random() % 40); b < size; b += 1 + std::uint32_t(random() % 2000))
      edges.push_back({ a, b, weight(random) });
  auto holds = [](const Signed_edge& e) { return (e.a + e.b) % 7 != 0; };
  std::vector<double> diagonal(size);
  std::vector<Eigen::Triplet<double> > entries;
  for(const Signed_edge& e : edges)
    if(holds(e))
    {
      entries.emplace_back(Eigen::Index(e.a), Eigen::Index(e.b), -e.weight);
      entries.emplace_back(Eigen::Index(e.b), Eigen::Index(e.a), -e.weight);
    }
  for(std::size_t v = 0; v < size; ++v)
  {
    diagonal[v] = 9 + weight(random);
    entries.emplace_back(Eigen::Index(v), Eigen::Index(v), diagonal[v]);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> eigen{ Eigen::Index(size), Eigen::Index(size) };
  eigen.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd x(size);
  for(std::size_t v = 0; v < size; ++v)
    x[Eigen::Index(v)] = weight(random);
  const Eigen::VectorXd expected = eigen * x;
  const CGAL::RRHT::internal::Relaxation_matrix<CGAL::Sequential_tag> sequential(edges, holds, diagonal);
  CHECK((sequential * x).eval() == expected);
#ifdef CGAL_LINKED_WITH_TBB
  const CGAL::RRHT::internal::Relaxation_matrix<CGAL::Parallel_tag> parallel(edges, holds, diagonal);
  CHECK((parallel * x).eval() == expected);
  // And so the relaxed signs.
  std::vector<int> signs(size);
  std::vector<std::uint32_t> cluster(size);
  for(std::size_t v = 0; v < size; ++v)
  {
    signs[v] = random() % 2 ? 1 : -1;
    cluster[v] = std::uint32_t(v % 3);
  }
  const std::vector<int> relaxed = CGAL::RRHT::internal::relaxed_signs<CGAL::Parallel_tag>(size, edges, cluster, signs);
  CHECK(relaxed != signs);
  CHECK(relaxed == CGAL::RRHT::internal::relaxed_signs<CGAL::Sequential_tag>(size, edges, cluster, signs));
#endif
}

TEST_CASE("Signed clusters: a point at a block's edge is joined by all its evidence", "[orientation]")
{
  // Blocks of 4 vertices, all agreeing. Vertex 4 begins the second block:
  // its strong evidence is with the first block, its only edge within its
  // own block is weak and wrong. Joined within its block first, it would
  // carry the second block along, flipped.
  using CGAL::RRHT::internal::Signed_edge;
  const std::vector<Signed_edge> edges = { { 0, 1, 1. }, { 1, 2, 1. }, { 2, 3, 1. }, { 5, 6, 1. }, { 6, 7, 1. },
                                           { 4, 5, -0.1 }, { 1, 4, 1. }, { 2, 4, 1. }, { 3, 4, 1. }, { 3, 5, 1. } };
  const CGAL::RRHT::internal::Signed_clusters clusters =
    CGAL::RRHT::internal::signed_clusters<CGAL::Sequential_tag>(8, edges, 4);
  for(std::size_t v = 0; v < 8; ++v)
  {
    INFO("vertex " << v);
    CHECK(clusters.cluster[v] == clusters.cluster[0]);
    CHECK(clusters.sign[v] == clusters.sign[0]);
  }
}

TEST_CASE("Consistent orientation of a thin open blade: its two sides point away from each other", "[orientation]")
{
  // 4% of its chord thick: at 20k points, the sides are 4 neighbor spacings
  // apart in the middle and meet at knife edges.
  Cloud cloud = thin_blade(20000, 0.08, 10);
  const auto end = estimate_and_orient(cloud);
  const double outward = share_outward(cloud, end);
  CHECK((std::max)(outward, 1 - outward) >= 0.99);
}

TEST_CASE("Consistent orientation of an open curved sheet: the whole sheet to one side", "[orientation]")
{
  // A quarter of a cylinder, sampled on one side: its winding number is
  // fractional everywhere, and turning some of its pieces would bring it
  // nearer 0 or 1 at many queries.
  for(const double noise : { 0., 0.2 })
  {
    Cloud cloud = bent_sheet(30000, 0, 2);
    add_noise(cloud, noise, 49);
    const auto end = estimate_and_orient(cloud);
    const double outward = share_outward(cloud, end);
    INFO("noise " << noise << "%");
    CHECK((std::max)(outward, 1 - outward) >= 0.99);
  }
}

TEST_CASE("Consistent orientation of separate objects: each outward", "[orientation]")
{
  Cloud cloud = cube(10000, 5), other = closed_cylinder(10000, 6);
  truth_outward(cloud);
  truth_outward(other);
  translate(other, Vector(5, 0, 0));
  cloud.insert(cloud.end(), other.begin(), other.end());
  const auto end = estimate_and_orient(cloud);
  CHECK(share_outward(cloud, end) >= 0.999);
}

TEST_CASE("Consistent orientation: the same normals for any number of threads", "[orientation]")
{
  Cloud cloud = closed_cylinder(20000, 8);
  add_noise(cloud, 0.2, 9);
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(
    cloud, 60, CGAL::RRHT::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
  // Random signs, so that the orientation has work to do.
  for(std::size_t i = 0; i < cloud.size(); i += 2)
    cloud[i].normal = -cloud[i].normal;
  Cloud sequential = cloud;
  CGAL::rrht_orient_normals<CGAL::Sequential_tag>(sequential, 18, maps);
#ifdef CGAL_LINKED_WITH_TBB
  Cloud parallel = cloud;
  CGAL::rrht_orient_normals<CGAL::Parallel_tag>(parallel, 18, maps);
  for(std::size_t i = 0; i < cloud.size(); ++i)
    REQUIRE(parallel[i].normal == sequential[i].normal);
#endif
  std::size_t flipped = 0;
  for(std::size_t i = 0; i < cloud.size(); ++i)
    flipped += (sequential[i].normal != cloud[i].normal);
  CHECK(flipped > 0);
}

TEST_CASE("Consistent orientation: only the normals' lines count, not the senses given", "[orientation]")
{
  // Thin walls under noise: the sheets' offsets are mirrored when a normal
  // is flipped, the case where rounding could tell the senses apart.
  Cloud cloud = hollow_box(20000, 0.01 * 2 * std::sqrt(3.), 12);
  add_noise(cloud, 0.2, 13);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    cloud, 60, CGAL::RRHT::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample())
                 .number_of_planes(300).number_of_rotations(2));
  Cloud as_estimated = cloud, all_flipped = cloud, some_flipped = cloud;
  for(std::size_t i = 0; i < cloud.size(); ++i)
  {
    all_flipped[i].normal = -all_flipped[i].normal;
    if(i % 3 == 0)
      some_flipped[i].normal = -some_flipped[i].normal;
  }
  for(Cloud* c : { &as_estimated, &all_flipped, &some_flipped })
    CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(*c, 18, maps);
  std::size_t differ = 0;
  for(std::size_t i = 0; i < cloud.size(); ++i)
    differ += (all_flipped[i].normal != as_estimated[i].normal) + (some_flipped[i].normal != as_estimated[i].normal);
  CHECK(differ == 0);
}

TEST_CASE("Orientation towards a direction and a viewpoint", "[orientation]")
{
  Cloud cloud = sphere(2000, 10);
  for(std::size_t i = 0; i < cloud.size(); ++i)
    cloud[i].normal = (i % 3 == 0) ? -cloud[i].truth : cloud[i].truth;
  SECTION("up")
  {
    CHECK(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(cloud, 0, maps.direction(Vector(0, 0, 1))) == cloud.end());
    for(const Sample& s : cloud)
      CHECK(s.normal.z() >= 0);
  }
  SECTION("a viewpoint inside: every normal points in")
  {
    CGAL::rrht_orient_normals<CGAL::Sequential_tag>(cloud, 0, maps.viewpoint(Point(0.1, 0, 0)));
    for(const Sample& s : cloud)
      CHECK(s.normal * s.truth < 0);
  }
  SECTION("each point's own viewpoint")
  {
    CGAL::rrht_orient_normals<CGAL::Sequential_tag>(cloud, 0, maps.viewpoint_map(Sensor()));
    for(const Sample& s : cloud)
      CHECK(s.normal * s.truth > 0);
  }
}

TEST_CASE("Orientation of bad input: documented results and clear errors", "[orientation]")
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Cloud cloud = cube(3000, 11);
  truth_outward(cloud);
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(
    cloud, 30, CGAL::RRHT::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
  cloud[5].normal = CGAL::NULL_VECTOR;                  // no plane
  cloud[7].point = Point(nan, 0, 0);                     // not finite
  cloud[9].normal = Vector(nan, 0, 1);                   // not finite
  const Point far_point = cloud[11].point;
  SECTION("points without an orientable normal come last, unchanged")
  {
    const auto end = CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(cloud, 18, maps);
    REQUIRE(std::distance(end, cloud.end()) == 3);
    CHECK(end[0].normal == CGAL::NULL_VECTOR);
    CHECK(std::isnan(end[1].point.x()));
    CHECK(std::isnan(end[2].normal.x()));
    CHECK(cloud[8].point == far_point); // the others keep their order

    CHECK(share_outward(cloud, end) >= 0.99);
  }
  SECTION("duplicate points")
  {
    Cloud doubled = cloud;
    doubled.insert(doubled.end(), cloud.begin(), cloud.end());
    const auto end = CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(doubled, 18, maps);
    CHECK(std::distance(end, doubled.end()) == 6);
    CHECK(share_outward(doubled, end) >= 0.99);
  }
  SECTION("fewer points than neighbors")
  {
    Cloud few(cloud.begin() + 20, cloud.begin() + 24);
    CHECK(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(few, 18, maps) == few.end());
  }
  SECTION("a point at its viewpoint keeps its normal")
  {
    const Vector before = cloud[0].normal;
    Cloud one(cloud.begin(), cloud.begin() + 1);
    CGAL::rrht_orient_normals<CGAL::Sequential_tag>(one, 0, maps.viewpoint(one[0].point));
    CHECK(one[0].normal == before);
  }
  SECTION("wrong parameters throw before anything changes")
  {
    const Cloud before = cloud;
    CHECK_THROWS_AS(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(cloud, 1, maps), std::invalid_argument);
    CHECK_THROWS_AS(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(cloud, 0, maps.direction(Vector(0, 0, 0))),
                    std::invalid_argument);
    CHECK_THROWS_AS(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(cloud, 0, maps.direction(Vector(nan, 0, 1))),
                    std::invalid_argument);
    CHECK_THROWS_AS(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(cloud, 0, maps.viewpoint(Point(0, nan, 0))),
                    std::invalid_argument);
    CHECK_THROWS_AS(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(
                      cloud, 0, maps.direction(Vector(0, 0, 1)).viewpoint(Point(0, 0, 0))),
                    std::invalid_argument);
    for(std::size_t i = 0; i < cloud.size(); ++i)
      REQUIRE(((cloud[i].normal == before[i].normal) || i == 9)); // NaN != NaN
    CHECK(std::distance(cloud.begin(), cloud.end()) == std::distance(before.begin(), before.end()));
  }
  SECTION("an empty range")
  {
    Cloud empty;
    CHECK(CGAL::rrht_orient_normals<CGAL::Sequential_tag>(empty, 18, maps) == empty.end());
  }
}
