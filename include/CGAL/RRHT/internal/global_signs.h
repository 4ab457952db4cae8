// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A global check of the signs of a consistent orientation: whole patches
// turned over where the winding number of the whole cloud says so.

#ifndef CGAL_RRHT_INTERNAL_GLOBAL_SIGNS_H
#define CGAL_RRHT_INTERNAL_GLOBAL_SIGNS_H

#include <CGAL/RRHT/internal/Patch_winding_numbers.h>
#include <CGAL/RRHT/internal/orientation_edges.h>
#include <CGAL/RRHT/internal/sign_patches.h>

#include <CGAL/for_each.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// How far a winding number is from those of a solid, 0 outside and 1
/// inside, beyond `tolerance`: the discrete sum over the points strays
/// from 0 or 1 by up to a tenth near the surface (the points' areas are
/// estimates), and a small patch turned over to cancel that is no evidence.
constexpr double winding_tolerance = 0.1;

inline double off_solid(double w)
{
  return (std::max)(0., (std::min)(std::abs(w), std::abs(w - 1)) - winding_tolerance);
}

/// The pieces of surface that `global_signs()` may turn over, its units:
/// the patches of at least `least` points (`size[p]` for patch `p`), and
/// the sets of smaller patches that the signs join (`small_sets`, lists of
/// patches: a small bore, cut into pieces of a few points each) where they
/// hold at least `least` points together; the `most` largest (largest
/// first, then in that order), each numbered from 0 in `unit`, the other
/// patches getting `units.size()`.
struct Flip_units
{
  std::vector<std::vector<std::uint32_t> > patches; // the patches of each unit
  std::vector<std::uint32_t> unit;                  // the unit of each patch
};

inline Flip_units flip_units(const Sign_patches& patches, const std::vector<std::size_t>& size,
                             const std::vector<std::vector<std::uint32_t> >& small_sets, std::size_t least,
                             std::size_t most)
{
  std::vector<std::vector<std::uint32_t> > candidates;
  std::vector<std::size_t> points;
  for(std::size_t p = 0; p < patches.count; ++p)
    if(size[p] >= least)
    {
      candidates.push_back({ std::uint32_t(p) });
      points.push_back(size[p]);
    }
  for(const std::vector<std::uint32_t>& set : small_sets)
  {
    std::size_t total = 0;
    for(std::uint32_t p : set)
      total += size[p];
    if(total >= least)
    {
      candidates.push_back(set);
      points.push_back(total);
    }
  }
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return points[x] > points[y]; });
  if(order.size() > most)
    order.resize(most);
  Flip_units units;
  for(std::size_t c : order)
    units.patches.push_back(std::move(candidates[c]));
  units.unit.assign(patches.count, std::uint32_t(units.patches.size()));
  for(std::size_t u = 0; u < units.patches.size(); ++u)
    for(std::uint32_t p : units.patches[u])
      units.unit[p] = std::uint32_t(u);
  return units;
}

/// An edge between two units, or between a unit and a point of none (`b`
/// the number of units), with its signed weight under the signs the units
/// were made from.
struct Unit_edge
{
  std::uint32_t a, b;
  double weight;
};

/// A turn gains what it brings the winding number nearer those of a solid,
/// and must gain at least this share of what it moves.
constexpr double least_winding_gain = 0.25;

/// A turn must move at least as much as a whole share at four queries.
constexpr double least_moved = 4 * 2.;

/// A thin wall turned over (`turn_thin_walls()`) that moves less than a
/// whole share at two queries may lose as much as one that moves that much:
/// so short a wall, at the inner end of a slot, moves the winding number by
/// no more than the sums' errors.
constexpr double least_judged_move = 2 * 2.;

/// The winding number of `field` at its queries, summed over its groups, as
/// units (groups) are turned over; what turning some of them would gain,
/// and what it would move, at the queries that judge them (`judging()`):
/// the grid's, where the turn moves enough there (`least_moved`), and all
/// of them, medial ones too, only where it does not. A face that the grid sees is
/// judged on a field that is only what the grid tells, and the medial
/// queries, inside a part thinner than the grid's clearance as well as in a
/// narrow space, judge only what the grid cannot see: a small bore.
class Winding_sums
{
public:
  Winding_sums(Patch_winding_numbers& field, std::size_t units)
    : m_field(field), m_total(field.size(), 0.), m_grid(field.grid_size())
  {
    for(std::size_t g = 0; g <= units; ++g)
      for(std::size_t q = 0; q < m_total.size(); ++q)
        m_total[q] += field.shares(g)[q];
  }

  /// The number of queries, from the first, that judge a turn of the units
  /// `members`: the grid's where it moves enough there, else all. It does
  /// not change as units are turned.
  std::size_t judging(const std::vector<std::uint32_t>& members) const
  {
    return moved(members, m_grid) >= least_moved ? m_grid : m_total.size();
  }

  /// How much nearer those of a solid (`off_solid()`, summed over the first
  /// `judged` queries) turning the units `members` over would bring the
  /// winding number: credited only where it moves it by more than the
  /// tolerance (elsewhere, a turn would only make up for the errors of the
  /// sum, the points' areas being estimates, by a little at many queries),
  /// debited wherever it moves it away.
  double gain(const std::vector<std::uint32_t>& members, std::size_t judged) const
  {
    double g = 0;
    for(std::size_t q = 0; q < judged; ++q)
    {
      const double s = share(members, q);
      const double change = off_solid(m_total[q]) - off_solid(m_total[q] - 2 * s);
      g += 2 * std::abs(s) > winding_tolerance ? change : (std::min)(0., change);
    }
    return g;
  }

  /// What turning the units `members` over moves: twice their share beyond
  /// the tolerance, summed over the first `judged` queries.
  double moved(const std::vector<std::uint32_t>& members, std::size_t judged) const
  {
    double m = 0;
    for(std::size_t q = 0; q < judged; ++q)
      m += (std::max)(0., 2 * std::abs(share(members, q)) - winding_tolerance);
    return m;
  }

  /// Turns the unit `u` over.
  void turn(std::uint32_t u)
  {
    float* s = m_field.shares(u);
    for(std::size_t q = 0; q < m_total.size(); ++q)
    {
      m_total[q] -= 2 * double(s[q]);
      s[q] = -s[q];
    }
  }

private:
  double share(const std::vector<std::uint32_t>& members, std::size_t q) const
  {
    double sum = 0;
    for(std::uint32_t u : members)
      sum += m_field.shares(u)[q];
    return sum;
  }

  Patch_winding_numbers& m_field;
  std::vector<double> m_total;
  std::size_t m_grid;
};

/// The units of `field` (its groups) to turn over, greedily, each move
/// one of `moves` (a list of units turned together: each unit alone, the
/// pieces of one smooth face), while a move gains at least
/// `least_winding_gain` of what it moves, and moves at least `least_moved`:
/// the gain is how much nearer those of a solid the move brings the
/// winding number (`off_solid()`, summed over the queries that judge it),
/// and what it moves, twice the move's share beyond the tolerance, summed. A
/// face turned inward leaves the winding number off those of a solid over
/// the region it sees, and turning it back makes it whole; turning over a
/// patch of an open surface, whose winding number is fractional anyway,
/// gains little of what it moves. A curved face turned inward must turn
/// back whole: turning back half of a bore leaves the winding number in it
/// near 1, as whole as 0. Of the moves that gain enough, the one taken gains
/// most, each gain weighed by how many of the move's edges to other units
/// across sharp edges and thin parts (`edges`) it makes agree: turning both
/// sides of a thin wall changes the winding number away from it by almost
/// nothing, so that, where one side is turned inward, the winding number
/// alone cannot tell which side to turn back, and the faces beside each side
/// can. Ends when no move gains enough: each move lowers the sum. The sums
/// are taken over the queries in order, the moves' gains apart (in
/// parallel), the best move the first of equal ones.
template <typename ConcurrencyTag>
std::vector<char> units_to_turn(Patch_winding_numbers& field, std::size_t units,
                                const std::vector<std::vector<std::uint32_t> >& moves,
                                const std::vector<Unit_edge>& edges)
{
  const double agreement_weight = 0.25;
  Winding_sums sums(field, units);
  std::vector<char> turned(units + 1, 0);
  std::vector<std::vector<char> > member(moves.size(), std::vector<char>(units + 1, 0));
  for(std::size_t m = 0; m < moves.size(); ++m)
    for(std::uint32_t u : moves[m])
      member[m][u] = 1;
  std::vector<double> moved(moves.size(), 0.), gain(moves.size(), 0.), agreement(moves.size(), 0.);
  std::vector<std::size_t> judged(moves.size(), 0);
  std::vector<std::size_t> numbers(moves.size());
  std::iota(numbers.begin(), numbers.end(), std::size_t(0));
  // How far the edges of each move agree with the signs as they are, from
  // -1 (all against) to 1.
  auto find_agreements = [&] {
    CGAL::for_each<ConcurrencyTag>(numbers, [&](std::size_t m) {
      double evidence = 0, agree = 0;
      for(const Unit_edge& e : edges)
        if(member[m][e.a] != member[m][e.b])
        {
          evidence += std::abs(e.weight);
          agree += (turned[e.a] != turned[e.b]) ? -e.weight : e.weight;
        }
      agreement[m] = evidence > 0 ? agree / evidence : 0.;
      return true;
    });
  };
  CGAL::for_each<ConcurrencyTag>(numbers, [&](std::size_t m) {
    judged[m] = sums.judging(moves[m]);
    moved[m] = sums.moved(moves[m], judged[m]);
    return true;
  });
  find_agreements();
  for(std::size_t turns = 0; turns < 2 * moves.size(); ++turns)
  {
    CGAL::for_each<ConcurrencyTag>(numbers, [&](std::size_t m) {
      gain[m] = sums.gain(moves[m], judged[m]);
      return true;
    });
    std::size_t best = moves.size();
    double best_score = 0;
    for(std::size_t m = 0; m < moves.size(); ++m)
    {
      const double score = gain[m] * (1 - agreement_weight * agreement[m]);
      if(gain[m] > 0 && gain[m] >= least_winding_gain * moved[m] && moved[m] >= least_moved &&
         (best == moves.size() || score > best_score))
      {
        best = m;
        best_score = score;
      }
    }
    if(best == moves.size())
      break;
    for(std::uint32_t u : moves[best])
    {
      sums.turn(u);
      turned[u] = char(!turned[u]);
    }
    find_agreements();
  }
  turned.pop_back();
  return turned;
}

/// How the units (`unit_of_point`, `units` for a point of none) are
/// joined: for each pair of units, the weight of the edges between them
/// that join one face (`joins_one_face()`), and of those that say they are
/// the two sides of a thin part or of a narrow gap (`joins_two_sides()`);
/// and, for a unit with itself, of the edges within it that say so: a patch
/// never holds both sides, but a set of small patches that the signs join
/// can (both sides of a thin wall near a corner, turned together).
struct Unit_link
{
  double one_face = 0, two_sides = 0;
};

/// Units joined by at least this weight of edges are joined.
constexpr double least_link_weight = 3;

inline std::map<std::pair<std::uint32_t, std::uint32_t>, Unit_link>
unit_links(std::size_t units, const std::vector<std::uint32_t>& unit_of_point,
           const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
           const std::vector<Signed_edge>& edges, const std::vector<int>& signs)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, Unit_link> links;
  for(const Signed_edge& e : edges)
  {
    const std::uint32_t a = unit_of_point[e.a], b = unit_of_point[e.b];
    if(a >= units || b >= units)
      continue;
    Unit_link& link = links[{ (std::min)(a, b), (std::max)(a, b) }];
    if(a == b)
    {
      if(joins_two_sides(e, normals))
        link.two_sides += std::abs(e.weight);
      continue;
    }
    if(joins_one_face(e, points, normals, signs))
      link.one_face += std::abs(e.weight);
    else if(joins_two_sides(e, normals))
      link.two_sides += std::abs(e.weight);
  }
  return links;
}

/// The sets of two or more of `count` elements that the pairs `joined`
/// join, each in increasing order, the sets in the order of their first
/// element.
inline std::vector<std::vector<std::uint32_t> >
joined_sets(std::size_t count, const std::vector<std::pair<std::uint32_t, std::uint32_t> >& joined)
{
  std::vector<std::uint32_t> parent(count);
  std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  auto find = [&](std::uint32_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const auto& pair : joined)
  {
    const std::uint32_t a = find(pair.first), b = find(pair.second);
    if(a != b)
      parent[(std::max)(a, b)] = (std::min)(a, b);
  }
  std::vector<std::vector<std::uint32_t> > members(count), sets;
  for(std::uint32_t u = 0; u < count; ++u)
    members[find(u)].push_back(u);
  for(std::vector<std::uint32_t>& set : members)
    if(set.size() > 1)
      sets.push_back(std::move(set));
  return sets;
}

/// Whether each of `count` elements is in one of `sets`.
inline std::vector<char> in_some_set(std::size_t count, const std::vector<std::vector<std::uint32_t> >& sets)
{
  std::vector<char> in(count, 0);
  for(const std::vector<std::uint32_t>& set : sets)
    for(std::uint32_t e : set)
      in[e] = 1;
  return in;
}

/// The moves of `units_to_turn()`: each unit that no smooth face joins to
/// another alone, then the pieces of each smooth face together, units joined
/// (`unit_links()`) by more weight of edges that join one face than twice
/// the weight of those that say they are the two sides of a thin part, and
/// at least `least_link_weight`. A piece of a smooth face never turns
/// alone: the winding number of a curved open sheet is fractional
/// everywhere, and turning some of its pieces can bring it nearer 0 or 1
/// while it breaks the face in two.
inline std::vector<std::vector<std::uint32_t> >
unit_moves(std::size_t units, const std::map<std::pair<std::uint32_t, std::uint32_t>, Unit_link>& links)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t> > joined;
  for(const auto& pair : links)
    if(pair.second.one_face >= least_link_weight && pair.second.one_face > 2 * pair.second.two_sides)
      joined.push_back(pair.first);
  std::vector<std::vector<std::uint32_t> > faces = joined_sets(units, joined), moves;
  const std::vector<char> in_face = in_some_set(units, faces);
  for(std::uint32_t u = 0; u < units; ++u)
    if(!in_face[u])
      moves.push_back({ u });
  for(std::vector<std::uint32_t>& face : faces)
    moves.push_back(std::move(face));
  return moves;
}

/// The pairs of units that are the two sides of a thin part or of a narrow
/// gap: joined (`unit_links()`) by at least `least_link_weight` of edges
/// that say so, and more than twice what joins them as one face; a unit
/// paired with itself holds both sides.
inline std::vector<std::pair<std::uint32_t, std::uint32_t> >
two_sided_pairs(const std::map<std::pair<std::uint32_t, std::uint32_t>, Unit_link>& links)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t> > pairs;
  for(const auto& pair : links)
    if(pair.second.two_sides >= least_link_weight && pair.second.two_sides > 2 * pair.second.one_face)
      pairs.push_back(pair.first);
  return pairs;
}

/// A chord between point `i` of one unit of a pair and point `j` of the
/// other, across a thin part or a narrow gap, with its edge's weight, and
/// the shares of the units in the winding number at its middle
/// (`Patch_winding_numbers::shares_at()`).
struct Wall_chord
{
  std::uint32_t i, j;
  double weight;
  std::vector<double> shares;
};

/// The chords of each pair of units of `pairs`: up to `most` of the `edges`
/// between them (within the unit, for a unit paired with itself) that say
/// they are the two sides of a thin part (`joins_two_sides()`), evenly
/// spread over those in their order, with the winding number's shares at
/// their middles.
template <typename ConcurrencyTag>
std::vector<std::vector<Wall_chord> >
wall_chords(const Patch_winding_numbers& field, const std::vector<std::pair<std::uint32_t, std::uint32_t> >& pairs,
            const std::vector<std::uint32_t>& unit_of_point, const std::vector<Eigen::Vector3d>& points,
            const std::vector<Eigen::Vector3d>& normals, const std::vector<Signed_edge>& edges)
{
  const std::size_t most = 64;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> number;
  for(std::size_t p = 0; p < pairs.size(); ++p)
    number[pairs[p]] = p;
  std::vector<std::vector<Wall_chord> > all(pairs.size()), chords(pairs.size());
  for(const Signed_edge& e : edges)
  {
    const std::uint32_t a = unit_of_point[e.a], b = unit_of_point[e.b];
    const auto found = number.find({ (std::min)(a, b), (std::max)(a, b) });
    if(found != number.end() && joins_two_sides(e, normals))
      all[found->second].push_back({ e.a, e.b, std::abs(e.weight), std::vector<double>() });
  }
  std::vector<std::size_t> numbers(pairs.size());
  std::iota(numbers.begin(), numbers.end(), std::size_t(0));
  CGAL::for_each<ConcurrencyTag>(numbers, [&](std::size_t p) {
    const std::size_t count = (std::min)(most, all[p].size());
    for(std::size_t t = 0; t < count; ++t)
    {
      Wall_chord c = all[p][t * all[p].size() / count];
      c.shares = field.shares_at(0.5 * (points[c.i] + points[c.j]));
      chords[p].push_back(std::move(c));
    }
    return true;
  });
  return chords;
}

/// How surely `x` says 0 or 1 rather than the other: nothing within a
/// quarter of 1/2, in full at 0 or 1 and beyond.
inline double how_sure(double x) { return (std::min)(1., (std::max)(0., 2 * std::abs(2 * x - 1) - 1)); }

/// The walls that the pairs of units `pairs` make where their chords are
/// against the signs (`agreement` at most `-least_disagreement`): the units
/// of such pairs that share a unit, together, each wall in increasing order,
/// the walls in order. A wall turned inward, in several units, is turned
/// back whole or not at all: turning back one pair of it leaves the chords
/// between its units and the rest of the wall no longer opposite, so that
/// nothing would turn the rest back, and the seam moves the far field.
inline std::vector<std::vector<std::uint32_t> >
walls_against(std::size_t units, const std::vector<std::pair<std::uint32_t, std::uint32_t> >& pairs,
              const std::vector<double>& agreement, double least_disagreement)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t> > against;
  for(std::size_t p = 0; p < pairs.size(); ++p)
    if(agreement[p] <= -least_disagreement)
      against.push_back(pairs[p]);
  std::vector<std::vector<std::uint32_t> > walls = joined_sets(units, against);
  std::vector<char> in_wall = in_some_set(units, walls);
  for(const auto& pair : against) // a unit paired with itself alone
    if(!in_wall[pair.first])
    {
      walls.push_back({ pair.first });
      in_wall[pair.first] = 1;
    }
  std::sort(walls.begin(), walls.end());
  return walls;
}

/// What the chords of one pair of units say (`turn_thin_walls()`): the
/// vote, from `-evidence` (all against the signs) to `evidence`, and the
/// evidence, their weights times how sure each is; both 0 where the chords
/// whose share tells anything weigh less than `least_sure` of all, or the
/// evidence less than `least_link_weight`, what makes two units a pair.
struct Pair_vote
{
  double vote = 0, evidence = 0;
};

/// The vote of the `chords` of the pair of units `a` and `b` under the
/// signs `oriented` and the units turned so far (`turned`).
inline Pair_vote pair_vote(const std::vector<Wall_chord>& chords, std::uint32_t a, std::uint32_t b,
                           const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& oriented,
                           const std::vector<std::uint32_t>& unit_of_point, const std::vector<char>& turned,
                           double least_sure)
{
  const std::size_t units = turned.size();
  auto sign = [&](std::uint32_t u) { return u < units && turned[u] ? -1. : 1.; };
  double sure = 0, votes = 0, weight = 0, telling = 0;
  for(const Wall_chord& c : chords)
  {
    weight += c.weight;
    const Eigen::Vector3d d = points[c.j] - points[c.i];
    const double oi = sign(unit_of_point[c.i]) * oriented[c.i].dot(d),
                 oj = sign(unit_of_point[c.j]) * oriented[c.j].dot(d);
    if(!(oi * oj < 0)) // the two normals not opposite along the chord
      continue;
    double rest = 0;
    for(std::uint32_t g = 0; g <= units; ++g)
      if(g != a && g != b)
        rest += sign(g) * c.shares[g];
    const double sureness = how_sure(rest);
    const bool away = oi < 0;
    sure += c.weight * sureness;
    telling += sureness > 0 ? c.weight : 0.;
    votes += (away == (rest < 0.5) ? 1 : -1) * c.weight * sureness;
  }
  Pair_vote v;
  if(sure >= least_link_weight && telling >= least_sure * weight)
  {
    v.vote = votes;
    v.evidence = sure;
  }
  return v;
}

/// Turns over, greedily, the walls of units of `field` that are the two
/// sides of a thin part or of a narrow gap (`pairs`), where the winding
/// number between the two sides says so, updating `turned`. Turned
/// together, the two sides of a wall swap which way they face, and the
/// winding number away from the wall barely changes: the normals of both
/// sides pointing into the wall, or both out of it, look alike from afar.
/// Between the two sides, the share of the rest of the cloud tells: near 0,
/// the sides are those of a thin part, whose normals point away from each
/// other; near 1, those of a gap between two parts, whose normals point
/// towards each other. The chords of each pair (`wall_chords()`) vote,
/// weighed by their edges and by how sure that share is (`how_sure()`). The
/// points' areas, taken from their nearest neighbors, shrink wherever the
/// neighbors hold both sides, and the shares with them: between the fins of
/// a finned part, the rest's share falls near 1/2, and only a few chords
/// near the gap's mouth seem sure. So a pair's vote counts only where the
/// chords whose share tells anything (`how_sure()` above 0) weigh at least
/// `least_sure` of its chords' weight (`pair_vote()`); across a wall about
/// a point spacing thick, the shrunken areas leave the share of every chord
/// well above 0, each chord a little sure. The pairs at least
/// `least_disagreement` against the signs (from -1 to 1) make walls
/// (`walls_against()`), each turned whole, most against first (the votes of
/// all the pairs within it), while the winding number away from the
/// surface loses at most `least_winding_gain` of what the wall moves, or of
/// `least_judged_move` where it moves less (`units_to_turn()`): a wall that
/// is none moves it. `oriented` are the normals under the signs the units
/// were made from.
template <typename ConcurrencyTag>
void turn_thin_walls(Patch_winding_numbers& field, const std::vector<std::pair<std::uint32_t, std::uint32_t> >& pairs,
                     const std::vector<std::vector<Wall_chord> >& chords, const std::vector<Eigen::Vector3d>& points,
                     const std::vector<Eigen::Vector3d>& oriented, const std::vector<std::uint32_t>& unit_of_point,
                     std::vector<char>& turned)
{
  const double least_disagreement = 0.5, least_sure = 0.5;
  const std::size_t units = turned.size();
  Winding_sums sums(field, units);
  std::vector<Pair_vote> votes(pairs.size());
  std::vector<double> agreement(pairs.size(), 0.);
  std::vector<std::size_t> numbers(pairs.size());
  std::iota(numbers.begin(), numbers.end(), std::size_t(0));
  for(std::size_t turns = 0; turns < pairs.size(); ++turns)
  {
    CGAL::for_each<ConcurrencyTag>(numbers, [&](std::size_t p) {
      votes[p] = pair_vote(chords[p], pairs[p].first, pairs[p].second, points, oriented, unit_of_point, turned,
                           least_sure);
      agreement[p] = votes[p].evidence > 0 ? votes[p].vote / votes[p].evidence : 0.;
      return true;
    });
    const std::vector<std::vector<std::uint32_t> > walls =
      walls_against(units, pairs, agreement, least_disagreement);
    std::vector<std::uint32_t> wall_of(units, std::uint32_t(walls.size()));
    for(std::size_t w = 0; w < walls.size(); ++w)
      for(std::uint32_t u : walls[w])
        wall_of[u] = std::uint32_t(w);
    std::vector<double> wall_vote(walls.size(), 0.), wall_evidence(walls.size(), 0.);
    for(std::size_t p = 0; p < pairs.size(); ++p)
    {
      const std::uint32_t w = wall_of[pairs[p].first];
      if(w < walls.size() && w == wall_of[pairs[p].second])
      {
        wall_vote[w] += votes[p].vote;
        wall_evidence[w] += votes[p].evidence;
      }
    }
    std::vector<char> allowed(walls.size(), 0);
    std::vector<std::size_t> wall_numbers(walls.size());
    std::iota(wall_numbers.begin(), wall_numbers.end(), std::size_t(0));
    CGAL::for_each<ConcurrencyTag>(wall_numbers, [&](std::size_t w) {
      const std::size_t judged = sums.judging(walls[w]);
      allowed[w] = wall_vote[w] <= -least_disagreement * wall_evidence[w] &&
                   sums.gain(walls[w], judged) >=
                     -least_winding_gain * (std::max)(sums.moved(walls[w], judged), least_judged_move);
      return true;
    });
    std::size_t best = walls.size();
    for(std::size_t w = 0; w < walls.size(); ++w)
      if(allowed[w] && (best == walls.size() ||
                        wall_vote[w] / wall_evidence[w] < wall_vote[best] / wall_evidence[best]))
        best = w;
    if(best == walls.size())
      break;
    for(std::uint32_t u : walls[best])
    {
      sums.turn(u);
      turned[u] = char(!turned[u]);
    }
  }
}

/// Each patch that is not a unit of `units` and touches a patch that
/// `patch_turned` says was turned, and then each one next to one that
/// this turns, turned where the sum of the signed weights of the `edges`
/// between it and the other patches, under `signs`, is negative: a piece of
/// surface too small for the winding number (a strip along an edge, a few
/// noisy points) goes with the patches around it. Each turn raises the sum
/// over all the edges, so it ends; the patches are visited in order, round
/// by round.
inline void follow_turned_patches(const Sign_patches& patches, const Flip_units& units,
                                  const std::vector<char>& patch_turned, const std::vector<Signed_edge>& edges,
                                  std::vector<int>& signs)
{
  const std::uint32_t no_unit = std::uint32_t(units.patches.size());
  // The edges between patches, by patch (compressed rows).
  std::vector<std::size_t> first(patches.count + 1, 0);
  for(const Signed_edge& e : edges)
    if(patches.patch[e.a] != patches.patch[e.b])
    {
      ++first[patches.patch[e.a] + 1];
      ++first[patches.patch[e.b] + 1];
    }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::uint32_t> across(first.back());
  std::vector<std::size_t> filled(first.begin(), first.end() - 1);
  for(std::size_t i = 0; i < edges.size(); ++i)
  {
    const std::uint32_t pa = patches.patch[edges[i].a], pb = patches.patch[edges[i].b];
    if(pa != pb)
    {
      across[filled[pa]++] = std::uint32_t(i);
      across[filled[pb]++] = std::uint32_t(i);
    }
  }
  std::vector<std::vector<std::uint32_t> > members(patches.count);
  for(std::size_t v = 0; v < patches.patch.size(); ++v)
    members[patches.patch[v]].push_back(std::uint32_t(v));
  auto other_patch = [&](const Signed_edge& e, std::uint32_t p) {
    return patches.patch[e.a] == p ? patches.patch[e.b] : patches.patch[e.a];
  };
  std::vector<char> pending(patches.count, 0);
  auto mark_neighbors = [&](std::uint32_t p) {
    for(std::size_t t = first[p]; t < first[p + 1]; ++t)
    {
      const std::uint32_t o = other_patch(edges[across[t]], p);
      if(units.unit[o] == no_unit)
        pending[o] = 1;
    }
  };
  for(std::uint32_t p = 0; p < patches.count; ++p)
    if(patch_turned[p])
      mark_neighbors(p);
  for(bool any = true; any;)
  {
    any = false;
    for(std::uint32_t p = 0; p < patches.count; ++p)
    {
      if(!pending[p])
        continue;
      pending[p] = 0;
      double sum = 0;
      for(std::size_t t = first[p]; t < first[p + 1]; ++t)
      {
        const Signed_edge& e = edges[across[t]];
        sum += e.weight * signs[e.a] * signs[e.b];
      }
      if(sum < 0)
      {
        for(std::uint32_t v : members[p])
          signs[v] = -signs[v];
        mark_neighbors(p);
        any = true;
      }
    }
  }
}

/// The patches of fewer than `least` points (`size[p]` for patch `p`) that
/// the `signs` join, each set a list of patches: joined by at least `least_link_weight` of the
/// weight of the `edges` between them that the signs keep (each at least
/// `least_joining_weight`), and more than twice the weight of those they
/// break. Unlike the pieces of one face (`joins_one_face()`), at whatever
/// angle: a bore a few neighborhoods across has the normals of a few
/// facets, each a few small patches.
inline std::vector<std::vector<std::uint32_t> >
small_patch_sets(const Sign_patches& patches, const std::vector<std::size_t>& size, std::size_t least,
                 const std::vector<Signed_edge>& edges, const std::vector<int>& signs)
{
  struct Kept
  {
    double kept = 0, broken = 0;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, Kept> links;
  for(const Signed_edge& e : edges)
  {
    const std::uint32_t a = patches.patch[e.a], b = patches.patch[e.b];
    if(a == b || size[a] >= least || size[b] >= least)
      continue;
    Kept& link = links[{ (std::min)(a, b), (std::max)(a, b) }];
    const double kept = e.weight * signs[e.a] * signs[e.b];
    if(kept >= least_joining_weight)
      link.kept += kept;
    else if(kept < 0)
      link.broken -= kept;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t> > joined;
  for(const auto& pair : links)
    if(pair.second.kept >= least_link_weight && pair.second.kept > 2 * pair.second.broken)
      joined.push_back(pair.first);
  return joined_sets(patches.count, joined);
}

/// Up to `per_unit` points of each of the `units` (`unit_of_point`, `units`
/// for a point of none), evenly spread over its points in their order:
/// where the winding number's medial queries are sought.
inline std::vector<std::uint32_t> medial_seeds(const std::vector<std::uint32_t>& unit_of_point, std::size_t units)
{
  const std::size_t per_unit = 48;
  std::vector<std::vector<std::uint32_t> > members(units);
  for(std::size_t v = 0; v < unit_of_point.size(); ++v)
    if(unit_of_point[v] < units)
      members[unit_of_point[v]].push_back(std::uint32_t(v));
  std::vector<std::uint32_t> seeds;
  for(const std::vector<std::uint32_t>& m : members)
  {
    const std::size_t count = (std::min)(per_unit, m.size());
    for(std::size_t t = 0; t < count; ++t)
      seeds.push_back(m[t * m.size() / count]);
  }
  return seeds;
}

/// The signs `signs` of the unit `normals` at `points` (each standing for
/// `areas[v]` of the surface), checked as a whole: the cloud falls into
/// patches that the signs orient as one (`sign_patches()`), of which the
/// largest, and the largest sets of smaller ones that the signs join
/// (`small_patch_sets()`), are turned over where the winding number of the
/// whole cloud, away from the surface and in the narrow spaces the surface
/// bounds, says so (`units_to_turn()`), and the two sides of
/// a thin wall together where it says so between them (`turn_thin_walls()`);
/// then each smaller patch next to a turned one follows the sum of the
/// `edges` that join it to the rest, as the agglomeration would have joined
/// it. Where nothing is turned, the signs are returned as they are.
template <typename ConcurrencyTag>
std::vector<int> global_signs(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                              const std::vector<double>& areas, const std::vector<Signed_edge>& edges,
                              std::vector<int> signs)
{
  // Patches of fewer points than this barely move the winding number a few
  // cells away; the local signs stand there.
  const std::size_t least_points = (std::max<std::size_t>)(50, points.size() / 1000), most_units = 128;
  const std::size_t size = points.size();
  const Sign_patches patches = sign_patches(points, edges, normals, signs);
  std::vector<std::size_t> patch_size(patches.count, 0);
  for(std::uint32_t p : patches.patch)
    ++patch_size[p];
  const Flip_units units =
    flip_units(patches, patch_size, small_patch_sets(patches, patch_size, least_points, edges, signs), least_points,
               most_units);
  const std::size_t unit_count = units.patches.size();
  if(unit_count == 0)
    return signs;
  std::vector<Eigen::Vector3d> oriented(size);
  std::vector<std::uint32_t> unit_of_point(size);
  for(std::size_t v = 0; v < size; ++v)
  {
    oriented[v] = double(signs[v]) * normals[v];
    unit_of_point[v] = units.unit[patches.patch[v]];
  }
  Patch_winding_numbers field(points, oriented, areas, unit_of_point, unit_count, ConcurrencyTag(),
                              medial_seeds(unit_of_point, unit_count));
  if(field.size() == 0)
    return signs;
  // The edges between units (or from a unit to a point of none) across a
  // sharp edge or a thin part: not those within one face.
  std::vector<Unit_edge> unit_edges;
  for(const Signed_edge& e : edges)
  {
    const std::uint32_t a = unit_of_point[e.a], b = unit_of_point[e.b];
    const double c = normals[e.a].dot(normals[e.b]);
    const bool within_face = std::abs(c) > cos_parallel && e.weight * c > 0;
    if(a != b && !within_face && e.weight != 0)
      unit_edges.push_back({ (std::min)(a, b), (std::max)(a, b), e.weight * signs[e.a] * signs[e.b] });
  }
  const auto links = unit_links(unit_count, unit_of_point, points, normals, edges, signs);
  const std::vector<std::vector<std::uint32_t> > moves = unit_moves(unit_count, links);
  std::vector<char> turned = units_to_turn<ConcurrencyTag>(field, unit_count, moves, unit_edges);
  const auto pairs = two_sided_pairs(links);
  const auto chords = wall_chords<ConcurrencyTag>(field, pairs, unit_of_point, points, normals, edges);
  turn_thin_walls<ConcurrencyTag>(field, pairs, chords, points, oriented, unit_of_point, turned);
  if(std::find(turned.begin(), turned.end(), char(1)) == turned.end())
    return signs;
  std::vector<char> patch_turned(patches.count, 0);
  for(std::size_t u = 0; u < unit_count; ++u)
    for(std::uint32_t p : units.patches[u])
      patch_turned[p] = turned[u];
  for(std::size_t v = 0; v < size; ++v)
    if(patch_turned[patches.patch[v]])
      signs[v] = -signs[v];
  follow_turned_patches(patches, units, patch_turned, edges, signs);
  return signs;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_GLOBAL_SIGNS_H
