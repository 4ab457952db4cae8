// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Synthetic point clouds with exact normals (the shapes of the paper's
// Section 6) and the error measures of the paper, for tests and benchmarks.

#ifndef CGAL_RRHT_TEST_SHAPES_H
#define CGAL_RRHT_TEST_SHAPES_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
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
  double confidence = -1; // written by RRHT through `Confidence_of_sample`
};
typedef std::vector<Sample> Cloud;

/// CGAL::mst_orient_normals() finds the point it starts from (the highest)
/// by comparing each element of the range with it: it compares what a pair
/// of a point and a normal, the usual element, would.
inline bool operator==(const Sample& a, const Sample& b) { return a.point == b.point && a.normal == b.normal; }

/// Property maps over `Sample`: the point an estimator reads and the normal
/// it writes (and an orientation flips).
struct Point_of_sample
{
  typedef Sample key_type;
  typedef Point value_type;
  typedef const Point& reference;
  typedef boost::readable_property_map_tag category;
  friend const Point& get(Point_of_sample, const Sample& s) { return s.point; }
};

/// The normal of a sample, written by the estimators, read and flipped by
/// the orientations.
struct Normal_of_sample
{
  typedef Sample key_type;
  typedef Vector value_type;
  typedef Vector reference;
  typedef boost::read_write_property_map_tag category;
  friend Vector get(Normal_of_sample, const Sample& s) { return s.normal; }
  friend void put(Normal_of_sample, Sample& s, const Vector& n) { s.normal = n; }
};

struct Confidence_of_sample
{
  typedef Sample key_type;
  typedef double value_type;
  typedef double reference;
  typedef boost::writable_property_map_tag category;
  friend void put(Confidence_of_sample, Sample& s, double c) { s.confidence = c; }
};

const double pi = CGAL_PI;

/// The diagonal of the axis-aligned bounding box of the points.
inline double bounding_box_diagonal(const Cloud& cloud)
{
  if(cloud.empty())
    return 0;
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for(const Sample& s : cloud)
    for(int d = 0; d < 3; ++d)
    {
      lo[d] = (std::min)(lo[d], s.point[d]);
      hi[d] = (std::max)(hi[d], s.point[d]);
    }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/// A vector of three draws of `distribution`, each in its own statement:
/// the order of a call's arguments is unspecified, and a test's cloud must
/// be the same with every compiler. The last coordinate is drawn first.
template <typename Distribution>
Vector random_vector(std::mt19937& rng, Distribution& distribution)
{
  const double z = distribution(rng), y = distribution(rng), x = distribution(rng);
  return Vector(x, y, z);
}

/// Gaussian noise of standard deviation `percent` % of the bounding-box
/// diagonal on each coordinate (paper, Section 6).
inline void add_noise(Cloud& cloud, double percent, unsigned int seed)
{
  if(percent <= 0 || cloud.empty())
    return;
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0., percent / 100. * bounding_box_diagonal(cloud));
  for(Sample& s : cloud)
    s.point = s.point + random_vector(rng, gauss);
}

/// Appends `percent` % of outliers to the first `inliers` samples of the
/// cloud: each is drawn uniformly in the ball of radius `radius` around a
/// random inlier (paper, Section 6, Fig. 15). Outliers have a null truth.
inline void add_outliers(Cloud& cloud, double percent, double radius, unsigned int seed)
{
  const std::size_t inliers = cloud.size(), count = std::size_t(inliers * percent / 100. + 0.5);
  if(inliers == 0)
    return;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, inliers - 1);
  std::uniform_real_distribution<double> u(-1, 1);
  cloud.reserve(inliers + count);
  for(std::size_t i = 0; i < count; ++i)
  {
    Vector offset;
    do
      offset = random_vector(rng, u);
    while(offset.squared_length() > 1);
    Sample outlier;
    outlier.point = cloud[pick(rng)].point + radius * offset;
    outlier.truth = CGAL::NULL_VECTOR;
    cloud.push_back(outlier);
  }
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
    // Drawn as random_vector() draws: one statement each, the last first.
    const double y = 2 * u(rng) - 1, x = 2 * u(rng) - 1;
    s.point = Point(x, y, 0);
    s.truth = Vector(0, 0, 1);
  });
}

/// The unit sphere, uniformly.
inline Cloud sphere(std::size_t n, unsigned int seed)
{
  std::normal_distribution<double> g(0, 1);
  return generate(n, seed, [&](std::mt19937& rng, std::uniform_real_distribution<double>&, Sample& s) {
    Vector v = random_vector(rng, g);
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

/// A thin box: the plate [-1,1]^2 x [-t/2, t/2], all six faces,
/// uniformly over its area.
inline Cloud thin_box(std::size_t n, double t, unsigned int seed)
{
  const double big = 4, side = 2 * t, total = 2 * big + 4 * side; // the areas of the faces
  return generate(n, seed, [=](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const double f = u(rng) * total, x = 2 * u(rng) - 1, y = 2 * u(rng) - 1, z = (u(rng) - 0.5) * t;
    if(f < 2 * big) { s.point = Point(x, y, f < big ? t / 2 : -t / 2); s.truth = Vector(0, 0, 1); return; }
    const int face = (std::min)(int((f - 2 * big) / side), 3);
    if(face < 2) { s.point = Point(face == 0 ? 1 : -1, y, z); s.truth = Vector(1, 0, 0); }
    else { s.point = Point(x, face == 2 ? 1 : -1, z); s.truth = Vector(0, 1, 0); }
  });
}

/// A bent sheet of thickness t: a quarter of a cylinder of axis z,
/// length 2, both sides (radii 1 - t/2 and 1 + t/2) equally sampled.
inline Cloud bent_sheet(std::size_t n, double t, unsigned int seed)
{
  return generate(n, seed, [=](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const double a = u(rng) * pi / 2, z = 2 * u(rng) - 1, r = u(rng) < 0.5 ? 1 - t / 2 : 1 + t / 2;
    s.point = Point(r * std::cos(a), r * std::sin(a), z);
    s.truth = Vector(std::cos(a), std::sin(a), 0);
  });
}

/// The box [-1,1]^3 with the closed cubic cavity [-1+w, 1-w]^3 inside (walls
/// of thickness w, 0 < w < 1; w = 0.01 * 2 * sqrt(3) makes walls 1% of the
/// diagonal thick), both surfaces uniformly over their total area. The truth
/// is oriented out of the material: away from the centre on the outer faces,
/// into the cavity (towards the centre) on the inner ones.
inline Cloud hollow_box(std::size_t n, double w, unsigned int seed)
{
  const double h = (std::max)(0., 1 - w), outer = 24, inner = 24 * h * h; // cavity half-side, areas
  return generate(n, seed, [=](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const bool cavity = u(rng) * (outer + inner) >= outer;
    const double r = cavity ? h : 1.;
    const int face = (std::min)(5, int(6 * u(rng))), axis = face / 2;
    double c[3] = { r * (2 * u(rng) - 1), r * (2 * u(rng) - 1), r * (2 * u(rng) - 1) }, t[3] = { 0, 0, 0 };
    c[axis] = (face % 2) ? r : -r;
    t[axis] = ((face % 2 == 1) != cavity) ? 1. : -1.;
    s.point = Point(c[0], c[1], c[2]);
    s.truth = Vector(t[0], t[1], t[2]);
  });
}

/// `n` samples drawn uniformly over faces of areas `areas`: a face is
/// picked with a probability proportional to its area, then
/// `draw(face, rng, u, sample)` draws a point of it, uniformly, and says
/// whether to keep it (a face that another covers is rejected, and the
/// density stays uniform). On degenerate input (no area, or 10^6 draws in a
/// row rejected) it stops and returns the samples it has, possibly fewer
/// than `n`.
template <typename Draw>
Cloud sample_faces(const std::vector<double>& areas, std::size_t n, unsigned int seed, Draw draw)
{
  std::vector<double> cumulated_area;
  double total = 0;
  for(double area : areas)
    cumulated_area.push_back(total += (area > 0 ? area : 0.));
  Cloud cloud;
  if(!(total > 0))
    return cloud;
  cloud.reserve(n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const std::size_t max_rejections = 1000000;
  for(std::size_t rejections = 0; cloud.size() < n && rejections < max_rejections;)
  {
    // upper_bound never picks a face of zero area.
    const std::size_t f = std::upper_bound(cumulated_area.begin(), cumulated_area.end(), u(rng) * total) -
                          cumulated_area.begin();
    Sample s;
    if(!draw((std::min)(f, areas.size() - 1), rng, u, s))
    {
      ++rejections;
      continue;
    }
    rejections = 0;
    cloud.push_back(s);
  }
  return cloud;
}

/// An axis-aligned box [lo[0], hi[0]] x [lo[1], hi[1]] x [lo[2], hi[2]].
struct Box
{
  double lo[3], hi[3];
};

/// `n` points drawn uniformly over the boundary of the union of the boxes,
/// with its outward normal as truth. A face of a box is picked with a
/// probability proportional to its area and a point uniformly on it; the point
/// is kept only if it is on the boundary of the union, that is if, moved by a
/// tiny epsilon (1e-9, relative to the coordinate if larger than 1) along the
/// outward normal of the face, it is out of every box: faces shared with or
/// covered by another box are rejected, and the density stays uniform. On
/// degenerate input (no area, or 10^6 draws in a row rejected) it stops and
/// returns the points it has, possibly fewer than `n`.
inline Cloud box_union(const std::vector<Box>& boxes, std::size_t n, unsigned int seed)
{
  struct Face { std::size_t box; int axis; bool high; };
  std::vector<Face> faces;
  std::vector<double> areas;
  for(std::size_t b = 0; b < boxes.size(); ++b)
    for(int axis = 0; axis < 3; ++axis)
    {
      const int i = (axis + 1) % 3, j = (axis + 2) % 3;
      const double area = (boxes[b].hi[i] - boxes[b].lo[i]) * (boxes[b].hi[j] - boxes[b].lo[j]);
      for(int high = 0; high < 2; ++high)
      {
        faces.push_back(Face{ b, axis, high == 1 });
        areas.push_back(area);
      }
    }
  return sample_faces(areas, n, seed, [&](std::size_t f, std::mt19937& rng, std::uniform_real_distribution<double>& u,
                                          Sample& s) {
    const Face& face = faces[f];
    const Box& box = boxes[face.box];
    double p[3], q[3];
    for(int d = 0; d < 3; ++d)
      p[d] = box.lo[d] + u(rng) * (box.hi[d] - box.lo[d]);
    p[face.axis] = face.high ? box.hi[face.axis] : box.lo[face.axis];
    const double epsilon = 1e-9 * (std::max)(1., std::abs(p[face.axis]));
    std::copy(p, p + 3, q);
    q[face.axis] += face.high ? epsilon : -epsilon;
    for(const Box& other : boxes)
      if(other.lo[0] <= q[0] && q[0] <= other.hi[0] && other.lo[1] <= q[1] && q[1] <= other.hi[1] &&
         other.lo[2] <= q[2] && q[2] <= other.hi[2])
        return false;
    double t[3] = { 0, 0, 0 };
    t[face.axis] = face.high ? 1. : -1.;
    s.point = Point(p[0], p[1], p[2]);
    s.truth = Vector(t[0], t[1], t[2]);
    return true;
  });
}

/// The boxes of a finned part: the base block [-1,1] x [-1,1] x [-0.3,0]
/// with 8 fins [x0, x0+0.03] x [-0.8,0.8] x [0,0.6] on top, 0.03 thick
/// (about 1% of the diagonal) with gaps of 0.03 between them, centred in x.
inline std::vector<Box> finned_part_boxes()
{
  const int fins = 8;
  const double thickness = 0.03, gap = 0.03, start = -(fins * thickness + (fins - 1) * gap) / 2;
  std::vector<Box> boxes(1, Box{ { -1, -1, -0.3 }, { 1, 1, 0 } });
  for(int i = 0; i < fins; ++i)
  {
    const double x0 = start + i * (thickness + gap);
    boxes.push_back(Box{ { x0, -0.8, 0 }, { x0 + thickness, 0.8, 0.6 } });
  }
  return boxes;
}

/// `finned_part_boxes()`'s union, uniformly over its area with the outward
/// normal.
inline Cloud finned_part(std::size_t n, unsigned int seed) { return box_union(finned_part_boxes(), n, seed); }

/// An open thin blade, like a turbine blade, uniformly over its area: the
/// ellipse c(u) = (cos u, (t/2) sin u) of the plane xy (chord 2 along x,
/// thickness t > 0 along y) extruded along z in [-1,1] and twisted about the
/// z axis by 0.5 z radians, S(u, z) = R(0.5 z) c(u) + z e_z, without caps.
/// The truth, dS/du x dS/dz normalised, points out of the blade.
inline Cloud thin_blade(std::size_t n, double t, unsigned int seed)
{
  const double b = t / 2, k = 0.5; // semi-axis along y, twist rate
  // The area element |dS/du x dS/dz| = sqrt(b^2 cos^2 u + sin^2 u + k^2 (1 - b^2)^2 sin^2 u cos^2 u)
  // does not depend on z, and is at most `bound`.
  const double bound = std::sqrt((std::max)(1., b * b) + k * k * (1 - b * b) * (1 - b * b) / 4);
  return generate(n, seed, [=](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    double a, area;
    do
    {
      a = 2 * pi * u(rng);
      const double ca = std::cos(a), sa = std::sin(a);
      area = std::sqrt(b * b * ca * ca + sa * sa + k * k * (1 - b * b) * (1 - b * b) * sa * sa * ca * ca);
    } while(u(rng) * bound > area);
    const double z = 2 * u(rng) - 1, ca = std::cos(a), sa = std::sin(a), cr = std::cos(k * z),
                 sr = std::sin(k * z);
    s.point = Point(cr * ca - sr * b * sa, sr * ca + cr * b * sa, z);
    // dS/du x dS/dz = (R(k z) (b cos u, sin u), k (b^2 - 1) sin u cos u): outward, as at u = 0 it is +x.
    const Vector normal(cr * b * ca - sr * sa, sr * b * ca + cr * sa, k * (b * b - 1) * sa * ca);
    s.truth = normal / std::sqrt(normal.squared_length());
  });
}

/// A right prism: a convex polygon, or a disk, of the plane spanned by the
/// orthonormal vectors `u` and `v` at `origin`, swept along u x v from
/// `bottom` to `top`; a block, a gear's tooth, a shaft, a bore.
struct Prism
{
  Point origin;
  Vector u, v;
  double bottom, top;
  std::vector<std::pair<double, double> > polygon; // counterclockwise in (u, v); empty for the disk
  double radius;                                     // of the disk

  Vector w() const { return CGAL::cross_product(u, v); }

  /// Whether `p` is in the prism, its boundary and a margin of `tolerance`
  /// included.
  bool contains(const Point& p, double tolerance = 0) const
  {
    const Vector d = p - origin;
    const double c = d * w();
    return bottom - tolerance <= c && c <= top + tolerance && in_section(d * u, d * v, tolerance);
  }

  /// Whether (`a`, `b`) is in the polygon or the disk, its boundary and a
  /// margin of `tolerance` included.
  bool in_section(double a, double b, double tolerance = 0) const
  {
    if(polygon.empty())
      return a * a + b * b <= (radius + tolerance) * (radius + tolerance);
    for(std::size_t i = 0; i < polygon.size(); ++i)
    {
      const auto& p0 = polygon[i];
      const auto& p1 = polygon[(i + 1) % polygon.size()];
      const double ex = p1.first - p0.first, ey = p1.second - p0.second;
      if(ex * (b - p0.second) - ey * (a - p0.first) < -tolerance * std::sqrt(ex * ex + ey * ey))
        return false;
    }
    return true;
  }
};

/// The box [lo, hi], axis-aligned, as a prism.
inline Prism box_prism(const Point& lo, const Point& hi)
{
  return Prism{ CGAL::ORIGIN, Vector(1, 0, 0), Vector(0, 1, 0), lo.z(), hi.z(),
                { { lo.x(), lo.y() }, { hi.x(), lo.y() }, { hi.x(), hi.y() }, { lo.x(), hi.y() } }, 0 };
}

/// The cylinder of `radius` whose axis runs from `base` along the unit `axis`
/// for `length`.
inline Prism cylinder_prism(const Point& base, const Vector& axis, double radius, double length)
{
  // Any unit u perpendicular to the axis.
  const Vector helper = std::abs(axis.x()) < 0.9 ? Vector(1, 0, 0) : Vector(0, 1, 0);
  Vector u = CGAL::cross_product(helper, axis);
  u = u / std::sqrt(u.squared_length());
  const Vector v = CGAL::cross_product(axis, u);
  return Prism{ base, u, v, 0, length, {}, radius };
}

/// The prism over the convex `polygon` (counterclockwise) of the plane xy,
/// turned by `angle` about the z axis, from z = `bottom` to `top`.
inline Prism turned_prism(const std::vector<std::pair<double, double> >& polygon, double angle, double bottom,
                          double top)
{
  return Prism{ CGAL::ORIGIN, Vector(std::cos(angle), std::sin(angle), 0), Vector(-std::sin(angle), std::cos(angle), 0),
                bottom, top, polygon, 0 };
}

/// A solid made of prisms: the union of the `added` ones, less the union of
/// the `removed` ones (holes, slots, grooves).
struct Solid
{
  std::vector<Prism> added, removed;

  bool contains(const Point& p) const
  {
    auto in = [&](const Prism& prism) { return prism.contains(p); };
    return std::any_of(added.begin(), added.end(), in) && std::none_of(removed.begin(), removed.end(), in);
  }
};

/// `n` points drawn uniformly over the boundary of `solid`, with the normal
/// out of it as truth. A face of a prism (a cap, a side of the polygon, the
/// disk's side) is picked with a probability proportional to its area and a
/// point uniformly on it; the point is kept if it is on the boundary of the
/// solid (moved by a tiny epsilon against its normal, in; along it, out) and
/// on no face of an earlier prism of the same list (where two caps
/// coincide, the first samples them). The density stays uniform. On
/// degenerate input (no area, or 10^6 draws in a row rejected) it stops and
/// returns the points it has, possibly fewer than `n`.
inline Cloud solid_boundary(const Solid& solid, std::size_t n, unsigned int seed)
{
  struct Face { bool removed; std::size_t prism; int side; }; // side: -2 bottom, -1 top, else an edge
  std::vector<Face> faces;
  std::vector<double> face_areas;
  for(int removed = 0; removed < 2; ++removed)
  {
    const std::vector<Prism>& prisms = removed ? solid.removed : solid.added;
    for(std::size_t i = 0; i < prisms.size(); ++i)
    {
      const Prism& p = prisms[i];
      // The two caps, then the sides: the disk's, or one per side of the polygon.
      double cap = pi * p.radius * p.radius;
      std::vector<double> sides;
      if(p.polygon.empty())
        sides.push_back(2 * pi * p.radius * (p.top - p.bottom));
      else
      {
        cap = 0;
        for(std::size_t e = 0; e < p.polygon.size(); ++e)
        {
          const auto& a = p.polygon[e];
          const auto& b = p.polygon[(e + 1) % p.polygon.size()];
          cap += (a.first * b.second - b.first * a.second) / 2;
          sides.push_back(std::hypot(b.first - a.first, b.second - a.second) * (p.top - p.bottom));
        }
      }
      for(int side = -2; side < int(sides.size()); ++side)
      {
        faces.push_back(Face{ removed == 1, i, side });
        face_areas.push_back(side < 0 ? cap : sides[std::size_t(side)]);
      }
    }
  }
  return sample_faces(face_areas, n, seed, [&](std::size_t f, std::mt19937& rng,
                                               std::uniform_real_distribution<double>& u, Sample& s) {
    const Face& face = faces[f];
    const std::vector<Prism>& prisms = face.removed ? solid.removed : solid.added;
    const Prism& prism = prisms[face.prism];
    double a = 0, b = 0, c = 0, na = 0, nb = 0, nc = 0; // the point and the normal out of the prism, in (u, v, w)
    if(face.side < 0)
    {
      c = face.side == -1 ? prism.top : prism.bottom;
      nc = face.side == -1 ? 1 : -1;
      // Uniformly in the polygon or the disk, by rejection from its bounding box.
      double lo[2] = { -prism.radius, -prism.radius }, hi[2] = { prism.radius, prism.radius };
      for(std::size_t e = 0; e < prism.polygon.size(); ++e)
      {
        const auto& q = prism.polygon[e];
        lo[0] = e ? (std::min)(lo[0], q.first) : q.first;
        hi[0] = e ? (std::max)(hi[0], q.first) : q.first;
        lo[1] = e ? (std::min)(lo[1], q.second) : q.second;
        hi[1] = e ? (std::max)(hi[1], q.second) : q.second;
      }
      do
      {
        a = lo[0] + u(rng) * (hi[0] - lo[0]);
        b = lo[1] + u(rng) * (hi[1] - lo[1]);
      } while(!prism.in_section(a, b));
    }
    else
    {
      c = prism.bottom + u(rng) * (prism.top - prism.bottom);
      const double t = u(rng);
      if(prism.polygon.empty())
      {
        na = std::cos(2 * pi * t);
        nb = std::sin(2 * pi * t);
        a = prism.radius * na;
        b = prism.radius * nb;
      }
      else
      {
        const auto& p0 = prism.polygon[std::size_t(face.side)];
        const auto& p1 = prism.polygon[(std::size_t(face.side) + 1) % prism.polygon.size()];
        const double length = std::hypot(p1.first - p0.first, p1.second - p0.second);
        a = p0.first + t * (p1.first - p0.first);
        b = p0.second + t * (p1.second - p0.second);
        na = (p1.second - p0.second) / length; // counterclockwise: out is to the right
        nb = -(p1.first - p0.first) / length;
      }
    }
    const Point p = prism.origin + a * prism.u + b * prism.v + c * prism.w();
    Vector normal = na * prism.u + nb * prism.v + nc * prism.w();
    if(face.removed)
      normal = -normal; // out of the solid is into the hole
    const double epsilon = 1e-9 * (std::max)(1., std::sqrt((p - CGAL::ORIGIN).squared_length()));
    bool rejected = !solid.contains(p - epsilon * normal) || solid.contains(p + epsilon * normal);
    for(std::size_t i = 0; i < face.prism && !rejected; ++i)
      rejected = prisms[i].contains(p, epsilon);
    s.point = p;
    s.truth = normal;
    return !rejected;
  });
}

/// A thick disk with narrow slots: the disk of radius 1, z in [-0.15, 0.15],
/// with a bore of radius 0.25 and its keyway, 0.06 wide and 0.08 deep, and 6
/// radial slots 0.03 wide (1% of the diagonal) cut through it from radius
/// 0.55 to the rim.
inline Solid slotted_disk_solid()
{
  Solid solid;
  solid.added.push_back(cylinder_prism(Point(0, 0, -0.15), Vector(0, 0, 1), 1, 0.3));
  solid.removed.push_back(cylinder_prism(Point(0, 0, -0.2), Vector(0, 0, 1), 0.25, 0.4));
  solid.removed.push_back(box_prism(Point(0.2, -0.03, -0.2), Point(0.33, 0.03, 0.2)));
  for(int slot = 0; slot < 6; ++slot)
    solid.removed.push_back(turned_prism({ { 0.55, -0.015 }, { 1.1, -0.015 }, { 1.1, 0.015 }, { 0.55, 0.015 } },
                                         pi / 6 + slot * pi / 3, -0.2, 0.2));
  return solid;
}

/// `slotted_disk_solid()`'s boundary (a closed surface, as every shape
/// below), uniformly over its area with the normal out of it.
inline Cloud slotted_disk(std::size_t n, unsigned int seed) { return solid_boundary(slotted_disk_solid(), n, seed); }

/// A spool: a shaft of radius 0.3 along z in [-0.8, 0.8] with a groove 0.1
/// wide and 0.08 deep around its middle, between two flanges of radius 1 and
/// 0.04 thick (1.2% of the diagonal), bored through with a radius of 0.12.
inline Solid spool_solid()
{
  Solid solid;
  const Vector z(0, 0, 1);
  solid.added.push_back(cylinder_prism(Point(0, 0, -0.8), z, 0.3, 0.75));
  solid.added.push_back(cylinder_prism(Point(0, 0, 0.05), z, 0.3, 0.75));
  solid.added.push_back(cylinder_prism(Point(0, 0, -0.8), z, 0.22, 1.6));
  solid.added.push_back(cylinder_prism(Point(0, 0, -0.84), z, 1, 0.04));
  solid.added.push_back(cylinder_prism(Point(0, 0, 0.8), z, 1, 0.04));
  solid.removed.push_back(cylinder_prism(Point(0, 0, -1), z, 0.12, 2));
  return solid;
}

/// `spool_solid()`'s boundary.
inline Cloud spool(std::size_t n, unsigned int seed) { return solid_boundary(spool_solid(), n, seed); }

/// A block [-1,1] x [-0.6,0.6] x [-0.4,0.4] drilled with holes: four
/// through its height (radii 0.2, 0.12, 0.08, 0.05), one through its width
/// (0.08), three blind bores from the top (0.15, 0.1, 0.05; 0.5, 0.4 and
/// 0.3 deep, with flat bottoms) and one from the side (0.08, 0.25 deep).
/// The smallest are a few neighborhood radii across at 100k points.
inline Solid drilled_block_solid()
{
  Solid solid;
  solid.added.push_back(box_prism(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4)));
  const Vector x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const double through[4][3] = { { -0.6, -0.25, 0.2 }, { -0.1, -0.3, 0.12 }, { 0.35, -0.3, 0.08 }, { 0.75, -0.3, 0.05 } };
  for(const auto& h : through)
    solid.removed.push_back(cylinder_prism(Point(h[0], h[1], -0.5), z, h[2], 1));
  solid.removed.push_back(cylinder_prism(Point(0.55, -0.7, 0), y, 0.08, 1.4));
  const double blind[3][4] = { { -0.6, 0.3, 0.15, 0.5 }, { -0.1, 0.3, 0.1, 0.4 }, { 0.35, 0.3, 0.05, 0.3 } };
  for(const auto& h : blind)
    solid.removed.push_back(cylinder_prism(Point(h[0], h[1], 0.4 - h[3]), z, h[2], h[3] + 0.1));
  solid.removed.push_back(cylinder_prism(Point(-1.1, 0, 0), x, 0.08, 0.35));
  return solid;
}

/// `drilled_block_solid()`'s boundary.
inline Cloud drilled_block(std::size_t n, unsigned int seed) { return solid_boundary(drilled_block_solid(), n, seed); }

/// A spur gear of 24 straight trapezoidal teeth, from the root circle of
/// radius 0.85 to the tip at radius 1 (0.12 wide at the root, 0.06 at the
/// tip, the gaps 0.1 wide at the root), z in [-0.1, 0.1], bored with a
/// radius of 0.3.
inline Solid spur_gear_solid()
{
  Solid solid;
  solid.added.push_back(cylinder_prism(Point(0, 0, -0.1), Vector(0, 0, 1), 0.85, 0.2));
  for(int tooth = 0; tooth < 24; ++tooth)
    solid.added.push_back(turned_prism({ { 0.8, -0.065 }, { 1, -0.03 }, { 1, 0.03 }, { 0.8, 0.065 } },
                                       tooth * pi / 12, -0.1, 0.1));
  solid.removed.push_back(cylinder_prism(Point(0, 0, -0.2), Vector(0, 0, 1), 0.3, 0.4));
  return solid;
}

/// `spur_gear_solid()`'s boundary.
inline Cloud spur_gear(std::size_t n, unsigned int seed) { return solid_boundary(spur_gear_solid(), n, seed); }

/// The machined parts above by name: "slotted_disk", "spool",
/// "drilled_block" or "gear".
inline Solid machined_part_solid(const std::string& name)
{
  if(name == "slotted_disk")
    return slotted_disk_solid();
  if(name == "spool")
    return spool_solid();
  if(name == "drilled_block")
    return drilled_block_solid();
  if(name == "gear")
    return spur_gear_solid();
  throw std::invalid_argument("unknown machined part " + name);
}

/// The camber of `closed_blade()`.
const double closed_blade_camber = 0.1;

/// The thickness at the middle of the closed blade that the tests and the
/// benchmark use: 2% of its chord.
const double closed_blade_thickness = 0.04;

/// A thin closed blade whose thickness goes to zero at its edges: between
/// the parabolas y = (c + t/2)(1 - x^2) and y = (c - t/2)(1 - x^2), x in
/// [-1,1] (camber c = `closed_blade_camber`, thickness t at the middle),
/// extruded along z in [-1,1] with flat caps.
inline Cloud closed_blade(std::size_t n, double t, unsigned int seed)
{
  const double high = closed_blade_camber + t / 2, low = closed_blade_camber - t / 2;
  // The sides' area element sqrt(1 + (2 a x)^2) dx dz is at most `bound`;
  // each side's area and a cap's (4 t / 3) weigh the pick.
  auto side_area = [](double a) { // the arc length of y = a (1 - x^2), x in [-1,1], times the length 2
    const double s = std::sqrt(1 + 4 * a * a);
    return 2 * (s + std::asinh(2 * a) / (2 * a));
  };
  const double upper = side_area(high), lower = side_area(std::abs(low) > 1e-12 ? std::abs(low) : 1e-12),
               caps = 2 * 4 * t / 3;
  return generate(n, seed, [=](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const double piece = u(rng) * (upper + lower + caps);
    double x;
    if(piece < upper + lower)
    {
      const double a = piece < upper ? high : low, bound = std::sqrt(1 + 4 * a * a);
      do
        x = 2 * u(rng) - 1;
      while(u(rng) * bound > std::sqrt(1 + 4 * a * a * x * x));
      const double side = piece < upper ? 1. : -1.; // up the upper side, down the lower one
      s.point = Point(x, a * (1 - x * x), 2 * u(rng) - 1);
      const Vector normal(side * 2 * a * x, side, 0);
      s.truth = normal / std::sqrt(normal.squared_length());
      return;
    }
    do // uniformly between the parabolas: the width t (1 - x^2)
      x = 2 * u(rng) - 1;
    while(u(rng) > 1 - x * x);
    const double z = u(rng) < 0.5 ? -1. : 1.;
    s.point = Point(x, low * (1 - x * x) + u(rng) * t * (1 - x * x), z);
    s.truth = Vector(0, 0, z);
  });
}

/// The box [-1,1]^3 with every edge and corner rounded to radius r
/// (0 <= r < 1): the points at distance r from the box [r-1, 1-r]^3,
/// uniformly over the area. Its faces meet the fillets (quarter cylinders)
/// and the corners (eighths of a sphere) tangentially: no sharp edge.
inline Cloud rounded_box(std::size_t n, double r, unsigned int seed)
{
  const double h = 1 - r; // the inner box's half-side
  const double faces = 24 * h * h, fillets = 12 * 2 * h * pi * r / 2, corners = 4 * pi * r * r;
  std::normal_distribution<double> g(0, 1);
  return generate(n, seed, [&](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    // A point c of the inner box and the unit normal t; the point is c + r t.
    double c[3] = { h * (2 * u(rng) - 1), h * (2 * u(rng) - 1), h * (2 * u(rng) - 1) }, t[3] = { 0, 0, 0 };
    const double piece = u(rng) * (faces + fillets + corners);
    const int axis = (std::min)(2, int(3 * u(rng)));
    auto sign = [&] { return u(rng) < 0.5 ? -1. : 1.; };
    if(piece < faces)
    {
      t[axis] = sign();
      c[axis] = t[axis] * h;
    }
    else if(piece < faces + fillets) // a fillet along `axis`
    {
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      const double angle = u(rng) * pi / 2, sa = sign(), sb = sign();
      c[a] = sa * h;
      c[b] = sb * h;
      t[a] = sa * std::cos(angle);
      t[b] = sb * std::sin(angle);
    }
    else // a corner: a uniform direction of its octant
    {
      double length = 0;
      for(double& x : t)
      {
        x = g(rng);
        length += x * x;
      }
      for(int d = 0; d < 3; ++d)
      {
        t[d] /= std::sqrt(length);
        c[d] = (t[d] < 0 ? -h : h);
      }
    }
    s.point = Point(c[0] + r * t[0], c[1] + r * t[1], c[2] + r * t[2]);
    s.truth = Vector(t[0], t[1], t[2]);
  });
}

/// A plane curve of segments and circular arcs, each tangent to the next,
/// by its arc length: the profile of an extruded part.
class Profile
{
public:
  /// Starts at (`x`, `y`), heading at `angle` (radians) from the x axis.
  Profile(double x, double y, double angle) : m_x(x), m_y(y), m_angle(angle) {}

  /// A segment of `length` straight ahead.
  Profile& line(double length) { return add(length, 0.); }

  /// An arc of `radius` that turns by `angle` (radians; positive: to the
  /// left).
  Profile& arc(double radius, double angle) { return add(radius * std::abs(angle), angle > 0 ? 1 / radius : -1 / radius); }

  double length() const { return m_total; }

  /// The largest curvature, in absolute value.
  double max_curvature() const
  {
    double largest = 0;
    for(const Piece& p : m_pieces)
      largest = (std::max)(largest, std::abs(p.curvature));
    return largest;
  }

  /// At arc length `s`: the position (`x`, `y`), the heading `angle` (the
  /// unit tangent is (cos, sin), the left normal (-sin, cos)) and the signed
  /// `curvature` (positive where the curve turns left).
  void at(double s, double& x, double& y, double& angle, double& curvature) const
  {
    std::size_t i = 0;
    while(i + 1 < m_pieces.size() && s > m_pieces[i].start + m_pieces[i].length)
      ++i;
    const Piece& p = m_pieces[i];
    const double d = (std::min)((std::max)(0., s - p.start), p.length);
    curvature = p.curvature;
    angle = p.angle + p.curvature * d;
    if(p.curvature == 0)
    {
      x = p.x + d * std::cos(p.angle);
      y = p.y + d * std::sin(p.angle);
    }
    else
    {
      // The centre is 1 / curvature to the left of the start.
      const double r = 1 / p.curvature;
      x = p.x + r * (std::sin(angle) - std::sin(p.angle));
      y = p.y - r * (std::cos(angle) - std::cos(p.angle));
    }
  }

private:
  struct Piece
  {
    double start, length, curvature, x, y, angle;
  };

  Profile& add(double length, double curvature)
  {
    m_pieces.push_back(Piece{ m_total, length, curvature, m_x, m_y, m_angle });
    m_total += length;
    double angle, k;
    at(m_total, m_x, m_y, angle, k);
    m_angle = angle;
    return *this;
  }

  std::vector<Piece> m_pieces;
  double m_x, m_y, m_angle, m_total = 0;
};

/// A bent plate of thickness t, closed: its mid-surface is a Z-shaped
/// profile of the plane xy (three flat parts, 0.7, 0.5 and 0.7 long, joined
/// by two 90 degree bends whose inner fillet radius is r > 0) extruded along
/// z in [-1,1]; the two sides, the ends and the two caps z = +-1 are
/// sampled uniformly over the area. The bends' fillets meet the flat parts
/// tangentially; the caps and ends have sharp edges.
inline Cloud filleted_plate(std::size_t n, double t, double r, unsigned int seed)
{
  const double radius = r + t / 2; // of the mid-surface's bends
  const Profile profile = Profile(-0.7 - radius, -0.25 - radius, 0)
                            .line(0.7).arc(radius, pi / 2).line(0.5).arc(radius, -pi / 2).line(0.7);
  const double length = profile.length(), sides = 2 * 2 * length, caps = 2 * length * t, ends = 2 * 2 * t;
  const double bound = 1 + profile.max_curvature() * t / 2;
  return generate(n, seed, [=](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    const double piece = u(rng) * (sides + caps + ends);
    const enum { side, cap, end } kind = piece < sides ? side : piece < sides + caps ? cap : end;
    double x, y, angle, curvature, along, w; // the point at offset w along the mid-surface's left normal
    if(kind != end)
      do // the area element (1 - curvature w) ds dz
      {
        along = u(rng) * length;
        w = kind == side ? (u(rng) < 0.5 ? -t / 2 : t / 2) : (u(rng) - 0.5) * t;
        profile.at(along, x, y, angle, curvature);
      } while(u(rng) * bound > 1 - curvature * w);
    else
    {
      along = u(rng) < 0.5 ? 0. : length;
      w = (u(rng) - 0.5) * t;
      profile.at(along, x, y, angle, curvature);
    }
    const double nx = -std::sin(angle), ny = std::cos(angle);
    double z = 2 * u(rng) - 1;
    if(kind == cap)
      z = u(rng) < 0.5 ? -1. : 1.;
    s.point = Point(x + w * nx, y + w * ny, z);
    if(kind == side)
      s.truth = w > 0 ? Vector(nx, ny, 0) : Vector(-nx, -ny, 0);
    else if(kind == cap)
      s.truth = Vector(0, 0, z);
    else
      s.truth = along > 0 ? Vector(std::cos(angle), std::sin(angle), 0) : Vector(-std::cos(angle), -std::sin(angle), 0);
  });
}

/// A slab with both fillets and sharp edges: the square [-1,1]^2 with its
/// corners rounded to radius r (0 <= r <= 1), extruded along z in
/// [-0.5, 0.5], uniformly over the area. Its four vertical edges are
/// fillets; the edges of its top and bottom faces are sharp (90 degrees).
inline Cloud rounded_slab(std::size_t n, double r, unsigned int seed)
{
  const double h = 1 - r;
  const Profile profile = Profile(-h, -1, 0)
                            .line(2 * h).arc(r, pi / 2).line(2 * h).arc(r, pi / 2)
                            .line(2 * h).arc(r, pi / 2).line(2 * h).arc(r, pi / 2);
  const double side = profile.length(), caps = 2 * (4 - (4 - pi) * r * r);
  return generate(n, seed, [=](std::mt19937& rng, std::uniform_real_distribution<double>& u, Sample& s) {
    if(u(rng) * (side + caps) < side)
    {
      double x, y, angle, curvature;
      profile.at(u(rng) * side, x, y, angle, curvature);
      s.point = Point(x, y, u(rng) - 0.5);
      s.truth = Vector(std::sin(angle), -std::cos(angle), 0); // counterclockwise: out is to the right
      return;
    }
    double x, y;
    do // uniformly in the rounded square
    {
      x = 2 * u(rng) - 1;
      y = 2 * u(rng) - 1;
    } while(std::abs(x) > h && std::abs(y) > h &&
            (std::abs(x) - h) * (std::abs(x) - h) + (std::abs(y) - h) * (std::abs(y) - h) > r * r);
    const double z = u(rng) < 0.5 ? -0.5 : 0.5;
    s.point = Point(x, y, z);
    s.truth = Vector(0, 0, z > 0 ? 1 : -1);
  });
}

/// `n` points drawn uniformly over the area of a polygon mesh (faces
/// fan-triangulated); the normal of the triangle a point is on is its truth.
/// Returns false if the file cannot be read or has no area.
inline bool sample_mesh(const std::string& path, std::size_t n, unsigned int seed, Cloud& cloud)
{
  std::vector<Point> vertices;
  std::vector<std::vector<std::size_t> > faces;
  if(!CGAL::IO::read_polygon_soup(path, vertices, faces))
    return false;
  struct Triangle { std::size_t a, b, c; };
  std::vector<Triangle> triangles;
  std::vector<double> cumulated_area;
  double total = 0;
  for(const auto& f : faces)
    for(std::size_t i = 2; i < f.size(); ++i)
    {
      const Triangle t = { f[0], f[i - 1], f[i] };
      total += std::sqrt(CGAL::cross_product(vertices[t.b] - vertices[t.a], vertices[t.c] - vertices[t.a])
                           .squared_length()) / 2;
      triangles.push_back(t);
      cumulated_area.push_back(total);
    }
  if(!(total > 0))
    return false;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  cloud.assign(n, Sample());
  for(Sample& s : cloud)
  {
    // upper_bound never picks a triangle of zero area.
    const std::size_t i = std::upper_bound(cumulated_area.begin(), cumulated_area.end(), u(rng) * total) -
                          cumulated_area.begin();
    const Triangle& t = triangles[(std::min)(i, triangles.size() - 1)];
    double a = u(rng), b = u(rng);
    if(a + b > 1) { a = 1 - a; b = 1 - b; }
    const Point &p = vertices[t.a], &q = vertices[t.b], &r = vertices[t.c];
    s.point = p + a * (q - p) + b * (r - p);
    s.truth = CGAL::cross_product(q - p, r - p);
  }
  return true;
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
  double mean = 0;         // mean angle error, degrees
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
    e.mean += a;
    e.rms_tau += (a < tau) ? a * a : 90. * 90.;
    e.share_above += (a > tau);
    e.max = (std::max)(e.max, a);
    ++n;
  }
  if(n > 0)
  {
    e.rms = std::sqrt(e.rms / n);
    e.mean /= n;
    e.rms_tau = std::sqrt(e.rms_tau / n);
    e.share_above /= n;
  }
  return e;
}

/// Errors over the samples that have a truth (outliers have none).
inline Errors errors(const Cloud& cloud, double tau = 10)
{
  return errors(cloud, [](const Sample& s) { return s.truth != CGAL::NULL_VECTOR; }, tau);
}

/// Rounds every coordinate to a multiple of `step` (a power of 2, say
/// 2^-20): such a cloud translated by any offset of a few million, as in
/// georeferenced coordinates, has exact coordinates in double precision.
inline void quantize(Cloud& cloud, double step)
{
  for(Sample& s : cloud)
    s.point = Point(std::round(s.point.x() / step) * step, std::round(s.point.y() / step) * step,
                    std::round(s.point.z() / step) * step);
}

/// Translates the points of the cloud by `offset` (rounded to double).
inline void translate(Cloud& cloud, const Vector& offset)
{
  for(Sample& s : cloud)
    s.point = s.point + offset;
}

/// Reads the points of a text file of lines "x y z ..." (the rest of a line
/// is ignored), keeping one line in `every`; they have no truth. Returns
/// false if the file cannot be read or has no point.
inline bool read_xyz(const std::string& path, std::size_t every, Cloud& cloud)
{
  std::ifstream in(path);
  cloud.clear();
  std::string line;
  for(std::size_t i = 0; std::getline(in, line); ++i)
  {
    std::istringstream fields(line);
    double x, y, z;
    if(i % every == 0 && (fields >> x >> y >> z))
    {
      Sample s;
      s.point = Point(x, y, z);
      s.truth = CGAL::NULL_VECTOR;
      cloud.push_back(s);
    }
  }
  return !cloud.empty();
}

} // namespace rrht_test

#endif // CGAL_RRHT_TEST_SHAPES_H
