// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Open3D's PointCloud::EstimateNormals (plane fitting by PCA on the
// neighborhood, with OpenMP threads; what Python's
// open3d.geometry.PointCloud.estimate_normals calls) and its
// OrientNormalsConsistentTangentPlane (orient_normals_consistent_tangent_plane)
// as peers of the benchmark. Its own translation unit keeps Open3D's headers and flags away
// from the CGAL code.

#include "shapes.h"

#include <open3d/geometry/KDTreeSearchParam.h>
#include <open3d/geometry/PointCloud.h>

#include <omp.h>

#include <cstdlib>
#include <string>

namespace rrht_benchmark {

namespace {

// Open3D 0.16 sizes some OpenMP loops by omp_get_max_threads(), others by the physical
// cores unless OMP_NUM_THREADS is set; both settings stay in the measurement's child process.
void use_threads(unsigned int threads)
{
  ::setenv("OMP_NUM_THREADS", std::to_string(threads).c_str(), 1);
  omp_set_num_threads(int(threads));
}

} // namespace

void open3d_estimate_normals(rrht_test::Cloud& cloud, unsigned int k, double radius, unsigned int threads)
{
  use_threads(threads);
  open3d::geometry::PointCloud points;
  points.points_.reserve(cloud.size());
  for(const rrht_test::Sample& s : cloud)
    points.points_.emplace_back(s.point.x(), s.point.y(), s.point.z());
  if(radius > 0)
    points.EstimateNormals(open3d::geometry::KDTreeSearchParamHybrid(radius, int(k)));
  else
    points.EstimateNormals(open3d::geometry::KDTreeSearchParamKNN(int(k)));
  for(std::size_t i = 0; i < cloud.size(); ++i)
  {
    const Eigen::Vector3d& n = points.normals_[i];
    // A null or NaN normal is no plane; the benchmark counts a null normal. (With fewer
    // than 3 neighbors Open3D 0.16 writes (0, 0, 1) instead, scored like any normal.)
    cloud[i].normal = (n.allFinite() && n.squaredNorm() > 0) ? rrht_test::Vector(n.x(), n.y(), n.z())
                                                             : CGAL::NULL_VECTOR;
  }
}

void open3d_orient_normals(rrht_test::Cloud& cloud, unsigned int k, unsigned int threads)
{
  use_threads(threads);
  // The points and their normals copied inside the timed call, as a user of the C++ API
  // holding them elsewhere would; Open3D's own pipeline has them in the PointCloud already.
  open3d::geometry::PointCloud points;
  points.points_.reserve(cloud.size());
  points.normals_.reserve(cloud.size());
  for(const rrht_test::Sample& s : cloud)
  {
    points.points_.emplace_back(s.point.x(), s.point.y(), s.point.z());
    points.normals_.emplace_back(s.normal.x(), s.normal.y(), s.normal.z());
  }
  points.OrientNormalsConsistentTangentPlane(k);
  for(std::size_t i = 0; i < cloud.size(); ++i)
  {
    const Eigen::Vector3d& n = points.normals_[i];
    cloud[i].normal = rrht_test::Vector(n.x(), n.y(), n.z());
  }
}

} // namespace rrht_benchmark
