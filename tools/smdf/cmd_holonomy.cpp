// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
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
