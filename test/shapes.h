// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Synthetic point clouds with exact normals (the shapes of the paper's
// Section 6) and the error measures of the paper, for tests and benchmarks.

#ifndef CGAL_RRHT_TEST_SHAPES_H
#define CGAL_RRHT_TEST_SHAPES_H

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace rrht_test {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;

/// A point with its exact normal and the normal an estimator writes.
struct Sample
{
  Point point;
  Vector truth;
  Vector normal = CGAL::NULL_VECTOR;
};
typedef std::vector<Sample> Cloud;

const double pi = 3.14159265358979323846;

/// Gaussian noise of standard deviation `percent` % of the bounding-box
/// diagonal on each coordinate (paper, Section 6).
inline void add_noise(Cloud& cloud, double percent, unsigned int seed)
{
  if(percent <= 0 || cloud.empty())
    return;
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for(const Sample& s : cloud)
    for(int d = 0; d < 3; ++d)
    {
      lo[d] = (std::min)(lo[d], s.point[d]);
      hi[d] = (std::max)(hi[d], s.point[d]);
    }
  const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0., percent / 100. * diagonal);
  for(Sample& s : cloud)
    s.point = s.point + Vector(gauss(rng), gauss(rng), gauss(rng));
}

/// `n` samples, each set by `sample(rng, u, s)` with `u` uniform in [0, 1).
template <typename Sample_one>
Cloud generate(std::size_t n, unsigned int seed, Sample_one sample)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Cloud cloud(n);
  for(Sample& s : cloud)
    sample(rng, u, s);
  return cloud;
}

/// The square [-1,1]^2 of the plane z = 0.
inline Cloud plane(std::size_t n, unsigned int seed)
{
  return generate(n, seed, [](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    s.point = Point(2 * u(rng) - 1, 2 * u(rng) - 1, 0);
    s.truth = Vector(0, 0, 1);
  });
}

/// The unit sphere, uniformly.
inline Cloud sphere(std::size_t n, unsigned int seed)
{
  std::normal_distribution<double> g(0, 1);
  return generate(n, seed, [&](std::mt19937& rng, std::uniform_real_distribution<double>&, Sample& s) {
    Vector v(g(rng), g(rng), g(rng));
    v = v / std::sqrt(v.squared_length());
    s.point = CGAL::ORIGIN + v;
    s.truth = v;
  });
}

/// The surface of the cube [-1,1]^3, uniformly.
inline Cloud cube(std::size_t n, unsigned int seed)
{
  return generate(n, seed, [](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const int face = std::min(5, int(6 * u(rng))), axis = face / 2;
    double c[3] = { 2 * u(rng) - 1, 2 * u(rng) - 1, 2 * u(rng) - 1 }, t[3] = { 0, 0, 0 };
    c[axis] = (face % 2) ? 1. : -1.;
    t[axis] = 1;
    s.point = Point(c[0], c[1], c[2]);
    s.truth = Vector(t[0], t[1], t[2]);
  });
}

/// The closed cylinder of radius 1 and height 2 (two sharp circular edges),
/// uniformly over its area.
inline Cloud closed_cylinder(std::size_t n, unsigned int seed)
{
  return generate(n, seed, [](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const double a = 2 * pi * u(rng);
    if(u(rng) < 2. / 3.) // lateral area 4 pi, caps 2 pi
    {
      s.point = Point(std::cos(a), std::sin(a), 2 * u(rng) - 1);
      s.truth = Vector(std::cos(a), std::sin(a), 0);
    }
    else
    {
      const double r = std::sqrt(u(rng)), z = (u(rng) < 0.5) ? -1. : 1.;
      s.point = Point(r * std::cos(a), r * std::sin(a), z);
      s.truth = Vector(0, 0, 1);
    }
  });
}

/// The corner of Fig. 11: three unit squares on the planes x = 0, y = 0 and
/// z = 0 meeting at the origin, with densities 1 : 5 : 10.
inline Cloud anisotropic_corner(std::size_t n, unsigned int seed)
{
  return generate(n, seed, [](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const double f = u(rng) * 16, a = u(rng), b = u(rng);
    if(f < 1) { s.point = Point(0, a, b); s.truth = Vector(1, 0, 0); }      // density 1
    else if(f < 6) { s.point = Point(a, 0, b); s.truth = Vector(0, 1, 0); } // density 5
    else { s.point = Point(a, b, 0); s.truth = Vector(0, 0, 1); }           // density 10
  });
}

/// Unoriented angle in degrees between the estimate and the truth; 90 for a
/// null estimate.
inline double angle_error(const Sample& s)
{
  const double norm = std::sqrt(s.normal.squared_length() * s.truth.squared_length());
  if(!(norm > 0))
    return 90;
  return std::acos((std::min)(1., std::abs(s.normal * s.truth) / norm)) * 180 / pi;
}

struct Errors
{
  double rms = 0;          // RMS angle error, degrees
  double rms_tau = 0;      // RMS_tau (paper, Section 6): errors above tau count as 90 degrees
  double share_above = 0;  // share of points with an error above tau
  double max = 0;          // largest error
};

/// Errors over the samples for which `keep(sample)` holds.
template <typename Keep>
Errors errors(const Cloud& cloud, Keep keep, double tau = 10)
{
  Errors e;
  std::size_t n = 0;
  for(const Sample& s : cloud)
  {
    if(!keep(s))
      continue;
    const double a = angle_error(s);
    e.rms += a * a;
    e.rms_tau += (a < tau) ? a * a : 90. * 90.;
    e.share_above += (a > tau);
    e.max = (std::max)(e.max, a);
    ++n;
  }
  if(n > 0)
  {
    e.rms = std::sqrt(e.rms / n);
    e.rms_tau = std::sqrt(e.rms_tau / n);
    e.share_above /= n;
  }
  return e;
}

inline Errors errors(const Cloud& cloud, double tau = 10)
{
  return errors(cloud, [](const Sample&) { return true; }, tau);
}

} // namespace rrht_test

#endif // CGAL_RRHT_TEST_SHAPES_H
