// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHOLMOD_ERRORS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHOLMOD_ERRORS_H

#include <cholmod.h>

#include <string>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// A library does not print: CHOLMOD's own printing is off and its error handler records the
// last message of the calling thread, which the failure messages then quote.
inline std::string& last_cholmod_error()
{
  static thread_local std::string message;
  return message;
}

inline void record_cholmod_error(int status, const char* file, int line, const char* message)
{
  (void)file;
  (void)line;
  last_cholmod_error() = std::string(message ? message : "unknown error") + " (CHOLMOD status " + std::to_string(status) + ")";
}

inline void make_cholmod_quiet(cholmod_common& cc)
{
  cc.print = 0;
  cc.error_handler = &record_cholmod_error;
}

// " (CHOLMOD: <last message>)", or "" if CHOLMOD reported nothing since the last call
inline std::string take_cholmod_error()
{
  std::string m;
  m.swap(last_cholmod_error());
  return m.empty() ? m : " (CHOLMOD: " + m + ")";
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHOLMOD_ERRORS_H
