// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The signs of a consistent orientation after every edge of each cluster has
// voted at once: the least-squares relaxation of the greedy signs.

#ifndef CGAL_RRHT_INTERNAL_RELAXED_SIGNS_H
#define CGAL_RRHT_INTERNAL_RELAXED_SIGNS_H

#include <CGAL/RRHT/internal/orientation_edges.h>

#include <CGAL/for_each.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

template <typename ConcurrencyTag>
class Relaxation_matrix;

} // namespace internal
} // namespace RRHT
} // namespace CGAL

namespace Eigen {
namespace internal {

// Eigen's solvers take an operator without stored entries for a sparse
// matrix of its traits.
template <typename ConcurrencyTag>
struct traits<CGAL::RRHT::internal::Relaxation_matrix<ConcurrencyTag> >
  : traits<Eigen::SparseMatrix<double, Eigen::RowMajor> >
{};

} // namespace internal
} // namespace Eigen

namespace CGAL {
namespace RRHT {
namespace internal {

/// The symmetric matrix of the relaxation, for Eigen's conjugate gradients:
/// -w off the diagonal for each edge (a, b, w) that it holds, and a given
/// diagonal, in rows of increasing columns. Its product with a vector, where
/// the solver spends its time, is taken in parallel by blocks of rows, each
/// row summed in the order of its columns: the sums of Eigen's own product
/// of a row-major matrix, which takes one thread, whatever the number of
/// threads.
template <typename ConcurrencyTag>
class Relaxation_matrix : public Eigen::EigenBase<Relaxation_matrix<ConcurrencyTag> >
{
public:
  typedef double Scalar;
  typedef double RealScalar;
  typedef int StorageIndex;
  enum
  {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = true
  };

  /// The matrix of the edges `edges` (each pair of vertices once) where
  /// `holds(edge)`, with the diagonal `diagonal`.
  template <typename Holds>
  Relaxation_matrix(const std::vector<Signed_edge>& edges, Holds holds, std::vector<double> diagonal)
    : m_first(diagonal.size() + 1, 0), m_diagonal(std::move(diagonal)),
      m_blocks((m_diagonal.size() + block_rows - 1) / block_rows)
  {
    const std::size_t size = m_diagonal.size();
    std::iota(m_blocks.begin(), m_blocks.end(), std::size_t(0));
    for(const Signed_edge& e : edges)
      if(holds(e))
        ++m_first[e.a + 1], ++m_first[e.b + 1];
    for(std::size_t v = 0; v < size; ++v)
      m_first[v + 1] += m_first[v] + 1;
    m_entries.resize(m_first[size]);
    std::vector<std::size_t> next(m_first.begin(), m_first.end() - 1);
    for(const Signed_edge& e : edges)
      if(holds(e))
      {
        m_entries[next[e.a]++] = { e.b, -e.weight };
        m_entries[next[e.b]++] = { e.a, -e.weight };
      }
    CGAL::for_each<ConcurrencyTag>(m_blocks, [&](std::size_t b) {
      for(std::size_t v = b * block_rows; v < (std::min)(size, (b + 1) * block_rows); ++v)
      {
        m_entries[next[v]] = { std::uint32_t(v), m_diagonal[v] };
        // By column, in place and stable: the rows are short.
        for(std::size_t t = m_first[v] + 1; t < m_first[v + 1]; ++t)
          for(std::size_t u = t; u > m_first[v] && m_entries[u].column < m_entries[u - 1].column; --u)
            std::swap(m_entries[u], m_entries[u - 1]);
      }
      return true;
    });
  }

  Eigen::Index rows() const { return Eigen::Index(m_diagonal.size()); }
  Eigen::Index cols() const { return rows(); }

  template <typename Rhs>
  Eigen::Product<Relaxation_matrix, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const
  {
    return Eigen::Product<Relaxation_matrix, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

  /// `destination` += `alpha` times the product of the matrix and `x`.
  template <typename Destination, typename Rhs>
  void add_product(Destination& destination, const Rhs& x, double alpha) const
  {
    const std::size_t size = m_diagonal.size();
    CGAL::for_each<ConcurrencyTag>(m_blocks, [&](std::size_t b) {
      for(std::size_t v = b * block_rows; v < (std::min)(size, (b + 1) * block_rows); ++v)
      {
        double sum = 0;
        for(std::size_t t = m_first[v]; t < m_first[v + 1]; ++t)
          sum += m_entries[t].value * x.coeff(Eigen::Index(m_entries[t].column));
        destination.coeffRef(Eigen::Index(v)) += alpha * sum;
      }
      return true;
    });
  }

  const std::vector<double>& diagonal() const { return m_diagonal; }

private:
  struct Entry
  {
    std::uint32_t column;
    double value;
  };
  static constexpr std::size_t block_rows = 4096;
  std::vector<std::size_t> m_first; // each row's first entry
  std::vector<Entry> m_entries;
  std::vector<double> m_diagonal;
  std::vector<std::size_t> m_blocks; // the numbers of the blocks of rows, for CGAL::for_each
};

/// Eigen's diagonal preconditioner, read from the diagonal of a
/// `Relaxation_matrix`, which has no iterators over its entries.
class Relaxation_preconditioner : public Eigen::DiagonalPreconditioner<double>
{
public:
  template <typename Matrix>
  Relaxation_preconditioner& analyzePattern(const Matrix&)
  {
    return *this;
  }

  template <typename Matrix>
  Relaxation_preconditioner& factorize(const Matrix& matrix)
  {
    m_invdiag.resize(matrix.cols());
    for(Eigen::Index v = 0; v < matrix.cols(); ++v)
    {
      const double d = matrix.diagonal()[std::size_t(v)];
      m_invdiag(v) = d != 0 ? 1 / d : 1.;
    }
    m_isInitialized = true;
    return *this;
  }

  template <typename Matrix>
  Relaxation_preconditioner& compute(const Matrix& matrix)
  {
    return factorize(matrix);
  }
};

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
template <typename ConcurrencyTag>
std::vector<int> relaxed_signs(std::size_t size, const std::vector<Signed_edge>& edges,
                               const std::vector<std::uint32_t>& cluster, std::vector<int> signs)
{
  const double anchor = 1e-3, tolerance = 1e-3;
  const int max_iterations = 1000;
  std::vector<double> degree(size, 0.);
  auto joins = [&](const Signed_edge& e) { return e.weight != 0 && cluster[e.a] == cluster[e.b]; };
  for(const Signed_edge& e : edges)
    if(joins(e))
    {
      degree[e.a] += std::abs(e.weight);
      degree[e.b] += std::abs(e.weight);
    }
  const Eigen::Index n = Eigen::Index(size);
  Eigen::VectorXd target(n), guess(n);
  std::vector<double> diagonal(size);
  for(std::size_t v = 0; v < size; ++v)
  {
    // A vertex with no edge keeps its sign: its row reads x_v = signs[v].
    const double d = degree[v] > 0 ? degree[v] : 1.;
    diagonal[v] = degree[v] > 0 ? (1 + anchor) * d : anchor * d;
    target[Eigen::Index(v)] = anchor * d * signs[v];
    guess[Eigen::Index(v)] = signs[v];
  }
  const Relaxation_matrix<ConcurrencyTag> matrix(edges, joins, std::move(diagonal));
  Eigen::ConjugateGradient<Relaxation_matrix<ConcurrencyTag>, Eigen::Lower | Eigen::Upper, Relaxation_preconditioner>
    solver;
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

namespace Eigen {
namespace internal {

// The product of a relaxation's matrix and a vector, in the matrix.
template <typename ConcurrencyTag, typename Rhs>
struct generic_product_impl<CGAL::RRHT::internal::Relaxation_matrix<ConcurrencyTag>, Rhs, SparseShape, DenseShape,
                            GemvProduct>
  : generic_product_impl_base<CGAL::RRHT::internal::Relaxation_matrix<ConcurrencyTag>, Rhs,
                              generic_product_impl<CGAL::RRHT::internal::Relaxation_matrix<ConcurrencyTag>, Rhs> >
{
  template <typename Destination>
  static void scaleAndAddTo(Destination& destination, const CGAL::RRHT::internal::Relaxation_matrix<ConcurrencyTag>& matrix,
                            const Rhs& x, const double& alpha)
  {
    matrix.add_product(destination, x, alpha);
  }
};

} // namespace internal
} // namespace Eigen

#endif // CGAL_RRHT_INTERNAL_RELAXED_SIGNS_H
