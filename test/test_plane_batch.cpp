// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planes of a batch of triples, their unit normals and bins.

#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Plane_batch.h>

#include "components.h"
#include "reference_bins.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("Plane_batch: unit normals and bins of the planes of a batch, degenerate triples flagged", "[accumulator]")
{
  Random rng(12, 0);
  std::vector<Eigen::Vector3f> points;
  for(int i = 0; i < 50; ++i)
    points.push_back(random_direction(rng).cast<float>() * float(rng.uniform_real()));
  // Three collinear points (exact in single precision) and a repeated one.
  const std::uint32_t line = std::uint32_t(points.size());
  points.emplace_back(0.f, 0.f, 0.f);
  points.emplace_back(0.5f, 0.25f, 0.125f);
  points.emplace_back(1.f, 0.5f, 0.25f);
  for(unsigned int slices : { 1u, 6u, 15u, 25u })
  {
    const Bin_layout layout(slices);
    const Reference_bins reference(layout);
    Plane_batch batch;
    std::size_t checked = 0;
    for(int round = 0; round < 200; ++round)
    {
      std::vector<Triple> triples;
      for(std::size_t i = 0; i < Plane_batch::capacity - 2; ++i)
        triples.push_back(Triple{{ rng.uniform_index(50), rng.uniform_index(50), rng.uniform_index(50) }});
      triples.push_back(Triple{{ line, line + 1, line + 2 }});
      triples.push_back(Triple{{ 7, 3, 7 }});
      batch.compute(points, triples.data(), triples.size(), layout);
      for(std::size_t i = 0; i < triples.size(); ++i)
      {
        const Triple& t = triples[i];
        const Eigen::Vector3d a = points[t[0]].cast<double>(), b = points[t[1]].cast<double>(),
                              c = points[t[2]].cast<double>();
        const Eigen::Vector3d u = b - a, v = c - a, n = u.cross(v);
        INFO("n_phi = " << slices << ", triple " << t[0] << " " << t[1] << " " << t[2]);
        if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || i + 2 >= triples.size())
        {
          REQUIRE(batch.bin(i) == Plane_batch::no_plane);
          continue;
        }
        if(n.squaredNorm() < 1e-6 * u.squaredNorm() * v.squaredNorm())
          continue; // nearly collinear: single precision may decide either way
        const Eigen::Vector3d unit = n.normalized();
        double sign;
        const std::size_t expected_bin = layout.bin_and_sign(unit.x(), unit.y(), unit.z(), sign);
        double to_boundary = 0;
        REQUIRE(reference.bin(unit, to_boundary) == expected_bin);
        if(to_boundary < 1e-5)
          continue; // rounding decides
        REQUIRE(batch.bin(i) == expected_bin);
        // Single precision: about 1e-7 / sin(angle of the triple).
        const double sine = n.norm() / (u.norm() * v.norm());
        REQUIRE((batch.normal(i) - sign * unit).norm() < 1e-6 / sine);
        ++checked;
      }
    }
    CHECK(checked > 10000);
  }
}
