// Prototype: a gated robust plane refit of the RRHT normal on its own neighborhood.
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/jet_estimate_normals.h>
#include "shapes.h"
#include "confidence_measures.h"
#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>
#include <tbb/enumerable_thread_specific.h>
#include <cstdio>
using namespace rrht_test;
using namespace CGAL::RRHT::internal;
namespace params = CGAL::RRHT::parameters;
static double ang(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{ return std::acos(std::min(1., std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI; }
static double median(std::vector<double> v) { std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end()); return v[v.size() / 2]; }

int main(int argc, char** argv)
{
  std::string which = argv[1];
  double noise = argc > 2 ? atof(argv[2]) : 0.2;
  double min_inliers = getenv("FRAC") ? atof(getenv("FRAC")) : 0.9;
  double kappa = getenv("KAPPA") ? atof(getenv("KAPPA")) : 2.5;
  double maxang = getenv("MAXANG") ? atof(getenv("MAXANG")) : 10;
  std::size_t n = 100000;
  Cloud cloud; unsigned seed = 1;
  if(which == "cube") cloud = cube(n, 1);
  else if(which == "cylinder") { cloud = closed_cylinder(n, 2); seed = 2; }
  else if(which == "corner") { cloud = anisotropic_corner(n, 12); seed = 12; }
  else if(which == "sphere") { cloud = sphere(n, 5); seed = 5; }
  else { sample_mesh(std::string(getenv("RRHT_DATA") ? getenv("RRHT_DATA") : "../shared/data") + "/meshes/" + which + ".off", n, 3, cloud); seed = 3; }
  add_noise(cloud, noise, seed + 1000);
  Cloud r = cloud, j = cloud;
  CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(r, 100, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
  CGAL::jet_estimate_normals<CGAL::Parallel_tag>(j, 80, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
  std::vector<Neighbor_search::Indexed_point> pts;
  for(auto& s : cloud) pts.emplace_back(Neighbor_search::Point(s.point.x(), s.point.y(), s.point.z()), pts.size());
  Neighbor_search search(std::move(pts), CGAL::Parallel_tag());
  std::vector<double> er(cloud.size()), ef(cloud.size()), ej(cloud.size());
  std::vector<int> used(cloud.size());
  struct S { Neighbor_search::Scratch s; Neighborhood nb; std::vector<double> d; };
  tbb::enumerable_thread_specific<S> tls;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, search.size()), [&](const tbb::blocked_range<std::size_t>& R) {
    S& sc = tls.local();
    for(std::size_t i = R.begin(); i < R.end(); ++i)
    {
      std::size_t idx = search.input_index(i);
      search.find(i, 100, 0, sc.nb, sc.s);
      const auto& P = sc.nb.points;
      Eigen::Vector3d n0(r[idx].normal.x(), r[idx].normal.y(), r[idx].normal.z());
      Eigen::Vector3d t(cloud[idx].truth.x(), cloud[idx].truth.y(), cloud[idx].truth.z());
      er[idx] = ang(n0, t); ef[idx] = er[idx]; ej[idx] = angle_error(j[idx]);
      Eigen::Vector3d nn = n0; bool ok = true; std::size_t cnt = 0; bool own = true;
      Eigen::Vector3d m = Eigen::Vector3d::Zero(); // the plane passes through m; first through the query point
      double tau = 0;
      for(int it = 0; it < 3 && ok; ++it)
      {
        std::vector<double> dev(P.size());
        for(std::size_t q = 0; q < P.size(); ++q) dev[q] = std::abs(nn.dot(P[q] - m));
        std::vector<double> sorted = dev;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 4, sorted.end());
        const double s = sorted[sorted.size() / 4] / 0.3186; // robust sigma from the nearest quarter
        tau = std::max(kappa * s, 1e-12 * sc.nb.radius);
        Eigen::Vector3d mm = Eigen::Vector3d::Zero(); cnt = 0;
        for(std::size_t q = 0; q < P.size(); ++q) if(dev[q] <= tau) { mm += P[q]; ++cnt; }
        if(cnt < 6) { ok = false; break; }
        mm /= double(cnt);
        Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
        for(std::size_t q = 0; q < P.size(); ++q) if(dev[q] <= tau) { Eigen::Vector3d v = P[q] - mm; C += v * v.transpose(); }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
        nn = es.eigenvectors().col(0);
        m = mm;
        own = std::abs(nn.dot(m)) <= (getenv("OWNK") ? atof(getenv("OWNK")) : 1.0) * tau;
      }
      if(ok && own && double(cnt) / P.size() >= min_inliers && ang(nn, n0) <= maxang) { ef[idx] = ang(nn, t); used[idx] = 1; }
    }
  });
  if(getenv("DIAG")) { int shown = 0; for(std::size_t i = 0; i < er.size() && shown < 15; ++i) if(ef[i] > 10 && er[i] <= 10) { std::printf("  worse: rrht %.1f refit %.1f jet %.1f at (%.3f %.3f %.3f)\n", er[i], ef[i], ej[i], cloud[i].point.x(), cloud[i].point.y(), cloud[i].point.z()); ++shown; }
    std::size_t w = 0, b = 0; for(std::size_t i = 0; i < er.size(); ++i) { w += ef[i] > 10 && er[i] <= 10; b += ef[i] <= 10 && er[i] > 10; } std::printf("  worse %zu better %zu\n", w, b); }
  auto stats = [&](const char* name, const std::vector<double>& e) {
    double s = 0, a = 0; for(double x : e) { s += x * x; a += x > 10; }
    std::printf("  %-8s >10 %6.2f%%  RMS %6.2f\n", name, 100 * a / e.size(), std::sqrt(s / e.size()));
  };
  std::size_t u = 0; for(int x : used) u += x;
  std::printf("%s noise %.2f: refit used on %.1f%%\n", which.c_str(), noise, 100. * u / used.size());
  stats("rrht", er); stats("refit", ef); stats("jet", ej);
}
