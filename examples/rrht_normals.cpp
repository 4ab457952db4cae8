// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// rrht_normals: estimates the normals of a point file with the Robust
// Randomized Hough Transform, from the command line.
//
//   rrht_normals input.{xyz,pwn,ply,off,las} [output.{xyz,pwn,ply,las}] [options]
//
// `rrht_normals --help` lists the options with their defaults.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/rrht_orient_normals.h>
#include <CGAL/RRHT/IO/LAS_file.h>
#include <CGAL/RRHT/IO/write_LAS_with_normals.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/IO/write_ply_points.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>

#include "ply_header_check.h"

#include <boost/algorithm/string/predicate.hpp>
#include <boost/algorithm/string/split.hpp>
#include <boost/program_options.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
// A point, its normal, the normal's confidence (written with --confidence)
// and the point's position in a LAS input, which orienting may reorder.
typedef std::tuple<Point, Vector, double, std::size_t> Point_with_normal;
typedef CGAL::Nth_of_tuple_property_map<0, Point_with_normal> Point_map;
typedef CGAL::Nth_of_tuple_property_map<1, Point_with_normal> Normal_map;
typedef CGAL::Nth_of_tuple_property_map<2, Point_with_normal> Confidence_map;

namespace fs = std::filesystem;
namespace po = boost::program_options;

namespace {

const int usage_error = 2;   // bad command line
const int runtime_error = 1; // unreadable input, failed estimation or output

// The extensions by which CGAL::IO::read_points() and write_points() choose
// a format (in any letter case), among those this tool offers, and LAS,
// which CGAL::RRHT::IO reads and writes.
const std::vector<std::string> input_extensions = { ".xyz", ".pwn", ".ply", ".off", ".las" };
const std::vector<std::string> output_extensions = { ".xyz", ".pwn", ".ply", ".las" };
// A LAZ file is given to the LAS reader, which says how to decompress it.
const std::vector<std::string> las_extensions = { ".las", ".laz" };

// "a, b or c".
std::string one_of(const std::vector<std::string>& names)
{
  std::string list;
  for(std::size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return list;
}

template <typename Table>
std::vector<std::string> names_of(const Table& table)
{
  std::vector<std::string> names;
  for(const auto& entry : table)
    names.push_back(entry.first);
  return names;
}

// The value of option `name` among the names of `table`.
template <typename Table>
auto choice(const po::variables_map& options, const char* name, const Table& table)
{
  const std::string& value = options[name].as<std::string>();
  for(const auto& entry : table)
    if(entry.first == value)
      return entry.second;
  throw po::error(std::string("--") + name + " must be " + one_of(names_of(table)) + ", not '" + value + "'");
}

bool has_extension(const fs::path& path, const std::vector<std::string>& extensions)
{
  const std::string extension = path.extension().string();
  return std::any_of(extensions.begin(), extensions.end(),
                     [&extension](const std::string& e) { return boost::algorithm::iequals(extension, e); });
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

// Writes the points with their normals and confidences: a binary PLY with a
// property `confidence` after the normal, as CGAL::IO::write_PLY() writes
// the rest, or an .xyz file with the confidence in a 7th column.
bool write_with_confidence(const fs::path& path, const std::vector<Point_with_normal>& points, int precision)
{
  if(boost::algorithm::iequals(path.extension().string(), ".ply"))
  {
    std::ofstream os(path, std::ios::binary);
    CGAL::IO::set_mode(os, CGAL::IO::BINARY);
    return CGAL::IO::write_PLY_with_properties(
             os, points, CGAL::IO::make_ply_point_writer(Point_map()), CGAL::IO::make_ply_normal_writer(Normal_map()),
             std::make_pair(Confidence_map(), CGAL::IO::PLY_property<double>("confidence"))) &&
           bool(os.flush());
  }
  std::ofstream os(path);
  os.precision(precision);
  for(const Point_with_normal& p : points)
    os << std::get<0>(p) << ' ' << std::get<1>(p) << ' ' << std::get<2>(p) << '\n';
  return bool(os.flush());
}

// Writes the points with their normals (and their confidences if
// `confidence`) to `path`, in the format of its extension, through a
// temporary file renamed at the end, so that a failed run never leaves a
// partial file in place of a good one. The temporary file ends with the same
// extension, by which write_points() chooses.
bool write_atomically(const fs::path& path, const std::vector<Point_with_normal>& points, int precision,
                      bool confidence)
{
  fs::path temporary = path;
  temporary += ".partial." + std::to_string(::getpid());
  temporary += path.extension();
  const bool written =
    confidence ? write_with_confidence(temporary, points, precision)
               : CGAL::IO::write_points(temporary.string(), points,
                                        CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).stream_precision(precision));
  std::error_code error;
  if(written)
    fs::rename(temporary, path, error);
  if(!written || error)
  {
    fs::remove(temporary, error);
    return false;
  }
  return true;
}

// The range checks that CGAL::rrht_estimate_normals() cannot make: on the
// command line's numbers before they are converted, and on the tool's own options.
void check_range(const po::variables_map& options, const char* name, long long low, long long high)
{
  const long long value = options[name].as<long long>();
  if(value < low || value > high)
    throw po::error(std::string("the value of --") + name + " must be from " + std::to_string(low) + " to " +
                    std::to_string(high));
}

// Three numbers "X,Y,Z", or a usage error about --orient.
Vector three_numbers(const std::string& text)
{
  double x, y, z;
  char comma1 = 0, comma2 = 0, rest = 0;
  std::istringstream in(text);
  if(!(in >> x >> comma1 >> y >> comma2 >> z) || comma1 != ',' || comma2 != ',' || (in >> rest) ||
     !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    throw po::error("the value of --orient must be consistent, mst, up, X,Y,Z, viewpoint:X,Y,Z or "
                    "viewpoint:NAME,NAME,NAME, not '" + text + "'");
  return Vector(x, y, z);
}

// The names of the fields of --orient=viewpoint:NAME,NAME,NAME, each
// point's scanner position in the extra bytes of a LAS input; none for
// --orient=viewpoint:X,Y,Z and the other values.
std::vector<std::string> viewpoint_fields(const std::string& how)
{
  if(how.rfind("viewpoint:", 0) != 0)
    return {};
  std::vector<std::string> names;
  boost::algorithm::split(names, how.substr(10), [](char c) { return c == ','; });
  const bool numbers = std::all_of(names.begin(), names.end(), [](const std::string& name) {
    std::istringstream in(name);
    double value;
    char rest;
    return (in >> value) && !(in >> rest);
  });
  if(numbers || names.size() != 3 || std::any_of(names.begin(), names.end(), [](auto& n) { return n.empty(); }))
    return {};
  return names;
}

// Checks the value of --orient before anything is read.
void check_orientation(const std::string& how, bool las_input)
{
  if(how == "consistent" || how == "mst" || how == "up")
    return;
  if(!viewpoint_fields(how).empty())
  {
    if(!las_input)
      throw po::error("--orient=viewpoint:NAME,NAME,NAME reads each scanner position from the extra bytes of a "
                      "LAS input; give a point, --orient=viewpoint:X,Y,Z, for this input");
    return;
  }
  const Vector v = three_numbers(how.rfind("viewpoint:", 0) == 0 ? how.substr(10) : how);
  if(how.rfind("viewpoint:", 0) != 0 && v == CGAL::NULL_VECTOR)
    throw po::error("the direction of --orient must not be null");
}

// Each point's scanner position, from the x y z triples of its record
// in a LAS input.
struct Scanner_map
{
  typedef Point_with_normal key_type;
  typedef Point value_type;
  typedef Point reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<double>* xyz;

  friend Point get(const Scanner_map& map, const Point_with_normal& p)
  {
    const double* v = map.xyz->data() + 3 * std::get<3>(p);
    return Point(v[0], v[1], v[2]);
  }
};

// Orients the normals as --orient says (see its help), towards `scanners`
// for --orient=viewpoint:NAME,NAME,NAME. The points without normal stay,
// in their order, after the others.
void orient(std::vector<Point_with_normal>& points, const std::string& how, const std::vector<double>& scanners)
{
  const auto maps = CGAL::RRHT::parameters::point_map(Point_map()).normal_map(Normal_map());
  if(how == "consistent")
    CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(points, 18, maps);
  else if(how == "mst")
    CGAL::mst_orient_normals(points, 18, maps);
  else if(how == "up")
    CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(points, 0, maps.direction(Vector(0, 0, 1)));
  else if(!viewpoint_fields(how).empty())
    CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(points, 0, maps.viewpoint_map(Scanner_map{ &scanners }));
  else if(how.rfind("viewpoint:", 0) == 0)
    CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(
      points, 0, maps.viewpoint(CGAL::ORIGIN + three_numbers(how.substr(10))));
  else
    CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(points, 0, maps.direction(three_numbers(how)));
}

} // namespace

int main(int argc, char** argv)
{
  const std::string setting_help =
    one_of(names_of(CGAL::RRHT::setting_names)) + ": least squares where the neighborhood is one smooth sheet, the adaptive Hough "
    "transform elsewhere (default), or the paper's settings, the Hough transform everywhere (paper_precise: T_R from "
    "eq. 7 and 5 rotations; paper_fast: 300 planes and 2 rotations, unless --planes or --rotations say otherwise)";
  const std::string sampling_help = "triple sampling: " + one_of(names_of(CGAL::RRHT::sampling_names)) +
                                    " (with the default setting, only unif changes anything)";
  const std::string aggregation_help = one_of(names_of(CGAL::RRHT::aggregation_names));
  po::options_description described("Options");
  described.add_options()
    ("help,h", "print this help and exit")
    ("neighbors,k", po::value<long long>()->default_value(100),
     "K: number of neighbors; with --radius, the cap on the points taken from a ball (0: no cap)")
    ("radius,r", po::value<double>()->default_value(0., "0 (k-neighborhoods)"),
     "r: neighborhood ball radius")
    ("setting", po::value<std::string>()->default_value("default"), setting_help.c_str())
    ("planes", po::value<long long>()->default_value(0, "eq. 7, 691 for 15 slices; 300 with paper_fast"),
     "T_R: most planes drawn per accumulator (1 to 100000000)")
    ("rotations", po::value<long long>()->default_value(5, "5; 2 with paper_fast"),
     "n_rot: randomly rotated accumulators (1 to 100000)")
    ("slices", po::value<long long>()->default_value(15), "n_phi: slices of the accumulator (1 to 1000)")
    ("sampling", po::value<std::string>()->default_value("points"), sampling_help.c_str())
    ("presampling", po::value<long long>()->default_value(4), "c: cubes per axis / small-ball factor (1 to 32)")
    ("aggregation", po::value<std::string>()->default_value("cluster"), aggregation_help.c_str())
    ("cluster-angle", po::value<double>()->default_value(45.), "a_cluster in degrees (0 to 180)")
    ("no-confidence-interval", "do not stop early on disjoint confidence intervals (eq. 10)")
    ("refit", "refit each normal by least squares (a quadric on the neighbors within the noise of its plane, "
              "or two parallel planes) where the neighborhood is one smooth sheet or the two sides of a thin part "
              "(beyond the paper)")
    ("seed", po::value<long long>()->default_value(0), "random seed (0 to 4294967295)")
    ("threads", po::value<long long>()->default_value(0, "all cores"), "number of threads (0 to 1024)")
    ("precision", po::value<long long>()->default_value(9),
     "significant digits written (1 to 17; 17 writes the computed doubles exactly)")
    ("orient", po::value<std::string>()->implicit_value("consistent"),
     "orient the normals: --orient (consistently, out of closed surfaces, with CGAL::rrht_orient_normals() and "
     "18 neighbors), --orient=up, --orient=X,Y,Z (towards a direction), --orient=viewpoint:X,Y,Z (a scanner's "
     "position), --orient=viewpoint:NAME,NAME,NAME (each point's scanner position, in these extra-bytes fields of a "
     "LAS input), or "
     "--orient=mst (CGAL::mst_orient_normals(), 18 neighbors)")
    ("confidence", "also write each normal's confidence, from 0 to 1: a PLY property 'confidence', a 7th "
                   "column in .xyz, extra bytes NormalConfidence in .las")
    ("quiet,q", "no progress bar");
  // Replaced by --setting, accepted with a warning for one release.
  po::options_description deprecated("Deprecated options");
  deprecated.add_options()
    ("adaptive", "with a paper setting, its adaptive Hough transform without least squares (use --setting)")
    ("least-squares-first", "with a paper setting, its least squares first (use --setting)");
  po::options_description hidden;
  hidden.add_options()("input", po::value<std::string>())("output", po::value<std::string>());
  po::options_description all;
  all.add(described).add(deprecated).add(hidden);
  po::positional_options_description positional;
  positional.add("input", 1).add("output", 1);

  const std::string usage = "Usage: rrht_normals INPUT [OUTPUT] [options]\n"
                            "Estimates normals with the Robust Randomized Hough Transform (Boulch and Marlet 2012).\n"
                            "INPUT: " + one_of(input_extensions) + "; OUTPUT: " + one_of(output_extensions) +
                            " with normals (default: INPUT's name + _normals.xyz, or\n"
                            "_normals.las for a LAS input, in the current folder). A LAS output keeps every record\n"
                            "of its LAS input and adds the normal as extra bytes NormalX, NormalY, NormalZ.\n"
                            "A failed run leaves OUTPUT as it was.\n";

  po::variables_map options;
  Progress_bar bar(false);
  const std::function<bool(double)> callback = [&bar](double advancement) { return bar(advancement); };
  std::function<void(std::vector<Point_with_normal>&)> estimate;
  std::string input, output;
  try
  {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), options);
    po::notify(options);
    if(options.count("help"))
    {
      std::cout << usage << "\n" << described << "\n" << deprecated << std::endl;
      return EXIT_SUCCESS;
    }
    if(!options.count("input"))
      throw po::error("no input file");
    check_range(options, "neighbors", 0, 4294967295LL); // k is an unsigned int
    check_range(options, "seed", 0, 4294967295LL);      // so is the seed
    check_range(options, "threads", 0, 1024);
    check_range(options, "precision", 1, 17);
    input = options["input"].as<std::string>();
    const bool las_input = has_extension(input, las_extensions);
    if(options.count("orient"))
      check_orientation(options["orient"].as<std::string>(), las_input);
    output = options.count("output") ? options["output"].as<std::string>()
                                     : fs::path(input).stem().string() + (las_input ? "_normals.las" : "_normals.xyz");
    if(!has_extension(input, input_extensions) && !las_input)
      throw po::error("cannot read '" + input + "': the input must be " + one_of(input_extensions));
    if(!has_extension(output, output_extensions))
      throw po::error("cannot write '" + output + "': the output must be " + one_of(output_extensions));
    if(has_extension(output, { ".las" }) && !las_input)
      throw po::error("a .las output needs a .las input, whose point records it keeps");
    if(options.count("confidence") && has_extension(output, { ".pwn" }))
      throw po::error("--confidence needs a .ply or .xyz output: .pwn holds points and normals only");

    const unsigned int k = static_cast<unsigned int>(options["neighbors"].as<long long>());
    // The setting gives the defaults of the options below; an option given
    // on the command line wins.
    const CGAL::RRHT::Setting setting = choice(options, "setting", CGAL::RRHT::setting_names);
    const bool paper = setting != CGAL::RRHT::Setting::DEFAULT, fast = setting == CGAL::RRHT::Setting::PAPER_FAST;
    for(const char* name : { "adaptive", "least-squares-first" })
      if(options.count(name))
        std::cerr << "rrht_normals: warning: --" << name << " is deprecated and will be removed: use --setting"
                  << std::endl;
    // 0 planes: the setting's default, the library's.
    const long long planes = options["planes"].as<long long>();
    const long long rotations = fast && options["rotations"].defaulted() ? 2 : options["rotations"].as<long long>();
    const auto np = CGAL::RRHT::parameters::point_map(Point_map())
                      .normal_map(Normal_map())
                      .neighbor_radius(options["radius"].as<double>())
                      .number_of_rotations(rotations)
                      .accumulator_slices(options["slices"].as<long long>())
                      .use_confidence_interval(options.count("no-confidence-interval") == 0)
                      .setting(setting)
                      // The deprecated switches: both on with the default setting.
                      .least_squares_first(!paper || options.count("least-squares-first") > 0)
                      .adaptive(!paper || options.count("adaptive") > 0)
                      .refit(options.count("refit") > 0)
                      .sampling(choice(options, "sampling", CGAL::RRHT::sampling_names))
                      .presampling_factor(options["presampling"].as<long long>())
                      .aggregation(choice(options, "aggregation", CGAL::RRHT::aggregation_names))
                      .cluster_angle(options["cluster-angle"].as<double>())
                      .random_seed(static_cast<unsigned int>(options["seed"].as<long long>()))
                      .callback(callback);
    // The estimation with the parameters of the command line, run once on no
    // point before the input is read: CGAL::rrht_estimate_normals() checks
    // its parameters before it looks at the points, so that a value out of
    // its ranges is a usage error, with the library's own message. The
    // confidence map is passed only when the confidences are written: with
    // one, the default also votes where it keeps a quadric.
    const bool confidence = options.count("confidence") > 0;
    estimate = [k, planes, confidence, np](std::vector<Point_with_normal>& points) {
      auto run = [&](const auto& parameters) {
        if(planes != 0)
          CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(points, k, parameters.number_of_planes(planes));
        else
          CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(points, k, parameters);
      };
      if(confidence)
        run(np.confidence_map(Confidence_map()));
      else
        run(np);
    };
    std::vector<Point_with_normal> no_point;
    estimate(no_point);
  }
  catch(const std::logic_error& e) // po::error, or std::invalid_argument from the library
  {
    std::cerr << "rrht_normals: " << e.what() << "\n" << usage << "Try 'rrht_normals --help'." << std::endl;
    return usage_error;
  }

  // Read.
  if(!std::ifstream(input))
  {
    std::cerr << "rrht_normals: cannot open '" << input << "'" << std::endl;
    return runtime_error;
  }
  if(boost::algorithm::iequals(fs::path(input).extension().string(), ".ply"))
  {
    const std::string damage = damaged_ply_header(input);
    if(!damage.empty())
    {
      std::cerr << "rrht_normals: cannot read points from '" << input << "' (malformed file: " << damage << ")"
                << std::endl;
      return runtime_error;
    }
  }
  std::vector<Point_with_normal> points;
  std::optional<CGAL::RRHT::IO::LAS_file> las;
  const std::string how = options.count("orient") ? options["orient"].as<std::string>() : std::string();
  std::vector<double> scanners; // x y z per record, for --orient=viewpoint:NAME,NAME,NAME
  if(has_extension(input, las_extensions))
  {
    try
    {
      las.emplace(input);
      std::vector<double> xyz;
      const std::uint64_t chunk = 1 << 20;
      points.reserve(std::size_t(las->size()));
      for(std::uint64_t first = 0; first < las->size(); first += chunk)
      {
        const std::uint64_t count = (std::min)(chunk, las->size() - first);
        xyz.resize(std::size_t(3 * count));
        las->read_points(first, count, xyz.data());
        for(std::size_t i = 0; i < count; ++i)
          points.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), CGAL::NULL_VECTOR, 0.,
                              std::size_t(first + i));
      }
      const std::vector<std::string> fields = viewpoint_fields(how);
      if(!fields.empty())
      {
        std::vector<double> values(std::size_t(las->size()));
        scanners.resize(3 * values.size());
        for(std::size_t axis = 0; axis < 3; ++axis)
        {
          las->read_field(fields[axis], 0, las->size(), values.data());
          for(std::size_t i = 0; i < values.size(); ++i)
            scanners[3 * i + axis] = values[i];
        }
      }
    }
    catch(const CGAL::RRHT::IO::LAS_error& e)
    {
      std::cerr << "rrht_normals: " << e.what() << std::endl;
      return runtime_error;
    }
  }
  else if(!CGAL::IO::read_points(input, std::back_inserter(points), CGAL::parameters::point_map(Point_map())))
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
  bar = Progress_bar(!options.count("quiet") && ::isatty(STDERR_FILENO)); // its clock starts now
  CGAL::Real_timer timer;
  timer.start();
  try
  {
    estimate(points);
  }
  catch(const std::exception& e)
  {
    bar.finish();
    std::cerr << "rrht_normals: " << e.what() << std::endl;
    return runtime_error;
  }
  bar.finish();
  if(!how.empty())
    orient(points, how, scanners);
  timer.stop();

  std::size_t without_normal = 0;
  for(const Point_with_normal& pn : points)
    without_normal += (std::get<1>(pn) == CGAL::NULL_VECTOR);

  // Write.
  if(has_extension(output, { ".las" }))
  {
    std::vector<double> normals(3 * points.size()), confidences(points.size());
    for(const Point_with_normal& p : points)
    {
      const std::size_t i = std::get<3>(p);
      const Vector& n = std::get<1>(p);
      normals[3 * i] = n.x(), normals[3 * i + 1] = n.y(), normals[3 * i + 2] = n.z();
      confidences[i] = std::get<2>(p);
    }
    try
    {
      CGAL::RRHT::IO::write_LAS_with_normals(*las, output, normals.data(),
                                             options.count("confidence") ? confidences.data() : nullptr);
    }
    catch(const CGAL::RRHT::IO::LAS_error& e)
    {
      std::cerr << "rrht_normals: cannot write '" << output << "': " << e.what() << std::endl;
      return runtime_error;
    }
  }
  else if(!write_atomically(output, points, int(options["precision"].as<long long>()),
                            options.count("confidence") > 0))
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
