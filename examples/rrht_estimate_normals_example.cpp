// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a point set, estimates its normals with the Robust Randomized Hough
// Transform (default parameters), writes them.
//
//   rrht_estimate_normals_example [input.xyz [output.xyz]]
//
// Without arguments: the bundled data/fandisk_20k.xyz, written with its
// normals (x y z nx ny nz) to fandisk_20k_normals.xyz in the current folder.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
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

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : CGAL_RRHT_EXAMPLE_DATA "/fandisk_20k.xyz";
  const std::string output = (argc > 2) ? argv[2] : "fandisk_20k_normals.xyz";

  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points),
                            CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())))
  {
    std::cerr << "Error: cannot read points from " << input << std::endl;
    return EXIT_FAILURE;
  }

  // The same call as CGAL::jet_estimate_normals(), with RRHT's defaults: a
  // quadric fitted by least squares where the neighborhood is one smooth
  // sheet, the Hough transform elsewhere, as along sharp features.
  // CGAL::RRHT::parameters::paper_precise().point_map(...).normal_map(...)
  // would run the paper's precise setting at every point instead.
  const unsigned int k = 100; // neighbors, as in the paper's Table 1
  CGAL::Real_timer timer;
  timer.start();
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    points, k,
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
      .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
  timer.stop();

  std::size_t without_normal = 0;
  for(const Point_with_normal& pn : points)
    without_normal += (pn.second == CGAL::NULL_VECTOR);

  if(!CGAL::IO::write_XYZ(output, points,
                          CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                            .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>())
                            .stream_precision(9)))
  {
    std::cerr << "Error: cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }

  std::cout << points.size() << " points read from " << input << "\n"
            << "normals estimated with RRHT (k = " << k << ") in " << timer.time() << " s";
  if(without_normal > 0)
    std::cout << "; " << without_normal << " points have no normal (null vector)";
  std::cout << "\nwritten with normals (x y z nx ny nz) to " << output << std::endl;
  return EXIT_SUCCESS;
}
