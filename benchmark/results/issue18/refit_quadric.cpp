// Prototype of refit(true) (issue 18, sections 3 and 4): a gated robust
// quadric refit of the RRHT normal (defaults, k = K) on its inliers, against
// jet fitting (K = KJ). Knobs (environment), defaults first:
//   KAPPA=2.5    band, in noise deviations
//   OUT=0.05     largest share of neighbors outside the band
//   SLACK=0      outliers allowed beyond OUT, in points
//   MAXANG=10    largest turn of the normal (degrees); refit(true) uses 20
//   ITERS=3      fits per point
//   QUAD=1       quadric (0: plane)
//   FLOOR=1e-9   smallest band, over the radius; refit(true) uses 0.01
//   MODE=0       noise: 0 the point's own (nearest quarter of its residuals),
//                1 the QQ-th percentile (QQ=50) of its neighbors' own; refit(true): MODE=1 QQ=25
//   SIG=         fixed noise deviation, as a share of the diagonal (an oracle)
//   FRAMES=1     fits in the frame of the previous fit's normal
//   CONF=0       refit only where the RRHT confidence is at least this
//   K=100 KJ=80 T=0.5 (thickness of box and sheet, % of the diagonal)
//   HIST=1 histograms of the errors in 10-degree steps (RRHT, refit, jet); DIAG=1 the cube's points made worse
// Usage: rq CLOUD NOISE_PERCENT, CLOUD one of sphere cube cylinder corner box
// sheet kitten bunny100k fandisk100k cube100k or a mesh of ../shared/data/meshes.
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/jet_estimate_normals.h>
#include "shapes.h"
#include <Eigen/Dense>
#include <tbb/parallel_for.h>
#include <tbb/enumerable_thread_specific.h>
#include <cstdio>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/property_map.h>
#include <fstream>
using namespace rrht_test;
using namespace CGAL::RRHT::internal;
namespace params = CGAL::RRHT::parameters;
static double ang(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{ return std::acos(std::min(1., std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI; }
static double env(const char* n, double d) { return getenv(n) ? atof(getenv(n)) : d; }

static bool load_points(const std::string& xyz, const std::string& normals, Cloud& c)
{
  std::ifstream in(xyz), nin(normals);
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream f(line); double x, y, z, a, b, d;
    if(!(f >> x >> y >> z)) continue;
    if(normals.empty()) { if(!(f >> a >> b >> d)) return false; }
    else if(!(nin >> a >> b >> d)) return false;
    Sample s; s.point = Point(x, y, z); s.truth = Vector(a, b, d); c.push_back(s);
  }
  return !c.empty();
}

int main(int argc, char** argv)
{
  std::string which = argv[1];
  double noise = argc > 2 ? atof(argv[2]) : 0.2;
  const unsigned k = unsigned(env("K", 100)), kj = unsigned(env("KJ", 80));
  const double kappa = env("KAPPA", 2.5), max_out = env("OUT", 0.05), maxang = env("MAXANG", 10), minconf = env("CONF", 0);
  const int iters = int(env("ITERS", 3)); const bool quad = env("QUAD", 1) != 0;
  std::string data = getenv("RRHT_DATA") ? getenv("RRHT_DATA") : "../shared/data";
  std::size_t n = 100000;
  Cloud cloud; unsigned seed = 1;
  if(which == "cube") cloud = cube(n, 1);
  else if(which == "cylinder") { cloud = closed_cylinder(n, 2); seed = 2; }
  else if(which == "corner") { cloud = anisotropic_corner(n, 12); seed = 12; }
  else if(which == "sphere") { cloud = sphere(n, 5); seed = 5; }
  else if(which == "box") { cloud = thin_box(n, env("T", 0.5) / 100 * std::sqrt(8.), 1); }
  else if(which == "sheet") { cloud = bent_sheet(n, env("T", 0.5) / 100 * std::sqrt(6.), 2); }
  else if(which == "kitten") { load_points(data + "/points/kitten.xyz", "", cloud); }
  else if(which.find("100k") != std::string::npos) { load_points(data + "/points/" + which + ".xyz", data + "/points/" + which + ".normals", cloud); }
  else { sample_mesh(data + "/meshes/" + which + ".off", n, 3, cloud); seed = 3; }
  if(noise > 0) add_noise(cloud, noise, seed + 1000);
  const double diag = bounding_box_diagonal(cloud);
  Cloud r = cloud, j = cloud;
  CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(r, k, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()).confidence_map(Confidence_of_sample()));
  CGAL::jet_estimate_normals<CGAL::Parallel_tag>(j, kj, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
  typedef CGAL::Simple_cartesian<double>::Point_3 P3;
  std::vector<P3> pp; for(auto& s : cloud) pp.emplace_back(s.point.x(), s.point.y(), s.point.z());
  typedef CGAL::Pointer_property_map<P3>::type Ppmap;
  typedef CGAL::Search_traits_adapter<std::size_t, Ppmap, CGAL::Search_traits_3<CGAL::Simple_cartesian<double> > > Tr;
  typedef CGAL::Orthogonal_k_neighbor_search<Tr> KNN;
  Ppmap pm = CGAL::make_property_map(pp);
  KNN::Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(pp.size()), KNN::Tree::Splitter(), Tr(pm));
  tree.build();
  const std::size_t N = pp.size();
  std::vector<std::uint32_t> nbr(N * (k + 1)); std::vector<double> radius(N);
  tbb::parallel_for(std::size_t(0), N, [&](std::size_t i) {
    KNN search(tree, pp[i], k + 1, 0, true, KNN::Distance(pm)); std::size_t c = 0; double far = 0;
    for(auto x : search) { nbr[i * (k + 1) + c++] = std::uint32_t(x.first); far = std::max(far, x.second); }
    radius[i] = std::sqrt(far); });
  std::vector<double> er(cloud.size()), ef(cloud.size()), ej(cloud.size()), sig(N, 0);
  std::vector<int> used(cloud.size());
  struct S { std::vector<Eigen::Vector3d> P; std::vector<double> res, sorted, ss; std::vector<char> in; };
  tbb::enumerable_thread_specific<S> tls;
  const int mode2 = int(env("MODE", 0)); // 0: local sigma; 1: median of the neighbors' local sigmas
  for(int pass = 0; pass < (mode2 ? 2 : 1); ++pass)
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N), [&](const tbb::blocked_range<std::size_t>& R) {
    S& sc = tls.local();
    for(std::size_t i = R.begin(); i < R.end(); ++i)
    {
      std::size_t idx = i;
      Eigen::Vector3d n0(r[idx].normal.x(), r[idx].normal.y(), r[idx].normal.z());
      Eigen::Vector3d t(cloud[idx].truth.x(), cloud[idx].truth.y(), cloud[idx].truth.z());
      er[idx] = ang(n0, t); ef[idx] = er[idx]; ej[idx] = angle_error(j[idx]); used[idx] = 0;
      if(r[idx].confidence < minconf || n0.squaredNorm() == 0) continue;
      sc.P.clear(); for(std::size_t c = 0; c <= k; ++c) { const P3& q = pp[nbr[i * (k + 1) + c]]; sc.P.emplace_back(q.x() - pp[i].x(), q.y() - pp[i].y(), q.z() - pp[i].z()); }
      const auto& P = sc.P;
      const double rad = radius[i];
      double sfix = -1;
      if(pass == 1) { sc.ss.clear(); for(std::size_t c = 0; c <= k; ++c) sc.ss.push_back(sig[nbr[i * (k + 1) + c]]); std::nth_element(sc.ss.begin(), sc.ss.begin() + sc.ss.size() * int(env("QQ", 50)) / 100, sc.ss.end()); sfix = sc.ss[sc.ss.size() * int(env("QQ", 50)) / 100]; }
      n0.normalize();
      const Eigen::Vector3d n_rrht = n0;
      for(int frame = 0; frame < int(env("FRAMES", 1)); ++frame) {
      Eigen::Vector3d u = n0.unitOrthogonal(), v = n0.cross(u);
      const std::size_t m = P.size();
      sc.res.resize(m); sc.in.assign(m, 0);
      for(std::size_t q = 0; q < m; ++q) sc.res[q] = n0.dot(P[q]);
      Eigen::Matrix<double, 6, 1> a = Eigen::Matrix<double, 6, 1>::Zero();
      bool ok = true; std::size_t cnt = 0; double tau = 0;
      for(int it = 0; it < iters && ok; ++it)
      {
        sc.sorted.resize(m);
        for(std::size_t q = 0; q < m; ++q) sc.sorted[q] = std::abs(sc.res[q]);
        std::nth_element(sc.sorted.begin(), sc.sorted.begin() + m / 4, sc.sorted.end());
        const double s = sfix >= 0 ? sfix : getenv("SIG") ? atof(getenv("SIG")) * diag : sc.sorted[m / 4] / 0.3186;
        if(pass == 0 && it == iters - 1) sig[i] = s; // robust sigma from the nearest quarter
        tau = std::max(kappa * s, env("FLOOR", 1e-9) * rad);
        Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
        cnt = 0;
        for(std::size_t q = 0; q < m; ++q)
        {
          sc.in[q] = std::abs(sc.res[q]) <= tau;
          if(!sc.in[q]) continue;
          const double x = u.dot(P[q]) / rad, y = v.dot(P[q]) / rad, h = n0.dot(P[q]) / rad;
          Eigen::Matrix<double, 6, 1> f; f << 1, x, y, quad ? x * x : 0, quad ? x * y : 0, quad ? y * y : 0;
          A.selfadjointView<Eigen::Lower>().rankUpdate(f);
          b += h * f;
          ++cnt;
        }
        if(cnt < 10) { ok = false; break; }
        if(!quad) for(int d = 3; d < 6; ++d) A(d, d) = 1;
        a = A.selfadjointView<Eigen::Lower>().ldlt().solve(b);
        if(!a.allFinite()) { ok = false; break; }
        for(std::size_t q = 0; q < m; ++q)
        {
          const double x = u.dot(P[q]) / rad, y = v.dot(P[q]) / rad, h = n0.dot(P[q]) / rad;
          sc.res[q] = rad * (h - (a[0] + a[1] * x + a[2] * y + a[3] * x * x + a[4] * x * y + a[5] * y * y));
        }
      }
      if(!ok) break;
      Eigen::Vector3d nn = (n0 - a[1] * u - a[2] * v).normalized();
      if(frame + 1 < int(env("FRAMES", 1))) { n0 = nn; continue; }
      n0 = n_rrht;
      const double out = 1 - double(cnt) / m;
      if(out * m <= max_out * m + env("SLACK", 0) && std::abs(a[0] * rad) <= tau && ang(nn, n0) <= maxang) { ef[idx] = ang(nn, t); used[idx] = 1;
        if(getenv("DIAG") && which == "cube" && ef[idx] > 10 && er[idx] <= 10) {
          double c[3] = {cloud[idx].point.x(), cloud[idx].point.y(), cloud[idx].point.z()}; int f = 0; for(int d = 1; d < 3; ++d) if(std::abs(c[d]) > std::abs(c[f])) f = d;
          double de = 1e9; for(int d = 0; d < 3; ++d) if(d != f) de = std::min(de, 1 - std::abs(c[d]));
          std::printf("  worse: edge %.2f r, out %.3f, moved %.1f, rrht %.1f refit %.1f, tau/r %.3f, a0/tau %.2f, curv %.3f %.3f %.3f conf %.3f\n", de / rad, out, ang(nn, n0), er[idx], ef[idx], tau / rad, a[0] * rad / tau, a[3], a[4], a[5], r[idx].confidence); } }
      }
    }
  });
  if(getenv("DIAG")) { std::size_t w = 0, b = 0; for(std::size_t i = 0; i < er.size(); ++i) { w += ef[i] > 10 && er[i] <= 10; b += ef[i] <= 10 && er[i] > 10; } std::printf("  worse %zu better %zu\n", w, b); }
  auto stats = [&](const char* name, const std::vector<double>& e) {
    double s = 0, a = 0; for(double x : e) { s += x * x; a += x > 10; }
    std::printf(" %s %5.2f%% %5.2f", name, 100 * a / e.size(), std::sqrt(s / e.size()));
  };
  if(getenv("HIST")) for(auto* e : {&er, &ef, &ej}) { int h[9] = {0}; for(double x : *e) h[std::min(8, int(x / 10))]++; for(int q = 0; q < 9; ++q) std::printf(" %6d", h[q]); std::printf("\n"); }
  std::size_t uu = 0; for(int x : used) uu += x;
  std::printf("%-12s %.2f used %5.1f%% |", which.c_str(), noise, 100. * uu / used.size());
  stats("rrht", er); stats("refit", ef); stats("jet", ej); std::printf("\n");
}
