// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: a regular quad or triangle mesh from a flat cone metric (Lai et al. 2010,
// section 5): the mesh's own metric, a metric read from a file, or the box polycube metric.

#include "commands.h"
#include "common.h"
#include "remesh_measures.h"
#include "remesh_placed_cones.h"
#include "remesh_pictures.h"
#include "remesh_polyhedra.h"
#include "remesh_untangle.h"

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>
#include <CGAL/Surface_mesh_direction_fields/tessellation_on_input.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/polycube_metric.h>
#include <CGAL/Surface_mesh_direction_fields/polyhedron_remeshing.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <array>
#include <iomanip>
#include <iostream>
#include <locale>
#include <sstream>
#include <map>
#include <cmath>
#include <string>
#include <vector>

namespace smdf_cli {

// The JSON of polyhedron_compatibility(): the face-by-face test of a metric against P.
Json compatibility_json(const SMDF::Polyhedron_compatibility& pc)
{
  Json c = Json::object(), failing = Json::array();
  c["compatible"] = pc.compatible;
  if(!pc.message.empty()) c["message"] = pc.message;
  c["max_angle_deviation"] = pc.max_angle_deviation;
  c["max_side_deviation"] = pc.max_side_deviation;
  c["curved_vertices"] = pc.curved_vertices;
  for(std::size_t i = 0; i < pc.failing_faces.size() && i < 20; ++i) {
    Json o = Json::object();
    o["face"] = pc.failing_faces[i];
    o["angle_deviation"] = pc.failing_face_angle_deviations[i];
    o["side_deviation"] = pc.failing_face_side_deviations[i];
    failing.push_back(std::move(o));
  }
  c["failing_faces"] = std::move(failing);   // the first 20
  return c;
}

Json run_remesh(const Args& args)
{
  const std::string& file = args.positional[0];
  const std::string grid_name = args.value("grid", "quad");
  if(grid_name != "quad" && grid_name != "triangle" && grid_name != "mixed")
    throw Usage_error("option --grid expects 'quad', 'triangle' or 'mixed', got '" + shorten(grid_name) + "'");
  SMDF::Planar_tessellation grid = grid_name == "quad" ? SMDF::SQUARE_GRID : SMDF::TRIANGULAR_GRID;
  if(args.has("edge-length") == args.has("faces")) throw Usage_error("give one of --edge-length and --faces");
  const double requested_h = args.has("edge-length") ? args.real("edge-length", 0) : 0;
  const long requested_faces = args.has("faces") ? args.integer("faces", 0) : 0;
  if(args.has("edge-length") && !(requested_h > 0)) throw Usage_error("option --edge-length expects a positive number");
  if(args.has("faces") && requested_faces < 1) throw Usage_error("option --faces expects a positive integer");
  const std::string polycube = args.value("polycube", "");
  if(args.has("polycube") && polycube.empty()) throw Usage_error("option --polycube expects 'box', 'octahedron' or a file");
  if(args.has("polycube") && args.has("lengths")) throw Usage_error("give at most one of --polycube and --lengths");
  if(polycube == "box" && grid != SMDF::SQUARE_GRID) throw Usage_error("--polycube box gives a metric for --grid quad");
  if(polycube == "octahedron" && args.has("grid") && grid_name != "triangle")
    throw Usage_error("--polycube octahedron gives a metric for --grid triangle");
  if(grid_name == "mixed" && (polycube.empty() || polycube == "box" || polycube == "octahedron"))
    throw Usage_error("--grid mixed needs a polyhedron of squares and triangles: --polycube obelisk or --polycube FILE");
  if(!args.has("polycube") && (args.has("segments") || args.has("relaxation")))
    throw Usage_error("--segments and --relaxation shape a polyhedron's metric: give --polycube");
  if(args.has("segments") && args.has("relaxation") && args.value("segments") == "ricci")
    throw Usage_error("--relaxation applies to --segments relaxed; Lai et al.'s Ricci flow segments are not relaxed");
  if(!args.has("out")) throw Usage_error("option --out FILE is required (.off or .obj)");
  const std::string out_file = args.value("out");
  if(args.has("knot-svg") && (grid_name != "quad" || polycube == "octahedron" || polycube == "obelisk"))
    throw Usage_error("--knot-svg draws a Celtic knot on a quad remesh: use --grid quad");
  if((args.has("cones") || args.has("cone-indices")) && args.has("lengths"))
    throw Usage_error("give at most one of --cones and --lengths (the lengths file is the metric)");
  if((args.has("cones") || args.has("cone-indices")) && polycube == "obelisk")
    throw Usage_error("--polycube obelisk places its own nine cones; with --cones give the polyhedron as a file");
  // Automatic cones (placed, then an integer-grid map): with --place-cones, and by default for
  // quads when no metric is given (--cones, --lengths, --polycube) and the input's own metric is
  // not already one to tessellate (every curvature a multiple of pi/2, as on a cube).
  const bool given_metric = args.has("cones") || args.has("cone-indices") || args.has("lengths") || args.has("polycube");
  const bool may_place = !given_metric && grid_name == "quad";
  if(args.has("place-cones") && given_metric)
    throw Usage_error("--place-cones chooses the cones itself: give none of --cones, --cone-indices, --lengths and --polycube");
  if(args.has("place-cones") && grid_name != "quad") throw Usage_error("--place-cones makes an integer-grid map for --grid quad");
  if(!may_place && (args.has("distortion-bound") || args.has("max-cones") || args.has("cone-spacing") || args.has("uv-out")))
    throw Usage_error("--distortion-bound, --max-cones, --cone-spacing and --uv-out apply to automatic cones (quads, no --cones, --lengths or --polycube)");
  const double distortion_bound = may_place ? args.real("distortion-bound", 2.0) : 0;
  if(may_place && !(distortion_bound > 0 && std::isfinite(distortion_bound)))
    throw Usage_error("option --distortion-bound expects a positive number, got '" + args.value("distortion-bound") + "'");
  const double cone_spacing = may_place && args.has("cone-spacing") ? args.real("cone-spacing", 0) : -1;   // -1: automatic
  if(may_place && args.has("cone-spacing") && !(cone_spacing >= 0 && cone_spacing <= 1000))
    throw Usage_error("option --cone-spacing expects a number from 0 to 1000, got '" + args.value("cone-spacing") + "'");
  const long max_cones = may_place ? args.integer("max-cones", 500) : 0;
  if(may_place && (max_cones < 1 || max_cones > 100000))
    throw Usage_error("option --max-cones expects an integer in [1, 100000], got '" + args.value("max-cones") + "'");
  const SMDF::Svg_options svg_check = svg_options(args);   // usage errors of --view and --width
  (void)svg_check;

  Mesh mesh;
  // a remesher replaces the faces anyway: quads and polygons are split into triangles first
  const SMDF::Polygon_soup_report soup = load_mesh(file, mesh, true);
  const bool place = args.has("place-cones") || (may_place && !embedding_fits_quads(mesh));
  if(args.has("uv-out") && !place)
    throw Error(file + ": --uv-out writes the integer-grid map of automatic cones, but this mesh's curvatures are all multiples of pi/2: "
                       "its own metric is tessellated (give --place-cones for the map) [invalid_input]");
  Stopwatch clock;
  const bool progress = args.has("progress");
  const bool untangle = !args.has("no-untangle");
  std::string untangle_message;
  const long relax = args.has("relaxation") ? args.integer("relaxation", 0) : 10;
  if(relax < 0 || relax > 1000) throw Usage_error("option --relaxation expects an integer from 0 to 1000");
  const int relax_steps = int(relax);
  const std::string segments = args.value("segments", "relaxed");
  if(segments != "relaxed" && segments != "ricci")
    throw Usage_error("option --segments expects relaxed or ricci, got '" + segments + "'");
  const SMDF::Segment_flattening flattening = segments == "ricci" ? SMDF::RICCI_FLOW_SEGMENTS : SMDF::RELAXED_SEGMENTS;
  auto stage = [&](const char* what) {
    if(!progress) return;
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << "smdf remesh: " << what << " (" << std::fixed << std::setprecision(3) << clock.total() << " s)";
    std::cerr << os.str() << std::endl;
  };
  const std::vector<std::pair<vertex_descriptor, double>> cones = cone_option(args, mesh);
  if(args.has("polycube")) {
    const SMDF::Mesh_topology<Mesh> topo = SMDF::mesh_topology(mesh);
    if(topo.components.size() != 1 || !topo.is_closed() || topo.components[0].genus != 0)
      throw Error(file + ": --polycube needs a closed genus-0 mesh of one component (a sphere); this one has " +
                  std::to_string(topo.components.size()) + " component(s), genus " + std::to_string(topo.components.empty() ? 0 : topo.components[0].genus) +
                  " and " + std::to_string(topo.boundary_loops.size()) + " boundary loop(s) [invalid_input]");
  }
  Json out = Json::object();
  if(soup.triangulated_polygons > 0) out["triangulated_polygons"] = soup.triangulated_polygons;
  const Input_faces_tree input_tree(mesh);   // for the read-backs of every attempt
  // Every route's untangling (every other check passed): the inverted faces (the tessellation's
  // count, `inverted`), the faces flipped against the input's normal nearest their centroid (a
  // face bent over a ridge, which the test at the corners misses) and the faces folded at a
  // corner, against their own area vector or that normal. Returns the measures against the
  // input after it.
  auto untangle_if_needed = [&](Mesh& remesh, bool& success, std::string& failure, std::size_t& inverted, Json& timings) {
    On_input_measures on_input = measures_on_input(input_tree, remesh);
    if(untangle && (inverted > 0 || (success && (on_input.flipped_faces > 0 || on_input.folded_faces > 0 || nonconvex_quads(remesh) > 0)))) {
      stage("untangling inverted faces");
      out["untangle"] = untangle_inverted(mesh, remesh, success, inverted, untangle_message);
      if(!success) failure += "; untangling: " + untangle_message;
      timings["untangle_s"] = clock.lap();
      on_input = measures_on_input(input_tree, remesh);
    }
    return on_input;
  };
  // the scaled Jacobian against the input (the measure of compare_quadriflow.py) beside the
  // remesh's own
  auto quality_json = [&](const Mesh& remesh, const On_input_measures& on_input) {
    Json q = remesh_quality(remesh);
    q["min_scaled_jacobian_on_input"] = on_input.min_scaled_jacobian;
    q["mean_scaled_jacobian_on_input"] = on_input.mean_scaled_jacobian;
    q["faces_folded_on_input"] = on_input.folded_faces;
    return q;
  };
  // Every route's last read-back, stricter than the library's normals under the corners: no face
  // whose normal opposes the input's at the input point nearest its centroid.
  auto check_flipped_faces = [&](std::size_t flipped, bool& success, std::string& failure) {
    out["flipped_faces"] = flipped;
    if(flipped > 0 && success) {
      success = false;
      failure = std::to_string(flipped) + " faces point against the input's normal at the input point nearest their centroid "
                "(flipped; the metric stretches too much for this edge length, or the grid folds near a cone)";
    }
  };
  out["grid"] = grid_name;
  const double unit_area = grid == SMDF::SQUARE_GRID ? 1. : std::sqrt(3.) / 4;
  // 1. the metric
  Edge_length_property lengths;
  Mesh refined;           // the input's conforming Delaunay refinement, if the metric needs it
  Mesh* surface = &mesh;  // the triangulation that carries the metric
  Intrinsic_surface intrinsic;   // where the metric needed intrinsic flips: surface is its copy
  double metric_s = 0, compensation_s = 0;
  Json metric = Json::object();
  double h = 1;   // the grid's edge length under the metric (1: an integer-grid map's own units)
  // once the metric is made: step 2 (throws Failed_result when the remesh fails; automatic cones
  // then try other cones)
  auto finish = [&]() {
    out["metric"] = metric;
    // 2. develop and tessellate, read the remesh back; with --faces, the admissible edge length
    // nearest to the request
    stage("development and tessellation");
    const auto dev = on_file(file, [&] { return SMDF::develop_flat_metric(*surface, SMDF::parameters::edge_length_map(lengths)); });
    Mesh remesh;
    SMDF::Grid_tessellation_status st = SMDF::tessellate_flat_metric(*surface, dev, grid, h, remesh);
    if(!st.success && !place && requested_faces > 0 && st.compatibility.compatible && st.compatibility.spacing > 0 &&
       st.message.find("does not divide") != std::string::npos) {
      const double s = st.compatibility.spacing, wx = grid == SMDF::SQUARE_GRID ? 0. : 0.5, wy = grid == SMDF::SQUARE_GRID ? 1. : std::sqrt(3.) / 2;
      double best = 0;
      for(long a = 0; a <= long(s / h) + 2; ++a)
        for(long b = 0; b <= long(s / h) + 2; ++b) {
          const double g = std::hypot(double(a) + double(b) * wx, double(b) * wy);
          if(g > 0.5 && (best == 0 || std::abs(std::log(s / g / h)) < std::abs(std::log(best / h)))) best = s / g;
        }
      h = best;
      st = SMDF::tessellate_flat_metric(*surface, dev, grid, h, remesh);
    }
    if(intrinsic.of != nullptr && num_faces(remesh) > 0) {
      // made on the intrinsic triangulation's copy: its vertices go to the surface through the
      // common subdivision, and the faces inverted there are counted again (the tessellation saw
      // the intrinsic triangles' chords)
      SMDF::place_tessellation_on_input(intrinsic.triangulation, *intrinsic.of, st, remesh);
      if(st.inverted_faces == 0) st.inverted_faces = measures_on_input(input_tree, remesh).flipped_faces;
    }
    const double tessellation_s = clock.lap();
    out["edge_length"] = h;
    out["cut_edges"] = dev.number_of_cut_edges();
    out["cones"] = dev.cones().size();
    out["grid_spacing_of_metric"] = st.compatibility.spacing;
    if(!st.failing_edges.empty()) {
      Json fe = Json::array();
      for(std::size_t i = 0; i < st.failing_edges.size() && i < 20; ++i) fe.push_back(st.failing_edges[i]);
      out["failing_cut_edges"] = std::move(fe);   // the first 20
      Json dv = Json::array();
      for(std::size_t i = 0; i < st.failing_edges.size() && i < 20 && i < st.failing_rotation_deviations.size(); ++i) {
        Json o = Json::object();
        o["rotation"] = st.failing_rotation_deviations[i];
        o["translation"] = st.failing_translation_deviations[i];
        dv.push_back(std::move(o));
      }
      out["failing_cut_edge_deviations"] = std::move(dv);
      out["failing_cut_edge_count"] = st.failing_edges.size();
    }
    Json timings = Json::object();
    timings["metric_s"] = metric_s;
    timings["compensation_s"] = compensation_s;
    timings["tessellation_s"] = tessellation_s;
    bool success = st.success;
    std::string failure = st.message;
    std::size_t inverted = st.inverted_faces;
    const On_input_measures on_input = num_faces(remesh) > 0 ? untangle_if_needed(remesh, success, failure, inverted, timings) : On_input_measures();
    if(num_faces(remesh) > 0) {
      Json sizes = Json::object(), val = Json::object();
      std::map<std::size_t, std::size_t> by_size;
      for(face_descriptor f : faces(remesh)) ++by_size[CGAL::halfedges_around_face(halfedge(f, remesh), remesh).size()];
      for(const auto& p : by_size) sizes[std::to_string(p.first)] = p.second;
      for(std::size_t k = 0; k < st.valences.size(); ++k) if(st.valences[k]) val[std::to_string(k)] = st.valences[k];
      out["vertices"] = num_vertices(remesh);
      out["faces_by_size"] = std::move(sizes);
      out["valences"] = std::move(val);
      Json irr = Json::array();
      for(const auto& p : st.irregular_vertices) {
        Json o = Json::object();
        o["vertex"] = p.first;
        if(p.second >= 0) o["cone"] = p.second; else o["cone"] = Json();
        o["valence"] = degree(vertex_descriptor(Mesh::size_type(p.first)), remesh);
        irr.push_back(std::move(o));
      }
      out["irregular_vertices"] = std::move(irr);
      out["inverted_faces"] = inverted;
      check_flipped_faces(on_input.flipped_faces, success, failure);
      out["quality"] = quality_json(remesh, on_input);
      // automatic cones promise a valid quad mesh: a quad still folded at a corner after untangling
      // (scaled Jacobian <= 0) fails it (the polycube routes report such quads and keep exit 0)
      if(place && success) {
        const std::size_t folded_quads = nonconvex_quads(remesh);
        if(folded_quads > 0) {
          success = false;
          failure = std::to_string(folded_quads) + " quads are folded at a corner (scaled Jacobian <= 0) after untangling";
        }
      }
      // (the integer-grid map's grid edge is 1 in its own units: on the surface, the mean quad's side)
      out["distance_over_edge_length"] = remesh_distances(input_tree, remesh, place ? std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / double(num_faces(remesh))) : h);
      out["area_ratio"] = remesh_area_ratio(mesh, remesh);
      if(!CGAL::IO::write_polygon_mesh(out_file, remesh, CGAL::parameters::stream_precision(17)))
        throw file_error(out_file, "cannot write the remesh (the extension must be .off or .obj)", "output");
      if(args.has("svg")) write_remesh_svg(args, mesh, remesh, grid == SMDF::SQUARE_GRID ? 4 : 6);
      if(args.has("knot-svg")) write_knot_svg(args, mesh, remesh);
    }
    stage("done");
    out["timings"] = std::move(timings);
    out["success"] = success;
    if(!success) throw Failed_result{out, file + ": " + failure, 3};
  };
  if(args.has("lengths")) { lengths = read_edge_lengths(args.value("lengths"), mesh); metric["source"] = "lengths"; }
  else if(!cones.empty() && !args.has("polycube")) {
    // the flat cone metric with the given cones, on the input triangulation; if that cannot
    // carry it, on its conforming Delaunay refinement (a triangulation of the same surface: the
    // remesh is pulled back through it onto the input, no intrinsic flips needed)
    stage("flat cone metric");
    auto flow = [&](Mesh& on, Edge_length_property& l) {
      auto targets = on.add_property_map<vertex_descriptor, double>("v:smdf_remesh_target", 0.).first;
      for(const auto& c : cones) targets[c.first] = c.second;   // a refinement keeps the input's vertex indices
      l = on.add_property_map<edge_descriptor, double>("e:smdf_remesh_length", 0.).first;
      return on_file(file, [&] { return SMDF::compute_cone_metric(on, targets, l, SMDF::parameters::intrinsic_edge_flips(false)); });
    };
    SMDF::Cone_metric_status cm = flow(mesh, lengths);
    metric["source"] = "cones";
    if(!cm.converged) {
      stage("flat cone metric on the Delaunay refinement");
      const SMDF::Delaunay_refinement_status rs = on_file(file, [&] { return SMDF::conforming_delaunay_refinement(mesh, refined); });
      metric["delaunay_refinement"] = refinement_json(cm.message, rs);
      if(!rs.success) {
        out["metric"] = metric;
        out["success"] = false;
        throw Failed_result{out, file + ": the flat cone metric with these cones does not converge on the input triangulation (" + cm.message +
                                     "), and its Delaunay refinement failed: " + rs.message, 3};
      }
      cm = flow(refined, lengths);
      surface = &refined;
      if(!cm.converged) {
        // with intrinsic flips: tessellated on that triangulation, brought back through its
        // common subdivision with the refinement
        stage("flat cone metric with intrinsic flips");
        cm = intrinsic_cone_metric(file, refined, cones, cm.message, intrinsic, surface, lengths, metric);
      }
    }
    metric["converged"] = cm.converged;
    metric["iterations"] = cm.iterations;
    metric["max_curvature_error"] = cm.max_curvature_error;
    if(!cm.converged) {
      out["metric"] = metric;
      out["success"] = false;
      throw Failed_result{out, file + ": the flat cone metric with these cones does not converge on the input triangulation" +
                                   std::string(surface == &refined ? ", nor on its Delaunay refinement, nor with intrinsic flips: " : ": ") + cm.message, 3};
    }
  } else if(place) {
    // --uv-out: the first valid map, kept in case every remesh fails its read-back afterwards (the
    // map is still a seamless parametrization a user may want)
    std::string first_valid_map;
    std::size_t first_valid_attempt = 0;
    try {
      lengths = placed_cones_metric(file, mesh, refined, intrinsic, surface, requested_h, requested_faces, distortion_bound, max_cones, cone_spacing, out,
                                    metric, stage, [&](Edge_length_property map_lengths) {
        if(args.has("uv-out") && intrinsic.of != nullptr)   // this attempt fails; another's metric may need no flips
          throw Failed_result{out, file + ": --uv-out: the flat cone metric needed intrinsic edge flips, so the integer-grid map lives on an "
                                          "intrinsic triangulation whose faces are not the input's", 3};
        if(args.has("uv-out") && first_valid_map.empty()) {
          first_valid_map = uv_obj_text(*surface);
          const Json* recorded = out.find("placement_attempts");
          first_valid_attempt = recorded ? recorded->size() - 1 : 0;
        }
        lengths = map_lengths;
        metric_s = clock.lap();
        finish();
      }, args.has("uv-out"), !args.has("distortion-bound"));
    } catch(Failed_result& f) {
      if(!first_valid_map.empty()) {
        write_lines_file(args.value("uv-out"), first_valid_map);
        f.json["uv_out_attempt"] = first_valid_attempt;
        f.message += " (--uv-out: the valid integer-grid map of attempt " + std::to_string(first_valid_attempt) + " written)";
      }
      throw;
    }
    if(args.has("uv-out")) write_lines_file(args.value("uv-out"), uv_obj_text(*surface));
    return out;   // tessellated and read back by the attempt that passed
  } else {
    lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_remesh_length", 0.).first;
    for(edge_descriptor e : edges(mesh)) lengths[e] = std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
    metric["source"] = args.has("polycube") ? "box polycube" : "embedding";
  }
  metric_s = clock.lap();
  // Lai et al.: P's edges become shortest paths under the flat cone metric with P's cones. Only
  // its conformal factors are needed, so the flow may flip edges (it converges on every mesh;
  // on the input triangulation alone it stalls on many). If it does not converge, u = 0: the
  // paths are Euclidean.
  auto u = mesh.add_property_map<vertex_descriptor, double>("v:smdf_remesh_u", 0.).first;
  auto flat_cone_factors = [&](Mesh::Property_map<vertex_descriptor, double> targets) {
    const Edge_length_property flat = mesh.add_property_map<edge_descriptor, double>("e:smdf_remesh_flat", 0.).first;
    const SMDF::Cone_metric_status cm = on_file(file, [&] {
      // edge paths need no more: 1e-10 costs one or two more Newton steps (0.5-1 s at 433k)
      return SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::conformal_factor_map(u).curvature_tolerance(1e-6).common_subdivision(false));
    });
    metric["flat_cone_metric_converged"] = cm.converged;
    metric["flat_cone_metric_edge_flips"] = cm.edge_flips;
    if(!cm.converged) for(vertex_descriptor v : vertices(mesh)) u[v] = 0;
    metric_s += clock.lap();   // the flat cone metric is the metric; compensation_s is P's
  };
  h = place ? 1. : requested_h > 0 ? requested_h : std::sqrt(metric_area(*surface, lengths) / (double(requested_faces) * unit_area));
  // A file that describes a box (six quadrilaterals glued as a cube's) gets the box's own
  // metric, scaled along its three axes, instead of six equal squares.
  bool file_box = false;
  std::array<vertex_descriptor, 8> file_box_corners;
  if(args.has("polycube") && polycube != "box" && polycube != "octahedron" && polycube != "obelisk") {
    std::vector<vertex_descriptor> pc;
    std::vector<std::vector<int>> pf;
    read_polyhedron(polycube, mesh, pc, pf);
    std::array<int, 8> order;
    if(pc.size() == 8 && SMDF::box_corner_order(pf, order)) {
      if(args.has("grid") && grid_name != "quad")
        throw Usage_error(polycube + ": the polyhedron is a box, which gives --grid quad, not --grid " + grid_name);
      file_box = true;
      for(int i = 0; i < 8; ++i) file_box_corners[std::size_t(i)] = pc[std::size_t(order[std::size_t(i)])];
      if(!cones.empty())   // its corners must be the given cones, of pi/2 each
        check_polyhedron_cones(polycube, pc, std::vector<double>(8, CGAL_PI / 2), cones);
    }
  }
  if(args.has("polycube") && polycube != "box" && !file_box) {
    // a polyhedron of unit squares and equilateral triangles: the octahedron, or from a file
    std::vector<vertex_descriptor> corners;
    std::vector<std::vector<int>> pfaces;
    bool mixed = false;
    if(polycube == "obelisk") {   // Lai et al. Figure 1c: a box of four squares on a base, a pyramid on top (y up)
      std::vector<K::Vector_3> d;
      for(double y : {-1., 0.5})
        for(int i = 0; i < 4; ++i) d.push_back(K::Vector_3(std::cos(CGAL_PI / 4 + i * CGAL_PI / 2), y, std::sin(CGAL_PI / 4 + i * CGAL_PI / 2)));
      d.push_back(K::Vector_3(0, 1, 0));
      corners = extreme_vertices(mesh, d);
      pfaces.push_back({0, 1, 2, 3});
      for(int i = 0; i < 4; ++i) pfaces.push_back({i, 4 + i, 4 + (i + 1) % 4, (i + 1) % 4});
      for(int i = 0; i < 4; ++i) pfaces.push_back({4 + i, 8, 4 + (i + 1) % 4});
      mixed = true;
      out["grid"] = "mixed";
    } else if(polycube == "octahedron") {
      corners = axis_corners(mesh);
      for(int sx : {1, -1})
        for(int sy : {1, -1})
          for(int sz : {1, -1}) {
            const int X = sx > 0 ? 0 : 1, Y = sy > 0 ? 2 : 3, Z = sz > 0 ? 4 : 5;
            pfaces.push_back(sx * sy * sz > 0 ? std::vector<int>{X, Y, Z} : std::vector<int>{X, Z, Y});
          }
      grid = SMDF::TRIANGULAR_GRID;
      out["grid"] = "triangle";
    } else {
      read_polyhedron(polycube, mesh, corners, pfaces);
      std::size_t quads = 0;
      for(const auto& f : pfaces) quads += f.size() == 4;
      const char* faces_are = quads == pfaces.size() ? "quad" : quads == 0 ? "triangle" : "mixed";
      if(args.has("grid") && grid_name != faces_are && !(grid_name == "mixed" && quads == pfaces.size()))
        throw Usage_error(polycube + ": the polyhedron's faces are " +
                          (quads == pfaces.size() ? std::string("all squares") : quads == 0 ? std::string("all triangles") : std::string("squares and triangles")) +
                          ", which give --grid " + faces_are + ", not --grid " + grid_name);
      mixed = grid_name == "mixed" || (quads != 0 && quads != pfaces.size());
      grid = quads ? SMDF::SQUARE_GRID : SMDF::TRIANGULAR_GRID;
      out["grid"] = mixed ? "mixed" : quads ? "quad" : "triangle";
    }
    if(!cones.empty() && polycube == "octahedron")
      corners = assign_cones("octahedron", mesh, cones, {K::Vector_3(1, 0, 0), K::Vector_3(-1, 0, 0), K::Vector_3(0, 1, 0), K::Vector_3(0, -1, 0),
                                                         K::Vector_3(0, 0, 1), K::Vector_3(0, 0, -1)}, 2 * CGAL_PI / 3, "2 pi/3");
    {
      // P's cones: 2 pi minus the angles of its faces at each corner; --cones must say the same
      std::vector<double> K_of(corners.size(), 2 * CGAL_PI);
      for(const auto& f : pfaces) for(int c : f) K_of[std::size_t(c)] -= f.size() == 4 ? CGAL_PI / 2 : CGAL_PI / 3;
      if(!cones.empty() && polycube != "octahedron") check_polyhedron_cones(polycube, corners, K_of, cones);
    }
    stage("flat cone metric and paths");
    std::size_t nq = 0;
    for(const auto& f : pfaces) nq += f.size() == 4;
    const double polygon_area = double(nq) + double(pfaces.size() - nq) * std::sqrt(3.) / 4;
    const double side = h * (std::max)(1., std::round(std::sqrt(metric_area(mesh, lengths) / polygon_area) / h));
    // the paths under the flat cone metric with P's cones (Lai et al.)
    auto targets = mesh.add_property_map<vertex_descriptor, double>("v:smdf_remesh_target", 0.).first;
    std::vector<double> angle_sum(corners.size(), 0.);
    for(const auto& f : pfaces) for(int c : f) angle_sum[std::size_t(c)] += f.size() == 4 ? CGAL_PI / 2 : CGAL_PI / 3;
    for(std::size_t i = 0; i < corners.size(); ++i) targets[corners[i]] = 2 * CGAL_PI - angle_sum[i];
    flat_cone_factors(targets);
    if(mixed) {   // each face of P its own grid (polyhedron_remesh), n grid edges per side
      const int n = int((std::max)(1., std::round(side / h)));
      Mesh remesh;
      const SMDF::Polyhedron_remesh_status rs = on_file(file, [&] {
        return SMDF::polyhedron_remesh(mesh, corners, pfaces, n, remesh, SMDF::parameters::conformal_factor_map(u).number_of_iterations(relax_steps).segment_flattening(flattening));
      });
      Json c = Json::array();
      for(vertex_descriptor v : corners) c.push_back(index(v));
      metric["corners"] = std::move(c);
      metric["max_path_stretch"] = rs.metric.max_path_stretch;
      metric["relaxation_steps"] = rs.metric.relaxation_steps;
      metric["segments"] = segments;
      if(flattening == SMDF::RICCI_FLOW_SEGMENTS) metric["max_side_parameter_gap"] = rs.metric.max_side_parameter_gap;
      out["metric"] = metric;
      // the mixed grid's Theorem 3.5 test, face by face of P, on the metric built
      if(rs.metric.success) out["polyhedron_compatibility"] = compatibility_json(rs.compatibility);
      out["subdivisions"] = n;
      Json timings = Json::object();
      timings["metric_s"] = metric_s;
      timings["compensation_s"] = Json();   // polyhedron_remesh() embeds P's faces and grids them in one call
      timings["tessellation_s"] = clock.lap();
      out["edge_length"] = side / n;
      bool success = rs.success;
      std::string failure = rs.message;
      std::size_t inverted = rs.inverted_faces;
      // irregular: a vertex whose faces do not fill 2 pi in the grid's angles (4 squares, 6
      // triangles, or 2 squares and 3 triangles), a cone of curvature 2 pi - sum; with the
      // corner of P at the same point (before untangling, which may let a cone slide)
      std::map<std::array<double, 3>, int> corner_at;
      for(vertex_descriptor v : corners) {
        const K::Point_3& q = mesh.point(v);
        corner_at[{{q.x(), q.y(), q.z()}}] = int(index(v));
      }
      Json irr = Json::array();
      if(num_faces(remesh) > 0) {
        const std::vector<double> curvature = grid_curvatures(remesh);
        for(auto v : vertices(remesh)) {
          if(is_border(v, remesh) || std::abs(curvature[index(v)]) < 1e-9) continue;
          Json o = Json::object();
          o["vertex"] = index(v);
          const K::Point_3& p = remesh.point(v);
          const auto it = corner_at.find({{p.x(), p.y(), p.z()}});
          if(it != corner_at.end()) o["cone"] = it->second; else o["cone"] = Json();
          o["valence"] = degree(v, remesh);
          o["curvature"] = curvature[index(v)];
          irr.push_back(std::move(o));
        }
      }
      const On_input_measures on_input = num_faces(remesh) > 0 ? untangle_if_needed(remesh, success, failure, inverted, timings) : On_input_measures();
      if(num_faces(remesh) > 0) {
        Json sizes = Json::object(), val = Json::object();
        sizes["4"] = rs.quads;
        sizes["3"] = rs.triangles;
        for(std::size_t k = 0; k < rs.valences.size(); ++k) if(rs.valences[k]) val[std::to_string(k)] = rs.valences[k];
        out["vertices"] = rs.vertices;
        out["faces_by_size"] = std::move(sizes);
        out["valences"] = std::move(val);
        out["unexpected_valences"] = rs.unexpected_valences;
        out["irregular_vertices"] = std::move(irr);
        out["inverted_faces"] = inverted;
        check_flipped_faces(on_input.flipped_faces, success, failure);
        out["quality"] = quality_json(remesh, on_input);
        out["distance_over_edge_length"] = remesh_distances(input_tree, remesh, side / n);
        out["area_ratio"] = remesh_area_ratio(mesh, remesh);
        if(!CGAL::IO::write_polygon_mesh(out_file, remesh, CGAL::parameters::stream_precision(17)))
          throw file_error(out_file, "cannot write the remesh (the extension must be .off or .obj)", "output");
        if(args.has("svg")) write_remesh_svg(args, mesh, remesh, 12);
      }
      stage("done");
      out["timings"] = std::move(timings);
      out["success"] = success;
      if(!success) throw Failed_result{out, file + ": " + failure, 3};
      return out;
    }
    const SMDF::Polycube_metric_status ps = on_file(file, [&] {
      return SMDF::polyhedron_metric(mesh, corners, pfaces, side, lengths, SMDF::parameters::conformal_factor_map(u).number_of_iterations(relax_steps).segment_flattening(flattening));
    });
    compensation_s = clock.lap();
    Json c = Json::array();
    for(vertex_descriptor v : corners) c.push_back(index(v));
    metric["corners"] = std::move(c);
    metric["side_length"] = side;
    metric["max_path_stretch"] = ps.max_path_stretch;
    metric["relaxation_steps"] = ps.relaxation_steps;
    metric["seam_relaxed_vertices"] = ps.seam_relaxed_vertices;
    metric["segments"] = segments;
    if(flattening == SMDF::RICCI_FLOW_SEGMENTS) metric["max_side_parameter_gap"] = ps.max_side_parameter_gap;
    out["metric"] = metric;
    if(!ps.success) throw Failed_result{out, file + ": polyhedron metric: " + ps.message, 3};
    // the face-by-face test too (the tessellation then runs the holonomy test of its grid)
    out["polyhedron_compatibility"] = compatibility_json(on_file(file, [&] {
      return SMDF::polyhedron_compatibility(mesh, corners, pfaces, h, SMDF::parameters::edge_length_map(lengths));
    }));
  } else if(args.has("polycube")) {
    std::array<vertex_descriptor, 8> corners = file_box ? file_box_corners : box_corners(mesh);
    if(file_box) metric["box_from_file"] = polycube;
    if(!cones.empty() && !file_box) {
      std::vector<K::Vector_3> d;
      for(int i = 0; i < 8; ++i) d.push_back(K::Vector_3((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1));
      const std::vector<vertex_descriptor> a = assign_cones("box", mesh, cones, d, CGAL_PI / 2, "pi/2");
      std::copy(a.begin(), a.end(), corners.begin());
    }
    stage("flat cone metric, paths and box metric");
    // Lai et al.: the paths under the flat cone metric with cones of pi/2 at the corners
    auto targets = mesh.add_property_map<vertex_descriptor, double>("v:smdf_remesh_target", 0.).first;
    for(vertex_descriptor v : corners) targets[v] = CGAL_PI / 2;
    flat_cone_factors(targets);
    const SMDF::Polycube_metric_status ps = on_file(file, [&] {
      return SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::conformal_factor_map(u).number_of_iterations(relax_steps).segment_flattening(flattening));
    });
    compensation_s = clock.lap();
    Json c = Json::array();
    for(vertex_descriptor v : corners) c.push_back(index(v));
    metric["corners"] = std::move(c);
    metric["dimensions"] = Json::array();
    for(double d : ps.dimensions) metric["dimensions"].push_back(d);
    metric["max_path_stretch"] = ps.max_path_stretch;
    metric["relaxation_steps"] = ps.relaxation_steps;
    metric["seam_relaxed_vertices"] = ps.seam_relaxed_vertices;
    metric["segments"] = segments;
    if(flattening == SMDF::RICCI_FLOW_SEGMENTS) metric["max_side_parameter_gap"] = ps.max_side_parameter_gap;
    out["metric"] = metric;
    if(!ps.success) throw Failed_result{out, file + ": box polycube metric: " + ps.message, 3};
  }
  finish();
  return out;
}

} // namespace smdf_cli
