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
// Added in the third session (all off by default, so the runs of refit_quadric.sh are unchanged):
//   MODE=2       noise: the median of all points' own (one value for the cloud);
//   MODE=3       the smaller of that and the QQ-th percentile of the neighbors' own
//   QC=1         factor on the noise of MODE 1 to 3
//   W=0          weights exp(-d^2 / 2 W^2) on the fit, d the distance to the point over the radius (0: none)
//   PCAFRAME=1   first frame: the neighbors' PCA instead of the RRHT normal
//   PCAIN=1      each fit in the frame of the PCA of the points in its band
//   ALLIN=4      if every neighbor lies within ALLIN noise deviations of the fit, the normal of
//                a quadric on all of them in the frame of their PCA (jet fitting's normal)
//   ALLIN2=1     ALLIN's quadric fitted once more in the frame of its normal
//   ALLINTURN=MAXANG  the largest turn where ALLIN applies
//   KURT=2       ... and only if the kurtosis of their residuals is at least this
//   KURTALL=2    keep the RRHT normal where the kurtosis of the residuals is below this
//   KAVG=1       for KURT and KURTALL, the median of the neighbors' kurtosis (first pass, MODE=1)
//   PLANES=300 ROT=2  the RRHT normals of another setting (here the paper's fast one)
//   SPLIT=1      errors of the points refitted and kept apart; RIM=1 the box's points above 10 degrees
//                by distance to its rim; CONSIST=1 errors where the given normals agree (clean point sets)
// Added in the fourth session (off by default):
//   TWOSHEET=1   where the refit is not kept, two parallel sheets (a thin part): the heights split in
//                two by 1D 2-means, one quadric with one more constant for the other sheet, its frame
//                iterated ITERS times, kept under the refit's gate (band, outliers, turn)
//   MINSIDE=0.05 the smaller sheet holds at least this share of the points; OFFC=1 the other sheet's
//                center lies within this many radii of the point, in the plane
//   PARA=90      the planes of the two sheets apart (PCA) are within this angle (degrees) of the fit
//   TWOQUAD=0    two parallel planes instead of quadrics; TWOBAND=1 after the first fit, fit only the
//                points within the band; TWOITERS=ITERS fits; TWOTLS=1 two parallel planes by total
//                least squares (the normal of the sheets' scatter about their own centers)
//   TWOFIRST=G   the two sheets tried before the refit, kept where their gap is at least G noise deviations
//                (OWNSPREAD=1: G deviations of the residuals of the two-sheet fit in its band);
//                GAPBAND=0 and at least this many bands; RING=R the other sheet's mean squared distance
//                along the sheets at most R times the point's sheet's (not a ring around a cap)
//   LIB=1        also the library's refit(true)
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
#include <atomic>
using namespace rrht_test;
using namespace CGAL::RRHT::internal;
namespace params = CGAL::RRHT::parameters;
static double ang(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{ return std::acos(std::min(1., std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI; }
static double env(const char* n, double d) { return getenv(n) ? atof(getenv(n)) : d; }
static Eigen::Vector3d eig(const Vector& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }
// The kurtosis of the residuals r: 3 for noise, less for two sides d deviations
// apart (3 - 2 (d/2)^4 / (1 + (d/2)^2)^2: 2.26 for d = 2.5, 1.51 for d = 5).
static double kurtosis(const std::vector<double>& r)
{
  double mean = 0, m2 = 0, m4 = 0; for(double x : r) mean += x; mean /= double(r.size());
  for(double x : r) { const double d2 = (x - mean) * (x - mean); m2 += d2; m4 += d2 * d2; }
  return m4 * double(r.size()) / (m2 * m2);
}
// The least-squares quadric height field h = a0 + a1 x + a2 y + a3 x^2 + a4 x y + a5 y^2
// (a plane if !quad) in the frame (u, v, n), lengths over rad, of the points P[q] with
// weight(q, x, y) > 0; count: how many.
template <class Weight>
static Eigen::Matrix<double, 6, 1> fit_quadric(const std::vector<Eigen::Vector3d>& P, const Eigen::Vector3d& n, const Eigen::Vector3d& u,
                                               const Eigen::Vector3d& v, double rad, bool quad, std::size_t& count, Weight weight)
{
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
  count = 0;
  for(std::size_t q = 0; q < P.size(); ++q)
  {
    const double x = u.dot(P[q]) / rad, y = v.dot(P[q]) / rad, h = n.dot(P[q]) / rad, w = weight(q, x, y);
    if(w <= 0) continue;
    Eigen::Matrix<double, 6, 1> f; f << 1, x, y, quad ? x * x : 0, quad ? x * y : 0, quad ? y * y : 0;
    A.selfadjointView<Eigen::Lower>().rankUpdate(f, w);
    b += w * h * f;
    ++count;
  }
  if(!quad) for(int d = 3; d < 6; ++d) A(d, d) = 1;
  return A.selfadjointView<Eigen::Lower>().ldlt().solve(b);
}
// The normal of the least-squares plane of the points P[q] with keep(q) (their PCA).
template <class Keep> static Eigen::Vector3d pca_normal(const std::vector<Eigen::Vector3d>& P, Keep keep)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero(); std::size_t n = 0;
  for(std::size_t q = 0; q < P.size(); ++q) if(keep(q)) { c += P[q]; ++n; }
  c /= double(n);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for(std::size_t q = 0; q < P.size(); ++q) if(keep(q)) C += (P[q] - c) * (P[q] - c).transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvectors().col(0);
}

// The normal of two parallel sheets through the points P (the point at the origin), from the frame
// of n: the heights split by 1D 2-means, then h = a0 + b s + quadric(x, y), s = 1 on the sheet
// without the point; iters times. Returns the outliers beyond tau, |a0|, the points of the
// smaller sheet and the gap b (lengths).
struct Two_sheets { Eigen::Vector3d normal; std::size_t outliers = 0, smaller = 0; double a0 = 0, gap = 0, off_center = 0, parallel = 90, spread = 0, ring = 0; bool ok = false; };
static Two_sheets two_sheet_fit(const std::vector<Eigen::Vector3d>& P, Eigen::Vector3d n, double rad, double tau, int iters,
                                bool quadric, bool robust, bool tls)
{
  Two_sheets t; const std::size_t m = P.size();
  std::vector<double> h(m), sorted(m), residual(m, 0); std::vector<int> side(m);
  Eigen::Matrix<double, 7, 1> a = Eigen::Matrix<double, 7, 1>::Zero();
  Eigen::Vector3d u, v;
  for(int it = 0; it < iters; ++it)
  {
    u = n.unitOrthogonal(); v = n.cross(u);
    for(std::size_t q = 0; q < m; ++q) h[q] = n.dot(P[q]) / rad;
    sorted = h; std::sort(sorted.begin(), sorted.end());
    double total = 0, total2 = 0; for(double x : sorted) { total += x; total2 += x * x; }
    double best = 1e300, threshold = 0, left = 0, left2 = 0;
    for(std::size_t c = 1; c < m; ++c) // the split before sorted[c]
    {
      left += sorted[c - 1]; left2 += sorted[c - 1] * sorted[c - 1];
      const double nl = double(c), nr = double(m - c);
      const double ss = left2 - left * left / nl + (total2 - left2) - (total - left) * (total - left) / nr;
      if(ss < best) { best = ss; threshold = 0.5 * (sorted[c - 1] + sorted[c]); }
    }
    std::size_t other = 0;
    for(std::size_t q = 0; q < m; ++q) { side[q] = (h[q] > threshold) != (0 > threshold); other += side[q]; }
    t.smaller = std::min(other, m - other);
    Eigen::Vector2d center = Eigen::Vector2d::Zero(); // of the other sheet, in the plane, over the radius
    for(std::size_t q = 0; q < m; ++q) if(side[q]) center += Eigen::Vector2d(u.dot(P[q]), v.dot(P[q])) / rad;
    t.off_center = other ? center.norm() / double(other) : 1;
    double far[2] = { 0, 0 }; // mean squared distance from the point along the sheets, over the radius
    for(std::size_t q = 0; q < m; ++q) far[side[q]] += (std::pow(u.dot(P[q]), 2) + std::pow(v.dot(P[q]), 2)) / (rad * rad);
    t.ring = other && other < m ? (far[1] / double(other)) / (far[0] / double(m - other)) : 1e9;
    if(tls) // total least squares: the normal of the sheets' scatter about their own centers
    {
      Eigen::Vector3d c[2] = { Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() }; double w[2] = { 0, 0 };
      auto in = [&](std::size_t q) { return !(robust && it > 0 && std::abs(residual[q]) > tau / rad); };
      for(std::size_t q = 0; q < m; ++q) if(in(q)) { c[side[q]] += P[q]; w[side[q]] += 1; }
      if(w[0] < 3 || w[1] < 3) return t;
      c[0] /= w[0]; c[1] /= w[1];
      Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
      for(std::size_t q = 0; q < m; ++q) if(in(q)) C += (P[q] - c[side[q]]) * (P[q] - c[side[q]]).transpose();
      Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvectors().col(0);
      n = e.dot(n) < 0 ? Eigen::Vector3d(-e) : e;
      for(std::size_t q = 0; q < m; ++q) residual[q] = n.dot(P[q] - c[side[q]]) / rad;
      t.a0 = std::abs(n.dot(c[0])); t.gap = n.dot(c[1] - c[0]);
      if(it + 1 < iters) continue;
      t.outliers = 0; t.spread = 0;
      for(std::size_t q = 0; q < m; ++q)
      { const double r = residual[q] * rad; t.outliers += std::abs(r) > tau; if(std::abs(r) <= tau) t.spread += r * r; }
      t.spread = std::sqrt(t.spread / double(m - t.outliers));
      t.normal = n; t.ok = true;
      if(t.smaller >= 3)
        t.parallel = std::max(ang(pca_normal(P, [&](std::size_t q) { return side[q] == 1; }), n), ang(pca_normal(P, [&](std::size_t q) { return side[q] == 0; }), n));
      return t;
    }
    Eigen::Matrix<double, 7, 7> A = Eigen::Matrix<double, 7, 7>::Zero(); Eigen::Matrix<double, 7, 1> b = Eigen::Matrix<double, 7, 1>::Zero();
    for(std::size_t q = 0; q < m; ++q)
    {
      const double x = u.dot(P[q]) / rad, y = v.dot(P[q]) / rad;
      if(robust && it > 0 && std::abs(residual[q]) > tau / rad) continue;
      Eigen::Matrix<double, 7, 1> f; f << 1, double(side[q]), x, y, x * x, x * y, y * y;
      if(!quadric) f.tail<3>().setZero();
      A.selfadjointView<Eigen::Lower>().rankUpdate(f); b += h[q] * f;
    }
    if(!quadric) for(int d = 4; d < 7; ++d) A(d, d) = 1;
    a = A.selfadjointView<Eigen::Lower>().ldlt().solve(b);
    if(!a.allFinite()) return t;
    for(std::size_t q = 0; q < m; ++q) // in the frame of this fit, for the band of the next one
    {
      const double x = u.dot(P[q]) / rad, y = v.dot(P[q]) / rad;
      residual[q] = h[q] - (a[0] + a[1] * side[q] + a[2] * x + a[3] * y + a[4] * x * x + a[5] * x * y + a[6] * y * y);
    }
    n = (n - a[2] * u - a[3] * v).normalized();
    if(it + 1 < iters) continue;
    // residuals of the last fit, in its own frame (the frame it was fitted in)
    t.outliers = 0;
    for(std::size_t q = 0; q < m; ++q)
    {
      const double x = u.dot(P[q]) / rad, y = v.dot(P[q]) / rad;
      const double r = h[q] - (a[0] + a[1] * side[q] + a[2] * x + a[3] * y + a[4] * x * x + a[5] * x * y + a[6] * y * y);
      t.outliers += std::abs(r * rad) > tau;
      if(std::abs(r * rad) <= tau) t.spread += r * r * rad * rad;
    }
    t.spread = std::sqrt(t.spread / double(m - t.outliers)); // the deviation of the residuals in the band
  }
  t.normal = n; t.a0 = std::abs(a[0] * rad); t.gap = a[1] * rad; t.ok = true;
  if(t.smaller >= 3) // the angle between the planes of the two sheets apart (their PCA)
    t.parallel = std::max(ang(pca_normal(P, [&](std::size_t q) { return side[q] == 1; }), n), ang(pca_normal(P, [&](std::size_t q) { return side[q] == 0; }), n));
  return t;
}

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
  if(getenv("PLANES")) // another RRHT setting, e.g. the paper's fast one: PLANES=300 ROT=2
    CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(r, k, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()).confidence_map(Confidence_of_sample())
      .number_of_planes(unsigned(env("PLANES", 0))).number_of_rotations(unsigned(env("ROT", 5))));
  else
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
  std::atomic<int> gap_hist[10] = {}, gap_bad[10] = {}; // GAPHIST: two-sheet fits by gap over spread, and RRHT above 10 degrees
  const double wsig = env("W", 0), qc = env("QC", 1);
  std::vector<double> noise_used(cloud.size(), 0); // the noise of each point's last fit
  std::vector<double> own_kurtosis(cloud.size(), 3); // of the residuals of each point's first-pass fit
  struct S { std::vector<Eigen::Vector3d> P; std::vector<double> res, sorted, ss; };
  tbb::enumerable_thread_specific<S> tls;
  const int mode2 = int(env("MODE", 0)); // 0: local sigma; 1: median of the neighbors' local sigmas
  double global_sig = 0;
  for(int pass = 0; pass < (mode2 ? 2 : 1); ++pass) {
  if(pass == 1 && mode2 >= 2) {
    std::vector<double> g = sig; std::nth_element(g.begin(), g.begin() + N / 2, g.end()); global_sig = g[N / 2] * qc;
    std::printf("  the cloud's noise over the true one: %.3f\n", global_sig / (noise / 100 * diag)); }
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
      // the percent-th percentile of the values of point i's neighbors (itself included)
      auto neighbors_quantile = [&](const std::vector<double>& values, int percent) {
        sc.ss.clear(); for(std::size_t c = 0; c <= k; ++c) sc.ss.push_back(values[nbr[i * (k + 1) + c]]);
        std::nth_element(sc.ss.begin(), sc.ss.begin() + sc.ss.size() * percent / 100, sc.ss.end()); return sc.ss[sc.ss.size() * percent / 100]; };
      if(pass == 1) { sfix = neighbors_quantile(sig, int(env("QQ", 50))) * qc;
        sfix = mode2 == 2 ? global_sig : mode2 == 3 ? std::min(sfix, global_sig) : sfix; }
      n0.normalize();
      const Eigen::Vector3d n_rrht = n0;
      if(getenv("PCAFRAME")) n0 = pca_normal(P, [](std::size_t) { return true; });
      for(int frame = 0; frame < int(env("FRAMES", 1)); ++frame) {
      Eigen::Vector3d u = n0.unitOrthogonal(), v = n0.cross(u);
      const std::size_t m = P.size();
      sc.res.resize(m);
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
        noise_used[idx] = s;
        tau = std::max(kappa * s, env("FLOOR", 1e-9) * rad);
        if(getenv("PCAIN")) { n0 = pca_normal(P, [&](std::size_t q) { return std::abs(sc.res[q]) <= tau; }); u = n0.unitOrthogonal(); v = n0.cross(u); }
        a = fit_quadric(P, n0, u, v, rad, quad, cnt, [&](std::size_t q, double x, double y) {
          if(std::abs(sc.res[q]) > tau) return 0.0;
          return wsig > 0 ? std::exp(-0.5 * (x * x + y * y) / (wsig * wsig)) : 1.0; });
        if(cnt < 10 || !a.allFinite()) { ok = false; break; }
        for(std::size_t q = 0; q < m; ++q)
        {
          const double x = u.dot(P[q]) / rad, y = v.dot(P[q]) / rad, h = n0.dot(P[q]) / rad;
          sc.res[q] = rad * (h - (a[0] + a[1] * x + a[2] * y + a[3] * x * x + a[4] * x * y + a[5] * y * y));
        }
      }
      if(!ok) break;
      double kurt = kurtosis(sc.res);
      if(pass == 0) own_kurtosis[idx] = kurt;
      if(pass == 1 && getenv("KAVG")) kurt = neighbors_quantile(own_kurtosis, 50);
      Eigen::Vector3d nn = (n0 - a[1] * u - a[2] * v).normalized();
      bool all_in = false; // jet fitting's normal replaced the fit's (ALLIN)
      if(getenv("ALLIN"))
      {
        bool all = true; for(std::size_t q = 0; q < m; ++q) all = all && std::abs(sc.res[q]) <= env("ALLIN", 4) * tau / kappa;
        if(getenv("KURT")) all = all && kurt >= env("KURT", 2);
        if(all) { const Eigen::Vector3d w = pca_normal(P, [](std::size_t) { return true; }), wu = w.unitOrthogonal(), wv = w.cross(wu);
          std::size_t all_count = 0;
          const Eigen::Matrix<double, 6, 1> g = fit_quadric(P, w, wu, wv, rad, true, all_count, [](std::size_t, double, double) { return 1.0; });
          if(g.allFinite()) { nn = (w - g[1] * wu - g[2] * wv).normalized(); all_in = true; }
          if(getenv("ALLIN2") && g.allFinite()) { // once more, in the frame of that normal
            const Eigen::Vector3d w2 = nn, w2u = w2.unitOrthogonal(), w2v = w2.cross(w2u);
            const Eigen::Matrix<double, 6, 1> g2 = fit_quadric(P, w2, w2u, w2v, rad, true, all_count, [](std::size_t, double, double) { return 1.0; });
            if(g2.allFinite()) nn = (w2 - g2[1] * w2u - g2[2] * w2v).normalized(); } }
      }
      if(frame + 1 < int(env("FRAMES", 1))) { n0 = nn; continue; }
      n0 = n_rrht;
      const double out = 1 - double(cnt) / m;
      if(getenv("KURTALL") && kurt < env("KURTALL", 2)) continue; // two sides apart: keep RRHT's normal
      if(getenv("TWOFIRST")) // the two sheets before the one sheet, where they pass the gate
      {
        const Two_sheets two = two_sheet_fit(P, n_rrht, rad, tau, int(env("TWOITERS", iters)), env("TWOQUAD", 1) != 0, getenv("TWOBAND") != nullptr, getenv("TWOTLS") != nullptr);
        if(two.ok && double(two.outliers) <= max_out * double(m) && two.a0 <= tau && ang(two.normal, n_rrht) <= maxang &&
           double(two.smaller) >= env("MINSIDE", 0.05) * double(m) && two.off_center <= env("OFFC", 1) && two.parallel <= env("PARA", 90) && std::abs(two.gap) >= env("TWOFIRST", 0) * (getenv("OWNSPREAD") ? two.spread : tau / kappa) && std::abs(two.gap) >= env("GAPBAND", 0) * tau && two.ring <= env("RING", 1e9))
        { ef[idx] = ang(two.normal, t); used[idx] = 2;
          if(getenv("DIAG2") && ef[idx] > 10 && er[idx] <= 10)
            std::printf("  two worse: smaller %zu, off %.2f, para %.1f, gap/spread %.2f, out %zu, a0/tau %.2f, rrht %.1f two %.1f at %.3f %.3f %.3f\n", two.smaller, two.off_center, two.parallel, two.gap / two.spread, two.outliers, two.a0 / tau, er[idx], ef[idx], cloud[idx].point.x(), cloud[idx].point.y(), cloud[idx].point.z());
          continue; }
        if(getenv("GAPHIST") && two.ok && two.spread > 0) { const int b = std::min(9, int(std::abs(two.gap) / two.spread)); gap_hist[b]++; if(er[idx] > 10) gap_bad[b]++; }
      }
      if(out * m <= max_out * m + env("SLACK", 0) && std::abs(a[0] * rad) <= tau && ang(nn, n0) <= (all_in ? env("ALLINTURN", maxang) : maxang)) { ef[idx] = ang(nn, t); used[idx] = 1;
        if(getenv("DIAG") && which == "cube" && ef[idx] > 10 && er[idx] <= 10) {
          double c[3] = {cloud[idx].point.x(), cloud[idx].point.y(), cloud[idx].point.z()}; int f = 0; for(int d = 1; d < 3; ++d) if(std::abs(c[d]) > std::abs(c[f])) f = d;
          double de = 1e9; for(int d = 0; d < 3; ++d) if(d != f) de = std::min(de, 1 - std::abs(c[d]));
          std::printf("  worse: edge %.2f r, out %.3f, moved %.1f, rrht %.1f refit %.1f, tau/r %.3f, a0/tau %.2f, curv %.3f %.3f %.3f conf %.3f\n", de / rad, out, ang(nn, n0), er[idx], ef[idx], tau / rad, a[0] * rad / tau, a[3], a[4], a[5], r[idx].confidence); } }
      else if(getenv("TWOSHEET"))
      {
        const Two_sheets two = two_sheet_fit(P, n_rrht, rad, tau, int(env("TWOITERS", iters)), env("TWOQUAD", 1) != 0, getenv("TWOBAND") != nullptr, getenv("TWOTLS") != nullptr);
        if(two.ok && double(two.outliers) <= max_out * double(m) && two.a0 <= tau && ang(two.normal, n_rrht) <= maxang &&
           double(two.smaller) >= env("MINSIDE", 0.05) * double(m) && two.off_center <= env("OFFC", 1) && two.parallel <= env("PARA", 90))
        { ef[idx] = ang(two.normal, t); used[idx] = 2;
          if(getenv("DIAG2") && ef[idx] > 10 && er[idx] <= 10) {
            double c[3] = {cloud[idx].point.x(), cloud[idx].point.y(), cloud[idx].point.z()}; int f = 0; for(int d = 1; d < 3; ++d) if(std::abs(c[d]) > std::abs(c[f])) f = d;
            double de = 1e9; for(int d = 0; d < 3; ++d) if(d != f) de = std::min(de, 1 - std::abs(c[d]));
            std::printf("  two worse: edge %.2f r, smaller %zu, off %.2f, gap/sig %.2f, out %zu, a0/tau %.2f, para %.1f, gap/spread %.2f, rrht %.1f two %.1f\n", de / rad, two.smaller, two.off_center, two.gap / (tau / kappa), two.outliers, two.a0 / tau, two.parallel, two.gap / two.spread, er[idx], ef[idx]); } }
      }
      }
    }
  }); }
  if(getenv("DIAG")) { std::size_t w = 0, b = 0; for(std::size_t i = 0; i < er.size(); ++i) { w += ef[i] > 10 && er[i] <= 10; b += ef[i] <= 10 && er[i] > 10; } std::printf("  worse %zu better %zu\n", w, b); }
  auto stats = [&](const char* name, const std::vector<double>& e) {
    double s = 0, a = 0; for(double x : e) { s += x * x; a += x > 10; }
    std::printf(" %s %5.2f%% %5.2f", name, 100 * a / e.size(), std::sqrt(s / e.size()));
  };
  if(getenv("HIST")) for(auto* e : {&er, &ef, &ej}) { int h[9] = {0}; for(double x : *e) h[std::min(8, int(x / 10))]++; for(int q = 0; q < 9; ++q) std::printf(" %6d", h[q]); std::printf("\n"); }
  auto subset = [&](const char* name, auto&& keep) { // RMS of RRHT, refit and jet on a subset
    double a = 0, b = 0, c = 0; std::size_t m = 0;
    for(std::size_t i = 0; i < er.size(); ++i) if(keep(i)) { c += er[i] * er[i]; a += ef[i] * ef[i]; b += ej[i] * ej[i]; ++m; }
    std::printf("  %-36s %6zu points: RMS rrht %5.2f refit %5.2f jet %5.2f\n", name, m, std::sqrt(c / m), std::sqrt(a / m), std::sqrt(b / m)); };
  if(getenv("SPLIT") && noise > 0) { std::nth_element(noise_used.begin(), noise_used.begin() + N / 2, noise_used.end());
    std::printf("  median of the points' noise over the true one: %.3f\n", noise_used[N / 2] / (noise / 100 * diag)); }
  if(getenv("SPLIT")) { subset("refitted", [&](std::size_t i) { return used[i] == 1; }); subset("kept", [&](std::size_t i) { return used[i] == 0; }); }
  if(getenv("CONSIST")) // the largest angle between a point's given normal and those of its 10 nearest neighbors
  {
    std::vector<double> spread(N, 0);
    for(std::size_t i = 0; i < N; ++i) for(std::size_t c = 1; c <= std::min<std::size_t>(10, k); ++c)
      spread[i] = std::max(spread[i], ang(eig(cloud[i].truth), eig(cloud[nbr[i * (k + 1) + c]].truth)));
    subset("given normals within 20 deg of 10 nearest", [&](std::size_t i) { return spread[i] <= 20; });
    subset("the others", [&](std::size_t i) { return spread[i] > 20; });
  }
  if(getenv("RIM")) { int h[6] = {0}, hj[6] = {0};
    for(std::size_t i = 0; i < er.size(); ++i) { const double m = std::max(std::abs(cloud[i].point.x()), std::abs(cloud[i].point.y())); const int b = std::min(5, int((1 - m) / radius[i])); h[b] += ef[i] > 10; hj[b] += ej[i] > 10; }
    std::printf("  above 10 deg by distance to the rim in radii 0, 1, ..., 5 and more: refit"); for(int q = 0; q < 6; ++q) std::printf(" %d", h[q]);
    std::printf(", jet"); for(int q = 0; q < 6; ++q) std::printf(" %d", hj[q]); std::printf("\n"); }
  if(getenv("GAPHIST")) { std::printf("  gap/spread 0..9+:"); for(int b = 0; b < 10; ++b) std::printf(" %d(%d)", gap_hist[b].load(), gap_bad[b].load()); std::printf("\n"); }
  if(getenv("LIB")) // the library's refit(true), to check that it does what the prototype does
  {
    Cloud l = cloud; std::vector<double> el(cloud.size());
    CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(l, k, params::point_map(Point_of_sample()).normal_map(Normal_of_sample()).refit(true));
    for(std::size_t i = 0; i < l.size(); ++i) el[i] = angle_error(l[i]);
    std::printf("  library:"); stats("refit(true)", el); std::printf("\n");
  }
  std::size_t uu = 0, u2 = 0; for(int x : used) { uu += x != 0; u2 += x == 2; }
  if(getenv("TWOSHEET")) std::printf("  two sheets on %.1f%% of the points\n", 100. * u2 / used.size());
  std::printf("%-12s %.2f used %5.1f%% |", which.c_str(), noise, 100. * uu / used.size());
  stats("rrht", er); stats("refit", ef); stats("jet", ej); std::printf("\n");
}
