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

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/remove_outliers.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
typedef CGAL::Surface_mesh<Point> Mesh;

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : CGAL_RRHT_EXAMPLE_DATA "/fandisk_20k.xyz";
  const std::string output = (argc > 2) ? argv[2] : "fandisk_20k_poisson.off";
  const auto maps = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  CGAL::Real_timer timer;

  // 1. Read.
  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points), CGAL::parameters::point_map(Point_map())))
  {
    std::cerr << "Error: cannot read points from " << input << std::endl;
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

  // 4. Orient them consistently (minimum spanning tree).
  timer.reset();
  timer.start();
  const std::size_t before_orientation = points.size();
  points.erase(CGAL::mst_orient_normals(points, 18, maps), points.end());
  timer.stop();
  std::cout << "4. oriented the normals in " << timer.time() << " s; " << before_orientation - points.size()
            << " points could not be oriented and were dropped" << std::endl;

  // 5. Poisson surface reconstruction.
  timer.reset();
  timer.start();
  Mesh mesh;
  if(!CGAL::poisson_surface_reconstruction_delaunay(points.begin(), points.end(), Point_map(), Normal_map(), mesh, spacing))
  {
    std::cerr << "Error: Poisson reconstruction failed" << std::endl;
    return EXIT_FAILURE;
  }
  timer.stop();
  std::cout << "5. reconstructed a surface of " << mesh.number_of_vertices() << " vertices and "
            << mesh.number_of_faces() << " faces (Poisson) in " << timer.time() << " s" << std::endl;

  // 6. Write.
  if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(9)))
  {
    std::cerr << "Error: cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "6. wrote the mesh to " << output << std::endl;
  return EXIT_SUCCESS;
}
