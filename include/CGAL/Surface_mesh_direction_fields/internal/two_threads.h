// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_THREADS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_THREADS_H

// The package's only parallelism: two halves of a job on two threads (the machines it is tuned
// for have two cores).

#include <future>
#include <system_error>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Runs f(0) on the calling thread and f(1) on another one (on the calling thread too if no
// thread can be started, or if concurrent is false), and returns when both are done.
template <typename F>
void run_on_two_threads(const F& f, bool concurrent = true)
{
  std::future<void> other;
  if(concurrent) try {
    other = std::async(std::launch::async, [&f] { f(1); });
  } catch(const std::system_error&) {
  }
  f(0);
  if(other.valid()) other.get();
  else f(1);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_THREADS_H
