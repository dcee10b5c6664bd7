// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf generators: tree-cotree homology generators.

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <utility>
#include <vector>

namespace smdf_cli {

Json run_generators(const Args& args)
{
  const std::string& file = args.positional[0];
  Mesh mesh;
  load_mesh(file, mesh);
  const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });
  const std::vector<SMDF::Homology_generator<Mesh>> gens =
    on_file(file, [&] { return SMDF::tree_cotree_generators(mesh); });

  Json list = Json::array();
  for(const SMDF::Homology_generator<Mesh>& g : gens) {
    Json dual = Json::array();
    for(halfedge_descriptor h : g.dual_cycle)
      dual.push_back(Json::pair(index(source(h, mesh)), index(target(h, mesh))));
    Json primal = Json::array();
    for(halfedge_descriptor h : g.primal_loop) primal.push_back(index(source(h, mesh)));
    Json j = Json::object();
    j["kind"] = kind_name(g.kind);
    j["component"] = g.component;
    j["dual_edges"] = std::move(dual);
    j["primal_loop"] = std::move(primal);
    list.push_back(std::move(j));
  }
  Json out = Json::object();
  out["file"] = file;
  out["count"] = gens.size();
  out["betti_1"] = topo.betti_1();
  out["generators"] = std::move(list);
  return out;
}

Command generators_command()
{
  return {"generators", {"MESH"}, {},
          "tree-cotree homology generators (handle and boundary loops)",
          "Prints {file, count, betti_1, generators: [{kind: \"handle\"|\"boundary\", component,\n"
          "dual_edges, primal_loop}]}. dual_edges lists, in cycle order, the edges the dual cycle\n"
          "crosses, each as the vertex pair [i, j] of the halfedge i->j it crosses from its right\n"
          "face into its left face. primal_loop lists the vertices of a closed primal edge loop\n"
          "(the first vertex is not repeated at the end).\n",
          run_generators};
}

} // namespace smdf_cli
