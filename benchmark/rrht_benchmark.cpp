// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The comparison benchmark: RRHT against CGAL's jet fitting, PCA and VCM
// (and PCL and Open3D when found) on the experiments of the paper's
// Section 6 and on real data. Writes one CSV per experiment;
// benchmark/report.py turns them into Markdown tables, plots and renderings.
// See benchmark/README.md.

#include "experiment.h"
#include "paper_experiments.h"
#include "speed_experiment.h"
#include "beyond_the_paper.h"
#include "orientation_experiment.h"

namespace {

typedef void (*Run)(const Config&);
const std::vector<std::pair<std::string, Run> >& experiments()
{
  static const std::vector<std::pair<std::string, Run> > all = {
    { "headline", headline }, { "fig6", fig6 },   { "fig7", fig7 },     { "fig9", fig9 },   { "fig10", fig10 },
    { "fig13", fig13 },       { "fig15", fig15 }, { "meshes", meshes }, { "points", points }, { "scans", scans },
    { "speed", speed },       { "scaling", scaling }, { "confidence", confidence },
    { "adaptive", adaptive }, { "refit", refit },   { "fillets", fillets }, { "least_squares_first", least_squares_first },
    { "orientation", orientation }, { "default", default_targets }, { "threads", threads }
  };
  return all;
}

std::vector<unsigned int> parse_threads(const std::string& list)
{
  std::vector<unsigned int> threads;
  std::stringstream in(list);
  std::string item;
  while(std::getline(in, item, ','))
  {
    const long t = std::stol(item);
    if(t < 1 || t > 1024)
      throw std::invalid_argument("--threads: " + item + " is not a thread count");
    threads.push_back(unsigned(t));
  }
  if(threads.empty())
    throw std::invalid_argument("--threads is empty");
  return threads;
}

} // namespace

int main(int argc, char** argv)
{
  po::options_description options("rrht_benchmark: RRHT against jet fitting, PCA, VCM (and PCL, Open3D)\nOptions");
  options.add_options()
    ("help,h", "this help")
    ("mode", po::value<std::string>()->default_value("quick"), "quick (a few minutes) or full")
    ("only", po::value<std::string>()->default_value(""), "comma-separated experiments (default: all), see --list")
    ("list", "list the experiments")
    ("out", po::value<std::string>()->default_value("benchmark/results/quick"), "folder of the CSV files")
    ("data", po::value<std::string>()->default_value("../shared/data"), "the shared evaluation data")
    ("scratch", po::value<std::string>()->default_value("."), "folder of the per-point error files")
    ("runs", po::value<int>()->default_value(3), "runs per measurement, the median is reported (1 to 16)")
    ("threads", po::value<std::string>()->default_value(""), "thread counts (default: quick 2, full 1,2; headline always 1,2)")
    ("timeout", po::value<unsigned int>()->default_value(3600), "seconds before a measurement is abandoned (0: none)");
  po::variables_map vm;
  Config config;
  std::set<std::string> only;
  try
  {
    po::store(po::parse_command_line(argc, argv, options), vm);
    po::notify(vm);
    if(vm.count("help"))
    {
      std::cout << options << std::endl;
      return 0;
    }
    if(vm.count("list"))
    {
      for(const auto& e : experiments())
        std::cout << e.first << '\n';
      return 0;
    }
    const std::string mode = vm["mode"].as<std::string>();
    if(mode != "quick" && mode != "full")
      throw std::invalid_argument("--mode must be quick or full, not '" + mode + "'");
    config.full = (mode == "full");
    config.runs = vm["runs"].as<int>();
    if(config.runs < 1 || config.runs > 16)
      throw std::invalid_argument("--runs must be between 1 and 16");
    const std::string threads = vm["threads"].as<std::string>();
    config.threads = parse_threads(threads.empty() ? (config.full ? "1,2" : "2") : threads);
    config.headline_threads = parse_threads(threads.empty() ? "1,2" : threads);
    config.timeout = vm["timeout"].as<unsigned int>();
    config.out = vm["out"].as<std::string>();
    config.data = vm["data"].as<std::string>();
    config.scratch = vm["scratch"].as<std::string>();
    std::stringstream list(vm["only"].as<std::string>());
    std::string item;
    while(std::getline(list, item, ','))
    {
      bool known = false;
      for(const auto& e : experiments())
        known = known || e.first == item;
      if(!known)
        throw std::invalid_argument("--only: unknown experiment '" + item + "' (see --list)");
      only.insert(item);
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "rrht_benchmark: " << e.what() << "\n(--help lists the options)" << std::endl;
    return 1;
  }

  std::cout << "mode " << (config.full ? "full" : "quick") << ", " << config.runs << " runs per measurement, data "
            << config.data << (std::ifstream(config.data + "/MANIFEST.md") ? "" : " (absent: its experiments are skipped)")
            << std::endl;
  try
  {
    for(const auto& e : experiments())
      if(only.empty() || only.count(e.first))
        e.second(config);
  }
  catch(const std::exception& e)
  {
    std::cerr << "rrht_benchmark: " << e.what() << std::endl;
    return 2;
  }
  return 0;
}
