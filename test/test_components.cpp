// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parts of the algorithm on their own: accumulator, stopping rules,
// random streams, triple sampling, aggregation.

#include <CGAL/RRHT/Accumulator.h>
#include <CGAL/RRHT/Plane_batch.h>
#include <CGAL/RRHT/aggregation.h>
#include <CGAL/RRHT/Random.h>
#include <CGAL/RRHT/Sampling.h>
#include <CGAL/RRHT/stopping_rules.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <vector>

using namespace CGAL::RRHT;

namespace {
Eigen::Vector3d random_direction(Random& rng)
{
  Eigen::Vector3d v;
  do
    v = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1);
  while(v.squaredNorm() > 1 || v.squaredNorm() < 1e-6);
  return v.normalized();
}
} // namespace

TEST_CASE("Accumulator size M is within 15% of the paper's Fig. 4", "[accumulator]")
{
  const std::map<unsigned int, double> figure_4 = { { 5, 23 }, { 10, 82 }, { 15, 171 }, { 20, 290 }, { 25, 441 } };
  for(const auto& entry : figure_4)
  {
    const Bin_layout layout(entry.first);
    INFO("n_phi = " << entry.first << ", M = " << layout.size() << ", paper " << entry.second);
    CHECK(std::abs(layout.size() - entry.second) <= 0.15 * entry.second);
  }
  CHECK(Bin_layout(15).size() == 172); // the documented value for the default
}

TEST_CASE("Accumulator bins have areas within 10% of each other and tile the half sphere", "[accumulator]")
{
  for(unsigned int slices : { 1u, 2u, 3u, 5u, 10u, 15u, 20u, 25u, 40u, 60u })
  {
    const Bin_layout layout(slices);
    double total = 0;
    for(std::size_t b = 0; b < layout.size(); ++b)
      total += layout.area(b);
    INFO("n_phi = " << slices);
    CHECK(total == Approx(2 * 3.14159265358979323846).epsilon(1e-12));
    CHECK(layout.area_ratio() >= 0.9);
  }
}

TEST_CASE("Every direction maps to a valid bin, n and -n to the same one", "[accumulator]")
{
  Random rng(7, 0);
  for(unsigned int slices : { 1u, 2u, 5u, 14u, 15u, 25u })
  {
    const Bin_layout layout(slices);
    std::vector<int> hits(layout.size(), 0);
    for(int i = 0; i < 200000; ++i)
    {
      const Eigen::Vector3d n = random_direction(rng);
      const std::size_t b = layout.bin(n);
      REQUIRE(b < layout.size());
      REQUIRE(layout.bin(-n) == b);
      REQUIRE(layout.bin(3.5 * n) == b);
      ++hits[b];
    }
    // Random directions hit every bin in proportion to its area.
    INFO("n_phi = " << slices);
    for(std::size_t b = 0; b < layout.size(); ++b)
    {
      const double expected = 200000 * layout.area(b) / (2 * 3.14159265358979323846);
      CHECK(std::abs(hits[b] - expected) < 6 * std::sqrt(expected) + 1);
    }
  }
  // Directions on the boundaries: poles, equator, axes.
  const Bin_layout layout(15);
  for(const Eigen::Vector3d& n : { Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                   Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, -1, 0),
                                   Eigen::Vector3d(0, 1e-300, -1) })
  {
    REQUIRE(layout.bin(n) < layout.size());
    REQUIRE(layout.bin(n) == layout.bin(-n));
  }
}

namespace {
// The bins by their definition (Bin_layout's documentation): slice of the
// polar angle of the upper representative, then bin of the azimuth in the
// slice, with acos and atan2.
class Reference_bins
{
public:
  explicit Reference_bins(const Bin_layout& layout) : m_slices(0), m_h(0)
  {
    first_of_slice.push_back(0);
    for(std::size_t b = 1; b < layout.size(); ++b)
      if(std::abs(std::acos(layout.center(b).z()) - std::acos(layout.center(b - 1).z())) > 1e-9)
        first_of_slice.push_back(b);
    first_of_slice.push_back(layout.size());
    m_slices = 2 * (first_of_slice.size() - 1) - (std::abs(layout.center(layout.size() - 1).z()) < 1e-12 ? 1 : 0);
    m_h = pi / m_slices;
  }

  // The bin of the unit vector n, and its distance (radians) to the nearest
  // boundary of its slice or bin.
  std::size_t bin(Eigen::Vector3d n, double& to_boundary) const
  {
    if(n.z() < 0)
      n = -n;
    const double phi = std::acos((std::min)(1., n.z()));
    const std::size_t s = (std::min)(std::size_t(phi / m_h), first_of_slice.size() - 2);
    const bool straddles = (m_slices % 2 == 1) && s + 2 == first_of_slice.size();
    const double period = straddles ? pi : 2 * pi;
    const double theta = std::fmod(std::atan2(n.y(), n.x()) + 2 * pi, period);
    const std::size_t bins = first_of_slice[s + 1] - first_of_slice[s];
    const double position = theta / period * bins;
    to_boundary = (std::min)(std::abs(position - std::round(position)) / bins * period * std::sin(phi),
                             std::abs(phi / m_h - std::round(phi / m_h)) * m_h);
    return first_of_slice[s] + (std::min)(std::size_t(position), bins - 1);
  }

  static constexpr double pi = 3.14159265358979323846;
  std::vector<std::size_t> first_of_slice;

private:
  std::size_t m_slices;
  double m_h;
};
} // namespace

TEST_CASE("The bin lookup tables give the bins defined by the angles", "[accumulator]")
{
  Random rng(11, 0);
  for(unsigned int slices : { 1u, 2u, 5u, 14u, 15u, 25u, 100u })
  {
    const Bin_layout layout(slices);
    const Reference_bins reference(layout);
    REQUIRE(reference.first_of_slice.size() == (slices + 1) / 2 + 1);
    for(int i = 0; i < 100000; ++i)
    {
      const Eigen::Vector3d n = random_direction(rng);
      double to_boundary = 0;
      const std::size_t expected = reference.bin(n, to_boundary);
      if(to_boundary < 1e-6)
        continue; // the tables hold single precision boundaries: rounding decides
      INFO("n_phi = " << slices << ", n = " << n.transpose());
      REQUIRE(layout.bin(n) == expected);
    }
  }
}

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

TEST_CASE("The AVX2 loops give the same planes and triples as the baseline ones, bit for bit", "[accumulator][sampling]")
{
  if(best_instruction_set() != Instruction_set::avx2)
  {
    WARN("this build or processor has no AVX2 loops: nothing to compare");
    return;
  }
  Random rng(14, 0);
  std::vector<Eigen::Vector3f> points;
  for(int i = 0; i < 101; ++i)
    points.push_back(random_direction(rng).cast<float>() * float(rng.uniform_real()));
  points.emplace_back(0.f, 0.f, 0.f); // with half of point 1 and point 1: a collinear triple
  points.emplace_back(points[1] * 0.5f);
  Plane_batch baseline(Instruction_set::baseline), avx2(Instruction_set::avx2);
  std::size_t compared = 0;
  for(unsigned int slices : { 1u, 6u, 15u, 25u })
  {
    const Bin_layout layout(slices);
    for(int round = 0; round < 200; ++round)
    {
      // Every count, so that every tail of the vectorized loops is run.
      const std::size_t count = 1 + std::size_t(round) % Plane_batch::capacity;
      std::vector<Triple> triples;
      for(std::size_t i = 0; i < count; ++i)
        triples.push_back(Triple{{ rng.uniform_index(103), rng.uniform_index(103), rng.uniform_index(103) }});
      triples.back() = Triple{{ 101, 102, 1 }};
      baseline.compute(points, triples.data(), count, layout);
      avx2.compute(points, triples.data(), count, layout);
      for(std::size_t i = 0; i < count; ++i)
      {
        INFO("n_phi = " << slices << ", plane " << i << " of " << count);
        REQUIRE(baseline.bin(i) == avx2.bin(i));
        if(baseline.bin(i) != Plane_batch::no_plane) // else no normal
        {
          REQUIRE(baseline.normal(i) == avx2.normal(i));
          ++compared;
        }
      }
    }
  }
  CHECK(compared > 20000);
  for(std::uint32_t n : { 5u, 20u, 101u, 4096u })
  {
    Points_sampler baseline_sampler(Instruction_set::baseline), avx2_sampler(Instruction_set::avx2);
    baseline_sampler.prepare(n, 300);
    avx2_sampler.prepare(n, 300);
    Random baseline_rng(15, n), avx2_rng(15, n);
    for(int run = 0; run < 20; ++run)
    {
      baseline_sampler.start_run();
      avx2_sampler.start_run();
      Triple baseline_triples[64], avx2_triples[64];
      for(std::size_t drawn = 0, count = 1; drawn < 300; drawn += count, count = count % 64 + 7)
      {
        const std::size_t wanted = (std::min)(count, std::size_t(300) - drawn);
        const std::size_t got = baseline_sampler.draw(baseline_rng, wanted, baseline_triples);
        REQUIRE(avx2_sampler.draw(avx2_rng, wanted, avx2_triples) == got);
        for(std::size_t i = 0; i < got; ++i)
        {
          INFO("n = " << n << ", run " << run << ", triple " << drawn + i);
          REQUIRE(baseline_triples[i] == avx2_triples[i]);
        }
      }
    }
  }
  // RRHT_Cubes, batches of every size up to two chunks.
  {
    std::vector<Eigen::Vector3d> neighborhood;
    for(int i = 0; i < 150; ++i)
      neighborhood.push_back(random_direction(rng) * rng.uniform_real());
    const Cube_weights weights(4);
    Cubes_sampler baseline_sampler(weights, Instruction_set::baseline), avx2_sampler(weights, Instruction_set::avx2);
    baseline_sampler.prepare(neighborhood, 1.);
    avx2_sampler.prepare(neighborhood, 1.);
    Random baseline_rng(17, 4), avx2_rng(17, 4);
    std::vector<Triple> baseline_triples(130), avx2_triples(130);
    for(std::size_t count = 1; count <= 130; ++count)
    {
      REQUIRE(baseline_sampler.draw(baseline_rng, count, baseline_triples.data()) == count);
      REQUIRE(avx2_sampler.draw(avx2_rng, count, avx2_triples.data()) == count);
      for(std::size_t i = 0; i < count; ++i)
      {
        INFO("RRHT_Cubes, batch of " << count << ", triple " << i);
        REQUIRE(baseline_triples[i] == avx2_triples[i]);
      }
    }
  }
  // RRHT_Unif: its probabilities come from loops of each instruction set
  // too (the spans of the lattice), from c = 1 to the largest c.
  for(unsigned int c : { 1u, 2u, 4u, 8u, 32u })
  {
    std::vector<Eigen::Vector3d> neighborhood;
    for(int i = 0; i < 150; ++i)
      neighborhood.push_back(random_direction(rng) * rng.uniform_real());
    Unif_sampler baseline_sampler(c, Instruction_set::baseline), avx2_sampler(c, Instruction_set::avx2);
    Random baseline_rng(16, c), avx2_rng(16, c);
    baseline_sampler.prepare(neighborhood, 1., baseline_rng);
    avx2_sampler.prepare(neighborhood, 1., avx2_rng);
    Triple baseline_triples[64], avx2_triples[64];
    for(int batch = 0; batch < 50; ++batch)
    {
      REQUIRE(baseline_sampler.draw(baseline_rng, 64, baseline_triples) == 64);
      REQUIRE(avx2_sampler.draw(avx2_rng, 64, avx2_triples) == 64);
      for(std::size_t i = 0; i < 64; ++i)
      {
        INFO("RRHT_Unif, c = " << c << ", batch " << batch << ", triple " << i);
        REQUIRE(baseline_triples[i] == avx2_triples[i]);
      }
    }
  }
}

TEST_CASE("The accumulator keeps the two most voted bins and the mean normal of the first", "[accumulator]")
{
  const Bin_layout layout(15);
  Accumulator accumulator(layout);
  const Eigen::Vector3d a = Eigen::Vector3d(0.1, 0.2, 1).normalized(), b = Eigen::Vector3d(1, 0.05, 0.1).normalized();
  REQUIRE(layout.bin(a) != layout.bin(b));
  for(int i = 0; i < 5; ++i)
    accumulator.vote(i % 2 ? a : Eigen::Vector3d(-2 * a)); // either sign, any length
  for(int i = 0; i < 3; ++i)
    accumulator.vote(b);
  CHECK(accumulator.number_of_votes() == 8);
  CHECK(accumulator.most_voted_bin() == layout.bin(a));
  CHECK(accumulator.votes_of_most_voted_bin() == 5);
  CHECK(accumulator.votes_of_second_most_voted_bin() == 3);
  CHECK(std::abs(accumulator.normal_of_most_voted_bin().dot(a)) == Approx(1).epsilon(1e-12));
  for(int i = 0; i < 3; ++i)
    accumulator.vote(b);
  CHECK(accumulator.most_voted_bin() == layout.bin(b));
  CHECK(accumulator.votes_of_second_most_voted_bin() == 5);
  accumulator.clear();
  CHECK(accumulator.number_of_votes() == 0);
  CHECK(accumulator.normal_of_most_voted_bin() == Eigen::Vector3d::Zero());
}

TEST_CASE("Eq. 7: the Hoeffding bound on the number of planes", "[stopping]")
{
  // ln(2 * 171 / 0.05) / (2 * 0.08^2) = 8.8306 / 0.0128 = 689.9
  CHECK(hoeffding_number_of_planes(171, 0.95, 0.08) == 690);
  CHECK(hoeffding_number_of_planes(172) == 691);
  // ln(2 * 100 / 0.1) / (2 * 0.1^2) = 7.6009 / 0.02 = 380.05
  CHECK(hoeffding_number_of_planes(100, 0.9, 0.1) == 381);
  CHECK_THROWS_AS(hoeffding_number_of_planes(0), std::invalid_argument);
  CHECK_THROWS_AS(hoeffding_number_of_planes(10, 1.0, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(hoeffding_number_of_planes(10, 0.9, 0.0), std::invalid_argument);
}

TEST_CASE("Eq. 10: disjoint confidence intervals of the two most voted bins", "[stopping]")
{
  // p1 - p2 >= 2 / sqrt(T)
  CHECK(confidence_intervals_are_disjoint(4, 0, 4));     // 1 - 0 >= 2 / 2
  CHECK(!confidence_intervals_are_disjoint(3, 0, 4));    // 0.75 < 1
  CHECK(confidence_intervals_are_disjoint(60, 20, 100)); // 0.4 >= 0.2
  CHECK(!confidence_intervals_are_disjoint(39, 20, 100));// 0.19 < 0.2
  CHECK(confidence_intervals_are_disjoint(40, 20, 100)); // 0.2 >= 0.2
  CHECK(!confidence_intervals_are_disjoint(20, 20, 100));
  CHECK(!confidence_intervals_are_disjoint(0, 0, 0));
}

TEST_CASE("Eq. 10 cannot hold while the most voted bin has fewer than 2 sqrt(T) votes", "[stopping]")
{
  // Exhaustively for small counts: whenever the test holds, the necessary
  // condition the accumulator waits for holds too, and it is tight (one
  // bin with all the votes passes the test as soon as it holds).
  for(std::size_t votes = 0; votes <= 300; ++votes)
  {
    for(std::size_t first = 0; first <= votes; ++first)
      for(std::size_t second = 0; second <= (std::min)(first, votes - first); ++second)
        if(confidence_intervals_are_disjoint(first, second, votes))
        {
          INFO(first << " " << second << " of " << votes);
          REQUIRE(confidence_intervals_can_be_disjoint(first, votes));
        }
    if(votes > 0)
      REQUIRE(confidence_intervals_can_be_disjoint(votes, votes) == confidence_intervals_are_disjoint(votes, 0, votes));
  }
  CHECK(!confidence_intervals_can_be_disjoint(34, 300)); // 34^2 = 1156 < 1200
  CHECK(confidence_intervals_can_be_disjoint(35, 300));  // 1225 >= 1200
}

namespace {
// Planes given by their bins only, in the interface of Plane_batch.
struct Bins_of_planes
{
  static constexpr std::uint32_t no_plane = Plane_batch::no_plane;
  std::vector<std::uint32_t> bins;
  std::uint32_t bin(std::size_t i) const { return bins[i]; }
  Eigen::Vector3d normal(std::size_t) const { return Eigen::Vector3d(0, 0, 1); }
};
} // namespace

TEST_CASE("The accumulator stops at the vote at which eq. 10 first holds, whatever the batches", "[accumulator]")
{
  // Votes of planes of random bins, skewed towards a few, given in batches
  // of random sizes: the accumulator calls the test at every vote at which
  // it can hold, and its two most voted bins are those of a plain count.
  const Bin_layout layout(15);
  Accumulator accumulator(layout);
  typedef Bins_of_planes Planes;
  Random rng(5, 6);
  std::size_t stopped_early = 0;
  for(int run = 0; run < 300; ++run)
  {
    accumulator.clear();
    std::vector<unsigned int> count(layout.size(), 0);
    const std::uint32_t spread = 2 + rng.uniform_index(40), skew = rng.uniform_index(4); // skew / 8 of the votes to bin 0
    std::size_t votes = 0, stop_at = 0;
    bool stopped = false;
    while(!stopped && votes < 700)
    {
      Planes planes;
      const std::size_t size = 1 + rng.uniform_index(64);
      for(std::size_t i = 0; i < size; ++i)
      {
        const std::uint32_t kind = rng.uniform_index(8);
        planes.bins.push_back(kind == 7 ? Planes::no_plane : kind < skew ? 0 : rng.uniform_index(spread));
      }
      std::size_t tests = 0;
      const std::size_t looked_at = accumulator.vote(planes, size, [&](unsigned int first, unsigned int second, std::size_t n) {
        ++tests;
        return stopped = confidence_intervals_are_disjoint(first, second, n);
      });
      // The same votes, counted plainly.
      for(std::size_t i = 0; i < looked_at; ++i)
      {
        if(planes.bins[i] == Planes::no_plane)
          continue;
        ++count[planes.bins[i]];
        ++votes;
        const unsigned int first = *std::max_element(count.begin(), count.end());
        std::vector<unsigned int> others = count;
        others.erase(std::max_element(others.begin(), others.end()));
        const unsigned int second = *std::max_element(others.begin(), others.end());
        if(stop_at == 0 && confidence_intervals_are_disjoint(first, second, votes))
          stop_at = votes;
      }
      REQUIRE(tests <= looked_at);
      REQUIRE(accumulator.number_of_votes() == votes);
      const unsigned int first = *std::max_element(count.begin(), count.end());
      REQUIRE(accumulator.votes_of_most_voted_bin() == first);
      REQUIRE(count[accumulator.most_voted_bin()] == first);
      std::vector<unsigned int> others = count;
      others.erase(others.begin() + std::ptrdiff_t(accumulator.most_voted_bin()));
      REQUIRE(accumulator.votes_of_second_most_voted_bin() == *std::max_element(others.begin(), others.end()));
    }
    // It stopped exactly at the first vote at which eq. 10 held.
    REQUIRE(stopped == (stop_at != 0));
    if(stopped)
    {
      REQUIRE(votes == stop_at);
      ++stopped_early;
    }
  }
  CHECK(stopped_early > 100); // both outcomes are tested
  CHECK(stopped_early < 250);
}

TEST_CASE("Random streams depend only on the seed and the stream number", "[random]")
{
  Random a(42, 17), b(42, 17), c(42, 18), d(43, 17);
  const auto x = a();
  CHECK(x == b());
  CHECK(x != c());
  CHECK(x != d());
  // Uniform indices are unbiased and in range.
  Random rng(1, 2);
  std::vector<int> counts(7, 0);
  for(int i = 0; i < 70000; ++i)
  {
    const std::uint32_t k = rng.uniform_index(7);
    REQUIRE(k < 7);
    ++counts[k];
  }
  for(int c7 : counts)
    CHECK(std::abs(c7 - 10000) < 500);
  // Rotations are rotations, and spread uniformly: the mean of R e_z vanishes.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(int i = 0; i < 20000; ++i)
  {
    const Eigen::Matrix3d r = rng.uniform_rotation();
    REQUIRE((r * r.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    REQUIRE(r.determinant() == Approx(1).epsilon(1e-12));
    mean += r.col(2);
  }
  CHECK((mean / 20000).norm() < 0.03);
}

TEST_CASE("RRHT_Points never draws the same triple twice in a run", "[sampling]")
{
  Points_sampler sampler;
  Random rng(3, 4);
  SECTION("more triples than draws: the filtered list of drawn triples")
  {
    sampler.prepare(30, 1000); // C(30,3) = 4060 > 1000
    for(int run = 0; run < 3; ++run)
    {
      sampler.start_run();
      std::set<Triple> seen;
      Triple t;
      for(int i = 0; i < 1000; ++i)
      {
        REQUIRE(sampler.draw(rng, 1, &t) == 1);
        REQUIRE(t[0] < t[1]);
        REQUIRE(t[1] < t[2]);
        REQUIRE(t[2] < 30);
        REQUIRE(seen.insert(t).second);
      }
    }
  }
  SECTION("large neighborhoods (the draw with Random::uniform_index), batches")
  {
    const std::uint32_t n = 5000;
    sampler.prepare(n, 2000);
    std::vector<int> uses(n, 0);
    for(int run = 0; run < 100; ++run)
    {
      sampler.start_run();
      std::set<Triple> seen;
      Triple batch[64];
      for(int drawn = 0; drawn < 2000; drawn += 50)
      {
        REQUIRE(sampler.draw(rng, 50, batch) == 50);
        for(int i = 0; i < 50; ++i)
        {
          REQUIRE(batch[i][0] < batch[i][1]);
          REQUIRE(batch[i][1] < batch[i][2]);
          REQUIRE(batch[i][2] < n);
          REQUIRE(seen.insert(batch[i]).second);
          for(std::uint32_t p : batch[i])
            ++uses[p];
        }
      }
    }
    // Each point is in a triple with probability 3 / n: 120 times expected.
    for(std::uint32_t p = 0; p < n; ++p)
      REQUIRE(std::abs(uses[p] - 120) < 6 * std::sqrt(120.) + 1);
  }
  SECTION("every triple equally likely (the vectorized draw of small neighborhoods)")
  {
    // C(12,3) = 220 triples, 100 per run: each is in a run with probability 100 / 220.
    std::map<Triple, int> runs_with;
    const int runs = 2000;
    for(int run = 0; run < runs; ++run)
    {
      sampler.prepare(12, 100);
      sampler.start_run();
      Triple batch[100];
      REQUIRE(sampler.draw(rng, 100, batch) == 100);
      for(const Triple& t : batch)
        ++runs_with[t];
    }
    REQUIRE(runs_with.size() == 220);
    const double expected = runs * 100. / 220., deviation = std::sqrt(runs * (100. / 220.) * (120. / 220.));
    for(const auto& triple_and_runs : runs_with)
      REQUIRE(std::abs(triple_and_runs.second - expected) < 6 * deviation);
  }
  SECTION("fewer triples than draws: each triple once, then the run ends")
  {
    sampler.prepare(10, 1000); // C(10,3) = 120
    sampler.start_run();
    std::set<Triple> seen;
    Triple batch[50];
    std::size_t got = 0;
    while((got = sampler.draw(rng, 50, batch)) > 0) // batches of 50, 50, then 20
      for(std::size_t i = 0; i < got; ++i)
        REQUIRE(seen.insert(batch[i]).second);
    CHECK(seen.size() == 120);
    sampler.start_run();
    CHECK(sampler.draw(rng, 1, batch) == 1); // a new run starts over
  }
}

namespace {
// A dense and a sparse cluster of points in the unit ball: a point-uniform
// draw favors the dense one, a space-uniform draw does not.
std::vector<Eigen::Vector3d> dense_and_sparse()
{
  std::vector<Eigen::Vector3d> points;
  Random rng(5, 5);
  for(int i = 0; i < 900; ++i) // dense: around (-0.5, 0, 0)
    points.emplace_back(-0.5 + 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real());
  for(int i = 0; i < 100; ++i) // sparse: around (0.3, 0, 0)
    points.emplace_back(0.3 + 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real());
  return points;
}
} // namespace

TEST_CASE("RRHT_Cubes and RRHT_Unif draw points uniformly in space, not among points", "[sampling]")
{
  const std::vector<Eigen::Vector3d> points = dense_and_sparse();
  Random rng(9, 9);
  auto sparse_share = [&](auto& sampler) {
    int sparse = 0;
    for(int i = 0; i < 20000; ++i)
      sparse += (sampler.draw_point(rng) >= 900);
    return sparse / 20000.;
  };
  const Cube_weights weights(4);
  Cubes_sampler cubes(weights);
  cubes.prepare(points, 1.0);
  Unif_sampler unif(4);
  unif.prepare(points, 1.0, rng);
  // Both clusters fill one cube of side 0.5 (resp. similar small-ball
  // volumes), so each gets about half of the draws, against 10% for points.
  CHECK(sparse_share(cubes) == Approx(0.5).margin(0.05));
  CHECK(sparse_share(unif) == Approx(0.5).margin(0.1));

  Triple t = {{ 0, 0, 0 }};
  for(int i = 0; i < 1000; ++i)
  {
    draw_distinct_triple(cubes, 1000, rng, t);
    REQUIRE((t[0] != t[1] && t[1] != t[2] && t[0] != t[2]));
  }
}

TEST_CASE("RRHT_Cubes draws each point with the weight of its cube over the points of the cube", "[sampling]")
{
  // 40 points spread over a few cubes of the unit ball, unevenly: point p of
  // cube C has probability w(C) / (W |C|), W the weight of the cubes that
  // hold points. Each frequency over 10^6 draws is within 6 sigma of it.
  std::vector<Eigen::Vector3d> points;
  Random rng(11, 12);
  for(int i = 0; i < 40; ++i)
  {
    const double spread = (i < 25) ? 0.2 : 0.9; // a dense cluster and sparse points
    Eigen::Vector3d p;
    do
      p = Eigen::Vector3d(rng.uniform_real(), rng.uniform_real(), rng.uniform_real()) * 2 * spread -
          Eigen::Vector3d::Constant(spread);
    while(p.norm() > 1);
    points.push_back(p);
  }
  const unsigned int c = 4;
  const Cube_weights weights(c);
  Cubes_sampler cubes(weights);
  cubes.prepare(points, 1.0);

  auto cube_of = [&](const Eigen::Vector3d& p) {
    std::size_t index = 0;
    for(int d = 0; d < 3; ++d)
      index = index * c + std::size_t((std::min)(c - 1., std::floor((p[d] + 1) / (2. / c))));
    return index;
  };
  std::map<std::size_t, int> points_of_cube;
  for(const Eigen::Vector3d& p : points)
    ++points_of_cube[cube_of(p)];
  double total = 0;
  for(const auto& cube : points_of_cube)
    total += weights.weight(cube.first);
  REQUIRE(points_of_cube.size() > 5);

  const int draws = 1000000;
  std::vector<int> count(points.size(), 0);
  for(int i = 0; i < draws; ++i)
    ++count[cubes.draw_point(rng)];
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const std::size_t cube = cube_of(points[i]);
    const double probability = weights.weight(cube) / (total * points_of_cube[cube]);
    const double sigma = std::sqrt(draws * probability * (1 - probability));
    INFO("point " << i << " of cube " << cube << ": " << count[i] << " draws, expected " << draws * probability);
    REQUIRE(std::abs(count[i] - draws * probability) <= 6 * sigma);
  }
}

namespace {
// Whether sampler.draw() (prepared for `n` points) gives the triples of
// draw_distinct_triple(): with `orders`, the frequency of each of the 6
// orders of 3 points; else each point's frequency at each place of the
// triple. Over 3 10^5 triples of each, in batches of 1 to 150, each
// frequency within 6 sigma of the other's.
template <typename Sampler>
void require_batches_as_draw_distinct_triple(Sampler& sampler, std::uint32_t n, Random& rng)
{
  const bool orders = (n == 3);
  auto category = [&](const Triple& t, int place) {
    REQUIRE((t[0] != t[1] && t[0] != t[2] && t[1] != t[2]));
    REQUIRE(t[place] < n);
    return orders ? std::size_t(t[0] * 3 + t[1]) : std::size_t(place) * n + t[place];
  };
  const int triples = 300000;
  const std::size_t categories = 3 * std::size_t(n);
  std::vector<int> batches(categories, 0), one_by_one(categories, 0);
  std::vector<Triple> batch(150);
  for(int drawn = 0, count = 1; drawn < triples; drawn += count, count = count % 150 + 1)
  {
    count = (std::min)(count, triples - drawn);
    REQUIRE(sampler.draw(rng, std::size_t(count), batch.data()) == std::size_t(count));
    for(int i = 0; i < count; ++i)
      for(int place = 0; place < (orders ? 1 : 3); ++place)
        ++batches[category(batch[i], place)];
  }
  for(int i = 0; i < triples; ++i)
  {
    Triple t;
    draw_distinct_triple(sampler, n, rng, t);
    for(int place = 0; place < (orders ? 1 : 3); ++place)
      ++one_by_one[category(t, place)];
  }
  std::size_t seen = 0;
  for(std::size_t k = 0; k < categories; ++k)
  {
    const double p = (batches[k] + one_by_one[k]) / (2. * triples);
    const double sigma = std::sqrt(2. * triples * p * (1 - p));
    INFO((orders ? "order " : "place and point ") << k << ": " << batches[k] << " in batches, " << one_by_one[k]
                                                     << " by draw_distinct_triple()");
    REQUIRE(std::abs(batches[k] - one_by_one[k]) <= 6 * sigma + 1);
    seen += (batches[k] > 0);
  }
  CHECK(seen >= (orders ? 6 : categories * 4 / 5));
}

// 40 points of the unit ball, 25 of them in a dense cluster.
std::vector<Eigen::Vector3d> spread_neighborhood(Random& rng)
{
  std::vector<Eigen::Vector3d> points;
  for(int i = 0; i < 40; ++i)
  {
    Eigen::Vector3d p;
    do
      p = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1) *
          (i < 25 ? 0.3 : 1.);
    while(p.norm() > 1);
    points.push_back(p);
  }
  return points;
}

// 3 points: one near the center, two close to each other at the boundary.
const std::vector<Eigen::Vector3d> concentrated_neighborhood = {
  Eigen::Vector3d(0.1, 0.1, 0.1), Eigen::Vector3d(0.53, 0.53, 0.53), Eigen::Vector3d(0.55, 0.52, 0.54)
};
} // namespace

TEST_CASE("RRHT_Cubes and RRHT_Unif draw their batches of triples as draw_distinct_triple() does", "[sampling]")
{
  // The batches of Weighted_points_sampler::draw(), which both use, take
  // the three draws of a triple from a chunk computed in advance, and go on
  // with draw_point() only when they are not distinct. The triples must
  // have the distribution of draw_distinct_triple(): in a spread
  // neighborhood (few repeats), and in a neighborhood of 3 points where one
  // has almost all the probability (many repeats, and after 64 of them a
  // uniform draw).
  Random rng(19, 20);
  const std::vector<Eigen::Vector3d> spread = spread_neighborhood(rng);
  // RRHT_Cubes: for the 3 points, the cube around the center, of weight
  // 1/64 (the whole cube), and a cube at the boundary of the ball, of
  // weight about 3 10^-5.
  const Cube_weights weights(4);
  for(const std::vector<Eigen::Vector3d>* points : { &spread, &concentrated_neighborhood })
  {
    Cubes_sampler sampler(weights);
    sampler.prepare(*points, 1.);
    require_batches_as_draw_distinct_triple(sampler, std::uint32_t(points->size()), rng);
  }
  // RRHT_Unif, with the probabilities of its lattice: c = 2 and 3 for the
  // 40 points, c = 1 for the 3.
  for(unsigned int c : { 1u, 2u, 3u })
  {
    const std::vector<Eigen::Vector3d>& points = (c == 1) ? concentrated_neighborhood : spread;
    Unif_sampler sampler(c);
    sampler.prepare(points, 1., rng);
    require_batches_as_draw_distinct_triple(sampler, std::uint32_t(points.size()), rng);
  }
}

TEST_CASE("RRHT_Unif draws each point about as often as the paper's procedure does", "[sampling]")
{
  // The paper's procedure, literally (Section 5): a center uniform in the
  // ball B_P (by rejection from its cube), redrawn while the small ball of
  // radius r/c around it holds no point, then a point of the small ball
  // uniformly. Against it, the sampler, whose probabilities come from the
  // midpoint rule over a randomly shifted lattice (`Unif_sampler`): 60
  // points, c = 2 to 5. Over 10^6 draws of each, the total variation
  // distance between their frequencies is below 0.03 (the frequencies
  // alone are about 0.005 apart), and the points drawn uniformly would be
  // more than 0.2 away.
  std::vector<Eigen::Vector3d> points;
  Random rng(17, 18);
  for(int i = 0; i < 60; ++i)
  {
    const double spread = (i < 40) ? 0.25 : 1.; // a dense cluster off center, and sparse points
    Eigen::Vector3d p;
    do
      p = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1) * spread +
          Eigen::Vector3d(i < 40 ? 0.4 : 0., 0., 0.);
    while(p.norm() > 1);
    points.push_back(p);
  }
  const int draws = 1000000;
  for(unsigned int c : { 2u, 3u, 4u, 5u })
  {
    const double small_radius = 1. / c;
    std::vector<int> paper(points.size(), 0), sampler_count(points.size(), 0);
    std::vector<std::uint32_t> in_small_ball;
    for(int d = 0; d < draws; ++d)
    {
      in_small_ball.clear();
      while(in_small_ball.empty())
      {
        Eigen::Vector3d center;
        do
          center = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1);
        while(center.squaredNorm() > 1);
        for(std::uint32_t i = 0; i < points.size(); ++i)
          if((points[i] - center).norm() <= small_radius)
            in_small_ball.push_back(i);
      }
      ++paper[in_small_ball[rng.uniform_index(std::uint32_t(in_small_ball.size()))]];
    }
    Unif_sampler sampler(c);
    sampler.prepare(points, 1., rng);
    for(int d = 0; d < draws; ++d)
      ++sampler_count[sampler.draw_point(rng)];
    double distance = 0, uniform_distance = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      distance += std::abs(sampler_count[i] - paper[i]) / (2. * draws);
      uniform_distance += std::abs(double(paper[i]) / draws - 1. / double(points.size())) / 2;
    }
    INFO("c = " << c << ": total variation distance " << distance << ", " << uniform_distance << " for uniform draws");
    CHECK(distance < 0.03);
    CHECK(uniform_distance > 0.2);
  }
}

TEST_CASE("Cube weights are the volume of the cubes inside the ball", "[sampling]")
{
  for(unsigned int c : { 1u, 2u, 4u, 7u })
  {
    const Cube_weights weights(c);
    double volume = 0;
    for(std::size_t i = 0; i < std::size_t(c) * c * c; ++i)
      volume += weights.weight(i) * (8. / (c * c * c));
    INFO("c = " << c);
    CHECK(volume == Approx(4. / 3. * 3.14159265358979323846).epsilon(0.01));
  }
  const Cube_weights four(4);
  CHECK(four.weight((1 * 4 + 1) * 4 + 1) == Approx(1)); // an inner cube
  CHECK(four.weight(0) > 0);                              // a corner cube meets the ball
  CHECK(four.weight(0) < 0.1);
}

TEST_CASE("Aggregation: mean, best and cluster", "[aggregation]")
{
  const Eigen::Vector3d z(0, 0, 1), x(1, 0, 0);
  const Eigen::Vector3d z10 = Eigen::Vector3d(std::sin(0.17), 0, std::cos(0.17)); // ~10 degrees from z
  const std::vector<Candidate_normal> candidates = { { x, 50 }, { z, 30 }, { -z10, 30 }, { Eigen::Vector3d::Zero(), 0 } };
  const double cos45 = std::cos(3.14159265358979323846 / 4);

  CHECK(aggregate(candidates, Aggregation::BEST, cos45) == x);
  // The z cluster (60 votes) beats x (50); its mean lies between z and z10.
  const Eigen::Vector3d c = aggregate(candidates, Aggregation::CLUSTER, cos45);
  CHECK(std::abs(c.dot((z + z10).normalized())) == Approx(1).epsilon(1e-12));
  // The mean mixes everything, weighted by votes, signs aligned.
  const Eigen::Vector3d m = aggregate(candidates, Aggregation::MEAN, cos45);
  CHECK(m.norm() == Approx(1));
  CHECK(std::abs(m.dot(x)) > 0.5);
  CHECK(std::abs(m.dot(z)) > 0.5);
  // No run voted: the zero vector.
  CHECK(aggregate({ { Eigen::Vector3d::Zero(), 0 } }, Aggregation::CLUSTER, cos45) == Eigen::Vector3d::Zero());
}
