// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The number of planes T_R that RRHT draws at most (paper, Section 3, eq. 7).

#ifndef CGAL_RRHT_HOEFFDING_NUMBER_OF_PLANES_H
#define CGAL_RRHT_HOEFFDING_NUMBER_OF_PLANES_H

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace CGAL {
namespace RRHT {

/// \ingroup PkgRRHTRef
/// Global upper bound T_R on the number of planes to draw (equation 7 of the
/// paper): the least T such that, with probability at least `alpha`, the
/// empirical vote share of every one of the `number_of_bins` bins is within
/// `delta` of its probability (Hoeffding's inequality and a union bound over
/// the bins):
/// \code{.unparsed}
///   T_R = ceil( ln(2 M / (1 - alpha)) / (2 delta^2) )
/// \endcode
/// With alpha = 0.95, delta = 0.08 and M = 171 it gives 690; the paper rounds
/// it to 700 (Section 6). It is the default of the named parameter
/// `number_of_planes` of `CGAL::rrht_estimate_normals()`, with the defaults of
/// `alpha` and `delta` and the number of bins of the accumulator.
///
/// \param number_of_bins M, the number of bins of the accumulator (at least 1)
/// \param alpha the confidence level, strictly between 0 and 1
/// \param delta the largest error on the vote share of a bin, strictly between 0 and 1
/// \return T_R, at least 1
/// \throws std::invalid_argument if `number_of_bins` is 0 or `alpha` or `delta`
///         is not strictly between 0 and 1
inline std::size_t hoeffding_number_of_planes(std::size_t number_of_bins, double alpha = 0.95, double delta = 0.08)
{
  if(number_of_bins == 0 || !(alpha > 0 && alpha < 1) || !(delta > 0 && delta < 1))
    throw std::invalid_argument("CGAL::RRHT::hoeffding_number_of_planes(): needs M > 0, 0 < alpha < 1 and 0 < delta < 1");
  return static_cast<std::size_t>(std::ceil(std::log(2. * number_of_bins / (1. - alpha)) / (2. * delta * delta)));
}

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_HOEFFDING_NUMBER_OF_PLANES_H
