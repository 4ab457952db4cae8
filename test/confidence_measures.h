// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How well a confidence per point predicts the error of its normal: the
// area under the ROC curve, and the points near sharp edges, for tests and
// benchmarks.

#ifndef CGAL_RRHT_TEST_CONFIDENCE_MEASURES_H
#define CGAL_RRHT_TEST_CONFIDENCE_MEASURES_H

#include "shapes.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <numeric>
#include <vector>

namespace rrht_test {

namespace internal {
// Index of a sample -> its point.
struct Index_point_map
{
  typedef std::size_t key_type;
  typedef Point value_type;
  typedef const Point& reference;
  typedef boost::readable_property_map_tag category;
  const Cloud* cloud;
  friend reference get(const Index_point_map& m, std::size_t i) { return (*m.cloud)[i].point; }
};
} // namespace internal

/// The area under the ROC curve of `score` as a predictor of `positive`:
/// the probability that a positive scores higher than a negative, ties
/// counting one half (the Mann-Whitney statistic). 0.5 when one class is
/// empty.
inline double roc_auc(const std::vector<double>& score, const std::vector<bool>& positive)
{
  std::vector<std::size_t> order(score.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return score[a] < score[b]; });
  double rank_sum = 0; // of the positives, ranks from 1, ties averaged
  std::size_t positives = 0;
  for(std::size_t i = 0; i < order.size();)
  {
    std::size_t j = i;
    while(j < order.size() && score[order[j]] == score[order[i]])
      ++j;
    const double rank = (double(i + 1) + double(j)) / 2;
    for(std::size_t t = i; t < j; ++t)
      if(positive[order[t]])
      {
        rank_sum += rank;
        ++positives;
      }
    i = j;
  }
  const double negatives = double(score.size() - positives);
  if(positives == 0 || negatives == 0)
    return 0.5;
  return (rank_sum - double(positives) * double(positives + 1) / 2) / (double(positives) * negatives);
}

/// The area under the ROC curve of 1 - confidence for "error above `tau`
/// degrees", over the samples that have a truth.
inline double confidence_auc(const Cloud& cloud, double tau = 10)
{
  std::vector<double> score;
  std::vector<bool> wrong;
  for(const Sample& s : cloud)
    if(s.truth != CGAL::NULL_VECTOR)
    {
      score.push_back(1 - s.confidence);
      wrong.push_back(angle_error(s) > tau);
    }
  return roc_auc(score, wrong);
}

/// For each sample of a clean cloud (before noise), whether a sample within
/// `distance` has an exact normal more than `angle` degrees away from its
/// own: the samples near a sharp edge, on any shape whose smooth parts turn
/// by less than `angle` over `distance`.
inline std::vector<bool> near_sharp_edges(const Cloud& clean, double distance, double angle = 30)
{
  typedef CGAL::Search_traits_adapter<std::size_t, internal::Index_point_map, CGAL::Search_traits_3<Kernel> > Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  const internal::Index_point_map map{ &clean };
  Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(clean.size()),
            Tree::Splitter(), Traits(map));
  tree.build();
  const double cos_angle = std::cos(angle * pi / 180);
  std::vector<bool> near(clean.size(), false);
  std::vector<std::size_t> ball;
  for(std::size_t i = 0; i < clean.size(); ++i)
  {
    if(clean[i].truth == CGAL::NULL_VECTOR)
      continue;
    const Vector n = clean[i].truth / std::sqrt(clean[i].truth.squared_length());
    ball.clear();
    tree.search(std::back_inserter(ball), CGAL::Fuzzy_sphere<Traits>(clean[i].point, distance, 0., Traits(map)));
    for(std::size_t j : ball)
    {
      const Vector& m = clean[j].truth;
      if(m != CGAL::NULL_VECTOR && std::abs(n * m) < cos_angle * std::sqrt(m.squared_length()))
        near[i] = true;
    }
  }
  return near;
}

/// The median confidence of the samples for which `keep[i]` is `wanted`.
inline double median_confidence(const Cloud& cloud, const std::vector<bool>& keep, bool wanted)
{
  std::vector<double> c;
  for(std::size_t i = 0; i < cloud.size(); ++i)
    if(keep[i] == wanted)
      c.push_back(cloud[i].confidence);
  if(c.empty())
    return 0;
  std::nth_element(c.begin(), c.begin() + c.size() / 2, c.end());
  return c[c.size() / 2];
}

} // namespace rrht_test

#endif // CGAL_RRHT_TEST_CONFIDENCE_MEASURES_H
