// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The working memory of one thread of `CGAL::rrht_estimate_normals()`.

#ifndef CGAL_RRHT_INTERNAL_SCRATCH_H
#define CGAL_RRHT_INTERNAL_SCRATCH_H

#include <CGAL/RRHT/internal/Accumulator.h>
#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Cube_weights.h>
#include <CGAL/RRHT/internal/Cubes_sampler.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Plane_batch.h>
#include <CGAL/RRHT/internal/Points_sampler.h>
#include <CGAL/RRHT/internal/Triple.h>
#include <CGAL/RRHT/internal/Unif_sampler.h>
#include <CGAL/RRHT/internal/aggregate.h>
#include <CGAL/RRHT/internal/neighbor_planes.h>
#include <CGAL/RRHT/internal/refit_normal.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The working memory of one thread, reused from point to point.
struct Scratch
{
  Scratch(const Bin_layout& layout, const Cube_weights& cube_weights, unsigned int presampling_factor)
    : accumulator(layout), cubes(cube_weights), unif(presampling_factor), triples(Plane_batch::capacity)
  {}

  Neighbor_search::Scratch search;
  Neighborhood neighborhood;
  std::vector<Eigen::Vector3f> rotated; // the neighborhood rotated, over its radius, in single precision
  Accumulator accumulator;
  Points_sampler points;
  Cubes_sampler cubes;
  Unif_sampler unif;
  std::vector<Triple> triples; // a batch of draws
  Plane_batch planes;          // and their planes
  std::vector<Candidate_normal> candidates;
  Neighbor_planes_scratch neighbor_planes;
  Refit_scratch refit;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_SCRATCH_H
