// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The orientation experiment: CGAL::rrht_orient_normals() against
// CGAL::mst_orient_normals() (and Open3D) on closed and open shapes and a scan.

#ifndef RRHT_BENCHMARK_ORIENTATION_EXPERIMENT_H
#define RRHT_BENCHMARK_ORIENTATION_EXPERIMENT_H

#include "experiment.h"

namespace {

// -- Orientation (beyond the paper): CGAL::rrht_orient_normals() (consistent,
// k = 18, as `rrht_normals --orient`) on the normals of both RRHT settings
// and of jet fitting (K = 80), against CGAL::mst_orient_normals() (k = 18) on
// RRHT's and on jet fitting's normals, and, when built with Open3D, Open3D's
// orientation (k = 10) on its own normals (K = 30) and on RRHT's. Quality on
// 50k- and 100k-point closed shapes, synthetic and real, three noise draws each
// (against the exact outward normal, and the largest connected patch of
// inward normals), open shapes (the share on the minority side) and a real
// scan (agreement with the nearest neighbors), written to
// orientation_quality.csv, with the floor of each noisy closed cloud (the
// points nearer the other side of a thin part) in orientation_floor.csv; time
// against the number of points, in rounds, to orientation.csv, and the time
// targets to orientation_targets.csv.

const unsigned int orient_k = 18;        // rrht_normals --orient, and CGAL's usual k
const unsigned int open3d_orient_k = 10; // the k of Open3D's documentation
// Open3D's orientation triangulates the whole cloud (a Delaunay tetrahedrization
// gives it a connected graph): on a 100k-point clean cube, all coplanar points,
// it ran for over 3 minutes (qhull). It runs on the clouds with noise (and the
// scan) only, each call abandoned after `open3d_orient_seconds`.
const unsigned int open3d_orient_seconds = 60;
// A measurement of the time part (RRHT's estimation at 1M points takes about
// 40 s) is abandoned after this; Open3D's orientation is the one that may reach it.
const unsigned int orientation_time_seconds = 180;

/// Writes the samples of a cloud in their order, after how many samples
/// there are and how many (the first ones) were oriented: a child process
/// hands what it made to the parent this way, since `measure()` reports
/// only times and unoriented errors.
void write_cloud(const Cloud& cloud, std::size_t oriented, const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  const double header[2] = { double(cloud.size()), double(oriented) };
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  for(const Sample& s : cloud)
  {
    const double v[10] = { s.point.x(),  s.point.y(),  s.point.z(),  s.truth.x(),  s.truth.y(),
                           s.truth.z(),  s.normal.x(), s.normal.y(), s.normal.z(), s.confidence };
    out.write(reinterpret_cast<const char*>(v), sizeof v);
  }
  if(!out)
    throw std::runtime_error("cannot write " + path);
}

bool read_cloud(const std::string& path, Cloud& cloud, std::size_t& oriented)
{
  std::ifstream in(path, std::ios::binary);
  double header[2];
  if(!in.read(reinterpret_cast<char*>(header), sizeof header))
    return false;
  cloud.assign(std::size_t(header[0]), Sample());
  oriented = std::size_t(header[1]);
  for(Sample& s : cloud)
  {
    double v[10];
    if(!in.read(reinterpret_cast<char*>(v), sizeof v))
      return false;
    s.point = Point(v[0], v[1], v[2]);
    s.truth = Vector(v[3], v[4], v[5]);
    s.normal = Vector(v[6], v[7], v[8]);
    s.confidence = v[9];
  }
  return true;
}

/// What one step of a pipeline left: the cloud (normals and order), how
/// many of its samples were oriented, and the measurement (one run).
struct Step
{
  Measurement measurement;
  Cloud cloud;
  std::size_t oriented = 0;
  bool ok() const { return measurement.status == Measurement::OK; }
};

/// Runs `step` once on `input` with 2 threads in a child process
/// (`measure()`), abandoned after `timeout` seconds (0: the configured
/// limit), and reads back the cloud it leaves. Its time includes writing
/// that cloud (a few milliseconds per 100k points).
Step run_step(const Config& config, const std::string& file, const Cloud& input, const Orient& step,
              unsigned int timeout = 0)
{
  const std::string path = config.scratch + "/" + file;
  const Estimate run_and_write = [&](Cloud& cloud, unsigned int threads) {
    write_cloud(cloud, step(cloud, threads), path);
  };
  Step s;
  s.measurement = measure(run_and_write, input, 2, 1, timeout ? timeout : config.timeout);
  if(s.ok() && !read_cloud(path, s.cloud, s.oriented))
  {
    s.measurement.status = Measurement::FAILED;
    s.measurement.message = "cannot read " + path;
  }
  std::remove(path.c_str());
  return s;
}

/// An estimator as a step: it leaves the points in their order, none oriented.
Orient estimation(const Estimator& e)
{
  return [e](Cloud& cloud, unsigned int threads) {
    e.estimate(cloud, threads);
    return std::size_t(0);
  };
}

/// Turns the exact normals out of the solid: each away from the origin on a
/// shape convex about it (the cube's and cylinder's truths are unoriented),
/// then all of them if the flux of the position through the surface, 3 times
/// the enclosed volume when they point out, is negative (a mesh's faces may
/// wind either way).
void truth_outward(Cloud& cloud, bool convex_about_origin)
{
  double flux = 0;
  for(Sample& s : cloud)
  {
    s.truth = s.truth / std::sqrt(s.truth.squared_length());
    if(convex_about_origin && s.truth * (s.point - CGAL::ORIGIN) < 0)
      s.truth = -s.truth;
    flux += s.truth * (s.point - CGAL::ORIGIN); // uniform samples: the flux up to the area per sample
  }
  if(flux < 0)
    for(Sample& s : cloud)
      s.truth = -s.truth;
}

/// The walls of the benchmark's hollow box: 1% of its diagonal thick.
const double hollow_box_wall = 0.01 * 2 * std::sqrt(3.);

/// The benchmark's thin shapes by name, `n` points: the hollow box, the
/// finned part (fins and gaps 1% of its diagonal) and the twisted blade 0.04
/// thick (2% of its chord); their generators give exact normals out of the
/// solid.
Cloud thin_shape(const std::string& name, std::size_t n, unsigned int seed)
{
  return name == "hollow_box" ? hollow_box(n, hollow_box_wall, seed)
         : name == "finned_part" ? finned_part(n, seed) : thin_blade(n, 0.04, seed);
}

/// The closed shapes of the experiment, in their order, each with the seed
/// of its cloud: the cube, the closed cylinder, the CAD meshes of
/// ../shared/data (`is_closed_mesh()`), the hollow box, the finned part, and the
/// machined parts of test/shapes.h (a slotted disk, a spool, a drilled block,
/// a spur gear, and the closed blade, whose thickness goes to zero at its
/// edges).
const std::pair<const char*, unsigned int> closed_shape_list[] = {
  { "cube", 41 },          { "cylinder", 42 },     { "fandisk", 43 },  { "anchor", 43 },
  { "dragknob", 57 },      { "pipe", 58 },         { "u", 59 },        { "handle", 60 },
  { "tripod", 61 },        { "cross", 62 },        { "hollow_box", 44 }, { "finned_part", 45 },
  { "slotted_disk", 52 },  { "spool", 53 },        { "drilled_block", 54 }, { "gear", 55 },
  { "closed_blade", 56 }
};

/// The closed CAD meshes of ../shared/data/meshes (MANIFEST.md): fandisk,
/// anchor, a knob with a bore, a thick tube, a U-shaped bracket, a rounded
/// handle with a hole, a tripod-shaped and a cross-shaped extrusion.
bool is_closed_mesh(const std::string& name)
{
  for(const char* mesh : { "fandisk", "anchor", "dragknob", "pipe", "u", "handle", "tripod", "cross" })
    if(name == mesh)
      return true;
  return false;
}

/// `n` points of the closed shape `name` (`closed_shape_list`) drawn with
/// `seed`, their exact normals turned outward; false (with a message) if it
/// is a mesh of ../shared/data that is absent.
bool closed_cloud(const Config& config, const std::string& name, std::size_t n, unsigned int seed, Cloud& cloud)
{
  bool convex_about_origin = false;
  if(name == "cube" || name == "cylinder")
  {
    cloud = name == "cube" ? cube(n, seed) : closed_cylinder(n, seed);
    convex_about_origin = true;
  }
  else if(is_closed_mesh(name))
  {
    if(!sample_mesh(config.shared("meshes/" + name + ".off"), n, seed, cloud))
    {
      warn_missing(config.shared("meshes/" + name + ".off"));
      return false;
    }
  }
  else if(name == "hollow_box" || name == "finned_part")
    cloud = thin_shape(name, n, seed);
  else if(name == "closed_blade")
    cloud = closed_blade(n, closed_blade_thickness, seed);
  else
    cloud = solid_boundary(machined_part_solid(name), n, seed); // throws on an unknown name
  truth_outward(cloud, convex_about_origin); // the machined parts' truths are outward already: harmless
  return true;
}

/// The share of the points of the noisy `cloud` whose nearest point of
/// `dense`, a dense noise-free sample of the same surface, has an exact
/// normal against their own (within 60 degrees of its opposite): they lie
/// nearer the other side of a thin part (a wall, a fin, a blade's edge) than
/// their own side, which therefore cannot be told from the points. A floor
/// for the share of wrong orientations. Nearer a face across an edge of a
/// little more than 90 degrees (a slot's wall and a disk's rim), a point is
/// not counted: the other face's normal is more than 60 degrees off its own,
/// where the scores count no orientation.
double share_nearer_the_other_side(const Cloud& cloud, const Cloud& dense)
{
  const Nearest_samples search(dense);
  std::size_t surface = 0, across = 0;
  for(const Sample& s : cloud)
  {
    if(s.truth == CGAL::NULL_VECTOR)
      continue;
    ++surface;
    const Nearest_samples::Knn nearest = search.nearest(s.point, 1);
    const Vector& other = dense[nearest.begin()->first].truth;
    across += other * s.truth <= -0.5 * std::sqrt(other.squared_length() * s.truth.squared_length());
  }
  return surface ? double(across) / double(surface) : 0.;
}

/// The clean closed shapes (`closed_shape_list`), `n` points each, exact
/// normals outward.
std::vector<Dataset> closed_shapes(const Config& config, std::size_t n)
{
  std::vector<Dataset> shapes;
  for(const auto& shape : closed_shape_list)
  {
    Cloud cloud;
    if(closed_cloud(config, shape.first, n, shape.second, cloud))
      shapes.push_back(with_noise(shape.first, std::move(cloud), 0, 0));
  }
  return shapes;
}

/// How the oriented normals of a cloud with exact normals compare with them.
struct Truth_score
{
  std::size_t surface = 0;  // samples with a truth (outliers have none)
  std::size_t counted = 0;  // of those, normals within 60 degrees of the truth's line
  std::size_t against = 0;  // of those counted, normals pointing against the truth
  std::size_t along = 0;    // surface samples whose normal points along the truth (null normals do not)
};

Truth_score score_against_truth(const Cloud& cloud)
{
  Truth_score t;
  for(const Sample& s : cloud)
  {
    if(s.truth == CGAL::NULL_VECTOR)
      continue;
    ++t.surface;
    const double c = cosine_to_truth(s);
    t.along += (c > 0);
    // A normal farther than 60 degrees off is not the surface's (at an edge, a wrong
    // plane): which way it points says nothing of the orientation.
    if(std::abs(c) >= 0.5)
    {
      ++t.counted;
      t.against += (c < 0);
    }
  }
  return t;
}

/// The share of the points whose oriented normal disagrees in sign with
/// most of their `k` nearest neighbors' (a tie agrees). Only neighbors whose
/// normal is within 60 degrees of the line of the point's normal vote: the
/// others are across an edge, where the sign of the dot product is noise.
/// Points with a null normal are left out.
double share_disagreeing_with_neighbors(const Cloud& cloud, unsigned int k)
{
  const Nearest_samples nearest_samples(cloud);
  std::size_t scored = 0, disagreeing = 0;
  for(std::size_t i = 0; i < cloud.size(); ++i)
  {
    const Vector& n = cloud[i].normal;
    if(n == CGAL::NULL_VECTOR)
      continue;
    int votes = 0;
    const Nearest_samples::Knn search = nearest_samples.nearest(cloud[i].point, k + 1);
    for(const auto& neighbor : search)
    {
      const Vector& m = cloud[neighbor.first].normal;
      const double norm = std::sqrt(n.squared_length() * m.squared_length());
      if(neighbor.first == i || !(norm > 0) || std::abs(n * m) < 0.5 * norm)
        continue;
      votes += (n * m > 0) ? 1 : -1;
    }
    ++scored;
    disagreeing += (votes < 0);
  }
  return scored ? double(disagreeing) / scored : 0.;
}

/// The pipelines compared: normals, then an orientation. Each step is a
/// child process; the normals of each estimator are computed once per cloud.
struct Pipelines
{
  Estimator rrht_normals = rrht_default(rrht_k), precise_normals = rrht_defaults(rrht_k), jet_normals = jet(paper_k);
  Orientation rrht = rrht_orient(orient_k), mst = mst_orient(orient_k);
  std::string name(const Estimator& e, const Orientation& o) const { return e.name + " + " + o.name; }
};

/// The closed shapes' sizes, and the seeds of their noise draws: whether
/// local evidence turns a whole face inward depends on the draw.
const std::size_t closed_sizes[] = { 50000, 100000 };
const unsigned int noise_seeds[] = { 47, 63, 64 };

/// The closed shapes' bound on the largest connected patch of inward
/// normals (`largest_inward_patch()`), in points, and the k of its graph.
const std::size_t inward_patch_target = 50;
const unsigned int inward_patch_k = 18;

/// One row of orientation_quality.csv and of the console. `kind` is closed,
/// open or scan; `wrong` is the score the target bounds (in %): against the
/// outward normal (closed), on the minority side (open), disagreeing with the
/// neighbors (scan); `wrong_all` the same over all surface points, and
/// `up_to_flip` the closed shapes' score up to a global flip, `patch` their
/// largest connected patch of inward normals (points), `floor` the share of
/// the points nearer the other side of a thin part than their own
/// (`share_nearer_the_other_side()`, in %; 0 on a clean cloud) (-1: n/a).
struct Quality_row
{
  std::string kind, pipeline;
  const Measurement* normals = nullptr;
  Step orientation;
  double counted = 0, wrong = 0, wrong_all = -1, up_to_flip = -1, floor = -1;
  long long patch = -1;
};

class Quality_csv
{
public:
  explicit Quality_csv(const Config& config) : csv_(config.out + "/orientation_quality.csv")
  {
    csv_ << "dataset,kind,points,outliers,noise_percent,noise_seed,outliers_percent,pipeline,status,counted_percent,"
            "wrong_percent,wrong_all_percent,up_to_flip_percent,largest_inward_patch,not_oriented,normals_s,orient_s,"
            "floor_percent,target_percent,target_patch,met\n";
  }

  void write(const Dataset& d, const Quality_row& r)
  {
    // Closed: at most max(0.1, floor + 0.1)% against the outward normal (>= 99.9% outward
    // where no thin part hides the side of the points) and no patch of more than
    // `inward_patch_target` inward normals; open and scan: >= 99% consistent.
    const bool closed = r.kind == "closed";
    const double target = closed ? (std::max)(0.1, (std::max)(r.floor, 0.) + 0.1) : 1.;
    const long long target_patch = closed ? (long long)inward_patch_target : -1;
    const bool ok = r.normals->status == Measurement::OK && r.orientation.ok();
    const bool met = r.wrong <= target && (!closed || r.patch <= target_patch);
    const std::size_t not_oriented = ok ? r.orientation.cloud.size() - r.orientation.oriented : 0;
    char line[1024];
    std::snprintf(line, sizeof line, "%s,%s,%zu,%zu,%g,%u,%g,%s,%s,%.3f,%.4f,%.4f,%.4f,%lld,%zu,%.4f,%.4f,%.4f,%g,%lld,%s",
                  d.name.c_str(), r.kind.c_str(), d.inliers, d.cloud.size() - d.inliers, d.noise_percent,
                  d.noise_seed, d.outliers_percent, r.pipeline.c_str(),
                  ok ? "ok" : (r.normals->status != Measurement::OK ? r.normals : &r.orientation.measurement)->status_name(),
                  r.counted, r.wrong, r.wrong_all, r.up_to_flip, ok ? r.patch : -1LL, not_oriented, r.normals->median(),
                  r.orientation.measurement.median(), r.floor, target, target_patch, ok ? (met ? "yes" : "no") : "n/a");
    csv_ << line << '\n';
    csv_.flush();
    auto percent = [](double value) { return value < 0 ? std::string("n/a") : std::to_string(value) + "%"; };
    const std::string patch = closed && ok ? "  inward patch " + std::to_string(r.patch) : std::string();
    std::printf("%-13s %-7zu noise %-4g seed %-3u out %-4g %-46s wrong %7.3f%% (all %s, up to a flip %s) "
                "of %5.1f%%%s  not oriented %zu  target %g%%  %s %s\n",
                d.name.c_str(), d.inliers, d.noise_percent, d.noise_seed, d.outliers_percent, r.pipeline.c_str(), r.wrong,
                percent(r.wrong_all).c_str(), percent(r.up_to_flip).c_str(), r.counted, patch.c_str(), not_oriented,
                target, ok ? (met ? "met" : "missed") : "FAILED",
                ok ? "" : (r.normals->message + " " + r.orientation.measurement.message).c_str());
    std::fflush(stdout);
  }

private:
  std::ofstream csv_;
};

/// Scores what `orientation` left as `kind` prescribes.
void score(const std::string& kind, Quality_row& r)
{
  if(!r.orientation.ok())
    return;
  const Cloud& cloud = r.orientation.cloud;
  if(kind == "scan")
  {
    r.counted = 100;
    r.wrong = 100 * share_disagreeing_with_neighbors(cloud, 10);
    return;
  }
  const Truth_score t = score_against_truth(cloud);
  const std::size_t along = t.counted - t.against, against_all = t.surface - t.along;
  r.counted = t.surface ? 100. * t.counted / t.surface : 0.;
  const double minority = t.counted ? 100. * (std::min)(t.against, along) / t.counted : 0.;
  if(kind == "closed")
  {
    r.wrong = t.counted ? 100. * t.against / t.counted : 0.;
    r.wrong_all = t.surface ? 100. * against_all / t.surface : 0.; // null normals count as wrong
    r.up_to_flip = minority;
    r.patch = (long long)largest_inward_patch(cloud, inward_patch_k);
  }
  else
  {
    r.wrong = minority;
    r.wrong_all = t.surface ? 100. * (std::min)(t.along, against_all) / t.surface : 0.;
  }
}

/// Every pipeline on one cloud, scored as `kind` says; Open3D's only if
/// `with_open3d`. `floor`: that of a closed cloud (in %, 0 if clean), which
/// raises its target.
void orientation_quality(const Config& config, Quality_csv& csv, const Dataset& d, const std::string& kind,
                         bool with_open3d, double floor = -1)
{
  const Pipelines p;
  const std::string prefix = "orientation_" + d.name + "_";
  const Step rrht_step = run_step(config, prefix + "rrht.bin", d.cloud, estimation(p.rrht_normals));
  const Step precise_step = run_step(config, prefix + "precise.bin", d.cloud, estimation(p.precise_normals));
  const Step jet_step = run_step(config, prefix + "jet.bin", d.cloud, estimation(p.jet_normals));
  auto orient = [&](const std::string& pipeline, const Step& normals, const Orientation& o, unsigned int timeout = 0) {
    Quality_row r;
    r.kind = kind;
    r.pipeline = pipeline;
    r.floor = floor;
    r.normals = &normals.measurement;
    if(normals.ok())
      r.orientation = run_step(config, prefix + "oriented.bin", normals.cloud, o.orient, timeout);
    score(kind, r);
    csv.write(d, r);
  };
  // The consistent orientation from both RRHT settings' normals and from jet
  // fitting's, which its users may bring; the MST on the same normals beside it.
  orient(p.name(p.rrht_normals, p.rrht), rrht_step, p.rrht);
  orient(p.name(p.precise_normals, p.rrht), precise_step, p.rrht);
  orient(p.name(p.jet_normals, p.rrht), jet_step, p.rrht);
  orient(p.name(p.rrht_normals, p.mst), rrht_step, p.mst);
  orient(p.name(p.jet_normals, p.mst), jet_step, p.mst);
#ifdef RRHT_BENCHMARK_WITH_OPEN3D
  if(!with_open3d)
    return;
  // Open3D's own pipeline, estimate_normals (K = 30) then
  // orient_normals_consistent_tangent_plane(10), is one step: its time is both.
  const Estimator open3d_normals = open3d(open3d_k);
  const Orientation open3d_orientation = open3d_orient(open3d_orient_k);
  Quality_row own;
  own.kind = kind;
  own.floor = floor;
  own.pipeline = p.name(open3d_normals, open3d_orientation);
  own.orientation = run_step(config, prefix + "open3d.bin", d.cloud, [&](Cloud& cloud, unsigned int threads) {
    open3d_normals.estimate(cloud, threads);
    return open3d_orientation.orient(cloud, threads);
  }, open3d_orient_seconds);
  own.normals = &own.orientation.measurement;
  score(kind, own);
  csv.write(d, own);
  orient(p.name(p.rrht_normals, open3d_orientation), rrht_step, open3d_orientation, open3d_orient_seconds);
#else
  (void)with_open3d;
#endif
}

/// The time of the orientations against the number of points, beside RRHT's
/// estimation of the normals they orient (fandisk with 0.2% noise, the cube
/// if the mesh is absent; 2 threads, in rounds), and the targets: the
/// orientation within the estimation's time at 100k and 1M points.
void orientation_time(const Config& config, Experiment& x)
{
  std::ofstream targets(config.out + "/orientation_targets.csv");
  targets << "target,ratio,bound,met,rounds\n";
  const Pipelines p;
  for(std::size_t n : { 100000, 200000, 500000, 1000000 })
  {
    Dataset d;
    if(!shared_mesh(config, "fandisk.off", "fandisk", n, 0.2, 46, d))
      d = synthetic("cube", cube, n, 0.2, 46);
    // The orientations run on RRHT's normals of this cloud.
    const Step normals = run_step(config, "orientation_time.bin", d.cloud, estimation(p.rrht_normals));
    if(!normals.ok())
    {
      std::cout << d.name << " " << n << ": no normals to orient (" << normals.measurement.message << ")" << std::endl;
      continue;
    }
    d.cloud = normals.cloud;
    std::vector<Experiment::Planned> planned = { { &d, p.rrht_normals, 2 },
                                                 { &d, p.rrht.timed(), 2 },
                                                 { &d, p.mst.timed(), 2 } }; // mst: one thread whatever TBB allows
#ifdef RRHT_BENCHMARK_WITH_OPEN3D
    planned.push_back({ &d, open3d_orient(open3d_orient_k).timed(), 2 });
#endif
    const std::vector<Measurement> m = x.run_in_rounds(planned);
    if(n == 100000 || n == 1000000)
    {
      const double ratio = ratio_by_rounds(m[1], m[0]);
      char line[256];
      std::snprintf(line, sizeof line, "%s %zuk 2 threads: %s / %s,%.3f,<= 1,%s,%zu", d.name.c_str(), n / 1000,
                    p.rrht.name.c_str(), p.rrht_normals.name.c_str(), ratio,
                    ratio > 0 ? (ratio <= 1 ? "yes" : "no") : "n/a", m[1].seconds.size());
      targets << line << '\n';
      std::printf("target: %s\n", line);
    }
  }
}

void orientation(const Config& config)
{
  Config limited = config;
  limited.timeout = config.timeout ? (std::min)(config.timeout, orientation_time_seconds) : orientation_time_seconds;
  Experiment x(limited, "orientation");
  {
    Quality_csv csv(config);
    std::ofstream floor(config.out + "/orientation_floor.csv");
    floor << "cloud,kind,points,noise_percent,noise_seed,floor_percent\n";
    for(const std::size_t n : closed_sizes)
      for(const Dataset& clean : closed_shapes(config, n))
      {
        Cloud dense; // noise-free, 10 times denser, another seed: the floors' reference
        if(!closed_cloud(config, clean.name, 10 * n, 51, dense))
          continue;
        floor << clean.name << ",closed," << n << ",0,0,0\n";
        orientation_quality(config, csv, clean, "closed", false, 0);
        // Each noise draw has its floor. A shape with thin parts (a floor above
        // 0.1% at 0.2% noise on the first draw) runs at 0.05% noise too. Clean,
        // the floor is 0: every point lies on its own side (measured against
        // the dense sample, it would count the points where a part is thinner
        // than that sample's spacing, as the closed blade near its edges).
        std::vector<double> levels(1, 0.2);
        for(std::size_t level = 0; level < levels.size(); ++level)
          for(const unsigned int seed : noise_seeds)
          {
            Dataset noisy = clean;
            add_noise(noisy.cloud, levels[level], seed);
            noisy.noise_percent = levels[level];
            noisy.noise_seed = seed;
            const double floor_percent = 100. * share_nearer_the_other_side(noisy.cloud, dense);
            floor << clean.name << ",closed," << n << ',' << levels[level] << ',' << seed << ',' << floor_percent
                  << std::endl;
            std::printf("%-13s %zu floor at %g%% noise (seed %u): %.4f%%\n", clean.name.c_str(), n, levels[level],
                        seed, floor_percent);
            if(levels[level] == 0.2 && seed == noise_seeds[0] && floor_percent > 0.1)
              levels.push_back(0.05);
            orientation_quality(config, csv, noisy, "closed", seed == noise_seeds[0], floor_percent);
          }
        Dataset outliers = clean; // the outliers alone, without the noise
        add_outliers(outliers, 1, 0.02 * bounding_box_diagonal(clean.cloud), 48);
        orientation_quality(config, csv, outliers, "closed", false, 0);
      }
    const std::size_t n = 100000;
    // Open: a single curved sheet, and a twisted blade 0.04 thick (2% of its
    // chord), sampled on both sides, without caps.
    for(double noise : { 0., 0.2 })
    {
      orientation_quality(config, csv, synthetic("bent_sheet", [](std::size_t m, unsigned int seed) {
                            return bent_sheet(m, 0, seed); }, n, noise, 49), "open", noise > 0);
      const Dataset blade = synthetic("thin_blade", [](std::size_t m, unsigned int seed) {
                                        return thin_shape("thin_blade", m, seed); }, n, noise, 50);
      const double blade_floor =
        noise > 0 ? 100. * share_nearer_the_other_side(blade.cloud, thin_shape("thin_blade", 10 * n, 51)) : -1;
      if(noise > 0)
        floor << "thin_blade,open," << n << ',' << noise << ',' << blade.noise_seed << ',' << blade_floor << '\n';
      orientation_quality(config, csv, blade, "open", noise > 0, blade_floor); // the floor does not move its target
    }
    Dataset bunny;
    if(scan(config.shared("scans/bun000.xyz"), "bun000", bunny))
      orientation_quality(config, csv, bunny, "scan", true);
    else
      warn_missing(config.shared("scans/bun000.xyz"));
  }
  orientation_time(limited, x);
}

} // namespace

#endif // RRHT_BENCHMARK_ORIENTATION_EXPERIMENT_H
