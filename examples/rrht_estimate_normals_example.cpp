// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shortest program, the README's C++ example: reads a point set,
// estimates its normals with the defaults, writes them.
//
//   rrht_estimate_normals_example [input.xyz [output.xyz]]
//
// Without arguments, run from the repository's top folder: the bundled
// fandisk, written with its normals to fandisk_20k_normals.xyz.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/property_map.h>
#include <CGAL/rrht_estimate_normals.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef std::pair<Kernel::Point_3, Kernel::Vector_3> Point_with_normal;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : "examples/data/fandisk_20k.xyz";
  const std::string output = argc > 2 ? argv[2] : "fandisk_20k_normals.xyz";
  const auto maps = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                      .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>());

  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points), maps))
  {
    std::cerr << "cannot read points from " << input << std::endl;
    return EXIT_FAILURE;
  }

  // As CGAL::jet_estimate_normals(points, 100, maps): unoriented unit normals;
  // jet fitting's quadric where a neighborhood is one smooth sheet, the Hough
  // transform elsewhere, as along sharp features.
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(points, 100, maps);

  if(!CGAL::IO::write_points(output, points, maps.stream_precision(9)))
  {
    std::cerr << "cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points with their normals written to " << output << std::endl;
  return EXIT_SUCCESS;
}
