// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT in the point-set pipeline of CGAL users:
//   read -> remove outliers -> RRHT normals -> orient -> Poisson surface -> write mesh
//
//   rrht_pipeline_example [input.xyz [output.off]]
//
// Without arguments: the bundled data/fandisk_20k.xyz, reconstructed into
// fandisk_20k_poisson.off in the current folder.
//
// What the surface cannot be trusted on: where two sides of the solid come
// within a few noise deviations of each other (thin walls and fins, and
// knife edges, under noise), the points alone cannot always tell which side
// a point is on. Some of their normals come out
// inward there, and Poisson grows a spurious sheet from each such patch.
// Fins and gaps a couple of neighbor spacings wide get poor normals even
// without noise, and a few such patches. The benchmark's README ("What the
// orientation misses") says how much.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/rrht_orient_normals.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/remove_outliers.h>
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
#include <CGAL/Random.h>
#endif
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>

#include "ply_header_check.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef Kernel::Sphere_3 Sphere;
typedef std::pair<Point, Vector> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Poisson_reconstruction_function<Kernel> Poisson_function;

// Meshes the zero level of `function` into `mesh` as
// CGAL::poisson_surface_reconstruction_delaunay() does, with its defaults:
// within 5 times the function's bounding sphere, facet angles of 20 degrees
// at least, Delaunay balls of radius 30 spacings at most, and a distance to
// the surface of 0.375 spacing at most. False if it found no surface; throws
// CGAL::Failure_exception if the mesher fails.
bool mesh_zero_level(const Poisson_function& function, double spacing, Mesh& mesh)
{
  const Sphere sphere(function.get_inner_point(), 25 * function.bounding_sphere().squared_radius());
  const double distance = 0.375 * spacing, error = distance / 1000 / std::sqrt(sphere.squared_radius());
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0) // Mesh_3, as CGAL 6 does (its Surface_mesher is deprecated)
  typedef CGAL::Labeled_mesh_domain_3<Kernel> Domain;
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
  const CGAL::Implicit_surface_3<Kernel, Poisson_function> surface(function, sphere, error);
  const CGAL::Surface_mesh_default_criteria_3<Triangulation> criteria(20., 30 * spacing, distance);
  Triangulation triangulation;
  C2t3 c2t3(triangulation);
  // The mesher's first points come from CGAL's default random generator,
  // seeded from the clock: a fixed seed makes the same surface at every run.
  CGAL::get_default_random() = CGAL::Random(0);
  CGAL::make_surface_mesh(c2t3, surface, criteria, CGAL::Manifold_with_boundary_tag());
  if(triangulation.number_of_vertices() == 0)
    return false;
  CGAL::facets_in_complex_2_to_triangle_mesh(c2t3, mesh);
#endif
  return true;
}

// Poisson surface reconstruction into `mesh`, with the steps and parameters of
// CGAL::poisson_surface_reconstruction_delaunay(), and checks that keep it
// from aborting on normals that are not consistently oriented. Returns why it
// failed, or an empty string.
std::string reconstruct(const std::vector<Point_with_normal>& points, double spacing, Mesh& mesh)
{
  if(points.empty()) // the function's constructor assumes some
    return "no points left";
  Poisson_function function(points.begin(), points.end(), Point_map(), Normal_map());
  if(function.tr().dimension() < 3) // its solver would read cells that do not exist
    return "the points lie in a plane: they bound no solid";
  if(!function.compute_implicit_function())
    return "the Poisson equation could not be solved";

  // Out of its Delaunay triangulation, the function takes the value of a hull
  // vertex. A hull vertex where it is negative brings the surface to the hull,
  // where the mesher stops on an error, at times after minutes. Closed
  // surfaces with consistent normals leave at most one hull vertex in a
  // hundred negative; inconsistent normals (such as a thin part's two sides
  // oriented alike) and some open surfaces, from a twentieth to a half.
  std::vector<Poisson_function::Triangulation::Vertex_handle> hull;
  function.tr().adjacent_vertices(function.tr().infinite_vertex(), std::back_inserter(hull));
  const std::size_t negative =
    std::count_if(hull.begin(), hull.end(), [](const auto& v) { return v->f() < 0; });
  if(function(function.get_inner_point()) >= 0 || negative > 0.02 * hull.size())
    return "the implicit function is negative at " + std::to_string(negative) + " of the " +
           std::to_string(hull.size()) + " vertices of its hull, where it must be positive: the normals are not "
           "consistently oriented, or the surface is too far from closed";

  try
  {
    if(!mesh_zero_level(function, spacing, mesh))
      return "the surface mesher found no surface";
  }
  catch(const CGAL::Failure_exception& e) // CGAL's mesher throws its errors in Release builds too
  {
    return "the surface mesher failed: " + e.message().substr(0, e.message().find('\n'));
  }
  return std::string();
}

// Writes `mesh` to `path` through a temporary file, renamed at the end, so that
// a failed write leaves no partial file. The temporary file keeps the
// extension, by which write_polygon_mesh() chooses the format.
bool write_mesh(const std::filesystem::path& path, const Mesh& mesh)
{
  std::filesystem::path temporary = path;
  temporary += ".partial" + path.extension().string();
  std::error_code error;
  if(CGAL::IO::write_polygon_mesh(temporary.string(), mesh, CGAL::parameters::stream_precision(9)))
  {
    std::filesystem::rename(temporary, path, error);
    if(!error)
      return true;
  }
  std::filesystem::remove(temporary, error);
  return false;
}

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : CGAL_RRHT_EXAMPLE_DATA "/fandisk_20k.xyz";
  const std::string output = (argc > 2) ? argv[2] : "fandisk_20k_poisson.off";
  const auto maps = CGAL::RRHT::parameters::point_map(Point_map()).normal_map(Normal_map());
  CGAL::Real_timer timer;

  // 1. Read.
  //    A PLY header is checked first: CGAL's reader crashes on some damaged ones.
  std::vector<Point_with_normal> points;
  const std::string damage = damaged_ply_header(input);
  if(!damage.empty() ||
     !CGAL::IO::read_points(input, std::back_inserter(points), CGAL::parameters::point_map(Point_map())) ||
     points.empty())
  {
    std::cerr << "Error: cannot read points from " << input << (damage.empty() ? "" : " (" + damage + ")")
              << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "1. read " << points.size() << " points from " << input << std::endl;

  // 2. Remove the points whose 24 nearest neighbors are, on average, more
  //    than twice as far as is usual in the cloud.
  timer.start();
  const double spacing_24 = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(points, 24, maps);
  const std::size_t before = points.size();
  points.erase(CGAL::remove_outliers<CGAL::Parallel_if_available_tag>(
                 points, 24, CGAL::parameters::point_map(Point_map()).threshold_percent(100.).threshold_distance(2. * spacing_24)),
               points.end());
  const double spacing = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(points, 6, maps);
  timer.stop();
  std::cout << "2. removed " << before - points.size() << " outliers in " << timer.time() << " s (average spacing "
            << spacing << ")" << std::endl;

  // 3. Normals that keep the sharp edges: RRHT, in place of jet or PCA fitting.
  timer.reset();
  timer.start();
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(points, 100, maps);
  const std::size_t before_null = points.size();
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const Point_with_normal& pn) { return pn.second == CGAL::NULL_VECTOR; }),
               points.end());
  timer.stop();
  std::cout << "3. estimated " << points.size() << " unoriented normals with RRHT (k = 100) in " << timer.time()
            << " s; " << before_null - points.size() << " points without normal dropped" << std::endl;

  // 4. Orient them consistently, out of the solid: Poisson needs it.
  timer.reset();
  timer.start();
  const std::size_t before_orientation = points.size();
  points.erase(CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(points, 18, maps), points.end());
  timer.stop();
  std::cout << "4. oriented the normals in " << timer.time() << " s; " << before_orientation - points.size()
            << " points could not be oriented and were dropped" << std::endl;

  // 5. Poisson surface reconstruction.
  timer.reset();
  timer.start();
  Mesh mesh;
  const std::string failure = reconstruct(points, spacing, mesh);
  if(!failure.empty())
  {
    std::cerr << "Error: Poisson reconstruction failed: " << failure << std::endl;
    return EXIT_FAILURE;
  }
  timer.stop();
  std::cout << "5. reconstructed a surface of " << mesh.number_of_vertices() << " vertices and "
            << mesh.number_of_faces() << " faces (Poisson) in " << timer.time() << " s" << std::endl;

  // 6. Write.
  if(!write_mesh(output, mesh))
  {
    std::cerr << "Error: cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "6. wrote the mesh to " << output << std::endl;
  return EXIT_SUCCESS;
}
