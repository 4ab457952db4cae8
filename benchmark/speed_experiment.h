// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The speed experiment: the performance targets and the time against k.

#ifndef RRHT_BENCHMARK_SPEED_EXPERIMENT_H
#define RRHT_BENCHMARK_SPEED_EXPERIMENT_H

#include "experiment.h"

#include <thread>

namespace {

// -- Speed: the targets, on the noisy 100k-point cube and 1M-point sphere,
// and the defaults' time against k.
void speed(const Config& config)
{
  Experiment x(config, "speed");
  Targets t(config);
  const Estimator fast = rrht(Rrht_setting::fast(), rrht_k), precise = rrht(Rrht_setting::precise(), rrht_k);
  const Estimator jet80 = jet(paper_k), queries = neighbor_queries(rrht_k);

  // The 100k-point cube with 0.2% noise and the 1M-point sphere with 0.2%
  // noise, measured in rounds.
  const Dataset c = synthetic("cube", cube, 100000, 0.2, 30);
  const std::size_t n = 1000000;
  const Dataset s = synthetic("sphere", sphere, n, 0.2, 31);
  const std::vector<Measurement> m = x.run_in_rounds({ { &c, jet80, 2 },
                                                       { &c, queries, 2 },
                                                       { &c, fast, 1 },
                                                       { &c, fast, 2 },
                                                       { &c, precise, 1 },
                                                       { &c, precise, 2 },
                                                       { &c, rrht(Rrht_setting::fast(Sampling::CUBES), rrht_k), 2 },
                                                       { &c, rrht(Rrht_setting::fast(Sampling::UNIF), rrht_k), 2 },
                                                       { &c, rrht_adaptive(rrht_k), 2 },
                                                       { &s, jet80, 2 },
                                                       { &s, fast, 2 },
                                                       { &s, queries, 2 } });
  // Time against k: the defaults on the cube with 2 threads, k from 6 to 200,
  // in rounds of their own.
  const std::vector<unsigned int> ks = { 6, 8, 10, 12, 14, 16, 17, 18, 20, 22, 25, 30, 40, 50, 60, 70, 80, 100, 120, 150, 200 };
  std::vector<Experiment::Planned> against_k;
  for(unsigned int k : ks)
    against_k.push_back({ &c, rrht_defaults(Neighborhood{ k, 0 }), 2 });
  const std::vector<Measurement> by_k = x.run_in_rounds(against_k);
  const Measurement &jet_2 = m[0], &queries_2 = m[1], &fast_1 = m[2], &fast_2 = m[3], &precise_1 = m[4],
                    &precise_2 = m[5], &cubes_2 = m[6], &unif_2 = m[7], &adaptive_2 = m[8], &jet_s = m[9],
                    &fast_s = m[10], &queries_s = m[11];
  t.add("cube 100k, 2 threads: fast / jet_K80", fast_2, jet_2, 0.5);
  t.add("cube 100k, 2 threads: precise (defaults) / jet_K80", precise_2, jet_2, 1.5);
  t.add("cube 100k, 2 threads: fast / its bare K=100 queries", fast_2, queries_2, 2.5);
  t.add("cube 100k: fast, 1 thread / 2 threads (speed-up)", fast_1, fast_2, 1.85, true);
  t.add("cube 100k: precise, 1 thread / 2 threads (speed-up)", precise_1, precise_2, 1.85, true);
  t.add("cube 100k, 2 threads, fast setting: Cubes / Points", cubes_2, fast_2, 1.3);
  t.add("cube 100k, 2 threads, fast setting: Unif / Points", unif_2, fast_2, 3);
  t.add("cube 100k, 2 threads: adaptive / jet_K80", adaptive_2, jet_2, 0.6);
  // The output is 3 doubles per point.
  const double output_mib = n * 3 * sizeof(double) / (1024. * 1024.);
  t.add("sphere 1M, 2 threads: fast / jet_K80", fast_s, jet_s, 0.4);
  t.add("sphere 1M, 2 threads: fast / its bare K=100 queries", fast_s, queries_s, 2.5);
  t.add("sphere 1M, 2 threads: fast peak memory / (jet_K80 peak + output)", fast_s.peak_mib,
        jet_s.peak_mib + output_mib, 1);
  // The slowest k against k = 100, round by round.
  const std::size_t at_100 = std::size_t(std::find(ks.begin(), ks.end(), 100u) - ks.begin());
  std::size_t slowest = at_100;
  double slowest_ratio = ratio_by_rounds(by_k[at_100], by_k[at_100]);
  for(std::size_t i = 0; i < ks.size(); ++i)
  {
    const double ratio = ratio_by_rounds(by_k[i], by_k[at_100]);
    if(ratio > slowest_ratio)
    {
      slowest = i;
      slowest_ratio = ratio;
    }
  }
  t.add("cube 100k, 2 threads, defaults: slowest k of 6-200 (k = " + std::to_string(ks[slowest]) + ") / k = 100",
        by_k[slowest], by_k[at_100], 1);
  t.print_and_write();
}

// -- Threads: the default, jet fitting (K = 80) and the bare K = 100 queries
// on the noisy 100k-point cube and 1M-point sphere, from 1 thread to all
// the machine's cores (1, 2, 4, ... and the number of cores), in rounds.
// The report gives each one's speed-up over its own time with 1 thread; the
// target is the default's with 2 threads, at least 1.85
// (threads_targets.csv).
void threads(const Config& config)
{
  Experiment x(config, "threads");
  Targets t(config, "threads_targets.csv");
  std::vector<unsigned int> counts;
  const unsigned int cores = (std::max)(1u, std::thread::hardware_concurrency());
  for(unsigned int c = 1; c < cores; c *= 2)
    counts.push_back(c);
  counts.push_back(cores);
  const Dataset c = synthetic("cube", cube, 100000, 0.2, 30), s = synthetic("sphere", sphere, 1000000, 0.2, 31);
  // The default first: its speed-up is the target.
  const std::vector<Estimator> estimators = { rrht_default(rrht_k), jet(paper_k), neighbor_queries(rrht_k) };
  for(const Dataset* d : { &c, &s })
    for(std::size_t e = 0; e < estimators.size(); ++e)
    {
      std::vector<Experiment::Planned> planned;
      for(unsigned int count : counts)
        planned.push_back({ d, estimators[e], count });
      const std::vector<Measurement> m = x.run_in_rounds(planned);
      if(e == 0 && counts.size() > 1 && counts[1] == 2)
        t.add(d->name + " " + std::to_string(d->inliers / 1000) + "k: " + estimators[e].name +
                ", speed-up from 1 to 2 threads",
              m[0], m[1], 1.85, true);
    }
  t.print_and_write();
}

} // namespace

#endif // RRHT_BENCHMARK_SPEED_EXPERIMENT_H
