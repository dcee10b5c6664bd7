// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf singularities: singularities and generator turning numbers of a face field.

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>

#include <cmath>
#include <string>
#include <vector>

namespace smdf_cli {

namespace {

// --matching FILE: lines 'i j k', the period jump k for crossing the edge of halfedge i -> j
// from its right face into its left face (as written by 'connection --matching-out');
// edges not listed have k = 0.
void read_matching(const std::string& mf, const Mesh& mesh, Edge_matching_property matching)
{
  const std::size_t nv = num_vertices(mesh);
  std::vector<std::size_t> seen(num_edges(mesh), 0);
  for_each_data_line(mf, [&](std::size_t line_no, const std::vector<std::string>& tok) {
    if(tok.size() != 3)
      throw line_error(mf, line_no, "expected 'i j k', got " + std::to_string(tok.size()) + " fields");
    const vertex_descriptor a(Mesh::size_type(vertex_field(mf, line_no, tok[0], nv)));
    const vertex_descriptor b(Mesh::size_type(vertex_field(mf, line_no, tok[1], nv)));
    const double k = finite_field(mf, line_no, tok[2]);
    if(k != std::round(k) || std::abs(k) > 1e9) throw line_error(mf, line_no, "period jump " + tok[2] + " is not an integer");
    const auto h = halfedge(a, b, mesh);
    if(!h.second) throw line_error(mf, line_no, "vertices " + tok[0] + " and " + tok[1] + " are not joined by an edge");
    const edge_descriptor e = edge(h.first, mesh);
    if(seen[std::size_t(e)]) throw line_error(mf, line_no, "edge " + tok[0] + " " + tok[1] + " was already given on line " + std::to_string(seen[std::size_t(e)]));
    seen[std::size_t(e)] = line_no;
    put(matching, e, halfedge(e, mesh) == h.first ? int(k) : -int(k));
  });
}

} // namespace

Json run_singularities(const Args& args)
{
  const std::string& file = args.positional[0];
  const long N = symmetry_order_option(args);
  if(!args.has("field")) throw Usage_error("missing option --field FILE" + see_help(args.command));
  const std::string ff = args.value("field");
  Mesh mesh;
  load_mesh(file, mesh);
  const std::size_t nf = num_faces(mesh);
  Face_vector_property vectors =
    mesh.add_property_map<face_descriptor, K::Vector_3>("f:smdf_vector", K::Vector_3(0, 0, 0)).first;
  std::size_t count = 0;
  for_each_data_line(ff, [&](std::size_t line_no, const std::vector<std::string>& tok) {
    if(count >= nf)
      throw line_error(ff, line_no, "more vectors than the " + std::to_string(nf) + " faces of the mesh");
    if(tok.size() != 3)
      throw line_error(ff, line_no, "expected 'x y z', got " + std::to_string(tok.size()) + " fields");
    double v[3];
    for(int k = 0; k < 3; ++k) v[k] = finite_field(ff, line_no, tok[k]);
    if(v[0] == 0 && v[1] == 0 && v[2] == 0)
      throw line_error(ff, line_no, "the vector of face " + std::to_string(count) + " is zero");
    put(vectors, face_descriptor(Mesh::size_type(count)), K::Vector_3(v[0], v[1], v[2]));
    ++count;
  });
  if(count < nf)
    throw file_error(ff, "only " + std::to_string(count) + " vectors for the " + std::to_string(nf) +
                     " faces of the mesh (one line 'x y z' per face)", "file_error");
  Face_angle_property angles = mesh.add_property_map<face_descriptor, double>("f:smdf_angle", 0.).first;
  SMDF::vectors_to_face_angles(mesh, vectors, angles);
  Edge_matching_property matching = mesh.add_property_map<edge_descriptor, int>("e:smdf_matching", 0).first;
  if(args.has("matching")) read_matching(args.value("matching"), mesh, matching);
  const SMDF::Field_topology<Mesh> topo = field_topology(file, mesh, angles, N, args.has("matching") ? &matching : nullptr);
  Json out = Json::object();
  out["N"] = N;
  out["singularities"] = found_list(topo);
  out["generator_turning_numbers"] = turning_numbers(topo);
  out["max_rounding_error"] = topo.max_rounding_error;
  return out;
}

Command singularities_command()
{
  return {"singularities", {"MESH"},
          {{"field", "FILE", "one direction 'x y z' per face, in file order (required)"},
           {"N", "n", "symmetry order (default 1)"},
           {"matching", "FILE", "period jumps 'i j k' per edge (connection --matching-out); default: principal matching"}},
          "singularities and generator turning numbers of a face field",
          "Reads one 3D direction per face (as written by 'connection --field-out'), projects it on\n"
          "the face plane and prints {N, singularities: [{vertex, index}], generator_turning_numbers,\n"
          "max_rounding_error}. Indices are multiples of 1/N; generators are those of 'generators'.\n"
          "Without --matching the rotation across each edge is the smallest one (principal\n"
          "matching); with it, the rotation is the wrapped angle difference plus 2 pi k / N.\n",
          run_singularities};
}

} // namespace smdf_cli
