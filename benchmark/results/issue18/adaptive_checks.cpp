#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/Real_timer.h>
#include "shapes.h"
#include "confidence_measures.h"
#include <cstdio>
using namespace rrht_test;
namespace params = CGAL::RRHT::parameters;
int main(int argc, char** argv)
{
  std::string which = argv[1];
  std::size_t n = 100000;
  Cloud cloud;
  unsigned seed = 1;
  if(which == "cube") { cloud = cube(n, 1); seed = 1; }
  else if(which == "cylinder") { cloud = closed_cylinder(n, 2); seed = 2; }
  else if(which == "corner") { cloud = anisotropic_corner(n, 12); seed = 12; }
  else if(which == "sphere") { cloud = sphere(n, 5); seed = 5; }
  else { sample_mesh(std::string(getenv("RRHT_DATA") ? getenv("RRHT_DATA") : "../shared/data") + "/meshes/" + which + ".off", n, 3, cloud); seed = 3; }
  std::vector<bool> near = near_sharp_edges(cloud, 0.01 * bounding_box_diagonal(cloud));
  add_noise(cloud, argc > 2 ? atof(argv[2]) : 0.2, seed + 1000);
  const auto maps = params::point_map(Point_of_sample()).normal_map(Normal_of_sample()).confidence_map(Confidence_of_sample());
  auto run = [&](const char* name, auto f) {
    Cloud c = cloud; CGAL::Real_timer t; t.start(); f(c); t.stop();
    std::size_t bad = 0, badnear = 0, nn = 0;
    for(std::size_t i = 0; i < c.size(); ++i) { bool b = angle_error(c[i]) > 10; bad += b; if(near[i]) { ++nn; badnear += b; } }
    std::printf("%-9s %-10s %6.3f s  >10 %.2f%%  near %.2f%%\n", which.c_str(), name, t.time(), 100. * bad / c.size(), 100. * badnear / nn);
  };
  if(!getenv("ONLY")) run("jet", [&](Cloud& c) { CGAL::jet_estimate_normals<CGAL::Parallel_tag>(c, 80, params::point_map(Point_of_sample()).normal_map(Normal_of_sample())); });
  if(!getenv("ONLY")) run("fast", [&](Cloud& c) { CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(c, 100, maps.number_of_planes(300).number_of_rotations(2)); });
  if(!getenv("ONLY")) run("precise", [&](Cloud& c) { CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(c, 100, maps); });
  if(!getenv("ONLY") && !getenv("NOCUBES")) run("cubes", [&](Cloud& c) { CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(c, 100, maps.sampling(CGAL::RRHT::Sampling::CUBES)); });
  run("adaptive", [&](Cloud& c) { CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(c, 100, maps.adaptive(true)); });
}
