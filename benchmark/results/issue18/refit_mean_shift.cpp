// Prototype: mean shift of the voted plane normals around each rotation's winner.
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/jet_estimate_normals.h>
#include "shapes.h"
#include <tbb/parallel_for.h>
#include <tbb/enumerable_thread_specific.h>
#include <cstdio>
using namespace CGAL::RRHT::internal;
using namespace rrht_test;
namespace params = CGAL::RRHT::parameters;
static double ang(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{ return std::acos(std::min(1., std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI; }

// thin_box() and bent_sheet() are in test/shapes.h.
int main(int argc, char** argv)
{
  std::string which = argv[1];
  double noise = argc > 2 ? atof(argv[2]) : 0.2;
  double cone = (getenv("CONE") ? atof(getenv("CONE")) : 8) * M_PI / 180;
  int iters = getenv("ITERS") ? atoi(getenv("ITERS")) : 3;
  std::size_t n = 100000;
  Cloud cloud; unsigned seed = 1;
  if(which == "cube") cloud = cube(n, 1);
  else if(which == "cylinder") { cloud = closed_cylinder(n, 2); seed = 2; }
  else if(which == "corner") { cloud = anisotropic_corner(n, 12); seed = 12; }
  else if(which == "box") cloud = thin_box(n, 0.005 * std::sqrt(8.), 1);
  else if(which == "sheet") cloud = bent_sheet(n, 0.005 * std::sqrt(6.), 2);
  else if(which == "sphere") { cloud = sphere(n, 5); seed = 5; }
  else { sample_mesh(std::string(getenv("RRHT_DATA") ? getenv("RRHT_DATA") : "../shared/data") + "/meshes/" + which + ".off", n, 3, cloud); seed = 3; }
  add_noise(cloud, noise, seed + 1000);
  Cloud j = cloud;
  CGAL::jet_estimate_normals<CGAL::Parallel_tag>(j, 80, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
  std::vector<Neighbor_search::Indexed_point> pts;
  for(auto& s : cloud) pts.emplace_back(Neighbor_search::Point(s.point.x(), s.point.y(), s.point.z()), pts.size());
  Neighbor_search search(std::move(pts), CGAL::Parallel_tag());
  Bin_layout layout(15); Cube_weights cw(1);
  Settings st; st.k = 100; st.neighbor_radius = 0; st.number_of_planes = 691; st.use_confidence_interval = true;
  st.sampling = CGAL::RRHT::Sampling::POINTS; st.presampling_factor = 4; st.number_of_rotations = 5;
  st.aggregation = CGAL::RRHT::Aggregation::CLUSTER; st.cos_cluster_angle = std::cos(M_PI / 4); st.seed = 0;
  std::vector<double> e0(cloud.size()), e1(cloud.size()), ej(cloud.size());
  tbb::enumerable_thread_specific<Scratch> tls([&] { return Scratch(layout, cw, 4); });
  const double cos_cone = std::cos(cone);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, search.size()), [&](const tbb::blocked_range<std::size_t>& R) {
    Scratch& scratch = tls.local();
    std::vector<Eigen::Vector3d> normals;
    std::vector<Candidate_normal> shifted;
    for(std::size_t i = R.begin(); i < R.end(); ++i)
    {
      std::size_t idx = search.input_index(i);
      search.find(i, st.k, 0, scratch.neighborhood, scratch.search);
      auto& P = scratch.neighborhood.points;
      Random rng(0, idx);
      scratch.points.prepare(std::uint32_t(P.size()), st.number_of_planes);
      scratch.candidates.clear(); shifted.clear();
      scratch.rotated.resize(P.size());
      for(unsigned r = 0; r < 5; ++r)
      {
        Eigen::Matrix3d rot = rng.uniform_rotation();
        rotate(P, rot / scratch.neighborhood.radius, scratch.rotated, best_instruction_set());
        // hough_transform, collecting the voted normals
        Accumulator& acc = scratch.accumulator; acc.clear(); scratch.points.start_run();
        std::size_t drawn = 0; bool stop = false; normals.clear();
        while(!stop && drawn < st.number_of_planes)
        {
          const std::size_t batch = acc.number_of_votes() / 2 + 8;
          const std::size_t wanted = std::min({ st.number_of_planes - drawn, scratch.triples.size(), batch });
          const std::size_t got = scratch.points.draw(rng, wanted, scratch.triples.data());
          scratch.planes.compute(scratch.rotated, scratch.triples.data(), got, acc.layout());
          std::size_t looked = acc.vote(scratch.planes, got, [&](unsigned a, unsigned b, std::size_t v) { return stop = confidence_intervals_are_disjoint(a, b, v); });
          for(std::size_t q = 0; q < looked; ++q) if(scratch.planes.bin(q) != Plane_batch::no_plane) normals.push_back(scratch.planes.normal(q));
          drawn += got; stop |= (got < wanted);
        }
        Candidate_normal c{ acc.normal_of_most_voted_bin(), acc.votes_of_most_voted_bin(), acc.number_of_votes() };
        // mean shift in a cone around the winner
        Eigen::Vector3d m = c.normal;
        if(getenv("BINS"))
        {
          // the same over the bins' sums (what the accumulator holds)
          std::vector<Eigen::Vector3d> bs(layout.size(), Eigen::Vector3d::Zero());
          for(const auto& v : normals) { double sg; std::size_t b = layout.bin_and_sign(v.x(), v.y(), v.z(), sg); bs[b] += sg * v; }
          normals.clear();
          for(auto& b : bs) if(b.squaredNorm() > 0) normals.push_back(b);
        }
        for(int it = 0; it < iters && m.squaredNorm() > 0; ++it)
        {
          Eigen::Vector3d sum = Eigen::Vector3d::Zero();
          for(const auto& v : normals) { double d = v.dot(m); if(std::abs(d) >= cos_cone * (getenv("BINS") ? v.norm() : 1.)) { d /= (getenv("BINS") ? v.norm() : 1.); double w = getenv("EPAN") ? (std::abs(d) - cos_cone) / (1 - cos_cone) : 1.; sum += w * (d >= 0 ? v : Eigen::Vector3d(-v)); } }
          if(sum.norm() > 0) m = sum.normalized();
        }
        Candidate_normal s = c; s.normal = rot.transpose() * m;
        c.normal = rot.transpose() * c.normal;
        scratch.candidates.push_back(c); shifted.push_back(s);
      }
      Eigen::Vector3d t(cloud[idx].truth.x(), cloud[idx].truth.y(), cloud[idx].truth.z());
      e0[idx] = ang(aggregate(scratch.candidates, st.aggregation, st.cos_cluster_angle), t);
      e1[idx] = ang(aggregate(shifted, st.aggregation, st.cos_cluster_angle), t);
      ej[idx] = angle_error(j[idx]);
    }
  });
  auto stats = [&](const char* name, const std::vector<double>& e) {
    double s = 0, a = 0; for(double x : e) { s += x * x; a += x > 10; }
    std::printf("  %-8s >10 %6.2f%%  RMS %6.2f\n", name, 100 * a / e.size(), std::sqrt(s / e.size()));
  };
  std::printf("%s noise %.2f cone %.1f iters %d\n", which.c_str(), noise, cone * 180 / M_PI, iters);
  stats("rrht", e0); stats("shifted", e1); stats("jet", ej);
}
