// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// cgal_rrht._core: CGAL::rrht_estimate_normals() and CGAL::rrht_orient_normals()
// on NumPy arrays. The documented Python API is cgal_rrht.estimate_normals() and
// cgal_rrht.orient_normals() (cgal_rrht/__init__.py), which check the arrays and
// call the functions below. LASFile is CGAL::RRHT::IO's LAS reader and writer,
// which cgal_rrht.point_files reads and writes LAS files with.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/rrht_orient_normals.h>
#include <CGAL/RRHT/IO/LAS_file.h>
#include <CGAL/RRHT/IO/write_LAS_with_normals.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#include <tbb/task_arena.h>

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace py = pybind11;

namespace {

typedef CGAL::Simple_cartesian<double> Kernel;
// The points are the row indices of the array, read and written in place.
typedef boost::iterator_range<boost::counting_iterator<std::size_t>> Rows;

/// Row i of a C-contiguous (N, 3) array of doubles, as a point, followed by
/// the rows of a second such array (the points that are only neighbors).
struct Row_point_map
{
  typedef std::size_t key_type;
  typedef Kernel::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  const double* data;
  std::size_t size;
  const double* neighbors;

  friend value_type get(const Row_point_map& map, std::size_t i)
  {
    const double* row = i < map.size ? map.data + 3 * i : map.neighbors + 3 * (i - map.size);
    return value_type(row[0], row[1], row[2]);
  }
};

/// Whether row i is one of the second array of `Row_point_map`.
struct Row_neighbor_only_map
{
  typedef std::size_t key_type;
  typedef bool value_type;
  typedef bool reference;
  typedef boost::readable_property_map_tag category;
  std::size_t size;

  friend bool get(const Row_neighbor_only_map& map, std::size_t i) { return i >= map.size; }
};

/// Row i of a C-contiguous (N, 3) array of doubles, read and written as a
/// normal (the estimation only writes it, the orientation reads and flips it).
struct Row_normal_map
{
  typedef std::size_t key_type;
  typedef Kernel::Vector_3 value_type;
  typedef value_type reference;
  typedef boost::read_write_property_map_tag category;
  double* data;

  friend value_type get(const Row_normal_map& map, std::size_t i)
  {
    const double* row = map.data + 3 * i;
    return value_type(row[0], row[1], row[2]);
  }
  friend void put(const Row_normal_map& map, std::size_t i, const value_type& n)
  {
    double* row = map.data + 3 * i;
    row[0] = n.x();
    row[1] = n.y();
    row[2] = n.z();
  }
};

/// Element i of a (N,) array of doubles, written (a confidence, a support
/// radius).
struct Row_value_map
{
  typedef std::size_t key_type;
  typedef double value_type;
  typedef double reference;
  typedef boost::writable_property_map_tag category;
  double* data;

  friend void put(const Row_value_map& map, std::size_t i, double value) { map.data[i] = value; }
};

/// Element i of a (N,) array of 64-bit ids, or i itself when `data` is null
/// (the library's default ids): one instantiation of the estimation serves
/// both.
struct Row_id_map
{
  typedef std::size_t key_type;
  typedef std::uint64_t value_type;
  typedef std::uint64_t reference;
  typedef boost::readable_property_map_tag category;
  const std::uint64_t* data;

  friend std::uint64_t get(const Row_id_map& map, std::size_t i) { return map.data ? map.data[i] : i; }
};

/// The value named `name` in one of the library's name tables
/// (`CGAL::RRHT::sampling_names`, `aggregation_names`), or a ValueError
/// listing the names.
template <typename Table>
auto from_name(const std::string& name, const Table& names, const char* what)
{
  std::string valid;
  for(const auto& entry : names)
  {
    if(entry.first == name)
      return entry.second;
    valid += (valid.empty() ? "'" : ", '") + std::string(entry.first) + "'";
  }
  throw py::value_error("unknown " + std::string(what) + " '" + name + "': use one of " + valid);
}

/// The names of a name table, as a tuple (cgal_rrht.SETTINGS, SAMPLINGS, AGGREGATIONS).
template <typename Table>
py::tuple names_of(const Table& names)
{
  py::list list;
  for(const auto& entry : names)
    list.append(entry.first);
  return py::tuple(list);
}

/// An integer argument of the Python functions (a Python or NumPy integer,
/// not a bool) as the C++ type: a TypeError for another type, a ValueError
/// outside the type's range. The binding's one check of its integers; the
/// library checks the ranges of its parameters itself.
template <typename Integer>
Integer integer(const py::handle& value, const char* what)
{
  if(PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw py::type_error(std::string(what) + " must be an integer, not " +
                         py::str(value.get_type().attr("__name__")).cast<std::string>());
  const auto number = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  if(!number)
    throw py::error_already_set();
  const Integer low = std::numeric_limits<Integer>::min(), high = std::numeric_limits<Integer>::max();
  if(number < py::int_(low) || number > py::int_(high))
    throw py::value_error(std::string(what) + " must be from " + std::to_string(low) + " to " + std::to_string(high) +
                          ", got " + py::repr(number).cast<std::string>());
  return number.cast<Integer>();
}

/// The threads of a call (`threads` of the Python functions): None, TBB's
/// default (all cores), or 1 to 1024, the bound of rrht_normals --threads.
int thread_count(const py::handle& threads)
{
  if(threads.is_none())
    return 0;
  const long long count = integer<long long>(threads, "threads");
  if(count < 1 || count > 1024)
    throw py::value_error("threads must be from 1 to 1024, got " + std::to_string(count));
  return int(count);
}

/// Whether `array` has the shape (rows, 3): a guard for the memory read, the
/// Python side having checked the user's arrays with the user's names.
void check_rows(const py::array_t<double, py::array::c_style>& array, std::size_t rows, const char* what)
{
  if(array.ndim() != 2 || array.shape(1) != 3 || static_cast<std::size_t>(array.shape(0)) != rows)
    throw py::value_error(std::string(what) + " must have the shape (" + std::to_string(rows) + ", 3)");
}

struct Options
{
  unsigned int k;
  double radius; // 0: k nearest neighbors
  std::optional<long long> planes; // none: the Hoeffding bound of the accumulator
  long long rotations, slices, presampling;
  bool confidence_interval;
  bool least_squares_first;
  bool adaptive;
  bool refit;
  CGAL::RRHT::Sampling sampling;
  CGAL::RRHT::Aggregation aggregation;
  double cluster_angle;
  unsigned int seed;
  int threads; // 0: TBB's default, all cores
};

/// Runs the estimation on a thread of its own, without the GIL, while the
/// calling thread checks for Ctrl-C (Python handles signals only there) and
/// reports progress every `poll`: the run stops within one block of points.
void run_interruptibly(const std::function<void(const std::function<bool(double)>&)>& estimate,
                       const std::function<void(double)>& progress)
{
  const auto poll = std::chrono::milliseconds(100);
  std::atomic<double> done(0.);
  std::atomic<bool> stop(false);
  std::mutex mutex;
  std::condition_variable finished_cv;
  bool finished = false;
  std::exception_ptr cpp_error, python_error;
  {
    py::gil_scoped_release no_gil;
    std::thread worker([&]() {
      try
      {
        estimate([&](double advancement) {
          done = advancement;
          return !stop.load();
        });
      }
      catch(...)
      {
        cpp_error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mutex);
      finished = true;
      finished_cv.notify_one();
    });
    for(;;)
    {
      {
        std::unique_lock<std::mutex> lock(mutex);
        if(finished_cv.wait_for(lock, poll, [&]() { return finished; }))
          break;
      }
      py::gil_scoped_acquire gil;
      try
      {
        if(PyErr_CheckSignals() != 0)
          throw py::error_already_set();
        if(progress)
          progress(done.load());
      }
      catch(...)
      {
        python_error = std::current_exception();
        stop = true;
        break;
      }
    }
    worker.join();
  }
  if(python_error)
    std::rethrow_exception(python_error);
  if(cpp_error)
    std::rethrow_exception(cpp_error);
}

/// The normals, their confidences if `with_confidence` (else None) and their
/// support radii if `with_support` (else None). Every row is written (a point
/// with no normal gets zeros); on an interruption or an error nothing is
/// returned.
py::tuple estimate_normals(const py::array_t<double, py::array::c_style>& points,
                           const std::optional<py::array_t<double, py::array::c_style>>& neighbors,
                           const std::optional<py::array_t<std::uint64_t, py::array::c_style>>& ids,
                           const Options& options, bool with_confidence, bool with_support,
                           const std::function<void(double)>& progress)
{
  if(points.ndim() != 2 || points.shape(1) != 3)
    throw py::value_error("points must have the shape (N, 3)");
  if(neighbors && (neighbors->ndim() != 2 || neighbors->shape(1) != 3))
    throw py::value_error("neighbors must have the shape (M, 3)");
  const std::size_t size = static_cast<std::size_t>(points.shape(0));
  const std::size_t extra = neighbors ? static_cast<std::size_t>(neighbors->shape(0)) : 0;
  if(ids && (ids->ndim() != 1 || static_cast<std::size_t>(ids->shape(0)) != size + extra))
    throw py::value_error("ids must have the shape (N + M,), one per point and neighbor");
  py::array_t<double> normals({points.shape(0), py::ssize_t(3)});
  py::array_t<double> confidence(with_confidence ? points.shape(0) : 0);
  py::array_t<double> support(with_support ? points.shape(0) : 0);
  Rows rows(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(size + extra));

  const auto np = CGAL::RRHT::parameters::point_map(Row_point_map{points.data(), size, neighbors ? neighbors->data() : nullptr})
                    .neighbor_only_map(Row_neighbor_only_map{size})
                    .normal_map(Row_normal_map{normals.mutable_data()})
                    .point_id_map(Row_id_map{ids ? ids->data() : nullptr})
                    .neighbor_radius(options.radius)
                    .number_of_rotations(options.rotations)
                    .accumulator_slices(options.slices)
                    .use_confidence_interval(options.confidence_interval)
                    .least_squares_first(options.least_squares_first)
                    .adaptive(options.adaptive)
                    .refit(options.refit)
                    .sampling(options.sampling)
                    .presampling_factor(options.presampling)
                    .aggregation(options.aggregation)
                    .cluster_angle(options.cluster_angle)
                    .random_seed(options.seed);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  run_interruptibly(
    [&](const std::function<bool(double)>& callback) {
      auto run = [&](const auto& parameters) {
        const auto with_callback = parameters.callback(callback);
        if(options.planes)
          CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(rows, options.k,
                                                          with_callback.number_of_planes(*options.planes));
        else
          CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(rows, options.k, with_callback);
      };
      // The confidence and support maps only where they are asked for: with a
      // confidence map the default also votes where it keeps a quadric, and
      // with a support map it measures every point's support.
      auto run_with_support = [&](const auto& parameters) {
        if(with_support)
          run(parameters.support_radius_map(Row_value_map{ support.mutable_data() }));
        else
          run(parameters);
      };
      arena.execute([&]() {
        if(with_confidence)
          run_with_support(np.confidence_map(Row_value_map{ confidence.mutable_data() }));
        else
          run_with_support(np);
      });
    },
    progress);
  return py::make_tuple(normals, with_confidence ? py::object(confidence) : py::none(),
                        with_support ? py::object(support) : py::none());
}

/// Orients `normals` (N, 3) in place: towards `direction`, towards
/// `viewpoint`, towards the row of `viewpoints` of each point, or, with none
/// of them, consistently with `k` neighbors. The range oriented is a vector of
/// row indices, which CGAL::rrht_orient_normals() partitions, while the maps
/// read and write the arrays by row: the arrays keep their order. Rows that
/// cannot be oriented are left as they are.
void orient_normals(const py::array_t<double, py::array::c_style>& points,
                    py::array_t<double, py::array::c_style>& normals,
                    const std::optional<std::array<double, 3>>& direction,
                    const std::optional<std::array<double, 3>>& viewpoint,
                    const std::optional<py::array_t<double, py::array::c_style>>& viewpoints, const py::handle& k,
                    const py::handle& threads)
{
  if(points.ndim() != 2 || points.shape(1) != 3)
    throw py::value_error("points must have the shape (N, 3)");
  const std::size_t size = static_cast<std::size_t>(points.shape(0));
  check_rows(normals, size, "normals");
  if(viewpoints)
    check_rows(*viewpoints, size, "viewpoints");
  if(int(direction.has_value()) + int(viewpoint.has_value()) + int(viewpoints.has_value()) > 1)
    throw py::value_error("give direction or viewpoint, not both");
  const unsigned int neighbors = integer<unsigned int>(k, "k");
  const int thread_limit = thread_count(threads);
  std::vector<std::size_t> rows(size);
  std::iota(rows.begin(), rows.end(), std::size_t(0));
  const auto np = CGAL::RRHT::parameters::point_map(Row_point_map{points.data(), size, nullptr})
                    .normal_map(Row_normal_map{normals.mutable_data()});
  // No callback to stop it: with the GIL released, a Ctrl-C is raised when it returns.
  py::gil_scoped_release no_gil;
  tbb::task_arena arena(thread_limit > 0 ? thread_limit : tbb::task_arena::automatic);
  arena.execute([&]() {
    if(direction)
      CGAL::rrht_orient_normals<CGAL::Parallel_tag>(
        rows, neighbors, np.direction(Kernel::Vector_3((*direction)[0], (*direction)[1], (*direction)[2])));
    else if(viewpoint)
      CGAL::rrht_orient_normals<CGAL::Parallel_tag>(
        rows, neighbors, np.viewpoint(Kernel::Point_3((*viewpoint)[0], (*viewpoint)[1], (*viewpoint)[2])));
    else if(viewpoints)
      CGAL::rrht_orient_normals<CGAL::Parallel_tag>(rows, neighbors,
                                                    np.viewpoint_map(Row_point_map{viewpoints->data(), size, nullptr}));
    else
      CGAL::rrht_orient_normals<CGAL::Parallel_tag>(rows, neighbors, np);
  });
}

/// Records `start` to `stop` (clipped to the file, as a slice) of `file`, as
/// a first record and a count.
std::pair<std::uint64_t, std::uint64_t> record_range(const CGAL::RRHT::IO::LAS_file& file, std::uint64_t start,
                                                     std::optional<std::uint64_t> stop)
{
  const std::uint64_t end = (std::min)(stop.value_or(file.size()), file.size());
  const std::uint64_t first = (std::min)(start, end);
  return { first, end - first };
}

void bind_LAS_file(py::module_& m)
{
  using CGAL::RRHT::IO::LAS_file;
  py::register_exception<CGAL::RRHT::IO::LAS_error>(m, "LASError", PyExc_ValueError);
  py::class_<LAS_file>(m, "LASFile",
                       "An uncompressed LAS file (1.0 to 1.4, point formats 0 to 10), checked when opened "
                       "(CGAL::RRHT::IO::LAS_file); LASError says what cannot be read.")
    .def(py::init<const std::string&>(), py::arg("path"), py::call_guard<py::gil_scoped_release>())
    .def("__len__", [](const LAS_file& file) { return file.size(); })
    .def_property_readonly("version", [](const LAS_file& file) { return py::make_tuple(1, file.version_minor()); })
    .def_property_readonly("point_format", &LAS_file::point_format)
    .def_property_readonly("fields",
                           [](const LAS_file& file) {
                             std::vector<std::string> names;
                             for(const auto& field : file.extra_bytes())
                               if(field.holds_one_number())
                                 names.push_back(field.name);
                             return names;
                           },
                           "The names of the extra bytes' fields of one number, in the records' order.")
    .def(
      "read_points",
      [](const LAS_file& file, std::uint64_t start, std::optional<std::uint64_t> stop) {
        const auto [first, count] = record_range(file, start, stop);
        py::array_t<double> xyz({ py::ssize_t(count), py::ssize_t(3) });
        double* out = xyz.mutable_data();
        py::gil_scoped_release release;
        file.read_points(first, count, out);
        return xyz;
      },
      py::arg("start") = 0, py::arg("stop") = py::none(),
      "The points of records `start` to `stop` (default: the end), as a float64 array (n, 3): X * scale + offset.")
    .def(
      "read_field",
      [](const LAS_file& file, const std::string& name, std::uint64_t start, std::optional<std::uint64_t> stop) {
        file.extra_bytes_field(name); // a LASError now if there is none
        const auto [first, count] = record_range(file, start, stop);
        py::array_t<double> values(py::ssize_t{ py::ssize_t(count) });
        double* out = values.mutable_data();
        py::gil_scoped_release release;
        file.read_field(name, first, count, out);
        return values;
      },
      py::arg("name"), py::arg("start") = 0, py::arg("stop") = py::none(),
      "The extra-bytes field `name` of records `start` to `stop`, scaled and offset as its descriptor says, as "
      "a float64 array (n,).")
    .def(
      "write_with_normals",
      [](const LAS_file& file, const std::string& path, const py::array_t<double, py::array::c_style>& normals,
         const std::optional<py::array_t<double, py::array::c_style>>& confidences) {
        check_rows(normals, std::size_t(file.size()), "normals");
        if(confidences && (confidences->ndim() != 1 || std::uint64_t(confidences->shape(0)) != file.size()))
          throw py::value_error("confidences must have the shape (" + std::to_string(file.size()) + ",)");
        const double* n = normals.data();
        const double* c = confidences ? confidences->data() : nullptr;
        py::gil_scoped_release release;
        CGAL::RRHT::IO::write_LAS_with_normals(file, path, n, c);
      },
      py::arg("path"), py::arg("normals").noconvert(), py::arg("confidences").noconvert().none(true) = py::none(),
      "Writes to `path` every record of this file, byte for byte, with its normal (a C-contiguous float64 array "
      "(N, 3)) and confidence (None or (N,)) in the extra bytes NormalX, NormalY, NormalZ (and NormalConfidence), "
      "as rrht_normals writes them, through a temporary file renamed at the end.");
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "CGAL::rrht_estimate_normals() and CGAL::rrht_orient_normals() on NumPy arrays; use "
            "cgal_rrht.estimate_normals() and cgal_rrht.orient_normals().";
  m.attr("SETTINGS") = names_of(CGAL::RRHT::setting_names);
  m.attr("SAMPLINGS") = names_of(CGAL::RRHT::sampling_names);
  m.attr("AGGREGATIONS") = names_of(CGAL::RRHT::aggregation_names);
  m.def(
    "estimate_normals",
    [](const py::array_t<double, py::array::c_style>& points,
       const std::optional<py::array_t<double, py::array::c_style>>& neighbors,
       const std::optional<py::array_t<std::uint64_t, py::array::c_style>>& ids, const py::handle& k,
       std::optional<double> radius, const py::handle& planes, const py::handle& rotations, const py::handle& slices,
       bool confidence_interval, const std::string& sampling, const py::handle& presampling,
       const std::string& aggregation, double cluster_angle, const py::handle& seed, bool least_squares_first,
       bool adaptive, bool refit, const py::handle& threads,
       bool return_confidence,
       bool return_support, const std::function<void(double)>& progress) {
      Options options;
      options.k = integer<unsigned int>(k, "k");
      options.radius = radius.value_or(0.);
      if(!planes.is_none())
        options.planes = integer<long long>(planes, "planes");
      options.rotations = integer<long long>(rotations, "rotations");
      options.slices = integer<long long>(slices, "slices");
      options.presampling = integer<long long>(presampling, "presampling");
      options.confidence_interval = confidence_interval;
      options.sampling = from_name(sampling, CGAL::RRHT::sampling_names, "sampling");
      options.aggregation = from_name(aggregation, CGAL::RRHT::aggregation_names, "aggregation");
      options.cluster_angle = cluster_angle;
      options.seed = integer<unsigned int>(seed, "seed");
      options.least_squares_first = least_squares_first;
      options.adaptive = adaptive;
      options.refit = refit;
      options.threads = thread_count(threads);
      return estimate_normals(points, neighbors, ids, options, return_confidence, return_support, progress);
    },
    py::arg("points").noconvert(), py::arg("neighbors").noconvert().none(true), py::arg("ids").noconvert().none(true),
    py::arg("k"), py::arg("radius").none(true), py::arg("planes").none(true),
    py::arg("rotations"), py::arg("slices"), py::arg("confidence_interval"), py::arg("sampling"),
    py::arg("presampling"), py::arg("aggregation"), py::arg("cluster_angle"), py::arg("seed"),
    py::arg("least_squares_first"), py::arg("adaptive"), py::arg("refit"), py::arg("threads").none(true), py::arg("return_confidence"),
    py::arg("return_support"), py::arg("progress").none(true),
    "The estimation behind cgal_rrht.estimate_normals(), whose documentation says what each argument is.\n"
    "`points` is a C-contiguous float64 array (N, 3), read in place, `neighbors` None or another (M, 3),\n"
    "`ids` None or a C-contiguous uint64 array (N + M,); `progress`, if not None, is called with the advancement (0 to 1). Returns the normals\n"
    "(N, 3), their confidences (N,) if `return_confidence` (else None) and their support radii (N,) if\n"
    "`return_support` (else None).");
  m.def("orient_normals", &orient_normals, py::arg("points").noconvert(), py::arg("normals").noconvert(),
        py::arg("direction").none(true), py::arg("viewpoint").none(true), py::arg("viewpoints").noconvert().none(true),
        py::arg("k"), py::arg("threads").none(true),
        "The orientation behind cgal_rrht.orient_normals(), whose documentation says what each argument is.\n"
        "`points` and `normals` are C-contiguous float64 arrays (N, 3); `normals` is oriented in place, row by row.\n"
        "At most one of `direction` (3 numbers), `viewpoint` (3 numbers) and `viewpoints` (a C-contiguous\n"
        "float64 array (N, 3)) is given; with none, the orientation is consistent, with `k` neighbors.");
  bind_LAS_file(m);
}
