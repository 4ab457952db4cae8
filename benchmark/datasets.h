// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmark's data: the paper's synthetic shapes (test/shapes.h) and the
// real data in ../shared/data (see its MANIFEST.md): meshes sampled with the
// face normal as truth, point sets with given normals, and scans without
// normals (timing only).

#ifndef CGAL_RRHT_BENCHMARK_DATASETS_H
#define CGAL_RRHT_BENCHMARK_DATASETS_H

#include "shapes.h"

#include <CGAL/IO/read_points.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace rrht_benchmark {

using namespace rrht_test;

struct Dataset
{
  std::string name;
  Cloud cloud;
  double noise_percent = 0;
  double outliers_percent = 0;
  std::size_t inliers = 0; // the samples before the outliers
  unsigned int noise_seed = 0; // the noise's draw, where several are compared (0: not said)
};

/// A clean cloud with noise added; every sample is an inlier.
inline Dataset with_noise(const std::string& name, Cloud cloud, double noise_percent, unsigned int seed)
{
  Dataset d;
  d.name = name;
  d.cloud = std::move(cloud);
  d.noise_percent = noise_percent;
  d.noise_seed = noise_percent > 0 ? seed + 1000 : 0;
  add_noise(d.cloud, noise_percent, d.noise_seed);
  d.inliers = d.cloud.size();
  return d;
}

/// `make(n, seed)` for a synthetic shape of test/shapes.h, with noise.
template <typename Make>
Dataset synthetic(const std::string& name, Make make, std::size_t n, double noise_percent, unsigned int seed)
{
  return with_noise(name, make(n, seed), noise_percent, seed);
}

/// Outliers after the noise, as in the paper's Fig. 15.
inline void add_outliers(Dataset& d, double percent, double radius, unsigned int seed)
{
  rrht_test::add_outliers(d.cloud, percent, radius, seed);
  d.outliers_percent = percent;
}

/// `n` points on a mesh of ../shared/data/meshes, with noise. False if absent.
inline bool mesh(const std::string& path, const std::string& name, std::size_t n, double noise_percent,
                 unsigned int seed, Dataset& d)
{
  Cloud cloud;
  if(!sample_mesh(path, n, seed, cloud))
    return false;
  d = with_noise(name, std::move(cloud), noise_percent, seed);
  return true;
}

namespace internal {
typedef std::pair<Point, Vector> Point_with_normal;
}

/// A point set with normals: "x y z nx ny nz" (.xyz, .ply) or "x y z" with the
/// normals in a second file of the same order (PCPNet's .xyz + .normals).
/// Every `stride`-th point is kept. False if absent or unreadable.
inline bool points_with_normals(const std::string& path, const std::string& normals_path, const std::string& name,
                                std::size_t stride, Dataset& d)
{
  d = Dataset();
  d.name = name;
  std::vector<internal::Point_with_normal> read;
  const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<internal::Point_with_normal>())
                    .normal_map(CGAL::Second_of_pair_property_map<internal::Point_with_normal>());
  if(!std::ifstream(path) || !CGAL::IO::read_points(path, std::back_inserter(read), np) || read.empty())
    return false;
  if(!normals_path.empty())
  {
    std::ifstream normals(normals_path);
    for(internal::Point_with_normal& p : read)
    {
      double x, y, z;
      if(!(normals >> x >> y >> z))
        return false;
      p.second = Vector(x, y, z);
    }
  }
  for(std::size_t i = 0; i < read.size(); i += stride)
  {
    Sample s;
    s.point = read[i].first;
    s.truth = read[i].second;
    d.cloud.push_back(s);
  }
  d.inliers = d.cloud.size();
  return true;
}

/// A scan without normals (every truth null: timing only).
inline bool scan(const std::string& path, const std::string& name, Dataset& d)
{
  d = Dataset();
  d.name = name;
  std::vector<Point> read;
  if(!std::ifstream(path) || !CGAL::IO::read_points(path, std::back_inserter(read)) || read.empty())
    return false;
  d.cloud.resize(read.size());
  for(std::size_t i = 0; i < read.size(); ++i)
  {
    d.cloud[i].point = read[i];
    d.cloud[i].truth = CGAL::NULL_VECTOR;
  }
  d.inliers = d.cloud.size();
  return true;
}

} // namespace rrht_benchmark

#endif // CGAL_RRHT_BENCHMARK_DATASETS_H
