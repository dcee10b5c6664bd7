// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: a regular quad or triangle mesh from a flat cone metric (Lai et al. 2010,
// section 5): the mesh's own metric, a metric read from a file, or the box polycube metric.

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>
#include <CGAL/Surface_mesh_direction_fields/polycube_metric.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace smdf_cli {

namespace {

// The eight vertices extreme in the directions of the box's corners (+-1, +-1, +-1) from the
// centroid, corner i at (i & 1, i & 2, i & 4).
std::array<vertex_descriptor, 8> box_corners(const Mesh& mesh)
{
  K::Vector_3 c(0, 0, 0);
  for(vertex_descriptor v : vertices(mesh)) c = c + (mesh.point(v) - CGAL::ORIGIN) / double(num_vertices(mesh));
  std::array<vertex_descriptor, 8> out;
  for(int i = 0; i < 8; ++i) {
    const K::Vector_3 d((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    double best = -1e300;
    for(vertex_descriptor v : vertices(mesh)) {
      const double x = (mesh.point(v) - (CGAL::ORIGIN + c)) * d;
      if(x > best) { best = x; out[std::size_t(i)] = v; }
    }
  }
  return out;
}

double metric_area(const Mesh& mesh, const Edge_length_property& l)
{
  double a = 0;
  for(face_descriptor f : faces(mesh)) {
    const halfedge_descriptor h = halfedge(f, mesh);
    const double x = l[edge(h, mesh)], y = l[edge(next(h, mesh), mesh)], z = l[edge(prev(h, mesh), mesh)];
    const double s = 0.5 * (x + y + z);
    a += std::sqrt((std::max)(0., s * (s - x) * (s - y) * (s - z)));
  }
  return a;
}

// Corner angles (degrees) and, for quads, scaled Jacobians of the remesh.
Json quality(const Mesh& out)
{
  double amin = 360, amax = 0, jmin = 1, jsum = 0;
  std::size_t jn = 0;
  for(face_descriptor f : faces(out)) {
    std::vector<K::Point_3> p;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, out), out)) p.push_back(out.point(target(h, out)));
    K::Vector_3 n(0, 0, 0);
    for(std::size_t i = 0; i < p.size(); ++i) n = n + CGAL::cross_product(p[i] - CGAL::ORIGIN, p[(i + 1) % p.size()] - CGAL::ORIGIN);
    for(std::size_t i = 0; i < p.size(); ++i) {
      const K::Vector_3 a = p[(i + 1) % p.size()] - p[i], b = p[(i + p.size() - 1) % p.size()] - p[i];
      const double la = std::sqrt(a.squared_length()), lb = std::sqrt(b.squared_length());
      if(!(la > 0) || !(lb > 0)) continue;
      const double ang = std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b) * 180 / CGAL_PI;
      amin = (std::min)(amin, ang);
      amax = (std::max)(amax, ang);
      if(p.size() == 4) {
        const double nl = std::sqrt(n.squared_length());
        const double j = nl > 0 ? (CGAL::cross_product(a, b) * n) / (la * lb * nl) : 0.;
        jmin = (std::min)(jmin, j);
        jsum += j;
        ++jn;
      }
    }
  }
  Json q = Json::object();
  q["min_corner_angle_deg"] = amin;
  q["max_corner_angle_deg"] = amax;
  if(jn) { q["min_scaled_jacobian"] = jmin; q["mean_scaled_jacobian"] = jsum / double(jn); }
  return q;
}

// Two-sided distance between input and remesh, over the edge length: output vertices to the
// input surface, input vertices to the remesh (its faces fanned into triangles).
Json distances(const Mesh& input, const Mesh& out, double h)
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  Tree tin(faces(input).first, faces(input).second, input);
  double d1 = 0, d2 = 0;
  for(vertex_descriptor v : vertices(out)) d1 = (std::max)(d1, std::sqrt(tin.squared_distance(out.point(v))));
  Mesh tri = out;
  std::vector<std::vector<vertex_descriptor>> fans;
  for(face_descriptor f : faces(tri)) {
    std::vector<vertex_descriptor> vs;
    for(halfedge_descriptor hh : CGAL::halfedges_around_face(halfedge(f, tri), tri)) vs.push_back(target(hh, tri));
    fans.push_back(vs);
  }
  tri.clear();
  Mesh fan;
  for(vertex_descriptor v : vertices(out)) fan.add_vertex(out.point(v));
  for(const auto& vs : fans)
    for(std::size_t i = 1; i + 1 < vs.size(); ++i) fan.add_face(vs[0], vs[i], vs[i + 1]);
  Json d = Json::object();
  if(num_faces(fan) > 0) {
    Tree tout(faces(fan).first, faces(fan).second, fan);
    for(vertex_descriptor v : vertices(input)) d2 = (std::max)(d2, std::sqrt(tout.squared_distance(input.point(v))));
  }
  d["remesh_to_input"] = d1 / h;
  d["input_to_remesh"] = d2 / h;
  return d;
}

} // namespace

Json run_remesh(const Args& args)
{
  const std::string& file = args.positional[0];
  const std::string grid_name = args.value("grid", "quad");
  if(grid_name != "quad" && grid_name != "triangle")
    throw Usage_error("option --grid expects 'quad' or 'triangle', got '" + shorten(grid_name) + "'");
  const SMDF::Planar_tessellation grid = grid_name == "quad" ? SMDF::SQUARE_GRID : SMDF::TRIANGULAR_GRID;
  if(args.has("edge-length") == args.has("faces")) throw Usage_error("give one of --edge-length and --faces");
  const double requested_h = args.has("edge-length") ? args.real("edge-length", 0) : 0;
  const long requested_faces = args.has("faces") ? args.integer("faces", 0) : 0;
  if(args.has("edge-length") && !(requested_h > 0)) throw Usage_error("option --edge-length expects a positive number");
  if(args.has("faces") && requested_faces < 1) throw Usage_error("option --faces expects a positive integer");
  const std::string polycube = args.value("polycube", "");
  if(args.has("polycube") && polycube != "box") throw Usage_error("option --polycube expects 'box', got '" + shorten(polycube) + "'");
  if(args.has("polycube") && args.has("lengths")) throw Usage_error("give at most one of --polycube and --lengths");
  if(args.has("polycube") && grid != SMDF::SQUARE_GRID) throw Usage_error("--polycube box gives a metric for --grid quad");
  if(!args.has("out")) throw Usage_error("option --out FILE is required (.off or .obj)");
  const std::string out_file = args.value("out");

  Mesh mesh;
  load_mesh(file, mesh);
  Stopwatch clock;
  Json out = Json::object();
  out["grid"] = grid_name;
  const double unit_area = grid == SMDF::SQUARE_GRID ? 1. : std::sqrt(3.) / 4;
  // 1. the metric
  Edge_length_property lengths;
  double metric_s = 0, compensation_s = 0;
  Json metric = Json::object();
  if(args.has("lengths")) { lengths = read_edge_lengths(args.value("lengths"), mesh); metric["source"] = "lengths"; }
  else {
    lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_remesh_length", 0.).first;
    for(edge_descriptor e : edges(mesh)) lengths[e] = std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
    metric["source"] = args.has("polycube") ? "box polycube" : "embedding";
  }
  metric_s = clock.lap();
  double h = requested_h > 0 ? requested_h : std::sqrt(metric_area(mesh, lengths) / (double(requested_faces) * unit_area));
  if(args.has("polycube")) {
    const auto corners = box_corners(mesh);
    // Lai et al.: the paths under the flat cone metric with cones of pi/2 at the corners
    auto targets = mesh.add_property_map<vertex_descriptor, double>("v:smdf_remesh_target", 0.).first;
    for(vertex_descriptor v : corners) targets[v] = CGAL_PI / 2;
    const Edge_length_property flat = mesh.add_property_map<edge_descriptor, double>("e:smdf_remesh_flat", 0.).first;
    const SMDF::Cone_metric_status cm = on_file(file, [&] {
      return SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::intrinsic_edge_flips(false));
    });
    metric["flat_cone_metric_converged"] = cm.converged;
    const SMDF::Polycube_metric_status ps = on_file(file, [&] {
      return cm.converged ? SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::edge_length_map(flat))
                          : SMDF::box_polycube_metric(mesh, corners, h, lengths);   // Euclidean paths and weights
    });
    compensation_s = clock.lap();
    Json c = Json::array();
    for(vertex_descriptor v : corners) c.push_back(index(v));
    metric["corners"] = std::move(c);
    metric["dimensions"] = Json::array();
    for(double d : ps.dimensions) metric["dimensions"].push_back(d);
    metric["max_path_stretch"] = ps.max_path_stretch;
    out["metric"] = metric;
    if(!ps.success) throw Failed_result{out, file + ": box polycube metric: " + ps.message, 3};
  }
  out["metric"] = metric;
  // 2. develop and tessellate; with --faces, the admissible edge length nearest to the request
  const auto dev = on_file(file, [&] { return SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths)); });
  Mesh remesh;
  SMDF::Grid_tessellation_status st = SMDF::tessellate_flat_metric(mesh, dev, grid, h, remesh);
  if(!st.success && requested_faces > 0 && st.compatibility.compatible && st.compatibility.spacing > 0 &&
     st.message.find("does not divide") != std::string::npos) {
    const double s = st.compatibility.spacing, wx = grid == SMDF::SQUARE_GRID ? 0. : 0.5, wy = grid == SMDF::SQUARE_GRID ? 1. : std::sqrt(3.) / 2;
    double best = 0;
    for(long a = 0; a <= long(s / h) + 2; ++a)
      for(long b = 0; b <= long(s / h) + 2; ++b) {
        const double g = std::hypot(double(a) + double(b) * wx, double(b) * wy);
        if(g > 0.5 && (best == 0 || std::abs(std::log(s / g / h)) < std::abs(std::log(best / h)))) best = s / g;
      }
    h = best;
    st = SMDF::tessellate_flat_metric(mesh, dev, grid, h, remesh);
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
    out["failing_cut_edge_count"] = st.failing_edges.size();
  }
  Json timings = Json::object();
  timings["metric_s"] = metric_s;
  timings["compensation_s"] = compensation_s;
  timings["tessellation_s"] = tessellation_s;
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
    out["inverted_faces"] = st.inverted_faces;
    out["quality"] = quality(remesh);
    out["distance_over_edge_length"] = distances(mesh, remesh, h);
    if(!CGAL::IO::write_polygon_mesh(out_file, remesh, CGAL::parameters::stream_precision(17)))
      throw file_error(out_file, "cannot write the remesh (the extension must be .off or .obj)", "output");
  }
  out["timings"] = std::move(timings);
  out["success"] = st.success;
  if(!st.success) throw Failed_result{out, file + ": " + st.message, 3};
  return out;
}

Command remesh_command()
{
  return {"remesh", {"MESH"},
          {{"grid", "G", "quad (default) or triangle"},
           {"edge-length", "H", "the grid's edge length on the surface"},
           {"faces", "N", "about N faces instead (the admissible edge length nearest to area / N)"},
           {"polycube", "box", "metric compensation with a box: corners at the 8 vertices extreme in the diagonal directions"},
           {"lengths", "FILE", "the flat cone metric: one line 'i j length' per edge (e.g. cone-metric --no-flips --lengths-out)"},
           {"out", "FILE", "write the remesh (.off or .obj)"}},
          "regular quad or triangle remesh from a flat cone metric",
          "Lai et al. 2010, section 5: develops a flat cone metric of the mesh (its own edge lengths,\n"
          "--lengths, or the box polycube metric of --polycube box) and carries the square (quad)\n"
          "or triangular grid onto the surface. The cut graph's motions must be symmetries of the\n"
          "grid (Theorem 3.5) and the cones grid points; otherwise the failing edges are reported.\n"
          "Output vertices lie on the input triangles (barycentric placement); every interior\n"
          "vertex has valence 4 (6) except at a cone of curvature K: 4 - K/(pi/2) (6 - K/(pi/3)).\n"
          "Prints {grid, metric: {source, corners, dimensions, max_path_stretch}, edge_length,\n"
          "cut_edges, cones, grid_spacing_of_metric, failing_cut_edges (first 20),\n"
          "failing_cut_edge_count, vertices, faces_by_size, valences (interior vertices),\n"
          "irregular_vertices: [{vertex, cone, valence}], inverted_faces, quality:\n"
          "{min_corner_angle_deg, max_corner_angle_deg, min_scaled_jacobian, mean_scaled_jacobian},\n"
          "distance_over_edge_length: {remesh_to_input, input_to_remesh}, timings: {metric_s,\n"
          "compensation_s, tessellation_s}, success}. Exit code 3 (JSON printed) when the metric is\n"
          "incompatible with the grid, the edge length does not fit its lattice, or the read-back\n"
          "fails (valences, inverted faces); the remesh is still written when its faces exist.\n",
          run_remesh};
}

} // namespace smdf_cli
