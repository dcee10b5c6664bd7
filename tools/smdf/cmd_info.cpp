// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf info: topology of a mesh.

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <algorithm>

namespace smdf_cli {

namespace {

// Faces whose Euclidean edge lengths do not form a proper triangle: the same test as the
// library's metric validation (is_valid_triangle() and relative area above 1e-14).
std::size_t count_degenerate_faces(const Mesh& mesh)
{
  const auto len = SMDF::get_edge_length_map(mesh);
  std::size_t n = 0;
  for(face_descriptor f : faces(mesh)) {
    const halfedge_descriptor h0 = halfedge(f, mesh), h1 = next(h0, mesh), h2 = next(h1, mesh);
    const double l0 = get(len, edge(h0, mesh)), l1 = get(len, edge(h1, mesh)),
                 l2 = get(len, edge(h2, mesh));
    const double lmax = (std::max)(l0, (std::max)(l1, l2));
    if(!SMDF::is_valid_triangle(l0, l1, l2) || SMDF::triangle_area(l0, l1, l2) <= 1e-14 * lmax * lmax)
      ++n;
  }
  return n;
}

} // namespace

Json run_info(const Args& args)
{
  const std::string& file = args.positional[0];
  Mesh mesh;
  const SMDF::Polygon_soup_report report = load_mesh(file, mesh);
  const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });

  Json genus = Json::array();
  for(const SMDF::Component_topology& c : topo.components) genus.push_back(c.genus);

  Json out = Json::object();
  out["file"] = file;
  out["vertices"] = num_vertices(mesh);
  out["edges"] = num_edges(mesh);
  out["faces"] = num_faces(mesh);
  out["components"] = topo.components.size();
  out["boundary_loops"] = topo.boundary_loops.size();
  out["euler_characteristic"] = topo.euler_characteristic();
  out["genus"] = genus;
  out["closed"] = topo.is_closed();
  out["betti_1"] = topo.betti_1();
  out["isolated_vertices"] = topo.isolated_vertices;
  out["reoriented_faces"] = report.reoriented_polygons;
  out["degenerate_faces"] = count_degenerate_faces(mesh);
  return out;
}

Command info_command()
{
  return {"info", {"MESH"}, {},
          "topology of a mesh: counts, components, boundary loops, genus",
          "Prints {file, vertices, edges, faces, components, boundary_loops, euler_characteristic,\n"
          "genus (one per component), closed, betti_1, isolated_vertices, reoriented_faces,\n"
          "degenerate_faces}. euler_characteristic and betti_1 are summed over the components\n"
          "(isolated vertices excluded); reoriented_faces counts faces flipped to make the\n"
          "orientation consistent; degenerate_faces counts faces of zero area (relative 1e-14) in\n"
          "the Euclidean metric, which info accepts but the geometric commands reject.\n",
          run_info};
}

} // namespace smdf_cli
