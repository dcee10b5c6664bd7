// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// smdf holonomy: Gauss-Bonnet check and holonomy of every generator, for the Euclidean metric
// or one given by edge lengths.

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace smdf_cli {

namespace {

typedef Mesh::Property_map<edge_descriptor, double> Edge_length_property;

// Reads an edge-length file: one line `i j length` per edge of `mesh` (vertex indices in
// either order); blank lines and lines starting with '#' are ignored. Every problem is an
// Error naming the file and the line.
Edge_length_property read_edge_lengths(const std::string& file, Mesh& mesh)
{
  Edge_length_property lengths =
    mesh.add_property_map<edge_descriptor, double>("e:smdf_length", 0.).first;
  std::vector<std::size_t> given_on(num_edges(mesh), 0);   // line number per edge, 0 = missing
  const std::size_t nv = num_vertices(mesh);
  for_each_data_line(file, [&](std::size_t line_no, const std::vector<std::string>& tok) {
    auto fail = [&](const std::string& what) { return line_error(file, line_no, what); };
    if(tok.size() != 3)
      throw fail("expected 'i j length', got " + std::to_string(tok.size()) + " fields");
    std::size_t ij[2];
    for(int k = 0; k < 2; ++k) ij[k] = vertex_field(file, line_no, tok[k], nv);
    const std::string pair = "(" + tok[0] + ", " + tok[1] + ")";
    const auto h = halfedge(vertex_descriptor(Mesh::size_type(ij[0])),
                            vertex_descriptor(Mesh::size_type(ij[1])), mesh);
    if(!h.second)
      throw fail("vertices " + tok[0] + " and " + tok[1] + " are not joined by an edge of the mesh");
    const edge_descriptor e = edge(h.first, mesh);
    if(given_on[std::size_t(e)] != 0)
      throw fail("edge " + pair + " was already given on line " + std::to_string(given_on[std::size_t(e)]));
    char* end = nullptr;
    const double l = std::strtod(tok[2].c_str(), &end);
    if(*end != '\0')
      throw fail("'" + shorten(tok[2]) + "' is not a number");
    if(!std::isfinite(l) || !(l > 0))
      throw fail("the length of edge " + pair + " must be positive and finite, got " + shorten(tok[2]));
    put(lengths, e, l);
    given_on[std::size_t(e)] = line_no;
  }, LINE_COMMENTS);
  const std::size_t missing = std::size_t(std::count(given_on.begin(), given_on.end(), std::size_t(0)));
  if(missing > 0) {
    for(edge_descriptor e : edges(mesh))
      if(given_on[std::size_t(e)] == 0) {
        const halfedge_descriptor h = halfedge(e, mesh);
        throw file_error(file, "no length for edge (" + std::to_string(index(source(h, mesh))) + ", " +
                         std::to_string(index(target(h, mesh))) + "); " + std::to_string(missing) +
                         " of " + std::to_string(num_edges(mesh)) + " edges are missing", "file_error");
      }
  }
  return lengths;
}

// Gauss-Bonnet and the holonomy of every generator for the metric given by `np`, read from
// `metric_file` (errors of the metric, such as degenerate faces, name that file).
template <typename NamedParameters>
void holonomy_report(const std::string& file, const std::string& metric_file, const Mesh& mesh,
                     const NamedParameters& np, Json& out, Json& timings, Stopwatch& clock)
{
  const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });
  const double total = on_file(metric_file, [&] { return SMDF::total_angle_defect(mesh, np); });
  timings["curvature"] = clock.lap();
  const SMDF::Intrinsic_holonomy<Mesh> holonomy =
    on_file(metric_file, [&] { return SMDF::Intrinsic_holonomy<Mesh>(mesh, np); });
  timings["precompute"] = clock.lap();
  const std::vector<SMDF::Homology_generator<Mesh>> gens =
    on_file(file, [&] { return SMDF::tree_cotree_generators(mesh); });
  timings["generators"] = clock.lap();

  Json list = Json::array();
  for(const SMDF::Homology_generator<Mesh>& g : gens) {
    const double lc = on_file(file, [&] { return holonomy.levi_civita_holonomy(g.dual_cycle); });
    const SMDF::Rigid_motion_2 m = on_file(file, [&] { return holonomy.generalized_holonomy(g.dual_cycle); });
    Json gh = Json::object();
    gh["rotation"] = m.rotation;
    gh["translation"] = Json::pair(m.translation.x(), m.translation.y());
    Json j = Json::object();
    j["kind"] = kind_name(g.kind);
    j["component"] = g.component;
    j["dual_cycle_length"] = g.dual_cycle.size();
    j["levi_civita_holonomy"] = lc;
    j["generalized_holonomy"] = std::move(gh);
    list.push_back(std::move(j));
  }
  timings["holonomy"] = clock.lap();

  const double two_pi_chi = 2 * CGAL_PI * double(topo.euler_characteristic());
  out["euler_characteristic"] = topo.euler_characteristic();
  out["total_angle_defect"] = total;
  out["two_pi_chi"] = two_pi_chi;
  out["gauss_bonnet_error"] = std::abs(total - two_pi_chi);
  out["generators"] = std::move(list);
}

} // namespace

Json run_holonomy(const Args& args)
{
  Stopwatch clock;
  const std::string& file = args.positional[0];
  Json out = Json::object();
  Json timings = Json::object();
  Mesh mesh;
  load_mesh(file, mesh);
  timings["read"] = clock.lap();
  out["file"] = file;
  if(args.has("lengths")) {
    const std::string lengths_file = args.value("lengths");
    const Edge_length_property lengths = read_edge_lengths(lengths_file, mesh);
    timings["lengths"] = clock.lap();
    out["metric"] = "lengths";
    out["lengths_file"] = lengths_file;
    holonomy_report(file, lengths_file, mesh, SMDF::parameters::edge_length_map(lengths), out,
                    timings, clock);
  } else {
    out["metric"] = "euclidean";
    holonomy_report(file, file, mesh, SMDF::parameters::default_values(), out, timings, clock);
  }
  timings["total"] = clock.total();
  out["timings"] = std::move(timings);
  return out;
}

Command holonomy_command()
{
  return {"holonomy", {"MESH"},
          {{"lengths", "FILE", "intrinsic metric: one line 'i j length' per edge"}},
          "Gauss-Bonnet check and Levi-Civita / generalized holonomy of every generator",
          "Prints {file, metric, euler_characteristic, total_angle_defect, two_pi_chi,\n"
          "gauss_bonnet_error, generators: [{kind, component, dual_cycle_length,\n"
          "levi_civita_holonomy, generalized_holonomy: {rotation, translation: [x, y]}}], timings}.\n"
          "Angles are in radians, in (-pi, pi]; timings are in seconds. The metric is Euclidean\n"
          "unless --lengths gives one length per edge (vertex indices in either order; blank lines\n"
          "and lines starting with '#' are ignored). Faces of zero area are an error.\n",
          run_holonomy};
}

} // namespace smdf_cli
