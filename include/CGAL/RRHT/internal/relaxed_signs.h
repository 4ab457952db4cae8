// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The signs of a consistent orientation after every edge of each cluster has
// voted at once: the least-squares relaxation of the greedy signs.

#ifndef CGAL_RRHT_INTERNAL_RELAXED_SIGNS_H
#define CGAL_RRHT_INTERNAL_RELAXED_SIGNS_H

#include <CGAL/RRHT/internal/orientation_edges.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The signs `signs` of the `size` vertices of the graph of the signed
/// `edges`, relaxed within each cluster of `cluster`: the signs of the
/// values x that minimise
///
///   sum over the edges (a, b, w) of |w| (x_a - sign(w) x_b)^2
///     + anchor * sum over the vertices v of D_v (x_v - signs[v])^2,
///
/// D_v the sum of the absolute weights of v's edges. The agglomeration
/// decides one join at a time, so that a join made early on little
/// evidence (the two sides of a thin edge that neighbors reach across)
/// carries its sign into all that joins later; here every edge votes at
/// once, and a wrongly joined part of a cluster is flipped back where the
/// edges around it say so. The small `anchor` keeps the greedy signs where
/// the edges do not decide. Clusters that the agglomeration left apart (the
/// walls of a cavity and the outside) are relaxed apart, their edges
/// between them left out. Solved by conjugate gradients (the matrix is
/// symmetric and strictly diagonally dominant), the same operations in the
/// same order whatever the number of threads.
inline std::vector<int> relaxed_signs(std::size_t size, const std::vector<Signed_edge>& edges,
                                      const std::vector<std::uint32_t>& cluster, std::vector<int> signs)
{
  const double anchor = 1e-3, tolerance = 1e-3;
  const int max_iterations = 1000;
  std::vector<double> degree(size, 0.);
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(2 * edges.size() + size);
  for(const Signed_edge& e : edges)
    if(e.weight != 0 && cluster[e.a] == cluster[e.b])
    {
      degree[e.a] += std::abs(e.weight);
      degree[e.b] += std::abs(e.weight);
      entries.emplace_back(Eigen::Index(e.a), Eigen::Index(e.b), -e.weight);
      entries.emplace_back(Eigen::Index(e.b), Eigen::Index(e.a), -e.weight);
    }
  const Eigen::Index n = Eigen::Index(size);
  Eigen::VectorXd target(n), guess(n);
  for(std::size_t v = 0; v < size; ++v)
  {
    // A vertex with no edge keeps its sign: its row reads x_v = signs[v].
    const double d = degree[v] > 0 ? degree[v] : 1.;
    entries.emplace_back(Eigen::Index(v), Eigen::Index(v), degree[v] > 0 ? (1 + anchor) * d : anchor * d);
    target[Eigen::Index(v)] = anchor * d * signs[v];
    guess[Eigen::Index(v)] = signs[v];
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
  solver.setTolerance(tolerance);
  solver.setMaxIterations(max_iterations);
  solver.compute(matrix);
  const Eigen::VectorXd relaxed = solver.solveWithGuess(target, guess);
  // Short of convergence, the iterate can be far from the minimum: the
  // greedy signs stand.
  if(solver.info() != Eigen::Success)
    return signs;
  for(std::size_t v = 0; v < size; ++v)
    if(relaxed[Eigen::Index(v)] != 0)
      signs[v] = relaxed[Eigen::Index(v)] < 0 ? -1 : 1;
  return signs;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_RELAXED_SIGNS_H
