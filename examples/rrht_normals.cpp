// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// rrht_normals: estimates the normals of a point file with the Robust
// Randomized Hough Transform, from the command line.
//
//   rrht_normals input.{xyz,pwn,ply,off[,las]} [output.{xyz,pwn,ply}] [options]
//
// `rrht_normals --help` lists the options with their defaults.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>

#include <boost/program_options.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

namespace po = boost::program_options;

namespace {

const int usage_error = 2;   // bad command line
const int runtime_error = 1; // unreadable input, failed estimation or output

std::string extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || path.find('/', dot) != std::string::npos)
    return "";
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

bool readable_extension(const std::string& e)
{
#ifdef CGAL_LINKED_WITH_LASLIB
  if(e == "las" || e == "laz")
    return true;
#endif
  return e == "xyz" || e == "pwn" || e == "ply" || e == "off";
}

// A progress bar on stderr, shown once a run has lasted half a second.
class Progress_bar
{
public:
  explicit Progress_bar(bool enabled) : m_enabled(enabled), m_start(clock::now()), m_last(m_start) {}

  bool operator()(double advancement)
  {
    const clock::time_point now = clock::now();
    if(!m_enabled || now - m_start < std::chrono::milliseconds(500) ||
       (now - m_last < std::chrono::milliseconds(100) && advancement < 1))
      return true;
    m_last = now;
    const int width = 40, done = int(advancement * width);
    std::cerr << "\rrrht_normals [" << std::string(done, '#') << std::string(width - done, ' ') << "] "
              << int(100 * advancement) << "%" << std::flush;
    m_shown = true;
    return true;
  }

  void finish()
  {
    if(m_shown)
      std::cerr << std::endl;
  }

private:
  typedef std::chrono::steady_clock clock;
  bool m_enabled, m_shown = false;
  clock::time_point m_start, m_last;
};

// Writes the points with their normals to `path` through a temporary file
// renamed at the end, so that a failed run never leaves a partial file in
// place of a good one.
bool write_atomically(const std::string& path, const std::vector<Point_with_normal>& points, int precision)
{
  const std::string e = extension(path);
  const std::string temporary = path + ".partial." + std::to_string(::getpid()) + "." + e;
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).stream_precision(precision);
  const bool written = (e == "ply") ? CGAL::IO::write_PLY(temporary, points, np) : CGAL::IO::write_XYZ(temporary, points, np);
  if(!written || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

template <typename T>
void check_range(const po::variables_map& options, const char* name, T low, T high)
{
  if(options.count(name) && !(options[name].as<T>() >= low && options[name].as<T>() <= high))
    throw po::error(std::string("the value of --") + name + " must be from " + std::to_string(low) + " to " +
                    std::to_string(high));
}

} // namespace

int main(int argc, char** argv)
{
  po::options_description described("Options");
  described.add_options()
    ("help,h", "print this help and exit")
    ("neighbors,k", po::value<long long>()->default_value(100),
     "K: number of neighbors; with --radius, the cap on the points taken from a ball (0: no cap)")
    ("radius,r", po::value<double>()->default_value(0., "0 (k-neighborhoods)"),
     "r: neighborhood ball radius")
    ("planes", po::value<long long>()->default_value(0, "eq. 7, 691 for 15 slices"),
     "T_R: most planes drawn per accumulator (1 to 100000000)")
    ("rotations", po::value<long long>()->default_value(5), "n_rot: randomly rotated accumulators (1 to 100000)")
    ("slices", po::value<long long>()->default_value(15), "n_phi: slices of the accumulator (1 to 1000)")
    ("sampling", po::value<std::string>()->default_value("points"), "triple sampling: points, cubes or unif")
    ("presampling", po::value<long long>()->default_value(4), "c: cubes per axis / small-ball factor (1 to 32)")
    ("aggregation", po::value<std::string>()->default_value("cluster"), "mean, best or cluster")
    ("cluster-angle", po::value<double>()->default_value(45.), "a_cluster in degrees (0 to 180)")
    ("no-confidence-interval", "do not stop early on disjoint confidence intervals (eq. 10)")
    ("seed", po::value<long long>()->default_value(0), "random seed (0 to 4294967295)")
    ("threads", po::value<long long>()->default_value(0, "all cores"), "number of threads (0 to 1024)")
    ("precision", po::value<long long>()->default_value(9),
     "significant digits written (1 to 17; 17 writes the computed doubles exactly)")
    ("orient", "orient the normals with CGAL::mst_orient_normals() (18 neighbors)")
    ("quiet,q", "no progress bar");
  po::options_description hidden;
  hidden.add_options()("input", po::value<std::string>())("output", po::value<std::string>());
  po::options_description all;
  all.add(described).add(hidden);
  po::positional_options_description positional;
  positional.add("input", 1).add("output", 1);

  const std::string usage = "Usage: rrht_normals INPUT [OUTPUT] [options]\n"
                            "Estimates normals with the Robust Randomized Hough Transform (Boulch and Marlet 2012).\n"
                            "INPUT: .xyz, .pwn, .ply or .off"
#ifdef CGAL_LINKED_WITH_LASLIB
                            ", .las"
#endif
                            "; OUTPUT: .xyz, .pwn or .ply with normals (default: INPUT's name + _normals.xyz,\n"
                            "in the current folder). A failed run leaves OUTPUT as it was.\n";
  po::variables_map options;
  try
  {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), options);
    po::notify(options);
    if(options.count("help"))
    {
      std::cout << usage << "\n" << described << std::endl;
      return EXIT_SUCCESS;
    }
    if(!options.count("input"))
      throw po::error("no input file");
    check_range<long long>(options, "neighbors", 0, 4294967295LL);
    check_range<long long>(options, "seed", 0, 4294967295LL);
    check_range<long long>(options, "threads", 0, 1024);
    check_range<long long>(options, "rotations", 1, 100000);
    check_range<long long>(options, "slices", 1, 1000);
    check_range<long long>(options, "presampling", 1, 32);
    check_range<double>(options, "cluster-angle", 0, 180);
    check_range<long long>(options, "precision", 1, 17);
    check_range<double>(options, "radius", 0, 1e300);
    if(options["planes"].as<long long>() != 0)
      check_range<long long>(options, "planes", 1, 100000000);
    if(options["neighbors"].as<long long>() == 0 && options["radius"].as<double>() == 0)
      throw po::error("-k 0 needs a --radius");
  }
  catch(const po::error& e)
  {
    std::cerr << "rrht_normals: " << e.what() << "\n" << usage << "Try 'rrht_normals --help'." << std::endl;
    return usage_error;
  }

  const std::string input = options["input"].as<std::string>();
  std::string output = options.count("output") ? options["output"].as<std::string>() : std::string();
  if(output.empty())
  {
    const std::string name = input.substr(input.find_last_of('/') + 1);
    output = name.substr(0, name.find_last_of('.')) + "_normals.xyz";
  }
  // Each name is spelled once: the tables both map and validate.
  const std::map<std::string, CGAL::RRHT::Sampling> samplings = {
    { "points", CGAL::RRHT::Sampling::POINTS }, { "cubes", CGAL::RRHT::Sampling::CUBES }, { "unif", CGAL::RRHT::Sampling::UNIF }
  };
  const std::map<std::string, CGAL::RRHT::Aggregation> aggregations = {
    { "mean", CGAL::RRHT::Aggregation::MEAN }, { "best", CGAL::RRHT::Aggregation::BEST },
    { "cluster", CGAL::RRHT::Aggregation::CLUSTER }
  };
  const auto sampling = samplings.find(options["sampling"].as<std::string>());
  const auto aggregation = aggregations.find(options["aggregation"].as<std::string>());
  std::string problem;
  if(sampling == samplings.end())
    problem = "--sampling must be points, cubes or unif, not '" + options["sampling"].as<std::string>() + "'";
  else if(aggregation == aggregations.end())
    problem = "--aggregation must be mean, best or cluster, not '" + options["aggregation"].as<std::string>() + "'";
  else if(!readable_extension(extension(input)))
    problem = "cannot read '" + input + "': the input must be .xyz, .pwn, .ply or .off";
  else if(extension(output) != "xyz" && extension(output) != "pwn" && extension(output) != "ply")
    problem = "cannot write '" + output + "': the output must be .xyz, .pwn or .ply";
  if(!problem.empty())
  {
    std::cerr << "rrht_normals: " << problem << std::endl;
    return usage_error;
  }

  // Read.
  if(!std::ifstream(input))
  {
    std::cerr << "rrht_normals: cannot open '" << input << "'" << std::endl;
    return runtime_error;
  }
  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points), CGAL::parameters::point_map(Point_map())))
  {
    std::cerr << "rrht_normals: cannot read points from '" << input << "' (malformed file)" << std::endl;
    return runtime_error;
  }
  if(points.empty())
  {
    std::cerr << "rrht_normals: '" << input << "' holds no point" << std::endl;
    return runtime_error;
  }

#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> threads;
  if(options["threads"].as<long long>() > 0)
    threads.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                          std::size_t(options["threads"].as<long long>())));
#endif

  // Estimate.
  Progress_bar bar(!options.count("quiet") && ::isatty(STDERR_FILENO));
  const std::function<bool(double)> callback = [&bar](double advancement) { return bar(advancement); };
  auto np = CGAL::RRHT::parameters::point_map(Point_map())
              .normal_map(Normal_map())
              .neighbor_radius(options["radius"].as<double>())
              .number_of_rotations(options["rotations"].as<long long>())
              .accumulator_slices(options["slices"].as<long long>())
              .use_confidence_interval(options.count("no-confidence-interval") == 0)
              .sampling(sampling->second)
              .presampling_factor(options["presampling"].as<long long>())
              .aggregation(aggregation->second)
              .cluster_angle(options["cluster-angle"].as<double>())
              .random_seed(static_cast<unsigned int>(options["seed"].as<long long>()))
              .callback(callback);
  const unsigned int k = static_cast<unsigned int>(options["neighbors"].as<long long>());
  CGAL::Real_timer timer;
  timer.start();
  try
  {
    if(options["planes"].as<long long>() != 0)
      CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(points, k, np.number_of_planes(options["planes"].as<long long>()));
    else
      CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(points, k, np);
  }
  catch(const std::exception& e)
  {
    bar.finish();
    std::cerr << "rrht_normals: " << e.what() << std::endl;
    return runtime_error;
  }
  bar.finish();
  if(options.count("orient"))
    CGAL::mst_orient_normals(points, 18, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  timer.stop();

  std::size_t without_normal = 0;
  for(const Point_with_normal& pn : points)
    without_normal += (pn.second == CGAL::NULL_VECTOR);

  // Write.
  if(!write_atomically(output, points, int(options["precision"].as<long long>())))
  {
    std::cerr << "rrht_normals: cannot write '" << output << "'" << std::endl;
    return runtime_error;
  }
  std::cout << points.size() << " points, " << timer.time() << " s, "
            << std::size_t(points.size() / (std::max)(timer.time(), 1e-6))
            << " points/s" << (options.count("orient") ? ", oriented" : "");
  if(without_normal > 0)
    std::cout << ", " << without_normal << " without normal (null vector)";
  std::cout << " -> " << output << std::endl;
  return EXIT_SUCCESS;
}
