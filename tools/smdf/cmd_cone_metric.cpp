// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf cone-metric: flat cone metric with prescribed cone angles (discrete conformal map).

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/remeshing_cones.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <locale>
#include <map>
#include <utility>
#include <vector>

#include <unistd.h>   // isatty

namespace smdf_cli {

namespace {

typedef Mesh::Property_map<vertex_descriptor, double> Vertex_real_property;

// The options of `cone-metric` that do not need the mesh, checked before it is read.
struct Cone_metric_options
{
  long iterations;
  double tolerance;
  Indexed_values cones, indices, kappa;
  bool want_uv;    // --uv-out or --svg
  double distortion_bound = 0;   // --place-cones
  long max_cones = 0;
  bool progress;
};

Cone_metric_options cone_metric_options(const Args& args)
{
  Cone_metric_options o;
  o.iterations = args.integer("iterations", 200);
  if(o.iterations < 0 || o.iterations > 1000000)
    throw Usage_error("option --iterations expects an integer in [0, 1000000], got '" + args.value("iterations") + "'");
  o.tolerance = args.real("tolerance", 1e-10);
  if(!(o.tolerance > 0))
    throw Usage_error("option --tolerance expects a positive number, got '" + args.value("tolerance") + "'");
  auto vertex_values = [&](const char* option, bool (*parse)(const std::string&, double&), const char* what) {
    return pairs_option(args, option, parse, std::string("'v:x,v:x,...' (x ") + what + ")");
  };
  o.cones = vertex_values("cones", parse_angle, "radians: decimal, p/q, pi/2, -4pi, 3*pi/4, ...");
  o.indices = vertex_values("cone-indices", parse_number, "an index k, K = 2 pi k: integer, p/q or decimal");
  o.kappa = vertex_values("boundary-curvature", parse_angle, "radians: decimal, p/q, pi/2, -pi/4, ...");
  o.want_uv = args.has("uv-out") || args.has("svg");
  if(args.has("place-cones")) {
    const std::string g = args.value("place-cones");
    if(g != "quad" && g != "triangle") throw Usage_error("option --place-cones expects 'quad' or 'triangle', got '" + shorten(g) + "'");
    if(args.has("cones") || args.has("cone-indices") || args.has("boundary-curvature") || args.has("refine") || args.has("no-flips"))
      throw Usage_error("--place-cones chooses the cones and boundary corners itself: give none of --cones, --cone-indices, "
                        "--boundary-curvature, --refine and --no-flips");
    o.distortion_bound = args.real("distortion-bound", 2.0);
    if(!(o.distortion_bound > 0) || !std::isfinite(o.distortion_bound))
      throw Usage_error("option --distortion-bound expects a positive number, got '" + args.value("distortion-bound") + "'");
    o.max_cones = args.integer("max-cones", 500);
    if(o.max_cones < 1 || o.max_cones > 100000) throw Usage_error("option --max-cones expects an integer in [1, 100000], got '" + args.value("max-cones") + "'");
  } else if(args.has("distortion-bound") || args.has("max-cones"))
    throw Usage_error("--distortion-bound and --max-cones apply to --place-cones");
  o.progress = args.has("progress") || isatty(2);
  return o;
}

// --uv-out and --svg need a topological disk: a usage error otherwise.
void require_disk(const Args& args, const std::string& file, const Mesh& mesh)
{
  const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });
  if(topo.components.size() != 1 || topo.components[0].boundary_loops != 1 || topo.components[0].genus != 0 ||
     topo.isolated_vertices != 0)
    throw Usage_error(std::string("option --") + (args.has("uv-out") ? "uv-out" : "svg") +
                      " needs a topological disk (one component, one boundary loop, genus 0, no isolated "
                      "vertex); " + file + " has " + std::to_string(topo.components.size()) + " component(s), " +
                      std::to_string(topo.boundary_loops.size()) + " boundary loop(s)");
}

// The target curvatures: 0 everywhere, then those of the options. A vertex out of range, given
// twice, isolated, or given by the option for the other kind (interior, boundary) is an Error.
Vertex_real_property set_targets(Mesh& mesh, const Cone_metric_options& opt)
{
  const std::size_t nv = num_vertices(mesh);
  Vertex_real_property targets = mesh.add_property_map<vertex_descriptor, double>("v:smdf_target_curvature", 0.).first;
  std::vector<const char*> given_by(nv, nullptr);
  auto set_target = [&](const char* option, std::size_t v, double k, bool boundary_option) {
    if(v >= nv)
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " does not exist (the mesh has " +
                  std::to_string(nv) + " vertices)");
    if(given_by[v])
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " is given twice" +
                  (std::string(given_by[v]) == option ? std::string() : std::string(" (also by --") + given_by[v] + ")"));
    const vertex_descriptor vd = vertex_descriptor(Mesh::size_type(v));
    if(halfedge(vd, mesh) == boost::graph_traits<Mesh>::null_halfedge())
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " is isolated");
    const bool boundary = bool(CGAL::is_border(vd, mesh));
    if(boundary && !boundary_option)
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) +
                  " is on the boundary: give its geodesic curvature with --boundary-curvature");
    if(!boundary && boundary_option)
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) +
                  " is an interior vertex: give its curvature with --cones or --cone-indices");
    given_by[v] = option;
    put(targets, vd, k);
  };
  for(const auto& c : opt.cones) set_target("cones", c.first, c.second, false);
  for(const auto& c : opt.indices) set_target("cone-indices", c.first, 2 * CGAL_PI * c.second, false);
  for(const auto& c : opt.kappa) set_target("boundary-curvature", c.first, c.second, true);
  return targets;
}

// Gauss-Bonnet failed: the first component whose targets do not sum to 2 pi chi, stated as
// cone indices (K / 2 pi) against chi, or "" if none is found.
std::string gauss_bonnet_detail(const Mesh& mesh, Vertex_real_property targets)
{
  const std::size_t nv = num_vertices(mesh);
  std::vector<std::size_t> parent(nv);
  for(std::size_t v = 0; v < nv; ++v) parent[v] = v;
  std::function<std::size_t(std::size_t)> root = [&](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(edge_descriptor ed : edges(mesh)) {
    const halfedge_descriptor h = halfedge(ed, mesh);
    parent[root(index(source(h, mesh)))] = root(index(target(h, mesh)));
  }
  std::map<std::size_t, std::pair<double, long>> comp;   // root -> (sum of targets, chi)
  for(vertex_descriptor v : vertices(mesh))
    if(halfedge(v, mesh) != boost::graph_traits<Mesh>::null_halfedge()) {
      auto& c = comp[root(index(v))];
      c.first += get(targets, v);
      c.second += 1;
    }
  for(edge_descriptor ed : edges(mesh)) comp[root(index(source(halfedge(ed, mesh), mesh)))].second -= 1;
  for(face_descriptor f : faces(mesh)) comp[root(index(target(halfedge(f, mesh), mesh)))].second += 1;
  for(const auto& c : comp)
    if(std::abs(c.second.first - 2 * CGAL_PI * double(c.second.second)) >
       1e-8 * (std::max)(1., 2 * CGAL_PI * std::abs(double(c.second.second))))
      return "; as cone indices (K / 2pi): the targets sum to " + format_real(c.second.first / (2 * CGAL_PI)) +
             " but the Euler characteristic is " + std::to_string(c.second.second);
  return std::string();
}

// Runs compute_cone_metric(); input errors name `file`.
SMDF::Cone_metric_status compute_metric(const Args& args, const std::string& file, const Cone_metric_options& opt,
                                        Mesh& mesh, Vertex_real_property targets, Edge_length_property lengths,
                                        Vertex_real_property ufac)
{
  const bool progress = opt.progress;
  auto visitor = [progress](int it, double err) {
    if(!progress) return;
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << "smdf: cone-metric: iteration " << it << ", max curvature error " << std::setprecision(3) << err << '\n';
    std::cerr << os.str() << std::flush;
  };
  try {
    return SMDF::compute_cone_metric(mesh, targets, lengths,
                                     SMDF::parameters::conformal_factor_map(ufac)
                                         .number_of_iterations(int(opt.iterations))
                                         .curvature_tolerance(opt.tolerance)
                                         .intrinsic_edge_flips(!args.has("no-flips") && !args.has("refine"))
                                         .visitor(visitor));
  } catch(const SMDF::Input_error& e) {
    if(e.kind() != SMDF::Input_error::INCONSISTENT_INDICES) throw file_error(file, e.what(), SMDF::Input_error::kind_name(e.kind()));
    throw file_error(file, e.what() + gauss_bonnet_detail(mesh, targets), SMDF::Input_error::kind_name(e.kind()));
  }
}

// --lengths-out: 'i j length' per edge of the triangulation carrying the metric (the input's,
// without the edges inside punched holes, or the intrinsic one).
void write_lengths(const std::string& out_file, const Mesh& mesh, Edge_length_property lengths,
                   const SMDF::Cone_metric_status& st)
{
  const SMDF::Intrinsic_triangulation& itri = st.intrinsic_triangulation;
  std::ostringstream os = number_stream();
  if(st.triangulation_changed) {
    for(std::size_t e = 0; e < itri.number_of_edges(); ++e)
      os << itri.source(int(2 * e)) << ' ' << itri.target(int(2 * e)) << ' ' << itri.length(int(e)) << '\n';
  } else {
    for(edge_descriptor e : edges(mesh)) {
      if(std::isnan(get(lengths, e))) continue;   // inside a punched hole
      const halfedge_descriptor h = halfedge(e, mesh);
      os << index(source(h, mesh)) << ' ' << index(target(h, mesh)) << ' ' << get(lengths, e) << '\n';
    }
  }
  write_lines_file(out_file, os.str());
}

// --triangulation-out: OFF file with the input vertex positions and the faces carrying the
// metric (the input's, without the faces of punched holes, or the intrinsic ones).
void write_triangulation(const std::string& out_file, const Mesh& mesh, const SMDF::Cone_metric_status& st)
{
  const bool changed = st.triangulation_changed;
  const SMDF::Intrinsic_triangulation& itri = st.intrinsic_triangulation;
  const std::size_t nv = num_vertices(mesh);
  std::ostringstream os = number_stream();
  std::vector<char> punched(nv, 0);
  for(std::size_t v : st.punched_vertices) punched[v] = 1;
  std::vector<face_descriptor> kept;   // without the faces of punched holes
  for(face_descriptor f : faces(mesh)) {
    bool in_hole = false;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) in_hole = in_hole || punched[index(v)];
    if(!in_hole) kept.push_back(f);
  }
  os << "OFF\n" << nv << ' ' << (changed ? itri.number_of_faces() : kept.size()) << " 0\n";
  for(vertex_descriptor v : vertices(mesh)) {
    const K::Point_3& p = mesh.point(v);
    os << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  if(changed) {
    for(std::size_t f = 0; f < itri.number_of_faces(); ++f) {
      const std::array<int, 3> t = itri.face_vertices(int(f));
      os << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
  } else {
    for(face_descriptor f : kept) {
      os << '3';
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) os << ' ' << index(v);
      os << '\n';
    }
  }
  write_lines_file(out_file, os.str());
}

// The JSON object of a result, converged or not (without uv_positively_oriented).
Json status_json(const Args& args, const Mesh& mesh, Vertex_real_property targets, const SMDF::Cone_metric_status& st)
{
  std::size_t ncones = 0, nkappa = 0;
  for(vertex_descriptor v : vertices(mesh))
    if(get(targets, v) != 0) ++(CGAL::is_border(v, mesh) ? nkappa : ncones);
  Json out = Json::object();
  out["status"] = st.converged ? "converged" : "not_converged";
  out["converged"] = st.converged;
  out["iterations"] = st.iterations;
  out["max_curvature_error"] = st.max_curvature_error;
  out["rounding_level"] = st.rounding_level;
  out["time_s"] = st.seconds;
  out["method"] = args.has("refine")  ? "discrete conformal vertex scaling (Newton, CHOLMOD) on the conforming Delaunay refinement of the input"
                  : args.has("no-flips") ? "discrete conformal vertex scaling (Newton, CHOLMOD) on the input triangulation"
                    : "discrete conformal vertex scaling (Newton, CHOLMOD), continued on an intrinsic "
                      "Delaunay triangulation (edge flips) if the input triangulation cannot carry the metric";
  out["message"] = st.message;
  out["cones"] = ncones;
  out["boundary_corners"] = nkappa;
  Json holes = Json::array();
  for(std::size_t v : st.punched_vertices) holes.push_back(v);
  out["punched_vertices"] = holes;
  out["triangulation_changed"] = st.triangulation_changed;
  out["edge_flips"] = st.edge_flips;
  if(st.triangulation_changed) {
    const SMDF::Intrinsic_triangulation& itri = st.intrinsic_triangulation;
    Json t = Json::object();
    t["faces"] = itri.number_of_faces();
    t["edges"] = itri.number_of_edges();
    t["new_edges"] = itri.number_of_new_edges();
    out["intrinsic_triangulation"] = std::move(t);
  }
  return out;
}

// Blue (negative) - white (0) - red (positive) colour of t in [-1, 1].
std::string diverging_color(double t)
{
  t = (std::max)(-1., (std::min)(1., std::isfinite(t) ? t : 0.));
  const double blue[3] = {33, 102, 172}, red[3] = {178, 24, 43};
  const double* end = t < 0 ? blue : red;
  const double a = std::abs(t);
  char buf[8];
  int rgb[3];
  for(int k = 0; k < 3; ++k) rgb[k] = int(std::lround(255 * (1 - a) + end[k] * a));
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buf;
}

// The flattened disk as SVG: one triangle per face, filled by the mean conformal factor u of
// its vertices (blue u < 0, white 0, red u > 0, scaled by max |u|); y points up.
std::string layout_svg(const Mesh& mesh, const std::vector<K::Point_2>& uv, const std::vector<double>& u)
{
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin, umax = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    const K::Point_2& p = uv[index(v)];
    xmin = (std::min)(xmin, p.x()); xmax = (std::max)(xmax, p.x());
    ymin = (std::min)(ymin, p.y()); ymax = (std::max)(ymax, p.y());
    umax = (std::max)(umax, std::abs(u[index(v)]));
  }
  const double width = 800, margin = 10;
  const double span = (std::max)(xmax - xmin, ymax - ymin);
  const double scale = span > 0 ? (width - 2 * margin) / span : 1;
  const double height = (ymax - ymin) * scale + 2 * margin;
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << std::fixed << std::setprecision(2);
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << int(width) << "\" height=\"" << int(std::ceil(height))
     << "\" viewBox=\"0 0 " << width << ' ' << std::ceil(height) << "\">\n"
     << "<title>cone metric layout, faces coloured by the conformal factor u (max |u| = "
     << std::setprecision(4) << umax << std::setprecision(2) << ")</title>\n"
     << "<g stroke=\"#404040\" stroke-width=\"0.1\" stroke-linejoin=\"round\">\n";
  for(face_descriptor f : faces(mesh)) {
    os << "<polygon points=\"";
    double us = 0;
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) {
      const K::Point_2& p = uv[index(v)];
      os << (k++ ? " " : "") << margin + (p.x() - xmin) * scale << ',' << margin + (ymax - p.y()) * scale;
      us += u[index(v)];
    }
    os << "\" fill=\"" << diverging_color(umax > 0 ? us / 3 / umax : 0) << "\"/>\n";
  }
  os << "</g>\n</svg>\n";
  return os.str();
}

// --uv-out and --svg: lays out the disk (a copy of the intrinsic triangulation if it changed:
// same vertices) and writes the files; returns whether every triangle is counterclockwise.
bool write_layout(const Args& args, const std::string& file, double tolerance, Mesh& mesh,
                  Edge_length_property lengths, Vertex_real_property ufac, const SMDF::Cone_metric_status& st)
{
  const bool changed = st.triangulation_changed;
  const std::size_t nv = num_vertices(mesh);
  Mesh copy;
  Edge_length_property copy_lengths =
    copy.add_property_map<edge_descriptor, double>("e:smdf_intrinsic_length", 0.).first;
  if(changed) SMDF::copy_intrinsic_triangulation(st.intrinsic_triangulation, mesh, copy, copy_lengths);
  Mesh& flat = changed ? copy : mesh;   // vertex i of the copy is vertex i of the input
  std::vector<K::Point_2> uv(nv, K::Point_2(0, 0));
  Mesh::Property_map<vertex_descriptor, K::Point_2> uvmap =
    flat.add_property_map<vertex_descriptor, K::Point_2>("v:smdf_uv", K::Point_2(0, 0)).first;
  const bool injective = on_file(file, [&] {
    const auto np = SMDF::parameters::curvature_tolerance((std::max)(1e-8, 10 * tolerance));
    return changed ? SMDF::lay_out_disk(copy, copy_lengths, uvmap, np) : SMDF::lay_out_disk(mesh, lengths, uvmap, np);
  });
  for(vertex_descriptor v : vertices(flat)) uv[index(v)] = get(uvmap, v);
  if(args.has("uv-out")) {
    std::ostringstream os = number_stream();
    for(vertex_descriptor v : vertices(mesh)) os << uv[index(v)].x() << ' ' << uv[index(v)].y() << '\n';
    write_lines_file(args.value("uv-out"), os.str());
  }
  if(args.has("svg")) {
    std::vector<double> u(nv, 0.);
    for(vertex_descriptor v : vertices(mesh)) u[index(v)] = get(ufac, v);
    write_lines_file(args.value("svg"), layout_svg(flat, uv, u));
  }
  return injective;
}

} // namespace

Json run_cone_metric(const Args& args)
{
  const std::string& file = args.positional[0];
  const Cone_metric_options opt = cone_metric_options(args);

  Mesh input, refined;
  load_mesh(file, input);
  Json refinement;
  if(args.has("refine")) {   // the metric on a triangulation of the same surface made of pieces of the input's triangles
    const SMDF::Delaunay_refinement_status rs = on_file(file, [&] { return SMDF::conforming_delaunay_refinement(input, refined); });
    refinement = Json::object();
    refinement["success"] = rs.success;
    refinement["faces"] = rs.faces;
    refinement["inserted_vertices"] = rs.inserted.size();
    refinement["max_opposite_angle_sum"] = rs.max_opposite_angle_sum;
    if(!rs.success) {
      Json out = Json::object();
      out["status"] = "not_converged";
      out["converged"] = false;
      out["delaunay_refinement"] = refinement;
      throw Failed_result{out, file + ": the Delaunay refinement failed: " + rs.message, 3};
    }
  }
  Mesh& mesh = args.has("refine") ? refined : input;
  if(opt.want_uv) require_disk(args, file, mesh);
  const Vertex_real_property targets = set_targets(mesh, opt);
  const Edge_length_property lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_cone_length", 0.).first;
  const Vertex_real_property ufac = mesh.add_property_map<vertex_descriptor, double>("v:smdf_conformal_factor", 0.).first;
  SMDF::Cone_metric_status st;
  Json placement;
  std::string placement_failure;
  if(args.has("place-cones")) {
    const int N = args.value("place-cones") == "quad" ? 4 : 6;
    const auto ps = on_file(file, [&] {
      return SMDF::place_remeshing_cones(mesh, lengths, SMDF::parameters::symmetry_order(N).distortion_bound(opt.distortion_bound)
                                                            .maximum_number_of_cones(int(opt.max_cones)).conformal_factor_map(ufac));
    });
    placement = Json::object();
    placement["success"] = ps.success;
    placement["message"] = ps.message;
    placement["distortion_bound"] = ps.distortion_bound;
    placement["scale_spread"] = ps.scale_spread;
    placement["negative_cone_quanta"] = ps.negative_cone_quanta;
    placement["linear_scale_spread"] = ps.linear_scale_spread;
    placement["placement_rounds"] = ps.placement_rounds;
    Json cones = Json::array();
    for(const auto& c : ps.cones) {
      Json o = Json::object();
      o["vertex"] = index(c.first);
      o["curvature"] = c.second;
      cones.push_back(std::move(o));
      put(targets, c.first, c.second);
    }
    placement["placed_cones"] = std::move(cones);
    if(!ps.success && ps.metric.converged) placement_failure = ps.message;
    st = ps.metric;
    if(!st.converged && st.message.empty()) st.message = ps.message;
  } else
    st = compute_metric(args, file, opt, mesh, targets, lengths, ufac);

  // With flips the metric lives on the intrinsic triangulation: its edges (not the input's)
  // go to --lengths-out, its faces to --triangulation-out.
  if(args.has("lengths-out")) write_lengths(args.value("lengths-out"), mesh, lengths, st);
  if(args.has("triangulation-out")) write_triangulation(args.value("triangulation-out"), mesh, st);
  if(args.has("factors-out")) {
    if(!st.punched_vertices.empty())
      throw Failed_result{status_json(args, mesh, targets, st),
                          file + ": --factors-out: the metric has punched holes, which no factors of the input's vertices describe", 3};
    std::ostringstream os = number_stream();
    for(vertex_descriptor v : vertices(mesh)) os << get(ufac, v) << '\n';
    write_lines_file(args.value("factors-out"), os.str());
  }

  Json out = status_json(args, mesh, targets, st);
  if(args.has("refine")) out["delaunay_refinement"] = refinement;
  if(args.has("place-cones")) out["placement"] = placement;
  if(!st.converged) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << file << ": cone metric not converged (tolerance " << std::setprecision(3) << opt.tolerance
       << ", " << st.iterations << " iterations): " << st.message
       << (opt.want_uv ? " (--uv-out/--svg not written)" : "");
    throw Failed_result{out, os.str(), 3};
  }
  if(opt.want_uv) out["uv_positively_oriented"] = write_layout(args, file, opt.tolerance, mesh, lengths, ufac, st);
  if(!placement_failure.empty()) throw Failed_result{out, file + ": --place-cones: " + placement_failure, 3};
  return out;
}

Command cone_metric_command()
{
  return {"cone-metric", {"MESH"},
          {{"cones", "LIST", "target curvatures 'v:K,...' of interior vertices, K in radians"},
           {"cone-indices", "LIST", "the same as indices 'v:k,...', K = 2 pi k (k integer, p/q, decimal)"},
           {"boundary-curvature", "LIST", "target geodesic curvatures 'v:kappa,...' of boundary vertices"},
           {"lengths-out", "FILE", "write the metric: one line 'i j length' per edge (intrinsic edges after flips)"},
           {"triangulation-out", "FILE", "write the triangulation carrying the metric as OFF (input faces if no flips)"},
           {"factors-out", "FILE", "write the conformal factor u of every vertex, one per line (connection --factors)"},
           {"uv-out", "FILE", "disks only: write the flat layout, one line 'u v' per vertex"},
           {"svg", "FILE", "disks only: draw the flat layout, faces coloured by the conformal factor"},
           {"iterations", "n", "maximum number of Newton iterations (default 200)"},
           {"tolerance", "t", "max curvature error accepted, radians (default 1e-10)"},
           {"no-flips", "", "keep the input triangulation (no intrinsic edge flips)"},
           {"refine", "", "compute the metric without flips on the input's conforming Delaunay refinement (vertices added on the input's edges; the output files describe the refinement)"},
           {"place-cones", "quad|triangle", "choose the cones for a quad or triangle remesh (multiples of pi/2 or pi/3) instead of --cones"},
           {"distortion-bound", "B", "with --place-cones: lengths scaled within e^B of each other away from the cones (default 2)"},
           {"max-cones", "n", "with --place-cones: at most n cones (default 500)"},
           {"progress", "", "print the error of every iteration to stderr (default: only on a terminal)"}},
          "flat cone metric with prescribed cone angles (discrete conformal map)",
          "Computes edge lengths, conformally equivalent to the Euclidean ones (l_ij = l0_ij\n"
          "exp((u_i + u_j) / 2)), whose discrete curvature is the target at every vertex: the angle\n"
          "defect 2 pi - sum(angles) at interior vertices (0 unless given by --cones/--cone-indices;\n"
          "a cone K >= 2 pi, index >= 1, is punched as a hole whose d ring vertices get the geodesic\n"
          "curvature (K - 2 pi) / d; the output files then describe the holed surface) and the\n"
          "geodesic curvature pi - sum(angles) at boundary vertices (0 unless given by\n"
          "--boundary-curvature; must be < pi). On every component the targets must sum to\n"
          "2 pi chi (Gauss-Bonnet), e.g. eight cones of pi/2 on a sphere, or four boundary corners of\n"
          "pi/2 on a disk (a rectangle).\n"
          "Newton's method runs on the input triangulation first; if that triangulation cannot\n"
          "carry the target metric (triangles degenerate), the flow continues on an intrinsic\n"
          "Delaunay triangulation of the same vertices (edge flips; same numbers of edges and faces),\n"
          "unless --no-flips is given. --refine instead computes it, without flips, on the input's\n"
          "conforming Delaunay refinement: vertices are added on the input's edges only (after the\n"
          "input's, which keep their numbers) and each input triangle is re-triangulated inside\n"
          "itself until every edge is Delaunay; a metric the input cannot carry usually exists there,\n"
          "and that triangulation lies on the input surface. The JSON then has delaunay_refinement:\n"
          "{success, faces, inserted_vertices, max_opposite_angle_sum}, and --lengths-out,\n"
          "--triangulation-out (with the new vertices' positions), --uv-out and --svg describe the\n"
          "refinement.\n"
          "Angles K, kappa: a decimal or p/q in radians, or a multiple of pi written [c][*]pi[/d]\n"
          "(pi, -pi, pi/2, 3*pi/4, -4pi, 0.5pi). Each vertex may be given once, by one option.\n"
          "Prints {status: \"converged\"|\"not_converged\", converged, iterations,\n"
          "max_curvature_error (radians), rounding_level (largest rounding level of an angle sum:\n"
          "the error allowed beyond the tolerance at a vertex next to needle triangles, about 1e-14\n"
          "elsewhere; see curvature_tolerance in the manual), time_s, method, message (empty when\n"
          "converged), cones\n"
          "(interior vertices with K != 0), boundary_corners (boundary vertices with kappa != 0),\n"
          "triangulation_changed (the metric lives on an intrinsic triangulation that differs from\n"
          "the input's), edge_flips (intrinsic flips performed), intrinsic_triangulation: {faces,\n"
          "edges, new_edges (edges that are not input edges)} (only when triangulation_changed),\n"
          "punched_vertices (cones of index >= 1 punched as holes), uv_positively_oriented (with\n"
          "--uv-out/--svg: every laid-out triangle is counterclockwise)}.\n"
          "--lengths-out writes 'i j length' per edge (i j 0-based vertex indices in file order, 17\n"
          "digits). Without flips these are the input's edges (i j the vertices of halfedge(e)),\n"
          "readable by 'holonomy --lengths'. When triangulation_changed they are the intrinsic\n"
          "triangulation's edges in its order: the edge list differs from the input's (some input\n"
          "edges are gone, new ones join other vertex pairs, two edges may join the same pair) and\n"
          "the faces are those of --triangulation-out. --triangulation-out writes an OFF file with\n"
          "the input vertex positions (for display only: the geometry is in the lengths) and the\n"
          "faces of the triangulation carrying the metric (the input faces if it did not change).\n"
          "An intrinsic triangulation may have two edges joining the same vertices or a face with a\n"
          "repeated vertex; smdf cannot read such an OFF back (its reader rejects non-manifold\n"
          "soups). --uv-out and --svg need a topological disk (usage error otherwise); the layout\n"
          "unfolds the faces (of the intrinsic triangulation when triangulation_changed, also the\n"
          "faces drawn by --svg) breadth-first from face 0 and may overlap itself globally. The SVG\n"
          "colours faces by the mean conformal factor u of their vertices (blue u < 0, white 0,\n"
          "red u > 0, scaled by max |u|).\n"
          "Not converged (tolerance not reached in --iterations, or, with --no-flips, the target\n"
          "metric does not exist on this triangulation): the JSON object is still printed on stdout,\n"
          "one error line goes to stderr and the exit code is 3; --lengths-out and\n"
          "--triangulation-out then hold the last valid iterate and --uv-out/--svg are not written.\n"
          "--place-cones quad|triangle places the cones itself (place_remeshing_cones()): few\n"
          "vertices, no two adjacent, with curvatures that are multiples of pi/2 (quad) or pi/3\n"
          "(triangle), boundary vertices as corners turning by such multiples, summing to 2 pi chi,\n"
          "chosen greedily where the flat metric would stretch most until the metric's log scale u\n"
          "varies by at most --distortion-bound away from the cones and their neighbours. The JSON\n"
          "then has placement: {success, message, distortion_bound, scale_spread (max u - min u\n"
          "read back from the metric), linear_scale_spread (the linear model's), placement_rounds,\n"
          "negative_cone_quanta (2 where 2 pi chi alone needs over half of --max-cones cones of -pi/2:\n"
          "negative cones of -pi then, vertices of valence 6; else 1),\n"
          "placed_cones: [{vertex, curvature}]}, and the metric is that of the placed cones. Bound\n"
          "not reached with --max-cones cones: the outputs are written, exit 3.\n",
          run_cone_metric};
}

} // namespace smdf_cli
