// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// PCL's NormalEstimationOMP (plane fitting by PCA on the neighborhood, with
// OpenMP threads) as a peer of the benchmark. Its own translation unit keeps
// PCL's headers and flags away from the CGAL code.

#include "shapes.h"

#include <pcl/features/normal_3d_omp.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <cmath>

namespace rrht_benchmark {

void pcl_estimate_normals(rrht_test::Cloud& cloud, unsigned int k, double radius, unsigned int threads)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  points->resize(cloud.size());
  for(std::size_t i = 0; i < cloud.size(); ++i)
    (*points)[i] = pcl::PointXYZ(float(cloud[i].point.x()), float(cloud[i].point.y()), float(cloud[i].point.z()));
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation(threads);
  estimation.setInputCloud(points);
  estimation.setSearchMethod(pcl::search::KdTree<pcl::PointXYZ>::Ptr(new pcl::search::KdTree<pcl::PointXYZ>));
  if(radius > 0)
    estimation.setRadiusSearch(radius);
  else
    estimation.setKSearch(int(k));
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  for(std::size_t i = 0; i < cloud.size(); ++i)
  {
    const pcl::Normal& n = normals[i];
    // PCL writes NaN where it cannot fit a plane; the benchmark counts a null normal.
    cloud[i].normal = (std::isfinite(n.normal_x) && std::isfinite(n.normal_y) && std::isfinite(n.normal_z))
                        ? rrht_test::Vector(n.normal_x, n.normal_y, n.normal_z)
                        : CGAL::NULL_VECTOR;
  }
}

} // namespace rrht_benchmark
