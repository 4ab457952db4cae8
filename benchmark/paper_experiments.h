// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The experiments of the paper's Section 6 (Fig. 6 to 15), the headline,
// the real data of ../shared/data and the time against the number of points.

#ifndef RRHT_BENCHMARK_PAPER_EXPERIMENTS_H
#define RRHT_BENCHMARK_PAPER_EXPERIMENTS_H

#include "experiment.h"

namespace {

// -- The headline: the default, the paper's precise and fast settings, Cubes
// and Unif against every peer on the cube, the closed cylinder and the
// fandisk, 100k points with 0.2% noise, in both modes, 1 and 2 threads.
// The per-point errors of the default and jet_K80 feed the Fig. 8
// renderings.
void headline(const Config& config)
{
  Experiment x(config, "headline");
  const std::size_t n = 100000;
  std::vector<Dataset> sets = { synthetic("cube", cube, n, 0.2, 1), synthetic("cylinder", closed_cylinder, n, 0.2, 2) };
  Dataset fandisk;
  if(shared_mesh(config, "fandisk.off", "fandisk", n, 0.2, 3, fandisk))
    sets.push_back(fandisk);
  for(const Dataset& d : sets)
  {
    x.run(d, rrht_default(rrht_k), config.headline_threads, d.name + "_RRHT_default.txt");
    x.run(d, rrht(Rrht_setting::precise(), rrht_k), config.headline_threads);
    x.run(d, rrht(Rrht_setting::fast(), rrht_k), config.headline_threads);
    x.run(d, rrht(Rrht_setting::precise(Sampling::CUBES), rrht_k), config.headline_threads);
    if(config.full) // RRHT_Unif is 10x RRHT_Points: quick mode has it in fig13 only
      x.run(d, rrht(Rrht_setting::precise(Sampling::UNIF), rrht_k), config.headline_threads);
    for(const Estimator& e : peers())
      x.run(d, e, config.headline_threads, e.name == "jet_K80" ? d.name + "_jet_K80.txt" : std::string());
  }
}

// -- Fig. 6: time against the number of points, sphere with 0.2% noise,
// global upper bound only (no confidence interval).
void fig6(const Config& config)
{
  Experiment x(config, "fig6_time_vs_points");
  const std::vector<std::size_t> sizes = config.pick<std::vector<std::size_t> >(
    { 5000, 10000, 20000 }, { 50000, 100000, 200000, 500000, 1000000, 2000000 });
  // RRHT_Unif costs 10x RRHT_Points, VCM is single-threaded: smaller clouds only.
  const std::size_t unif_limit = config.pick<std::size_t>(5000, 100000);
  const std::size_t vcm_limit = config.pick<std::size_t>(5000, 1000000);
  for(std::size_t n : sizes)
  {
    const Dataset d = synthetic("sphere", sphere, n, 0.2, 6);
    x.run(d, rrht(Rrht_setting::precise(Sampling::POINTS).without_confidence_interval(), rrht_k));
    x.run(d, rrht(Rrht_setting::precise(Sampling::CUBES).without_confidence_interval(), rrht_k));
    if(n <= unif_limit)
      x.run(d, rrht(Rrht_setting::precise(Sampling::UNIF).without_confidence_interval(), rrht_k));
    x.run(d, jet(paper_k));
    x.run(d, pca(paper_k));
    if(n <= vcm_limit)
      x.run(d, vcm(paper_k));
  }
}

const std::vector<double>& noise_levels(const Config& config)
{
  static const std::vector<double> quick = { 0, 0.2, 1 }, full = { 0, 0.1, 0.2, 0.3, 0.5, 0.75, 1 };
  return config.full ? full : quick;
}

// -- Fig. 7: time with and without the confidence-interval stop (eq. 10)
// against noise, on three shapes; the report plots the ratio.
void fig7(const Config& config)
{
  Experiment x(config, "fig7_confidence_interval");
  const std::size_t n = config.pick<std::size_t>(5000, 50000);
  for(double noise : noise_levels(config))
  {
    const std::vector<Dataset> sets = { synthetic("sphere", sphere, n, noise, 7),
                                        synthetic("cube", cube, n, noise, 8),
                                        synthetic("cylinder", closed_cylinder, n, noise, 9) };
    for(const Dataset& d : sets)
      for(const Rrht_setting& s : { Rrht_setting::precise(), Rrht_setting::fast() })
      {
        x.run(d, rrht(s, rrht_k));
        x.run(d, rrht(s.without_confidence_interval(), rrht_k));
      }
  }
}

// -- Fig. 9: RMS and RMS_10 against noise, closed cylinder.
void fig9(const Config& config)
{
  Experiment x(config, "fig9_noise");
  const std::size_t n = config.pick<std::size_t>(5000, 50000);
  const std::vector<Aggregation> all = { Aggregation::MEAN, Aggregation::BEST, Aggregation::CLUSTER };
  for(double noise : noise_levels(config))
  {
    const Dataset d = synthetic("cylinder", closed_cylinder, n, noise, 10);
    for(Sampling s : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
      for(Aggregation a : all)
        if(s != Sampling::UNIF || config.full) // quick mode: RRHT_Unif in fig13 only
          x.run(d, rrht(Rrht_setting::precise(s, a), rrht_k));
    for(const Estimator& e : peers())
      x.run(d, e);
  }
}

// -- Fig. 10: precision against time over T_R (n_rot = 5) and over n_rot
// (T_R = 700), noisy cube; the paper's two settings are on these curves.
void fig10(const Config& config)
{
  Experiment x(config, "fig10_precision_vs_time");
  const std::size_t n = config.pick<std::size_t>(10000, 50000);
  const Dataset d = synthetic("cube", cube, n, 0.2, 11);
  std::set<std::pair<int, int> > settings; // (T_R, n_rot)
  for(int t : config.pick<std::vector<int> >({ 50, 100, 300, 700 }, { 25, 50, 100, 200, 300, 500, 700, 1000, 1500 }))
    settings.insert({ t, 5 });
  for(int r : config.pick<std::vector<int> >({ 1, 2, 5 }, { 1, 2, 3, 4, 5, 7, 10 }))
    settings.insert({ 700, r });
  settings.insert({ 300, 2 });
  for(const auto& tr : settings)
  {
    Rrht_setting s = Rrht_setting::precise();
    s.planes = tr.first;
    s.rotations = tr.second;
    s.label = "_T" + std::to_string(tr.first) + "_rot" + std::to_string(tr.second);
    x.run(d, rrht(s, rrht_k));
  }
  x.run(d, jet(paper_k));
}

// -- Fig. 11 and 13: the corner with densities 1:5:10, RMS_10 against noise;
// errors at 0.2% noise for the Fig. 11 renderings.
void fig13(const Config& config)
{
  Experiment x(config, "fig13_anisotropy");
  const std::size_t n = config.pick<std::size_t>(10000, 20000); // 20000 in the paper
  for(double noise : config.pick<std::vector<double> >({ 0.2, 1 }, noise_levels(config)))
  {
    const Dataset d = synthetic("corner", anisotropic_corner, n, noise, 12);
    for(Sampling s : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
      for(Aggregation a : { Aggregation::MEAN, Aggregation::BEST, Aggregation::CLUSTER })
        if(a == Aggregation::CLUSTER || config.full)
        {
          const Estimator e = rrht(Rrht_setting::precise(s, a), rrht_k);
          x.run(d, e, config.threads,
                (noise == 0.2 && a == Aggregation::CLUSTER) ? "corner_" + e.name + ".txt" : std::string());
        }
    x.run(d, jet(paper_k), config.threads, noise == 0.2 ? "corner_jet_K80.txt" : std::string());
    x.run(d, pca(paper_k));
    x.run(d, vcm(paper_k));
  }
}

// -- Fig. 15: outliers (+100%, +300%) drawn within r = 3% of the
// bounding-box diagonal of the surface, 0.2% noise; errors on the inliers.
void fig15(const Config& config)
{
  Experiment x(config, "fig15_outliers");
  const std::size_t n = config.pick<std::size_t>(5000, 50000);
  std::vector<Dataset> sets = { synthetic("cylinder", closed_cylinder, n, 0.2, 13) };
  Dataset bunny;
  if(shared_mesh(config, "bunny00.off", "bunny", n, 0.2, 14, bunny))
    sets.push_back(bunny);
  for(const Dataset& clean : sets)
    for(double outliers : { 0., 100., 300. })
    {
      Dataset d = clean;
      add_outliers(d, outliers, 0.03 * bounding_box_diagonal(clean.cloud), 15);
      x.run(d, rrht(Rrht_setting::precise(), rrht_k));
      x.run(d, rrht(Rrht_setting::precise(Sampling::CUBES), rrht_k));
      x.run(d, jet(paper_k));
      x.run(d, pca(paper_k));
    }
}

/// RRHT (precise, fast, Cubes) and every peer.
void compare_all(Experiment& x, const Dataset& d)
{
  x.run(d, rrht(Rrht_setting::precise(), rrht_k));
  x.run(d, rrht(Rrht_setting::fast(), rrht_k));
  x.run(d, rrht(Rrht_setting::precise(Sampling::CUBES), rrht_k));
  for(const Estimator& e : peers())
    x.run(d, e);
}

// -- Real meshes of ../shared/data/meshes, sampled, the face normal as truth.
void meshes(const Config& config)
{
  Experiment x(config, "real_meshes");
  const std::size_t n = config.pick<std::size_t>(10000, 50000);
  const std::vector<std::string> names = config.pick<std::vector<std::string> >(
    { "fandisk", "anchor_dense", "bunny00" },
    { "fandisk", "fandisk_large", "anchor", "anchor_dense", "cube-meshed", "cylinder", "corner_with_sharp_edge",
      "bunny00", "elephant" });
  for(double noise : config.pick<std::vector<double> >({ 0.2 }, { 0, 0.2 }))
    for(std::size_t i = 0; i < names.size(); ++i)
    {
      Dataset d;
      if(shared_mesh(config, names[i] + ".off", names[i], n, noise, unsigned(20 + i), d))
        compare_all(x, d);
    }
}

// -- Point sets with given normals of ../shared/data/points.
void points(const Config& config)
{
  Experiment x(config, "real_points");
  struct File { std::string name, points, normals; };
  const std::vector<File> files = config.pick<std::vector<File> >(
    { { "kitten", "kitten.xyz", "" }, { "fandisk100k", "fandisk100k.xyz", "fandisk100k.normals" } },
    { { "kitten", "kitten.xyz", "" },
      { "building", "building.ply", "" },
      { "cube100k", "cube100k.xyz", "cube100k.normals" },
      { "fandisk100k", "fandisk100k.xyz", "fandisk100k.normals" },
      { "bunny100k", "bunny100k.xyz", "bunny100k.normals" } });
  const std::size_t stride = config.pick<std::size_t>(5, 1); // quick: every 5th point of the 100k sets
  for(const File& f : files)
  {
    Dataset d;
    const std::string path = config.shared("points/" + f.points);
    const bool large = !f.normals.empty();
    if(!points_with_normals(path, f.normals.empty() ? "" : config.shared("points/" + f.normals),
                            large && stride > 1 ? f.name + "_1of" + std::to_string(stride) : f.name,
                            large ? stride : 1, d))
    {
      warn_missing(path);
      continue;
    }
    compare_all(x, d);
  }
}

// -- Real scans of ../shared/data/scans, no truth: time and memory only.
void scans(const Config& config)
{
  Experiment x(config, "real_scans");
  const std::vector<std::string> names =
    config.pick<std::vector<std::string> >({ "bun000" }, { "bun000", "room_scan1" });
  for(const std::string& name : names)
  {
    Dataset d;
    const std::string path = config.shared("scans/" + name + ".xyz");
    if(!scan(path, name, d))
    {
      warn_missing(path);
      continue;
    }
    compare_all(x, d);
  }
}

// -- Time and peak memory against the number of points, the default and the
// fast setting against jet fitting and the bare queries: sphere with 0.2%
// noise, 2 threads (the report fits n log n).
void scaling(const Config& config)
{
  Experiment x(config, "scaling");
  const std::vector<std::size_t> sizes = config.pick<std::vector<std::size_t> >(
    { 100000, 200000, 400000 }, { 100000, 200000, 500000, 1000000, 2000000, 4000000 });
  for(std::size_t n : sizes)
  {
    const Dataset d = synthetic("sphere", sphere, n, 0.2, 32);
    x.run(d, rrht_default(rrht_k));
    x.run(d, rrht(Rrht_setting::fast(), rrht_k));
    x.run(d, jet(paper_k));
    x.run(d, neighbor_queries(rrht_k));
    x.run(d, rrht_neighborhoods(rrht_k));
  }
}

} // namespace

#endif // RRHT_BENCHMARK_PAPER_EXPERIMENTS_H
