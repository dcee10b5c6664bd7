// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// libFuzzer target: the mesh reading and validation of the package on arbitrary bytes.
// The first byte chooses the format ('o' OFF, 'b' OBJ, 'p' PLY, 's' STL; other values by their
// remainder), the rest is the file. Every input must end in a mesh or an Input_error; a mesh
// that is read is also validated as an Intrinsic_mesh and, when small, solved for a trivial
// connection.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  const char* ext = ".off";
  switch(data[0]) {
    case 'o': ext = ".off"; break;
    case 'b': ext = ".obj"; break;
    case 'p': ext = ".ply"; break;
    case 's': ext = ".stl"; break;
    default: { const char* e[4] = {".off", ".obj", ".ply", ".stl"}; ext = e[data[0] % 4]; }
  }
  const std::string file = "/tmp/smdf_fuzz_mesh_" + std::to_string(getpid()) + ext;
  {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  try {
    Mesh mesh;
    SMDF::read_triangle_mesh(file, mesh);
    SMDF::Intrinsic_mesh<Mesh> im(mesh);
    if(num_faces(mesh) <= 2000) {
      SMDF::Trivial_connection<Mesh> tc(mesh, SMDF::parameters::intrinsic_mesh(im));
      bool closed_nonzero_chi = false;
      for(std::size_t c = 0; c < im.topology_arrays().components.size(); ++c) {
        const auto& comp = im.topology_arrays().components[c];
        closed_nonzero_chi = closed_nonzero_chi || (comp.boundary_loops == 0 && comp.euler_characteristic() != 0);
      }
      if(!closed_nonzero_chi) tc.solve();   // otherwise the zero indices are rejected by design
    }
  } catch(const SMDF::Input_error&) {
  }
  std::remove(file.c_str());
  return 0;
}
