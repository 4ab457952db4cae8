// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Progress report and interruption through the `callback` named parameter.

#ifndef CGAL_RRHT_INTERNAL_PROGRESS_H
#define CGAL_RRHT_INTERNAL_PROGRESS_H

#include <atomic>
#include <cstddef>
#include <functional>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Progress report and interruption through the user's callback, called
/// after every block of points: directly in a sequential run; in a parallel
/// run by the thread that finishes a block, one thread at a time (a thread
/// that finds the callback busy does not wait for it).
class Progress
{
public:
  Progress(const std::function<bool(double)>& callback, std::size_t total)
    : m_callback(callback), m_total(total), m_done(0), m_busy(false), m_interrupted(false)
  {}

  bool interrupted() const { return m_interrupted.load(std::memory_order_relaxed); }

  void add(std::size_t done)
  {
    const std::size_t now = m_done.fetch_add(done) + done;
    if(!m_callback || m_busy.exchange(true))
      return;
    if(!m_callback(double(now) / double(m_total)))
      m_interrupted = true;
    m_busy = false;
  }

  void finish()
  {
    if(m_callback && !interrupted())
      m_callback(1.);
  }

private:
  const std::function<bool(double)>& m_callback;
  std::size_t m_total;
  std::atomic<std::size_t> m_done;
  std::atomic<bool> m_busy;
  std::atomic<bool> m_interrupted;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_PROGRESS_H
