// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Consistent signs on a graph whose edges say, with a signed weight, whether
// their two ends agree: a greedy agglomeration of consistently oriented
// clusters, after the greedy collapse of Jakob et al. (2019) and the signed
// union-find of Schertler et al. (2017).

#ifndef CGAL_RRHT_INTERNAL_SIGNED_AGGLOMERATION_H
#define CGAL_RRHT_INTERNAL_SIGNED_AGGLOMERATION_H

#include <CGAL/RRHT/internal/orientation_edges.h>

#include <CGAL/for_each.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The clusters of a graph of `size` vertices and the sign of each vertex
/// in its cluster, from the signed `edges`.
///
/// Every vertex starts as a cluster of its own. Two adjacent clusters are
/// joined, one of them flipped if the sum of the signed weights of the edges
/// between them is negative, in the order of the largest absolute sum first:
/// a cluster is joined by all the evidence between it and its neighbors,
/// not by its single strongest edge as in a spanning tree, so that a few
/// wrong edges (noise at a sharp edge, an outlier) are outvoted. Clusters
/// with no evidence between them (no edge, or weights summing to 0) stay
/// apart, and so do two clusters of at least `large` points each whose sum
/// is under a hundredth of the smaller one's points: two surfaces that a few
/// neighbors reach across (the walls of a cavity and the outside, close
/// objects), which the signs out of the solid (`outward_signs()`) orient
/// better one by one than a few edges together. Each vertex stands for
/// `points[v]` points (1 each if `points` is empty). Where the graph is part
/// of a larger one, `outside[v]` is the sum of the absolute weights of the
/// edges from `v` to vertices out of it (none if `outside` is empty): two
/// clusters whose sum is under the evidence either has outside stay apart,
/// since that evidence could outvote their join. Ties are broken by the
/// vertices' numbers: the result depends only on the edges and their order.
class Signed_agglomeration
{
public:
  Signed_agglomeration(std::size_t size, const std::vector<Signed_edge>& edges,
                       const std::vector<std::size_t>& points = std::vector<std::size_t>(),
                       std::size_t large = std::size_t(-1), std::vector<double> outside = std::vector<double>())
  {
    // The number of points of each cluster.
    std::vector<std::size_t> weight(points);
    if(weight.empty())
      weight.assign(size, 1);
    if(outside.empty())
      outside.assign(size, 0.);
    // A forest of the joins: each cluster's parent and its sign relative to
    // the parent.
    std::vector<std::uint32_t> parent(size);
    std::vector<signed char> sign_to_parent(size, 1);
    for(std::size_t v = 0; v < size; ++v)
      parent[v] = std::uint32_t(v);
    std::vector<Adjacency> adjacency(size);
    for(const Signed_edge& e : edges)
    {
      adjacency[e.a][e.b] += e.weight;
      adjacency[e.b][e.a] += e.weight;
    }
    std::vector<Candidate> initial;
    for(std::size_t a = 0; a < size; ++a)
      for(const auto& neighbor : adjacency[a])
        if(a < neighbor.first && neighbor.second != 0)
          initial.push_back({ neighbor.second, std::uint32_t(a), neighbor.first });
    std::priority_queue<Candidate> candidates(std::less<Candidate>(), std::move(initial));
    while(!candidates.empty())
    {
      const Candidate best = candidates.top();
      candidates.pop();
      // Skip what a join made stale: a cluster joined to another, or a sum
      // that has changed since (its new value was pushed then).
      if(parent[best.a] != best.a || parent[best.b] != best.b)
        continue;
      const auto between = adjacency[best.a].find(best.b);
      if(between == adjacency[best.a].end() || between->second != best.sum)
        continue;
      // Two large clusters on too little evidence for their size stay apart
      // (it may grow with later joins, and be pushed again then).
      if(weight[best.a] >= large && weight[best.b] >= large &&
         std::abs(best.sum) < min_share * double((std::min)(weight[best.a], weight[best.b])))
        continue;
      if(std::abs(best.sum) < (std::min)(outside[best.a], outside[best.b]))
        continue;
      // The cluster with fewer neighbors joins the other.
      std::uint32_t kept = best.a, joined = best.b;
      if(adjacency[joined].size() > adjacency[kept].size())
        std::swap(kept, joined);
      const double flip = best.sum < 0 ? -1. : 1.;
      parent[joined] = kept;
      weight[kept] += weight[joined];
      outside[kept] += outside[joined];
      sign_to_parent[joined] = static_cast<signed char>(flip);
      adjacency[kept].erase(joined);
      for(const auto& neighbor : adjacency[joined])
      {
        if(neighbor.first == kept)
          continue;
        double& sum = adjacency[kept][neighbor.first];
        sum += flip * neighbor.second;
        Adjacency& other = adjacency[neighbor.first];
        other.erase(joined);
        other[kept] = sum;
        if(sum != 0)
          candidates.push({ sum, (std::min)(kept, neighbor.first), (std::max)(kept, neighbor.first) });
      }
      Adjacency().swap(adjacency[joined]);
    }
    // Signs relative to the roots, each root the representative of its
    // cluster.
    for(std::size_t v = 0; v < size; ++v)
    {
      std::uint32_t root = std::uint32_t(v);
      int sign = 1;
      while(parent[root] != root)
      {
        sign *= sign_to_parent[root];
        root = parent[root];
      }
      m_root_of.push_back(root);
      m_sign_in_cluster.push_back(static_cast<signed char>(sign));
    }
  }

  /// The representative of the cluster of vertex `v`.
  std::uint32_t cluster(std::size_t v) const { return m_root_of[v]; }

  /// The sign, +1 or -1, of vertex `v` in its cluster.
  int sign(std::size_t v) const { return m_sign_in_cluster[v]; }

private:
  typedef std::unordered_map<std::uint32_t, double> Adjacency; // neighbor cluster: sum of signed weights

  static constexpr double min_share = 0.01;

  struct Candidate
  {
    double sum;
    std::uint32_t a, b;
    // The strongest first, then the smallest vertex numbers.
    bool operator<(const Candidate& other) const
    {
      const double strength = std::abs(sum), other_strength = std::abs(other.sum);
      if(strength != other_strength)
        return strength < other_strength;
      return a != other.a ? a > other.a : b > other.b;
    }
  };

  std::vector<std::uint32_t> m_root_of;
  std::vector<signed char> m_sign_in_cluster;
};

/// Each vertex's cluster and sign in it, as `Signed_agglomeration` gives
/// them.
struct Signed_clusters
{
  std::vector<std::uint32_t> cluster;
  std::vector<signed char> sign;
};

/// `Signed_agglomeration` of a graph of `size` vertices, the edges between
/// vertices of the same block of `block` consecutive numbers first, each
/// block on its own (in parallel, and in a heap that stays in the cache),
/// then the clusters of all the blocks, joined by the sums of all the edges
/// between them. Where the vertices are numbered along a space-filling
/// curve, a block is a compact part of the surface: within it, the joins
/// are those of the agglomeration of the whole graph, unless evidence from
/// outside the block would have come first. The result does not depend on
/// the number of threads. Clusters of 100 points and a thousandth of the
/// graph are large.
template <typename ConcurrencyTag>
Signed_clusters signed_clusters(std::size_t size, const std::vector<Signed_edge>& edges, std::size_t block)
{
  const std::size_t large = (std::max<std::size_t>)(100, size / 1000);
  const std::size_t blocks = (size + block - 1) / block;
  std::vector<std::vector<Signed_edge> > within(blocks);
  std::vector<double> outside(size, 0.);
  for(const Signed_edge& e : edges)
    if(e.a / block == e.b / block)
    {
      const std::uint32_t first = std::uint32_t(e.a / block * block);
      within[e.a / block].push_back({ e.a - first, e.b - first, e.weight });
    }
    else
    {
      outside[e.a] += std::abs(e.weight);
      outside[e.b] += std::abs(e.weight);
    }
  Signed_clusters result;
  result.cluster.resize(size);
  result.sign.resize(size);
  std::vector<std::size_t> block_numbers(blocks);
  std::iota(block_numbers.begin(), block_numbers.end(), std::size_t(0));
  CGAL::for_each<ConcurrencyTag>(block_numbers, [&](std::size_t b) {
    const std::size_t first = b * block, count = (std::min)(size, first + block) - first;
    const Signed_agglomeration local(count, within[b], std::vector<std::size_t>(), large,
                                     std::vector<double>(outside.begin() + std::ptrdiff_t(first),
                                                         outside.begin() + std::ptrdiff_t(first + count)));
    for(std::size_t v = 0; v < count; ++v)
    {
      result.cluster[first + v] = std::uint32_t(first + local.cluster(v));
      result.sign[first + v] = static_cast<signed char>(local.sign(v));
    }
    return true;
  });
  // The clusters of the blocks, numbered from 0, and all the edges between
  // them, those within a block that it left apart included.
  std::vector<std::uint32_t> number(size, std::uint32_t(-1));
  std::uint32_t count = 0;
  for(std::size_t v = 0; v < size; ++v)
    if(number[result.cluster[v]] == std::uint32_t(-1))
      number[result.cluster[v]] = count++;
  std::vector<Signed_edge> across;
  for(const Signed_edge& e : edges)
  {
    const std::uint32_t a = number[result.cluster[e.a]], b = number[result.cluster[e.b]];
    if(a != b)
      across.push_back({ (std::min)(a, b), (std::max)(a, b), e.weight * result.sign[e.a] * result.sign[e.b] });
  }
  std::vector<std::size_t> points(count, 0);
  for(std::size_t v = 0; v < size; ++v)
    ++points[number[result.cluster[v]]];
  const Signed_agglomeration global(count, across, points, large);
  for(std::size_t v = 0; v < size; ++v)
  {
    const std::uint32_t c = number[result.cluster[v]];
    result.sign[v] = static_cast<signed char>(result.sign[v] * global.sign(c));
    result.cluster[v] = global.cluster(c);
  }
  return result;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_SIGNED_AGGLOMERATION_H
