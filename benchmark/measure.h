// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One measurement of one normal estimator on one cloud: wall time of each
// run, peak memory and the angle errors against the truth.
//
// Each measurement runs in a child process (fork), so that
// - its peak memory is its own: the child resets the kernel's high-water
//   mark (/proc/self/clear_refs) once its copy of the input is made, and the
//   peak is the resident size above that baseline at the end (input and
//   output excluded, everything the estimator allocates included);
// - TBB's number of threads is set for that measurement alone
//   (tbb::global_control), the parent never starting TBB, and so are the
//   cores it may run on, if given (sched_setaffinity);
// - a crash or a time-out of one estimator is recorded, not fatal.

#ifndef CGAL_RRHT_BENCHMARK_MEASURE_H
#define CGAL_RRHT_BENCHMARK_MEASURE_H

#include "shapes.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <malloc.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rrht_benchmark {

using namespace rrht_test;

/// Writes normals into the samples of a cloud.
typedef std::function<void(Cloud&, unsigned int threads)> Estimate;

struct Measurement
{
  enum Status { OK, FAILED, TIMEOUT, CRASHED };
  Status status = FAILED;
  std::vector<double> seconds;  // one wall time per run
  double peak_mib = 0;          // peak resident memory above the input, MiB
  Errors errors;                // on the samples that have a truth
  std::size_t null_normals = 0; // samples left with a null normal
  std::string message;          // why, when not OK

  double median() const
  {
    if(seconds.empty())
      return 0;
    std::vector<double> s = seconds;
    std::sort(s.begin(), s.end());
    return (s.size() % 2) ? s[s.size() / 2] : (s[s.size() / 2 - 1] + s[s.size() / 2]) / 2;
  }
  const char* status_name() const
  {
    static const char* names[] = { "ok", "failed", "timeout", "crashed" };
    return names[status];
  }
};

namespace internal {

// Resident memory from /proc/self/status: "VmRSS" or "VmHWM", in kB.
inline double resident_kib(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen(field);
  while(std::getline(status, line))
    if(line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':')
      return std::stod(line.substr(length + 1));
  return 0;
}

inline bool reset_peak_resident()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5"; // resets VmHWM to the current VmRSS (Linux >= 4.0)
  clear.flush();
  return bool(clear);
}

// What the child sends back through the pipe.
struct Report
{
  int status;
  int runs;
  double seconds[16];
  double peak_mib;
  Errors errors;
  std::size_t null_normals;
  char message[240];
};

inline bool write_all(int fd, const void* data, std::size_t size)
{
  const char* p = static_cast<const char*>(data);
  while(size > 0)
  {
    const ssize_t n = ::write(fd, p, size);
    if(n <= 0)
      return false;
    p += n;
    size -= std::size_t(n);
  }
  return true;
}

inline std::size_t read_all(int fd, void* data, std::size_t size)
{
  char* p = static_cast<char*>(data);
  std::size_t got = 0;
  while(got < size)
  {
    const ssize_t n = ::read(fd, p + got, size - got);
    if(n <= 0)
      break;
    got += std::size_t(n);
  }
  return got;
}

// Per-point errors for the renderings: x y z, truth, error in degrees, and
// the confidence (-1 unless the estimator wrote one), for every sample in
// order (a sample without truth has the error -1).
inline void write_errors(const Cloud& cloud, const std::string& path)
{
  std::FILE* f = std::fopen(path.c_str(), "w");
  if(!f)
    return;
  for(const Sample& s : cloud)
    std::fprintf(f, "%.6g %.6g %.6g %.4g %.4g %.4g %.3f %.6g\n", s.point.x(), s.point.y(), s.point.z(), s.truth.x(),
                 s.truth.y(), s.truth.z(), s.truth != CGAL::NULL_VECTOR ? angle_error(s) : -1., s.confidence);
  std::fclose(f);
}

} // namespace internal

/// The first `count` cores this process may run on, or none if it may run
/// on fewer.
inline std::vector<int> first_cores(std::size_t count)
{
  std::vector<int> cores;
  cpu_set_t set;
  CPU_ZERO(&set);
  if(::sched_getaffinity(0, sizeof set, &set) == 0)
    for(int c = 0; c < CPU_SETSIZE && cores.size() < count; ++c)
      if(CPU_ISSET(c, &set))
        cores.push_back(c);
  return cores.size() == count ? cores : std::vector<int>();
}

/// Runs `estimate` `runs` times on copies of `cloud` with `threads` threads,
/// on the `cores` given (any, if none), in a child process killed after
/// `timeout_seconds` (0: no limit). Writes the per-point errors of the first
/// run to `errors_path` if not empty.
inline Measurement measure(const Estimate& estimate, const Cloud& cloud, unsigned int threads, int runs,
                           unsigned int timeout_seconds, const std::string& errors_path = std::string(),
                           const std::vector<int>& cores = std::vector<int>())
{
  runs = (std::max)(1, (std::min)(runs, 16));
  std::fflush(stdout);
  std::fflush(stderr);
  int fd[2];
  Measurement m;
  if(::pipe(fd) != 0)
  {
    m.message = "pipe() failed";
    return m;
  }
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fd[0]);
    ::close(fd[1]);
    m.message = "fork() failed";
    return m;
  }
  if(pid == 0) // the child: measure, report, exit without unwinding the parent's state
  {
    ::close(fd[0]);
    if(timeout_seconds > 0)
      ::alarm(timeout_seconds);
    internal::Report r{};
    r.status = Measurement::FAILED;
    try
    {
      if(!cores.empty())
      {
        cpu_set_t set;
        CPU_ZERO(&set);
        for(int c : cores)
          CPU_SET(c, &set);
        if(::sched_setaffinity(0, sizeof set, &set) != 0)
          throw std::runtime_error("sched_setaffinity() failed");
      }
      tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, threads);
      Cloud work;
      for(int run = 0; run < runs; ++run)
      {
        work = cloud; // not timed
        if(run == 0)
        {
          ::malloc_trim(0);
          internal::reset_peak_resident();
        }
        const double baseline = (run == 0) ? internal::resident_kib("VmRSS") : 0;
        const auto start = std::chrono::steady_clock::now();
        estimate(work, threads);
        r.seconds[run] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if(run == 0)
        {
          r.peak_mib = (internal::resident_kib("VmHWM") - baseline) / 1024.;
          r.errors = errors(work);
          for(const Sample& s : work)
            r.null_normals += (s.normal == CGAL::NULL_VECTOR);
          if(!errors_path.empty())
            internal::write_errors(work, errors_path);
        }
      }
      r.runs = runs;
      r.status = Measurement::OK;
    }
    catch(const std::exception& e)
    {
      std::snprintf(r.message, sizeof r.message, "%s", e.what());
    }
    internal::write_all(fd[1], &r, sizeof r);
    ::_exit(0);
  }
  ::close(fd[1]);
  internal::Report r;
  const std::size_t got = internal::read_all(fd[0], &r, sizeof r);
  ::close(fd[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if(got != sizeof r)
  {
    const bool alarm = WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM;
    m.status = alarm ? Measurement::TIMEOUT : Measurement::CRASHED;
    m.message = alarm ? "time limit of " + std::to_string(timeout_seconds) + " s reached"
                      : (WIFSIGNALED(status) ? std::string("killed by signal ") + std::to_string(WTERMSIG(status))
                                              : std::string("exited without a report"));
    return m;
  }
  m.status = Measurement::Status(r.status);
  m.seconds.assign(r.seconds, r.seconds + r.runs);
  m.peak_mib = r.peak_mib;
  m.errors = r.errors;
  m.null_normals = r.null_normals;
  m.message = r.message;
  return m;
}

} // namespace rrht_benchmark

#endif // CGAL_RRHT_BENCHMARK_MEASURE_H
