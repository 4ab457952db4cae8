// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Poisson experiment (README.md here, "Poisson surfaces"): how close
// CGAL's Poisson surface comes to the true surface when its normals are
// RRHT's defaults oriented by CGAL::rrht_orient_normals() or given the exact
// normals' signs, jet fitting's oriented by CGAL::mst_orient_normals(), or the
// exact normals. Writes
// poisson.csv and poisson.md into --out, the surfaces into --scratch.

#include "datasets.h"
#include "orientation_scores.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/rrht_orient_normals.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/Poisson_reconstruction_function.h>
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#else
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/make_surface_mesh.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#endif
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
// GCC 12 at -O3 warns of a maybe uninitialized value within CGAL 5.5's
// self_intersections.h, which corefinement.h instantiates.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/Random.h>
#include <CGAL/centroid.h>
#include <CGAL/Real_timer.h>

#include <boost/program_options.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace po = boost::program_options;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef K::Segment_3 Segment;
typedef std::pair<Point, Vector> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor Face;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh> > > Face_tree;
typedef std::vector<Segment>::const_iterator Segment_iterator;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segment_iterator> > > Segment_tree;
typedef CGAL::Poisson_reconstruction_function<K> Poisson_function;
typedef CGAL::Exact_predicates_exact_constructions_kernel E; // the corefinements'
typedef CGAL::Surface_mesh<E::Point_3> Exact_mesh;

const double sharp_angle = 30;     // degrees between the normals of two faces: a sharp edge
const double near_edge = 0.01;     // near a sharp edge: within 1% of the diagonal of it
const std::size_t samples = 200000; // points sampled on each surface for the distances

/// A true surface: its triangles, outward, and its sharp edges.
struct Truth
{
  Mesh mesh;
  std::vector<Segment> sharp_edges;
  double diagonal = 0;
};

/// Triangulates `mesh`, turns it outward, and finds its sharp edges. False
/// if it is not closed (outward is then undefined).
bool make_truth(Mesh mesh, Truth& truth)
{
  PMP::triangulate_faces(mesh);
  if(!CGAL::is_closed(mesh))
    return false;
  if(!PMP::is_outward_oriented(mesh))
    PMP::reverse_face_orientations(mesh);
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(mesh, sharp_angle, sharp);
  truth.sharp_edges.clear();
  for(Mesh::Edge_index e : mesh.edges())
    if(sharp[e])
      truth.sharp_edges.emplace_back(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1)));
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  truth.diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                             CGAL::square(box.zmax() - box.zmin()));
  truth.mesh = std::move(mesh);
  return true;
}

/// How far the true meshes of the machined parts and the closed blade may
/// stray from their curved surfaces (cylinders as inscribed polygons, the
/// blade's parabolas as polylines), in parts of the diagonal; their samples
/// must lie within twice that of the mesh (the other true meshes are exact:
/// 1e-9).
const double chord_error = 0.5e-5;

/// `value` rounded to a multiple of 2^-40 (about 1e-12): the coordinates of
/// the prisms are computed in double as test/shapes.h computes them, where
/// -0.84 + 0.04 is not -0.8; rounded, faces meant to be coplanar (a flange
/// and a shaft's end) are, and the corefinement makes no sliver between them.
double snapped(double value)
{
  const double grid = std::ldexp(1., 40);
  return std::round(value * grid) / grid;
}

/// A prism of test/shapes.h (`rrht_test::Prism`) as a closed triangle mesh,
/// outward: its convex polygon as it is, its disk as the inscribed regular
/// polygon with the fewest sides whose chord error, radius (1 - cos(pi /
/// sides)), is at most `max_error`.
Exact_mesh prism_mesh(const rrht_test::Prism& prism, double max_error)
{
  std::vector<std::pair<double, double> > polygon = prism.polygon;
  const bool disk = polygon.empty();
  if(disk)
  {
    const double half_angle = std::acos((std::max)(-1., 1 - max_error / prism.radius));
    const std::size_t sides = (std::max)(std::size_t(16), std::size_t(std::ceil(CGAL_PI / half_angle)));
    for(std::size_t i = 0; i < sides; ++i)
      polygon.emplace_back(prism.radius * std::cos(2 * CGAL_PI * double(i) / double(sides)),
                           prism.radius * std::sin(2 * CGAL_PI * double(i) / double(sides)));
  }
  const auto point = [&](double a, double b, double c) { // as rrht_test::solid_boundary() places a sample
    const rrht_test::Point p = prism.origin + a * prism.u + b * prism.v + c * prism.w();
    return E::Point_3(snapped(p.x()), snapped(p.y()), snapped(p.z()));
  };
  Exact_mesh m;
  const std::size_t n = polygon.size();
  std::vector<Exact_mesh::Vertex_index> bottom, top;
  for(const auto& q : polygon)
  {
    bottom.push_back(m.add_vertex(point(q.first, q.second, prism.bottom)));
    top.push_back(m.add_vertex(point(q.first, q.second, prism.top)));
  }
  std::vector<Exact_mesh::Face_index> added;
  // The caps: a fan about the polygon's first vertex. (With a fan about a
  // disk's centre, the union of the spool's coaxial cylinders, whose caps are
  // coplanar and whose fans' edges overlap along the same lines, ran for over
  // 15 minutes.)
  for(std::size_t i = 1; i + 1 < n; ++i)
  {
    added.push_back(m.add_face(top[0], top[i], top[i + 1]));
    added.push_back(m.add_face(bottom[0], bottom[i + 1], bottom[i]));
  }
  for(std::size_t i = 0; i < n; ++i) // counterclockwise in (u, v): out is to the right of each side
  {
    const std::size_t j = (i + 1) % n;
    added.push_back(m.add_face(bottom[i], bottom[j], top[j]));
    added.push_back(m.add_face(bottom[i], top[j], top[i]));
  }
  if(std::count(added.begin(), added.end(), Exact_mesh::null_face()) > 0 || !CGAL::is_closed(m))
    throw std::runtime_error("a prism's mesh is not closed");
  if(!PMP::is_outward_oriented(m))
    PMP::reverse_face_orientations(m);
  return m;
}

/// The boundary of a solid of test/shapes.h (`rrht_test::Solid`) as a closed
/// mesh: the union of its added prisms less the union of its removed ones
/// (exact corefinement, then rounded), the disks as polygons whose chord
/// error is at most `max_error`.
Mesh solid_mesh(const rrht_test::Solid& solid, double max_error)
{
  if(solid.added.empty())
    throw std::runtime_error("a solid with no prism");
  Exact_mesh part = prism_mesh(solid.added.front(), max_error);
  for(std::size_t i = 1; i < solid.added.size(); ++i)
  {
    Exact_mesh prism = prism_mesh(solid.added[i], max_error);
    if(!PMP::corefine_and_compute_union(part, prism, part))
      throw std::runtime_error("the union of a solid's prisms failed");
  }
  for(const rrht_test::Prism& removed : solid.removed)
  {
    Exact_mesh prism = prism_mesh(removed, max_error);
    if(!PMP::corefine_and_compute_difference(part, prism, part))
      throw std::runtime_error("the difference of a solid's prisms failed");
  }
  Mesh mesh;
  CGAL::copy_face_graph(part, mesh);
  return mesh;
}

/// `rrht_test::closed_blade()` with thickness `t` as a closed mesh: each side,
/// y = a (1 - x^2) for x in [-1,1], as the polyline through `sides` + 1
/// points evenly spaced in x (its chord error a (2 / sides)^2 / 4) extruded
/// along z in [-1,1], the two sides sharing their ends (x = -1 and 1), and
/// the caps z = -1 and 1 between them.
Mesh closed_blade_mesh(double t, std::size_t sides)
{
  const double high = rrht_test::closed_blade_camber + t / 2, low = rrht_test::closed_blade_camber - t / 2;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > triangles;
  // Vertex (side, i, end): side 0 low, 1 high; the ends i = 0 and `sides` are shared.
  const auto vertex = [&](int side, std::size_t i, int end) {
    const std::size_t shared = (i == 0 || i == sides) ? 0 : std::size_t(side);
    return (2 * i + shared) * 2 + std::size_t(end);
  };
  for(std::size_t i = 0; i <= sides; ++i)
    for(int side = 0; side < 2; ++side)
      for(int end = 0; end < 2; ++end)
      {
        const double x = -1 + 2 * double(i) / double(sides), a = side ? high : low;
        // Every slot is filled, the ends' second side with a copy that no triangle uses.
        points.emplace_back(x, (i == 0 || i == sides) ? 0. : a * (1 - x * x), end ? 1. : -1.);
      }
  for(std::size_t i = 0; i < sides; ++i)
  {
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t a0 = vertex(side, i, 0), a1 = vertex(side, i, 1), b0 = vertex(side, i + 1, 0),
                        b1 = vertex(side, i + 1, 1);
      triangles.push_back({ a0, b0, b1 });
      triangles.push_back({ a0, b1, a1 });
    }
    for(int end = 0; end < 2; ++end)
    {
      const std::size_t l0 = vertex(0, i, end), l1 = vertex(0, i + 1, end), h0 = vertex(1, i, end),
                        h1 = vertex(1, i + 1, end);
      if(l0 != h0)
        triangles.push_back({ l0, l1, h0 });
      if(l1 != h1)
        triangles.push_back({ h0, l1, h1 });
    }
  }
  // Drop the unused copies, then orient the soup consistently, and outward.
  std::vector<std::size_t> index(points.size(), std::size_t(-1));
  std::vector<Point> used;
  for(auto& triangle : triangles)
    for(std::size_t& v : triangle)
    {
      if(index[v] == std::size_t(-1))
      {
        index[v] = used.size();
        used.push_back(points[v]);
      }
      v = index[v];
    }
  if(!PMP::orient_polygon_soup(used, triangles))
    throw std::runtime_error("the closed blade's triangles cannot be oriented consistently");
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(used, triangles, mesh);
  if(!CGAL::is_closed(mesh))
    throw std::runtime_error("the closed blade's mesh is not closed");
  if(!PMP::is_outward_oriented(mesh))
    PMP::reverse_face_orientations(mesh);
  return mesh;
}

/// The polyline's segments for a chord error of at most `max_error` on the
/// closed blade's more curved side, y = a (1 - x^2): a (2 / sides)^2 / 4.
std::size_t closed_blade_sides(double max_error)
{
  const double a = rrht_test::closed_blade_camber + rrht_test::closed_blade_thickness / 2;
  return (std::max)(std::size_t(16), std::size_t(std::ceil(2 * std::sqrt(a / (4 * max_error)))));
}

/// One normal set fed to Poisson. RRHT_SIGNED is RRHT's unoriented normals,
/// each given the sign of the exact normal: what the surface would be with
/// an orientation that makes no mistake, so that the orientation's part and
/// the normals' part of a surface's error are told apart.
enum class Normals { RRHT, RRHT_SIGNED, JET, EXACT };
const char* name(Normals n)
{
  return n == Normals::RRHT          ? "rrht_orient"
         : n == Normals::RRHT_SIGNED ? "rrht_exact_signs"
         : n == Normals::JET         ? "jet_mst"
                                     : "exact";
}
const char* label(Normals n)
{
  return n == Normals::RRHT          ? "RRHT defaults (K = 100) + `rrht_orient_normals` (k = 18)"
         : n == Normals::RRHT_SIGNED ? "RRHT defaults (K = 100), the exact normals' signs"
         : n == Normals::JET         ? "jet fitting (K = 18) + `mst_orient_normals` (k = 18)"
                                     : "exact normals";
}

/// Estimates and orients the normals of `points`, the points of `cloud` in
/// its order; returns how many points were dropped (not oriented) and the
/// seconds taken.
std::pair<std::size_t, double> normals(Normals which, std::vector<Point_with_normal>& points,
                                       const rrht_test::Cloud& cloud)
{
  const auto maps = CGAL::RRHT::parameters::point_map(Point_map()).normal_map(Normal_map());
  const std::size_t before = points.size();
  CGAL::Real_timer timer;
  timer.start();
  if(which == Normals::RRHT || which == Normals::RRHT_SIGNED)
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(points, 100, maps);
  if(which == Normals::RRHT)
    points.erase(CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(points, 18, maps), points.end());
  else if(which == Normals::JET)
  {
    CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(points, 18, maps);
    points.erase(CGAL::mst_orient_normals(points, 18, maps), points.end());
  }
  timer.stop();
  // The estimation keeps the points in their order.
  if(which == Normals::RRHT_SIGNED)
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const rrht_test::Vector& truth = cloud[i].truth;
      if(points[i].second * Vector(truth.x(), truth.y(), truth.z()) < 0)
        points[i].second = -points[i].second;
    }
  return { before - points.size(), timer.time() };
}

/// Meshes the zero level of `function`: mesh_zero_level() of
/// examples/rrht_pipeline_example.cpp, which has the comments.
bool mesh_zero_level(const Poisson_function& function, double spacing, Mesh& mesh)
{
  const K::Sphere_3 sphere(function.get_inner_point(), 25 * function.bounding_sphere().squared_radius());
  const double distance = 0.375 * spacing, error = distance / 1000 / std::sqrt(sphere.squared_radius());
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
  typedef CGAL::Labeled_mesh_domain_3<K> Domain;
  typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Triangulation;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Triangulation> C3t3;
  const Domain domain =
    Domain::create_implicit_mesh_domain(function, sphere, CGAL::parameters::relative_error_bound(error));
  const CGAL::Mesh_criteria_3<Triangulation> criteria(CGAL::parameters::facet_angle = 20.,
                                                      CGAL::parameters::facet_size = 30 * spacing,
                                                      CGAL::parameters::facet_distance = distance);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria,
                                            CGAL::parameters::no_exude().no_perturb().manifold_with_boundary());
  if(c3t3.triangulation().number_of_vertices() == 0)
    return false;
  CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, mesh);
#else
  typedef CGAL::Surface_mesh_default_triangulation_3 Triangulation;
  typedef CGAL::Surface_mesh_complex_2_in_triangulation_3<Triangulation> C2t3;
  const CGAL::Implicit_surface_3<K, Poisson_function> surface(function, sphere, error);
  const CGAL::Surface_mesh_default_criteria_3<Triangulation> criteria(20., 30 * spacing, distance);
  Triangulation triangulation;
  C2t3 c2t3(triangulation);
  CGAL::get_default_random() = CGAL::Random(0);
  CGAL::make_surface_mesh(c2t3, surface, criteria, CGAL::Manifold_with_boundary_tag());
  if(triangulation.number_of_vertices() == 0)
    return false;
  CGAL::facets_in_complex_2_to_triangle_mesh(c2t3, mesh);
#endif
  return true;
}

/// Poisson with the checks of reconstruct() in
/// examples/rrht_pipeline_example.cpp. Returns why it failed, or an empty
/// string.
std::string poisson(const std::vector<Point_with_normal>& points, double spacing, Mesh& mesh)
{
  if(points.empty())
    return "no points left";
  Poisson_function function(points.begin(), points.end(), Point_map(), Normal_map());
  if(function.tr().dimension() < 3)
    return "the points lie in a plane";
  if(!function.compute_implicit_function())
    return "the Poisson equation could not be solved";
  std::vector<Poisson_function::Triangulation::Vertex_handle> hull;
  function.tr().adjacent_vertices(function.tr().infinite_vertex(), std::back_inserter(hull));
  const std::size_t negative =
    std::count_if(hull.begin(), hull.end(), [](const auto& v) { return v->f() < 0; });
  if(function(function.get_inner_point()) >= 0 || negative > 0.02 * hull.size())
    return "refused: the implicit function is negative at " + std::to_string(negative) + " of the " +
           std::to_string(hull.size()) + " vertices of its hull";
  try
  {
    if(!mesh_zero_level(function, spacing, mesh))
      return "the surface mesher found no surface";
  }
  catch(const CGAL::Failure_exception& e)
  {
    return "the surface mesher failed: " + e.message().substr(0, e.message().find('\n'));
  }
  return std::string();
}

/// poisson() in a process of its own (this program, `--reconstruct`), the
/// points and the surface passed through files in `folder`: run after other
/// work in this process, CGAL's surface mesher made other surfaces from the
/// same normals.
/// Returns why it failed, or an empty string.
std::string poisson_apart(const std::vector<Point_with_normal>& points, double spacing, const std::string& folder,
                          Mesh& mesh)
{
  const std::string input = folder + "/reconstruct.bin", output = folder + "/reconstruct.off",
                    failure = output + ".failure";
  {
    std::ofstream out(input, std::ios::binary);
    const double header[2] = { double(points.size()), spacing };
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    for(const Point_with_normal& p : points)
    {
      const double v[6] = { p.first.x(), p.first.y(), p.first.z(), p.second.x(), p.second.y(), p.second.z() };
      out.write(reinterpret_cast<const char*>(v), sizeof v);
    }
    if(!out)
      return "cannot write " + input;
  }
  std::remove(output.c_str());
  std::remove(failure.c_str());
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const int status = std::system(("'" + self + "' --reconstruct '" + input + "' '" + output + "'").c_str());
  std::remove(input.c_str());
  std::string message;
  if(std::ifstream in{ failure })
    std::getline(in, message);
  else if(status != 0)
    message = "the reconstruction ended abnormally (status " + std::to_string(status) + ")";
  else if(!CGAL::IO::read_polygon_mesh(output, mesh))
    message = "cannot read " + output;
  std::remove(output.c_str());
  std::remove(failure.c_str());
  return message;
}

/// The child of poisson_apart(): reconstructs the points of `input` into
/// `output` (vertices to the last bit), or writes why it failed into
/// `output`.failure.
int reconstruct(const std::string& input, const std::string& output)
{
  std::ifstream in(input, std::ios::binary);
  double header[2];
  if(!in.read(reinterpret_cast<char*>(header), sizeof header))
    return 1;
  std::vector<Point_with_normal> points(static_cast<std::size_t>(header[0]));
  for(Point_with_normal& p : points)
  {
    double v[6];
    if(!in.read(reinterpret_cast<char*>(v), sizeof v))
      return 1;
    p = { Point(v[0], v[1], v[2]), Vector(v[3], v[4], v[5]) };
  }
  Mesh mesh;
  const std::string failure = poisson(points, header[1], mesh);
  if(!failure.empty())
    return std::ofstream(output + ".failure") << failure << '\n' ? 0 : 1;
  return CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)) ? 0 : 1;
}

/// Distances from a uniform sample of `from` to `to`, in % of `diagonal`:
/// the mean and the 99th percentile.
std::pair<double, double> distances(const Mesh& from, const Face_tree& to, double diagonal)
{
  // The sampler draws from CGAL's default random generator too, whose seed
  // is the time.
  CGAL::get_default_random() = CGAL::Random(1);
  std::vector<Point> sample;
  PMP::sample_triangle_mesh(from, std::back_inserter(sample),
                            CGAL::parameters::number_of_points_on_faces(samples)
                              .do_sample_vertices(false)
                              .do_sample_edges(false)
                              .random_seed(1));
  std::vector<double> d;
  d.reserve(sample.size());
  double sum = 0;
  for(const Point& p : sample)
  {
    d.push_back(std::sqrt(to.squared_distance(p)) / diagonal * 100);
    sum += d.back();
  }
  if(d.empty())
    return { 0, 0 };
  std::nth_element(d.begin(), d.begin() + d.size() * 99 / 100, d.end());
  return { sum / d.size(), d[d.size() * 99 / 100] };
}

/// The normal error of the reconstructed surface: for each of its faces, the
/// unoriented angle between its normal and the true normal at the point of
/// the true surface closest to its centroid, weighted by its area; near a
/// sharp edge when that closest point is within `near_edge` of the diagonal
/// of one.
struct Normal_errors
{
  double near_mean = 0, near_above10 = 0, near_area_percent = 0, far_mean = 0;
};

Normal_errors normal_errors(const Mesh& mesh, const Truth& truth, const Face_tree& true_faces,
                            const Segment_tree& sharp_edges)
{
  double near_area = 0, near_sum = 0, near_bad = 0, far_area = 0, far_sum = 0;
  for(Face f : mesh.faces())
  {
    const auto h = mesh.halfedge(f);
    const Point &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
                &c = mesh.point(mesh.target(mesh.next(h)));
    const Vector n = CGAL::cross_product(b - a, c - a);
    const double area = std::sqrt(n.squared_length()) / 2;
    if(!(area > 0))
      continue;
    const auto closest = true_faces.closest_point_and_primitive(CGAL::centroid(a, b, c));
    const Vector t = PMP::compute_face_normal(closest.second, truth.mesh);
    const double cosine = std::min(1., std::abs(n * t) / (2 * area));
    const double angle = std::acos(cosine) * 180 / CGAL_PI;
    const bool near = !truth.sharp_edges.empty() &&
                      sharp_edges.squared_distance(closest.first) <= CGAL::square(near_edge * truth.diagonal);
    (near ? near_area : far_area) += area;
    (near ? near_sum : far_sum) += area * angle;
    if(near && angle > 10)
      near_bad += area;
  }
  Normal_errors e;
  if(near_area > 0)
  {
    e.near_mean = near_sum / near_area;
    e.near_above10 = near_bad / near_area * 100;
  }
  if(far_area > 0)
    e.far_mean = far_sum / far_area;
  e.near_area_percent = near_area / (near_area + far_area) * 100;
  return e;
}

/// The share of the points whose oriented normal points into the solid
/// (`rrht_test::inward()`), among those within 60 degrees of the exact
/// normal's line. The points are matched by position: the orientations
/// reorder them.
double flipped_percent(const std::vector<Point_with_normal>& oriented, rrht_test::Cloud cloud)
{
  const auto less = [](const rrht_test::Sample& s, const rrht_test::Sample& t) { return s.point < t.point; };
  std::sort(cloud.begin(), cloud.end(), less);
  std::size_t flipped = 0, scored = 0;
  for(const Point_with_normal& p : oriented)
  {
    rrht_test::Sample key;
    key.point = rrht_test::Point(p.first.x(), p.first.y(), p.first.z());
    const auto s = std::lower_bound(cloud.begin(), cloud.end(), key, less);
    if(s == cloud.end() || s->point != key.point)
      continue;
    s->normal = rrht_test::Vector(p.second.x(), p.second.y(), p.second.z());
    scored += std::abs(rrht_test::cosine_to_truth(*s)) >= 0.5;
    flipped += rrht_test::inward(*s);
  }
  return scored == 0 ? 0 : 100. * flipped / scored;
}

std::string fixed(double value, int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << value;
  return s.str();
}

struct Shape
{
  std::string name;
  rrht_test::Cloud cloud; // clean, truth outward
  Truth truth;
};

/// The shapes: meshes of ../shared/data sampled (face normal as truth), the
/// finned part, the machined parts (slotted disk, spool, drilled block, gear)
/// and the closed blade of test/shapes.h, their meshes built from their
/// prisms (the finned part's boxes) or the blade's polylines. A mesh absent
/// is skipped, with a message. The samples must lie on the true mesh:
/// exactly on the meshes of ../shared/data, within twice `chord_error` of
/// the diagonal on the built ones.
std::vector<Shape> shapes(const std::string& data, const std::vector<std::string>& names, std::size_t n)
{
  std::vector<Shape> result;
  for(const std::string& name : names)
  {
    Shape s;
    s.name = name;
    Mesh mesh;
    double tolerance = 1e-9; // of the diagonal: how far a sample may lie from the true mesh
    if(name == "finned" || name == "slotted_disk" || name == "spool" || name == "drilled_block" || name == "gear" ||
       name == "closed_blade")
    {
      s.cloud = name == "finned"         ? rrht_test::finned_part(n, 7)
                : name == "closed_blade" ? rrht_test::closed_blade(n, rrht_test::closed_blade_thickness, 7)
                                         : rrht_test::solid_boundary(rrht_test::machined_part_solid(name), n, 7);
      // The diagonal of the cloud, a little under the mesh's, bounds the chord error.
      const double max_error = chord_error * rrht_test::bounding_box_diagonal(s.cloud);
      CGAL::Real_timer timer;
      timer.start();
      if(name == "closed_blade")
        mesh = closed_blade_mesh(rrht_test::closed_blade_thickness, closed_blade_sides(max_error));
      else
      {
        rrht_test::Solid solid;
        if(name == "finned")
          for(const rrht_test::Box& box : rrht_test::finned_part_boxes())
            solid.added.push_back(rrht_test::box_prism(rrht_test::Point(box.lo[0], box.lo[1], box.lo[2]),
                                                       rrht_test::Point(box.hi[0], box.hi[1], box.hi[2])));
        else
          solid = rrht_test::machined_part_solid(name);
        mesh = solid_mesh(solid, max_error);
      }
      timer.stop();
      std::cout << name << ": true mesh built in " << fixed(timer.time(), 1) << " s" << std::endl;
      tolerance = 2 * chord_error;
    }
    else
    {
      const std::string file = name == "cube" ? "cube-meshed" : name;
      const std::string path = data + "/meshes/" + file + ".off";
      if(!CGAL::IO::read_polygon_mesh(path, mesh) || !rrht_test::sample_mesh(path, n, 7, s.cloud))
      {
        std::cout << "skipped (not found): " << path << std::endl;
        continue;
      }
    }
    // A mesh's faces may wind either way; so do the normals sampled on them.
    PMP::triangulate_faces(mesh);
    const double sign = CGAL::is_closed(mesh) && PMP::is_outward_oriented(mesh) ? 1. : -1.;
    if(!make_truth(mesh, s.truth))
      throw std::runtime_error("the true surface of " + name + " is not closed");
    for(rrht_test::Sample& t : s.cloud)
      t.truth = sign * t.truth / std::sqrt(t.truth.squared_length());
    // The cloud must lie on the true surface, and its normals point out.
    Face_tree tree(faces(s.truth.mesh).first, faces(s.truth.mesh).second, s.truth.mesh);
    tree.accelerate_distance_queries();
    double farthest = 0, outward = 0;
    for(const rrht_test::Sample& t : s.cloud)
    {
      const Point p(t.point.x(), t.point.y(), t.point.z());
      farthest = std::max(farthest, std::sqrt(tree.squared_distance(p)));
      const auto closest = tree.closest_point_and_primitive(p);
      const Vector normal = PMP::compute_face_normal(closest.second, s.truth.mesh);
      outward += normal.x() * t.truth.x() + normal.y() * t.truth.y() + normal.z() * t.truth.z() > 0;
    }
    if(farthest > tolerance * s.truth.diagonal || outward < 0.999 * s.cloud.size())
      throw std::runtime_error(name + ": the cloud is not on its true surface, or not outward (farthest sample " +
                               std::to_string(farthest / s.truth.diagonal) + " of the diagonal off, " +
                               std::to_string(100 * outward / s.cloud.size()) + "% outward)");
    std::cout << name << ": " << s.cloud.size() << " points, true mesh of " << s.truth.mesh.number_of_faces()
              << " triangles and " << s.truth.sharp_edges.size() << " sharp edges (above " << sharp_angle
              << " degrees); farthest sample " << farthest / s.truth.diagonal << " of the diagonal off it, "
              << 100 * outward / s.cloud.size() << "% of the exact normals outward" << std::endl;
    result.push_back(std::move(s));
  }
  return result;
}

std::vector<std::string> split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream stream(list);
  for(std::string item; std::getline(stream, item, ',');)
    if(!item.empty())
      items.push_back(item);
  return items;
}

} // namespace

int main(int argc, char** argv)
{
  po::options_description options("poisson_benchmark: Poisson surfaces from four sets of normals against the true "
                                  "surfaces (benchmark/README.md)");
  options.add_options()("help", "this help")
    ("data", po::value<std::string>()->default_value("../shared/data"), "the shared data folder (MANIFEST.md)")
    ("out", po::value<std::string>()->required(), "folder of poisson.csv and poisson.md")
    ("scratch", po::value<std::string>()->default_value(""), "folder of the surfaces (.off), if given")
    ("shapes",
     po::value<std::string>()->default_value("fandisk,anchor,cube,dragknob,pipe,u,handle,tripod,cross,"
                                             "finned,slotted_disk,spool,drilled_block,gear,closed_blade"),
     "comma-separated: fandisk, anchor, cube, dragknob, pipe, u, handle, tripod, cross (meshes of "
     "--data), finned, slotted_disk, spool, drilled_block, gear and closed_blade (test/shapes.h)")
    ("points", po::value<std::size_t>()->default_value(100000), "points per cloud")
    ("noise", po::value<std::string>()->default_value("0,0.2"),
     "comma-separated noise levels, in % of the bounding-box diagonal")
    ("threads", po::value<unsigned int>()->default_value(2), "threads of the estimations and orientations")
    ("reconstruct", po::value<std::vector<std::string> >()->multitoken(),
     "INPUT OUTPUT: reconstruct the points of INPUT into OUTPUT, for the benchmark itself");
  po::variables_map vm;
  try
  {
    po::store(po::parse_command_line(argc, argv, options), vm);
    if(vm.count("help"))
    {
      std::cout << options << std::endl;
      return 0;
    }
    if(vm.count("reconstruct"))
    {
      const std::vector<std::string> files = vm["reconstruct"].as<std::vector<std::string> >();
      return files.size() == 2 ? reconstruct(files[0], files[1]) : 2;
    }
    po::notify(vm);
  }
  catch(const std::exception& e)
  {
    std::cerr << "poisson_benchmark: " << e.what() << std::endl;
    return 2;
  }
  const std::string out = vm["out"].as<std::string>(), scratch = vm["scratch"].as<std::string>();
  const std::string work = scratch.empty() ? out : scratch; // poisson_apart()'s files
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, vm["threads"].as<unsigned int>());

  std::ofstream csv(out + "/poisson.csv"), md(out + "/poisson.md");
  if(!csv || !md)
  {
    std::cerr << "poisson_benchmark: cannot write into " << out << std::endl;
    return 1;
  }
  csv << "shape,noise_percent,points,normals,dropped,flipped_percent,normals_s,poisson_s,status,faces,"
         "to_true_mean_percent,to_true_p99_percent,from_true_mean_percent,from_true_p99_percent,"
         "near_edge_area_percent,near_edge_mean_deg,near_edge_above10_percent,elsewhere_mean_deg,message\n";
  md << "# Poisson surfaces against the true surfaces\n\n"
        "CGAL's Poisson reconstruction (the parameters of `poisson_surface_reconstruction_delaunay()`, average "
        "spacing of 6 neighbors, through the checks of `examples/rrht_pipeline_example.cpp`) from four sets of "
        "oriented normals. Distances in % of the true mesh's bounding-box diagonal, over "
        << samples
        << " points sampled uniformly on each surface: *to true* from the reconstructed surface to the true "
           "one (how far it strays), *from true* from the true surface to the reconstructed one (what it "
           "misses). Normal errors are unoriented angles, weighted by area, between each reconstructed face "
           "and the true face closest to its centroid; *near edges*: that closest point is within "
        << near_edge * 100 << "% of the diagonal of a sharp edge of the true mesh (faces whose normals differ by "
        << sharp_angle
        << " degrees or more). *Flipped*: points whose oriented normal points into the solid, among those "
           "within 60 degrees of the exact normal's line. A failed or refused reconstruction is reported with "
           "its message.\n";

  try
  {
    const std::vector<Shape> all =
      shapes(vm["data"].as<std::string>(), split(vm["shapes"].as<std::string>()), vm["points"].as<std::size_t>());
    for(const Shape& shape : all)
    {
      Face_tree true_faces(faces(shape.truth.mesh).first, faces(shape.truth.mesh).second, shape.truth.mesh);
      true_faces.accelerate_distance_queries();
      Segment_tree sharp_edges(shape.truth.sharp_edges.begin(), shape.truth.sharp_edges.end());
      if(!shape.truth.sharp_edges.empty())
        sharp_edges.accelerate_distance_queries();
      for(const std::string& noise_text : split(vm["noise"].as<std::string>()))
      {
        const double noise = std::stod(noise_text);
        rrht_test::Cloud cloud = shape.cloud;
        rrht_test::add_noise(cloud, noise, 1007);
        md << "\n## " << shape.name << ", " << cloud.size() << " points, noise " << noise << "%\n\n"
           << "| normals | dropped | flipped % | to true: mean % | p99 % | from true: mean % | p99 % "
              "| near edges: mean ° | > 10° (area %) | elsewhere: mean ° | faces | normals s | Poisson s |\n"
           << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        for(Normals which : { Normals::RRHT, Normals::RRHT_SIGNED, Normals::JET, Normals::EXACT })
        {
          std::vector<Point_with_normal> points;
          for(const rrht_test::Sample& s : cloud)
            points.emplace_back(Point(s.point.x(), s.point.y(), s.point.z()),
                                which == Normals::EXACT ? Vector(s.truth.x(), s.truth.y(), s.truth.z())
                                                        : CGAL::NULL_VECTOR);
          const double spacing = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(
            points, 6, CGAL::parameters::point_map(Point_map()));
          const auto [dropped, normals_s] = normals(which, points, cloud);
          const double flipped = flipped_percent(points, cloud);
          std::cout << shape.name << ", noise " << noise << "%, " << name(which) << ": " << std::flush;
          CGAL::Real_timer timer;
          timer.start();
          Mesh mesh;
          const std::string failure = poisson_apart(points, spacing, work, mesh);
          timer.stop();
          csv << shape.name << ',' << noise << ',' << cloud.size() << ',' << name(which) << ',' << dropped << ','
              << flipped << ',' << normals_s << ',' << timer.time() << ',';
          md << "| " << label(which) << " | " << dropped << " | " << fixed(flipped, 2) << " | ";
          if(!failure.empty())
          {
            std::cout << failure << std::endl;
            csv << "failed,,,,,,,,,\"" << failure << "\"\n";
            md << "failed: " << failure << " | | | | | | | | " << fixed(normals_s, 1) << " | "
               << fixed(timer.time(), 1) << " |\n";
            continue;
          }
          if(!scratch.empty())
            CGAL::IO::write_polygon_mesh(scratch + "/" + shape.name + "_noise" + noise_text + "_" + name(which) +
                                           ".off",
                                         mesh, CGAL::parameters::stream_precision(9));
          Face_tree reconstructed(faces(mesh).first, faces(mesh).second, mesh);
          reconstructed.accelerate_distance_queries();
          const auto to_true = distances(mesh, true_faces, shape.truth.diagonal);
          const auto from_true = distances(shape.truth.mesh, reconstructed, shape.truth.diagonal);
          const Normal_errors e = normal_errors(mesh, shape.truth, true_faces, sharp_edges);
          std::cout << mesh.number_of_faces() << " faces; to true " << to_true.first << "% (p99 "
                    << to_true.second << "%), from true " << from_true.first << "% (p99 " << from_true.second
                    << "%); near edges " << e.near_mean << " deg, " << e.near_above10 << "% above 10 deg"
                    << std::endl;
          csv << "ok," << mesh.number_of_faces() << ',' << to_true.first << ',' << to_true.second << ','
              << from_true.first << ',' << from_true.second << ',' << e.near_area_percent << ',' << e.near_mean
              << ',' << e.near_above10 << ',' << e.far_mean << ",\n";
          md << fixed(to_true.first, 3) << " | " << fixed(to_true.second, 3) << " | " << fixed(from_true.first, 3)
             << " | " << fixed(from_true.second, 3) << " | " << fixed(e.near_mean, 1) << " | "
             << fixed(e.near_above10, 1) << " | " << fixed(e.far_mean, 1) << " | " << mesh.number_of_faces()
             << " | " << fixed(normals_s, 1) << " | " << fixed(timer.time(), 1) << " |\n";
        }
      }
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "poisson_benchmark: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
