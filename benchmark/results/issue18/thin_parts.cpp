// Thin parts: a thin box (plate) and a bent sheet, both sides sampled, 0.2% noise.
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/jet_estimate_normals.h>
#include "shapes.h"
#include <cstdio>
using namespace rrht_test;
namespace params = CGAL::RRHT::parameters;

// thin_box() and bent_sheet() are in test/shapes.h.
int main(int argc, char** argv)
{
  std::string which = argv[1];
  double tp = atof(argv[2]); // thickness, % of the diagonal
  std::size_t n = 100000;
  Cloud c;
  if(which == "box") { double diag = std::sqrt(8.); c = thin_box(n, tp / 100 * diag, 1); }
  else { double diag = std::sqrt(1 + 1 + 4.); c = bent_sheet(n, tp / 100 * diag, 2); }
  add_noise(c, 0.2, 7);
  const auto maps = params::point_map(Point_of_sample()).normal_map(Normal_of_sample()).confidence_map(Confidence_of_sample());
  auto report = [&](const char* name, const Cloud& r) {
    Errors e = errors(r);
    std::printf("%s t=%.1f%% %-10s >10 %6.2f%%  RMS %6.2f\n", which.c_str(), tp, name, 100 * e.share_above, e.rms);
  };
  for(unsigned k : { 30u, 100u })
  {
    Cloud r = c, j = c;
    CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(r, k, maps);
    CGAL::jet_estimate_normals<CGAL::Parallel_tag>(j, k, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
    std::string a = "rrht_K" + std::to_string(k), b = "jet_K" + std::to_string(k);
    report(a.c_str(), r); report(b.c_str(), j);
    if(getenv("HIST")) { int h[10] = {0}; for(auto& s : r) h[std::min(9, int(angle_error(s) / 5))]++; std::printf("   rrht error histogram (5 deg bins):"); for(int q = 0; q < 10; ++q) std::printf(" %d", h[q]); std::printf("\n");
      int g[10] = {0}; for(auto& s : j) g[std::min(9, int(angle_error(s) / 5))]++; std::printf("   jet  error histogram (5 deg bins):"); for(int q = 0; q < 10; ++q) std::printf(" %d", g[q]); std::printf("\n"); }
  }
}
