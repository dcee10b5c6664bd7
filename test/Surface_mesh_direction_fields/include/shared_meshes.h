// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef SMDF_TEST_SHARED_MESHES_H
#define SMDF_TEST_SHARED_MESHES_H

#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>

#include <exception>
#include <iostream>
#include <string>

#include "test_util.h"

namespace smdf_test {

// Every shared mesh that is manifold, oriented, of one component, without degenerate faces and
// of at most 120k faces, closed or open as asked, read and handed to f(entry, mesh).
template <typename Mesh, typename F>
void for_each_shared_mesh(const std::string& dir, bool open, const F& f)
{
  for(const auto& e : read_manifest(dir)) {
    if(e.manifold != "yes" || e.pure_tri != "yes" || e.orientable != "yes" || e.components != 1 ||
       (e.boundary_loops > 0) != open || e.degenerate_faces > 0 || e.F > 120000)
      continue;
    Mesh mesh;
    try {
      CGAL::Surface_mesh_direction_fields::read_triangle_mesh(dir + "/meshes/" + e.file, mesh);
    } catch(const std::exception& x) {
      std::cout << e.file << ": not read (" << x.what() << ")" << std::endl;
      continue;
    }
    f(e, mesh);
  }
}

} // namespace smdf_test

#endif
