// Prototype: per-point features for a confidence, and a refit.
#include <CGAL/rrht_estimate_normals.h>
#include "shapes.h"
#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>
#include <tbb/enumerable_thread_specific.h>
#include <cstdio>
#include <string>
using namespace CGAL::RRHT::internal;
using namespace rrht_test;

struct Feat { double support, err_jet; double share, lead, cluster_share, agree10, inl_frac, err, err_refit, err_own, ratio, own_gain; };

// PCA plane on points selected by slab |n.(p - c)| < tau
static bool slab_fit(const std::vector<Eigen::Vector3d>& P, const Eigen::Vector3d& n, double c, double tau,
                     Eigen::Vector3d& out, double& off, std::size_t& count, double& rms, double& ratio)
{
  Eigen::Vector3d m = Eigen::Vector3d::Zero(); count = 0;
  for(auto& p : P) if(std::abs(n.dot(p) - c) < tau) { m += p; ++count; }
  if(count < 6) return false;
  m /= double(count);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for(auto& p : P) if(std::abs(n.dot(p) - c) < tau) { Eigen::Vector3d d = p - m; C += d * d.transpose(); }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  out = es.eigenvectors().col(0);
  off = out.dot(m);
  rms = std::sqrt(std::max(0., es.eigenvalues()(0)) / count);
  ratio = es.eigenvalues()(0) / std::max(1e-300, es.eigenvalues()(1));
  return true;
}

static double ang(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  double c = std::abs(a.normalized().dot(b.normalized()));
  return std::acos(std::min(1., c)) * 180 / M_PI;
}

int main(int argc, char** argv)
{
  std::string which = argv[1];
  double noise = argc > 2 ? atof(argv[2]) : 0.2;
  std::size_t n = 100000;
  Cloud cloud;
  if(which == "cube") cloud = cube(n, 1);
  else if(which == "cylinder") cloud = closed_cylinder(n, 2);
  else if(which == "corner") cloud = anisotropic_corner(n, 12);
  else if(which == "sphere") cloud = sphere(n, 5);
  else { sample_mesh(std::string(getenv("RRHT_DATA") ? getenv("RRHT_DATA") : "../shared/data") + "/meshes/" + which + ".off", n, 3, cloud); }
  add_noise(cloud, noise, 1001);
  std::vector<Neighbor_search::Indexed_point> pts;
  for(auto& s : cloud) pts.emplace_back(Neighbor_search::Point(s.point.x(), s.point.y(), s.point.z()), pts.size());
  Neighbor_search search(std::move(pts), CGAL::Parallel_tag());
  Bin_layout layout(15);
  Cube_weights cw(1);
  Settings st; st.k = 100; st.neighbor_radius = 0; st.number_of_planes = 691; st.use_confidence_interval = true;
  st.sampling = CGAL::RRHT::Sampling::POINTS; st.presampling_factor = 4; st.number_of_rotations = 5;
  st.aggregation = CGAL::RRHT::Aggregation::CLUSTER; st.cos_cluster_angle = std::cos(M_PI / 4); st.seed = 0;
  std::vector<Feat> F(cloud.size());
  tbb::enumerable_thread_specific<Scratch> tls([&] { return Scratch(layout, cw, 4); });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, search.size()), [&](const tbb::blocked_range<std::size_t>& R) {
    Scratch& scratch = tls.local();
    for(std::size_t i = R.begin(); i < R.end(); ++i)
    {
      std::size_t idx = search.input_index(i);
      search.find(i, st.k, 0, scratch.neighborhood, scratch.search);
      auto& P = scratch.neighborhood.points;
      double r = scratch.neighborhood.radius;
      Random rng(0, idx);
      scratch.points.prepare(std::uint32_t(P.size()), st.number_of_planes);
      scratch.candidates.clear();
      scratch.rotated.resize(P.size());
      double share = 0, lead = 0, total_all = 0;
      for(unsigned rr = 0; rr < 5; ++rr)
      {
        Eigen::Matrix3d rot = rng.uniform_rotation();
        rotate(P, rot / r, scratch.rotated, best_instruction_set());
        Candidate_normal c = hough_transform(scratch.rotated, scratch.points, rng, st, scratch);
        double tot = double(scratch.accumulator.number_of_votes());
        double second = scratch.accumulator.votes_of_second_most_voted_bin();
        share += c.votes / tot / 5; total_all += tot; lead += (c.votes - second) / tot / 5;
        c.normal = rot.transpose() * c.normal;
        scratch.candidates.push_back(c);
      }
      Eigen::Vector3d nrm = aggregate(scratch.candidates, st.aggregation, st.cos_cluster_angle);
      double all = 0, cl = 0; int agree = 0;
      for(auto& c : scratch.candidates) { all += c.votes; if(std::abs(c.normal.dot(nrm)) > std::cos(M_PI/4)) cl += c.votes; if(ang(c.normal, nrm) < 10) ++agree; }
      const Sample& s = cloud[idx];
      Eigen::Vector3d truth(s.truth.x(), s.truth.y(), s.truth.z());
      Feat f{};
      f.share = share; f.support = cl / total_all; f.lead = lead; f.cluster_share = cl / all; f.agree10 = agree / 5.;
      f.err = ang(nrm, truth);
      // robust refit: median/MAD slab, 3 iterations, then quadratic height fit on the inliers
      {
        Eigen::Vector3d nn = nrm; f.err_refit = f.err; f.inl_frac = 0; f.ratio = 0; f.err_jet = f.err;
        std::vector<double> d(P.size()), e;
        double c = 0, tau = 0; std::size_t cnt = 0;
        bool ok = true;
        for(int it = 0; it < 3 && ok; ++it)
        {
          for(std::size_t j = 0; j < P.size(); ++j) d[j] = nn.dot(P[j]);
          e = d; std::nth_element(e.begin(), e.begin() + e.size()/2, e.end()); c = e[e.size()/2];
          for(auto& x : e) x = std::abs(x - c);
          std::nth_element(e.begin(), e.begin() + e.size()/2, e.end());
          tau = std::max(3 * 1.4826 * e[e.size()/2], 1e-9 * r);
          Eigen::Vector3d m = Eigen::Vector3d::Zero(); cnt = 0;
          for(std::size_t j = 0; j < P.size(); ++j) if(std::abs(d[j] - c) <= tau) { m += P[j]; ++cnt; }
          if(cnt < 6) { ok = false; break; }
          m /= double(cnt);
          Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
          for(std::size_t j = 0; j < P.size(); ++j) if(std::abs(d[j] - c) <= tau) { Eigen::Vector3d q = P[j] - m; C += q * q.transpose(); }
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
          Eigen::Vector3d n1 = es.eigenvectors().col(0);
          if(ang(n1, nrm) > 20) { ok = false; break; }
          nn = n1.dot(nn) >= 0 ? n1 : Eigen::Vector3d(-n1);
        }
        if(ok)
        {
          f.inl_frac = double(cnt) / P.size();
          f.err_refit = ang(nn, truth); f.ratio = ang(nn, nrm);
          // quadratic height field in the frame of nn over the inliers
          Eigen::Vector3d u = nn.unitOrthogonal(), v = nn.cross(u);
          Eigen::MatrixXd A(cnt, 6); Eigen::VectorXd b(cnt); std::size_t row = 0;
          for(std::size_t j = 0; j < P.size(); ++j) if(std::abs(d[j] - c) <= tau) {
            double x = u.dot(P[j]) / r, y = v.dot(P[j]) / r; A.row(row) << x*x, x*y, y*y, x, y, 1; b(row++) = nn.dot(P[j]) / r; }
          Eigen::VectorXd sol = A.colPivHouseholderQr().solve(b);
          Eigen::Vector3d nj = nn - sol(3) * u - sol(4) * v;
          f.err_jet = ang(nj, truth);
        }
      }
      // own side: among candidate normals, most inliers in slab through query
      std::size_t best = 0; Eigen::Vector3d bn = nrm;
      for(auto& c : scratch.candidates) { std::size_t k = 0; for(auto& p : P) k += std::abs(c.normal.dot(p)) < 0.1 * r; if(k > best) { best = k; bn = c.normal; } }
      f.err_own = ang(bn, truth);
      f.own_gain = double(best) / P.size() - f.inl_frac;
      F[idx] = f;
    }
  });
  for(auto& f : F) std::printf("%.4f %.3f %.4f %.4f %.4f %.2f %.4f %.3f %.3f %.3f %.4g %.4f\n", f.support, f.err_jet, f.share, f.lead, f.cluster_share, f.agree10, f.inl_frac, f.err, f.err_refit, f.err_own, f.ratio, f.own_gain);
}
