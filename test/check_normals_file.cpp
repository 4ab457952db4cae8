// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks a file written by an example against the exact normals:
//   check_normals_file output.xyz truth.xyz max_share_above_10_degrees
// output: x y z nx ny nz per line; truth: the same points with exact normals.
// Fails unless both have the same points, every normal is a unit vector,
// and at most the given share of normals is more than 10 degrees off.

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {
bool read(const char* path, std::vector<std::vector<double> >& rows)
{
  std::ifstream in(path);
  if(!in)
    return false;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream words(line);
    std::vector<double> row(6);
    for(double& x : row)
      if(!(words >> x))
        return false;
    rows.push_back(row);
  }
  return true;
}
} // namespace

int main(int argc, char** argv)
{
  if(argc != 4)
  {
    std::cerr << "usage: check_normals_file output.xyz truth.xyz max_share_above_10_degrees\n";
    return EXIT_FAILURE;
  }
  std::vector<std::vector<double> > output, truth;
  if(!read(argv[1], output) || !read(argv[2], truth))
  {
    std::cerr << "FAILED: cannot read six numbers per line from " << argv[1] << " and " << argv[2] << "\n";
    return EXIT_FAILURE;
  }
  if(output.size() != truth.size())
  {
    std::cerr << "FAILED: " << output.size() << " points written, " << truth.size() << " expected\n";
    return EXIT_FAILURE;
  }
  std::size_t above = 0;
  for(std::size_t i = 0; i < output.size(); ++i)
  {
    const std::vector<double>& o = output[i];
    const std::vector<double>& t = truth[i];
    for(int d = 0; d < 3; ++d)
      if(std::abs(o[d] - t[d]) > 1e-5)
      {
        std::cerr << "FAILED: point " << i << " moved\n";
        return EXIT_FAILURE;
      }
    const double norm = std::sqrt(o[3] * o[3] + o[4] * o[4] + o[5] * o[5]);
    if(!(std::abs(norm - 1) < 1e-6))
    {
      std::cerr << "FAILED: normal " << i << " has length " << norm << "\n";
      return EXIT_FAILURE;
    }
    const double cosine = std::abs(o[3] * t[3] + o[4] * t[4] + o[5] * t[5]) /
                          std::sqrt(t[3] * t[3] + t[4] * t[4] + t[5] * t[5]);
    above += cosine < std::cos(10 * 3.14159265358979323846 / 180);
  }
  const double share = double(above) / output.size();
  std::cout << output.size() << " unit normals, " << 100 * share << "% more than 10 degrees off the exact normals\n";
  if(!(share <= std::atof(argv[3])))
  {
    std::cerr << "FAILED: more than " << 100 * std::atof(argv[3]) << "%\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
