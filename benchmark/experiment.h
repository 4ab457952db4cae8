// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every experiment of rrht_benchmark shares: the configuration, an
// experiment's CSV of measurements, the peers, the targets and the clouds
// with sharp edges, fillets and thin parts. Included by rrht_benchmark.cpp only.

#ifndef RRHT_BENCHMARK_EXPERIMENT_H
#define RRHT_BENCHMARK_EXPERIMENT_H

#include "confidence_measures.h"
#include "datasets.h"
#include "estimators.h"
#include "measure.h"
#include "orientation_scores.h"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace po = boost::program_options;
using namespace rrht_benchmark;
typedef CGAL::RRHT::Sampling Sampling;
typedef CGAL::RRHT::Aggregation Aggregation;

namespace {

struct Config
{
  bool full = false;
  int runs = 3;
  std::vector<unsigned int> threads;          // for every experiment but the headline
  std::vector<unsigned int> headline_threads; // 1 and 2
  unsigned int timeout = 0;
  std::string out, data, scratch;

  template <typename T>
  T pick(T quick, T full_mode) const { return full ? full_mode : quick; }
  std::string shared(const std::string& file) const { return data + "/" + file; }
};

// The neighborhoods of Section 6: K = 100 for RRHT (Table 1; the paper's
// K = 500 on synthetic data is 5x the cost for the same conclusions), K = 80
// for jet fitting, PCA and VCM as in the paper, CGAL's usual K = 18, and
// Open3D's documented default K = 30.
const Neighborhood rrht_k{ 100, 0 }, paper_k{ 80, 0 }, small_k{ 18, 0 }, open3d_k{ 30, 0 };

/// One experiment: its CSV file and how it runs an estimator on a dataset.
class Experiment
{
public:
  Experiment(const Config& config, const std::string& name) : config_(config), name_(name)
  {
    csv_.open(config.out + "/" + name + ".csv");
    if(!csv_)
      throw std::runtime_error("cannot write " + config.out + "/" + name + ".csv");
    csv_ << "experiment,dataset,points,outliers,noise_percent,outliers_percent,estimator,planes,rotations,"
            "threads,runs,median_s,min_s,max_s,peak_mib,rms_deg,rms10_deg,above10_percent,null_normals,status,mean_deg\n";
    std::cout << "\n== " << name << " ==" << std::endl;
  }

  /// Measures `e` on `d` with each thread count (once with 1 thread if `e`
  /// is sequential). The per-point errors of the first measurement go to
  /// `errors_file` in the scratch folder if not empty.
  void run(const Dataset& d, const Estimator& e, const std::vector<unsigned int>& threads,
           const std::string& errors_file = std::string())
  {
    std::vector<unsigned int> counts = e.parallel ? threads : std::vector<unsigned int>{ 1 };
    for(std::size_t i = 0; i < counts.size(); ++i)
      run_with(d, e, counts[i], i == 0 ? errors_file : std::string());
  }
  void run(const Dataset& d, const Estimator& e) { run(d, e, config_.threads); }

  /// Measures `e` on `d` with `threads` threads and returns the measurement.
  Measurement run_with(const Dataset& d, const Estimator& e, unsigned int threads,
                       const std::string& errors_file = std::string())
  {
    const std::string errors_path = errors_file.empty() ? std::string() : config_.scratch + "/" + errors_file;
    const Measurement m = measure(e.estimate, d.cloud, threads, config_.runs, config_.timeout, errors_path);
    write(d, e, threads, m);
    return m;
  }

  /// A measurement for `run_in_rounds()`.
  struct Planned
  {
    const Dataset* dataset;
    Estimator estimator;
    unsigned int threads;
    std::vector<int> cores = {}; // the cores it runs on (any, if none)
  };

  /// Measures each of `planned` as many times as `run_with()` does, but in
  /// rounds: each round runs each of them once, in order, so that a drift
  /// of the machine's speed during the experiment (10-25% over minutes on
  /// this shared 2-core machine) weighs on all of them alike. Run k of each
  /// measurement is from round k, so two measurements can be compared round
  /// by round (`Targets::add()`). A measurement that fails is not run again.
  std::vector<Measurement> run_in_rounds(const std::vector<Planned>& planned)
  {
    std::vector<Measurement> all(planned.size());
    for(int round = 0; round < config_.runs; ++round)
      for(std::size_t i = 0; i < planned.size(); ++i)
      {
        if(round > 0 && all[i].status != Measurement::OK)
          continue;
        const Measurement m = measure(planned[i].estimator.estimate, planned[i].dataset->cloud, planned[i].threads, 1,
                                      config_.timeout, std::string(), planned[i].cores);
        if(round == 0)
          all[i] = m;
        else if(m.status != Measurement::OK)
        {
          all[i].status = m.status;
          all[i].message = m.message;
        }
        else
        {
          all[i].seconds.push_back(m.seconds.front());
          all[i].peak_mib = (std::max)(all[i].peak_mib, m.peak_mib);
        }
      }
    for(std::size_t i = 0; i < planned.size(); ++i)
      write(*planned[i].dataset, planned[i].estimator, planned[i].threads, all[i]);
    return all;
  }

private:
  void write(const Dataset& d, const Estimator& e, unsigned int threads, const Measurement& m)
  {
    char line[1024];
    std::snprintf(line, sizeof line, "%s,%s,%zu,%zu,%g,%g,%s,%d,%d,%u,%zu,%.4f,%.4f,%.4f,%.1f,%.3f,%.3f,%.3f,%zu,%s,%.3f",
                  name_.c_str(), d.name.c_str(), d.inliers, d.cloud.size() - d.inliers, d.noise_percent,
                  d.outliers_percent, e.name.c_str(), e.planes, e.rotations, threads, m.seconds.size(), m.median(),
                  m.seconds.empty() ? 0. : *std::min_element(m.seconds.begin(), m.seconds.end()),
                  m.seconds.empty() ? 0. : *std::max_element(m.seconds.begin(), m.seconds.end()), m.peak_mib,
                  m.errors.rms, m.errors.rms_tau, 100 * m.errors.share_above, m.null_normals, m.status_name(),
                  m.errors.mean);
    csv_ << line << '\n';
    csv_.flush();
    std::printf("%-14s %-9zu noise %-4g out %-4g %-26s %ut  %8.3f s  %7.1f MiB  RMS %6.2f  RMS10 %6.2f  >10deg %6.2f%%  %s %s\n",
                d.name.c_str(), d.inliers, d.noise_percent, d.outliers_percent, e.name.c_str(), threads, m.median(),
                m.peak_mib, m.errors.rms, m.errors.rms_tau, 100 * m.errors.share_above, m.status_name(),
                m.message.c_str());
    std::fflush(stdout);
  }

  const Config& config_;
  std::string name_;
  std::ofstream csv_;
};

/// jet fitting (K = 80 and CGAL's usual K = 18), PCA and VCM (K = 80), PCL
/// (K = 80) and Open3D (K = 30, and at most 30 within a radius) when built
/// with them.
std::vector<Estimator> peers()
{
  std::vector<Estimator> p = { jet(paper_k), jet(small_k), pca(paper_k), vcm(paper_k) };
#ifdef RRHT_BENCHMARK_WITH_PCL
  p.push_back(pcl(paper_k));
#endif
#ifdef RRHT_BENCHMARK_WITH_OPEN3D
  p.push_back(open3d(open3d_k));
  p.push_back(open3d_hybrid(open3d_k));
#endif
  return p;
}

void warn_missing(const std::string& path) { std::cout << "skipped (not found): " << path << std::endl; }

/// `mesh()` on ../shared/data/meshes/`file`, with a message if it is absent.
bool shared_mesh(const Config& config, const std::string& file, const std::string& name, std::size_t n,
                 double noise_percent, unsigned int seed, Dataset& d)
{
  const std::string path = config.shared("meshes/" + file);
  if(mesh(path, name, n, noise_percent, seed, d))
    return true;
  warn_missing(path);
  return false;
}

// -- Speed: the performance targets, each a ratio of two measurements of
// this run, taken in rounds (times: the median of the ratios round by
// round), and the time against k, printed at the end and written to
// speed_ratios.csv.

/// Whether both measurements succeeded, in the same number of rounds.
bool measured_alike(const Measurement& a, const Measurement& b)
{
  return a.status == Measurement::OK && b.status == Measurement::OK && a.seconds.size() == b.seconds.size();
}

/// The time of `numerator` over that of `denominator`, measured in the same
/// rounds (`Experiment::run_in_rounds()`): the median of the ratios of their
/// runs round by round; 0 if either failed.

double ratio_by_rounds(const Measurement& numerator, const Measurement& denominator)
{
  if(!measured_alike(numerator, denominator))
    return 0;
  Measurement ratios;
  for(std::size_t k = 0; k < numerator.seconds.size(); ++k)
    ratios.seconds.push_back(numerator.seconds[k] / denominator.seconds[k]);
  return ratios.median();
}

/// The speed-up from 1 to 2 threads, from measurements in the same rounds:
/// `two` with 2 threads on two cores, `one_a` and `one_b` with 1 thread on
/// each of them. Each round gives the harmonic mean of the 1-thread times
/// over the 2-thread time: on cores of equal speed, the ratio of the times;
/// on a shared machine, whose cores need not run alike, the 2-thread time
/// against that of ideal sharing between those two cores, whichever one
/// thread would have landed on. The median over the rounds; 0 if any failed.
double speed_up_over_two_cores(const Measurement& two, const Measurement& one_a, const Measurement& one_b)
{
  if(!measured_alike(one_a, two) || !measured_alike(one_b, two))
    return 0;
  Measurement ratios;
  for(std::size_t k = 0; k < two.seconds.size(); ++k)
    ratios.seconds.push_back(2 / (1 / one_a.seconds[k] + 1 / one_b.seconds[k]) / two.seconds[k]);
  return ratios.median();
}

/// The targets of an experiment, each a measured value against its bound,
/// printed at the end and written to a CSV file of the results folder.
class Targets
{
public:
  /// Writes to `file`, whose value column is named `value` ("ratio" where
  /// the values are ratios of two measurements).
  explicit Targets(const Config& config, const std::string& file = "speed_ratios.csv",
                   const std::string& value = "ratio")
    : out_(config.out + "/" + file), value_(value)
  {}

  /// `numerator` / `denominator`, which should be at most `target` (or at
  /// least, if `at_least`). A failed measurement gives no ratio.
  void add(const std::string& what, double numerator, double denominator, double target, bool at_least = false)
  {
    const bool valid = numerator > 0 && denominator > 0;
    rows_.push_back(Row{ what, valid ? numerator / denominator : 0., target, at_least, valid });
  }

  /// The time of `numerator` over that of `denominator` (`ratio_by_rounds()`).
  void add(const std::string& what, const Measurement& numerator, const Measurement& denominator, double target,
           bool at_least = false)
  {
    add(what, ratio_by_rounds(numerator, denominator), 1., target, at_least);
  }

  /// `value`, which should be at most `bound`; no value where `valid` is false
  /// (a failed measurement).
  void add_value(const std::string& what, double value, double bound, bool valid)
  {
    rows_.push_back(Row{ what, value, bound, false, valid && std::isfinite(value) && std::isfinite(bound) });
  }

  /// Prints the targets, how many are met, and writes them to the file.
  void print_and_write() const
  {
    std::ofstream csv(out_);
    csv << "target," << value_ << ",bound,met\n";
    std::printf("\n%-80s %8s %10s %s\n", "target", value_.c_str(), "bound", "met");
    std::size_t missed = 0;
    for(const Row& r : rows_)
    {
      const bool met = r.valid && (r.at_least ? r.value >= r.target : r.value <= r.target);
      missed += r.valid && !met;
      const char* verdict = !r.valid ? "n/a" : (met ? "yes" : "no");
      char bound[32];
      std::snprintf(bound, sizeof bound, "%s %.3f", r.at_least ? ">=" : "<=", r.target);
      std::printf("%-80s %8.3f %10s %s\n", r.what.c_str(), r.value, bound, verdict);
      csv << '"' << r.what << "\"," << r.value << ',' << bound << ',' << verdict << '\n';
    }
    std::printf("%zu of %zu targets met\n", rows_.size() - missed, rows_.size());
    std::fflush(stdout);
  }

private:
  struct Row
  {
    std::string what;
    double value, target;
    bool at_least, valid;
  };
  std::string out_, value_;
  std::vector<Row> rows_;
};

// -- The sharp shapes: the noisy cube, cylinder, fandisk and anisotropic
// corner (100k points, 0.2% noise), each with its points near a sharp edge
// (within 1% of the diagonal, found on the clean cloud).
struct Shape_with_edges
{
  Dataset dataset;
  std::vector<bool> near_edges;
};

/// `clean` with `noise_percent` noise, and its points within 1% of the
/// diagonal of a sharp edge, found on the clean cloud.
Shape_with_edges with_edges(const std::string& name, Cloud clean, double noise_percent, unsigned int seed)
{
  std::vector<bool> near = near_sharp_edges(clean, 0.01 * bounding_box_diagonal(clean));
  return Shape_with_edges{ with_noise(name, std::move(clean), noise_percent, seed), std::move(near) };
}

std::vector<Shape_with_edges> shapes_with_edges(const Config& config)
{
  const std::size_t n = 100000;
  std::vector<Shape_with_edges> shapes;
  shapes.push_back(with_edges("cube", cube(n, 1), 0.2, 1));
  shapes.push_back(with_edges("cylinder", closed_cylinder(n, 2), 0.2, 2));
  Cloud fandisk;
  if(sample_mesh(config.shared("meshes/fandisk.off"), n, 3, fandisk))
    shapes.push_back(with_edges("fandisk", std::move(fandisk), 0.2, 3));
  else
    warn_missing(config.shared("meshes/fandisk.off"));
  shapes.push_back(with_edges("corner", anisotropic_corner(n, 12), 0.2, 12));
  return shapes;
}

/// The fillet shapes (100k points, `noise_percent` noise): the box [-1,1]^3
/// with every edge rounded to 0.25, 0.5, 1 and 2 times the radius of the
/// disk that holds 100 points of 100k on its area (24), a Z-shaped plate
/// 0.05 thick whose bends have an inner fillet radius of 0.1, and last a
/// slab with both fillets (radius 0.2) and sharp edges, with its points
/// near them.
std::vector<Shape_with_edges> fillet_shapes(double noise_percent)
{
  const std::size_t n = 100000;
  const double radius = std::sqrt(double(rrht_k.k) * 24 / (CGAL_PI * double(n)));
  const std::vector<bool> none;
  std::vector<Shape_with_edges> shapes;
  for(double times : { 0.25, 0.5, 1., 2. })
  {
    char name[64];
    std::snprintf(name, sizeof name, "rounded_box_r%gx", times);
    shapes.push_back({ with_noise(name, rounded_box(n, times * radius, 61), noise_percent, 61), none });
  }
  shapes.push_back({ with_noise("filleted_plate", filleted_plate(n, 0.05, 0.1, 62), noise_percent, 62), none });
  shapes.push_back(with_edges("rounded_slab", rounded_slab(n, 0.2, 63), noise_percent, 63));
  return shapes;
}

/// The point set ../shared/data/points/`name`.xyz with its given normals
/// (kitten.xyz holds them, the others have a .normals file beside), with a
/// message if it is absent.
bool shared_points(const Config& config, const std::string& name, Dataset& d)
{
  const std::string path = config.shared("points/" + name + ".xyz");
  const std::string normals = name == "kitten" ? "" : config.shared("points/" + name + ".normals");
  if(points_with_normals(path, normals, name, 1, d))
    return true;
  warn_missing(path);
  return false;
}

/// What a cloud that shaped the default is.
enum class Cloud_kind
{
  SHARP,  // sharp edges only
  MIXED,  // sharp edges and fillets
  SMOOTH, // smooth or filleted
  THIN,   // the two sides of a thin part in one neighborhood
  DENSE,  // many features at or below the neighborhood's size
  OTHER   // the cube with 1% noise
};

/// Calls `visit(dataset, kind, near_edges)` on each cloud that shaped least
/// squares first and the default (100k points unless said; `near_edges`:
/// the points within 1% of a sharp edge, for the sharp and mixed shapes):
/// the sharp shapes (0.2% noise), the cube with 1% noise, the fillet shapes,
/// the sphere and the bunny, clean and with 0.2% noise, the thin parts
/// (0.5% and 2% of the diagonal thick, 0.2% noise), and the parts 2% thick
/// and the filleted plate at 20k points, where both sides lie well inside
/// every neighborhood.
template <typename Visit>
void for_each_design_cloud(const Config& config, Visit visit)
{
  const std::vector<bool> none;
  const std::size_t n = 100000;
  for(const Shape_with_edges& shape : shapes_with_edges(config))
    visit(shape.dataset, Cloud_kind::SHARP, shape.near_edges);
  visit(synthetic("cube", cube, n, 1, 1), Cloud_kind::OTHER, none);
  for(double noise : { 0., 0.2 })
  {
    for(const Shape_with_edges& shape : fillet_shapes(noise))
      visit(shape.dataset, shape.near_edges.empty() ? Cloud_kind::SMOOTH : Cloud_kind::MIXED, shape.near_edges);
    visit(synthetic("sphere", sphere, n, noise, 5), Cloud_kind::SMOOTH, none);
    Dataset bunny;
    if(shared_mesh(config, "bunny00.off", "bunny00", n, noise, 3, bunny))
      visit(bunny, Cloud_kind::SMOOTH, none);
  }
  for(double percent : { 0.5, 2. })
  {
    char t[32];
    std::snprintf(t, sizeof t, "_t%g%%", percent);
    visit(with_noise(std::string("thin_box") + t, thin_box(n, percent / 100 * std::sqrt(8.), 1), 0.2, 1),
          Cloud_kind::THIN, none);
    visit(with_noise(std::string("bent_sheet") + t, bent_sheet(n, percent / 100 * std::sqrt(6.), 2), 0.2, 2),
          Cloud_kind::THIN, none);
  }
  const std::size_t sparse = 20000;
  visit(with_noise("thin_box_t2%", thin_box(sparse, 0.02 * std::sqrt(8.), 1), 0.2, 1), Cloud_kind::THIN, none);
  visit(with_noise("bent_sheet_t2%", bent_sheet(sparse, 0.02 * std::sqrt(6.), 2), 0.2, 2), Cloud_kind::THIN, none);
  visit(with_noise("filleted_plate", filleted_plate(sparse, 0.05, 0.1, 62), 0.2, 62), Cloud_kind::SMOOTH, none);
}

/// Calls `visit(dataset)` on the feature-dense parts (100k points, clean and
/// with 0.2% noise): the spur gear (24 teeth), the block drilled with bores
/// of several diameters and the finned part, whose fins and gaps are half
/// the neighborhood's radius; the shapes of the orientation experiment.
template <typename Visit>
void for_each_feature_dense_cloud(Visit visit)
{
  const std::size_t n = 100000;
  for(double noise : { 0., 0.2 })
  {
    visit(synthetic("gear", [](std::size_t m, unsigned int seed) {
      return solid_boundary(machined_part_solid("gear"), m, seed);
    }, n, noise, 55));
    visit(synthetic("drilled_block", [](std::size_t m, unsigned int seed) {
      return solid_boundary(machined_part_solid("drilled_block"), m, seed);
    }, n, noise, 54));
    visit(synthetic("finned_part", finned_part, n, noise, 45));
  }
}

/// Calls `visit(dataset, k)` on the smooth clouds at CGAL's usual small k
/// (12 and 18): the sphere and the bunny (100k points), clean and with 0.2%
/// noise.
template <typename Visit>
void for_each_small_k_cloud(const Config& config, Visit visit)
{
  const std::size_t n = 100000;
  for(double noise : { 0., 0.2 })
  {
    std::vector<Dataset> smooth = { synthetic("sphere", sphere, n, noise, 5) };
    Dataset bunny;
    if(shared_mesh(config, "bunny00.off", "bunny00", n, noise, 3, bunny))
      smooth.push_back(bunny);
    for(const Dataset& d : smooth)
      for(unsigned int k : { 12u, 18u })
        visit(d, k);
  }
}

/// The errors (-1 without truth) and confidences of the `size` samples of a
/// per-point file (`measure()`'s `errors_path`); false if it has fewer lines.
bool read_per_point(const std::string& path, std::size_t size, std::vector<double>& errors,
                    std::vector<double>& confidences)
{
  std::ifstream in(path);
  errors.clear();
  confidences.clear();
  double x, y, z, tx, ty, tz, error, confidence;
  while(errors.size() < size && (in >> x >> y >> z >> tx >> ty >> tz >> error >> confidence))
  {
    errors.push_back(error);
    confidences.push_back(confidence);
  }
  return errors.size() == size;
}

} // namespace

#endif // RRHT_BENCHMARK_EXPERIMENT_H
