// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "common.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/IO/svg_writer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <locale>
#include <utility>

namespace smdf_cli {

namespace {

// Silences std::cerr while alive: CGAL's readers may print diagnostics of their own, and the
// tool promises exactly one error line.
class Silence_cerr
{
public:
  Silence_cerr() : old_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~Silence_cerr() { std::cerr.rdbuf(old_); }
  Silence_cerr(const Silence_cerr&) = delete;
  Silence_cerr& operator=(const Silence_cerr&) = delete;

private:
  std::ostringstream sink_;
  std::streambuf* old_;
};

std::size_t index_field(const std::string& file, std::size_t line_no, const std::string& field, std::size_t n,
                        const char* what, const char* plural)
{
  std::size_t i;
  if(!parse_index(field, i))
    throw line_error(file, line_no, "'" + shorten(field) + "' is not a " + what + " index");
  if(i >= n)
    throw line_error(file, line_no, std::string(what) + " " + field + " does not exist (the mesh has " +
                     std::to_string(n) + " " + plural + ")");
  return i;
}

} // namespace

// ---- Files and their errors ---------------------------------------------------------------

Error file_error(const std::string& file, const std::string& message, const char* kind)
{
  return Error(file + ": " + message + " [" + kind + "]");
}

Error line_error(const std::string& file, std::size_t line_no, const std::string& what)
{
  return file_error(file, "line " + std::to_string(line_no) + ": " + what, "file_error");
}

void for_each_data_line(const std::string& file,
                        const std::function<void(std::size_t, const std::vector<std::string>&)>& f,
                        Comment_style comments)
{
  std::ifstream in(file);
  if(!in) throw file_error(file, "cannot open file", "file_error");
  std::string line;
  std::size_t line_no = 0;
  while(std::getline(in, line)) {
    ++line_no;
    const std::size_t hash = comments == TRAILING_COMMENTS ? line.find('#') : std::string::npos;
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream is(line);
    std::vector<std::string> tok;
    for(std::string t; is >> t;) tok.push_back(t);
    if(tok.empty() || tok[0][0] == '#') continue;
    f(line_no, tok);
  }
  if(in.bad()) throw file_error(file, "read error", "file_error");
}

std::size_t vertex_field(const std::string& file, std::size_t line_no, const std::string& field, std::size_t n)
{
  return index_field(file, line_no, field, n, "vertex", "vertices");
}

std::size_t face_field(const std::string& file, std::size_t line_no, const std::string& field, std::size_t n)
{
  return index_field(file, line_no, field, n, "face", "faces");
}

double finite_field(const std::string& file, std::size_t line_no, const std::string& field)
{
  char* end = nullptr;
  const double d = std::strtod(field.c_str(), &end);
  if(*end != '\0' || !std::isfinite(d))
    throw line_error(file, line_no, "'" + shorten(field) + "' is not a finite number");
  return d;
}

void write_lines_file(const std::string& file, const std::string& text)
{
  std::ofstream out(file);
  if(!out) throw file_error(file, "cannot open file for writing", "file_error");
  out << text;
  out.flush();
  if(!out) throw file_error(file, "write error", "file_error");
}

std::ostringstream number_stream()
{
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(17);
  return os;
}

std::string format_real(double d)
{
  std::ostringstream os = number_stream();
  os << d;
  return os.str();
}

// ---- Meshes -------------------------------------------------------------------------------

SMDF::Polygon_soup_report load_mesh(const std::string& file, Mesh& mesh, bool triangulate)
{
  return on_file(file, [&] {
    Silence_cerr quiet;
    return SMDF::read_triangle_mesh(file, mesh, SMDF::parameters::triangulate_polygons(triangulate));
  });
}

const char* kind_name(SMDF::Generator_kind k)
{
  return k == SMDF::HANDLE_GENERATOR ? "handle" : "boundary";
}

// ---- Direction fields ---------------------------------------------------------------------

Indexed_values prescribed_singularities(const Args& args, const Indexed_values& listed, std::size_t nv)
{
  Indexed_values sing = listed;
  std::vector<std::string> given_by(nv);   // where each vertex's index was given
  for(const auto& s : sing) {
    if(s.first >= nv)
      throw Error("--singularities: vertex " + std::to_string(s.first) + " does not exist (the mesh has " +
                  std::to_string(nv) + " vertices)");
    if(!given_by[s.first].empty())
      throw Error("--singularities: vertex " + std::to_string(s.first) + " is given twice");
    given_by[s.first] = "--singularities";
  }
  if(args.has("singularities-file")) {
    const std::string sf = args.value("singularities-file");
    for_each_data_line(sf, [&](std::size_t line_no, const std::vector<std::string>& tok) {
      double k;
      if(tok.size() != 2) throw line_error(sf, line_no, "expected 'vertex index', got " + std::to_string(tok.size()) + " fields");
      const std::size_t v = vertex_field(sf, line_no, tok[0], nv);
      if(!parse_number(tok[1], k)) throw line_error(sf, line_no, "'" + shorten(tok[1]) + "' is not a number (integer, p/q or decimal)");
      if(!given_by[v].empty()) throw line_error(sf, line_no, "vertex " + tok[0] + " was already given by " + given_by[v]);
      given_by[v] = "line " + std::to_string(line_no);
      sing.push_back(std::make_pair(v, k));
    });
  }
  return sing;
}

Json singularity_list(const Indexed_values& s)
{
  Json list = Json::array();
  for(const auto& p : s) {
    Json j = Json::object();
    j["vertex"] = p.first;
    j["index"] = p.second;
    list.push_back(std::move(j));
  }
  return list;
}

SMDF::Field_topology<Mesh> field_topology(const std::string& file, const Mesh& mesh,
                                          Face_angle_property angles, long N,
                                          const Edge_matching_property* matching)
{
  return on_file(file, [&] {
    if(matching)
      return SMDF::field_singularities(mesh, angles, SMDF::parameters::symmetry_order(int(N)).matching(*matching));
    return SMDF::field_singularities(mesh, angles, SMDF::parameters::symmetry_order(int(N)));
  });
}

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

void write_matching(const std::string& file, const Mesh& mesh, Edge_matching_property matching)
{
  std::ostringstream os;
  for(edge_descriptor e : edges(mesh)) {
    if(is_border(e, mesh)) continue;
    const halfedge_descriptor h = halfedge(e, mesh);
    os << index(source(h, mesh)) << ' ' << index(target(h, mesh)) << ' ' << get(matching, e) << '\n';
  }
  write_lines_file(file, os.str());
}

Json found_list(const SMDF::Field_topology<Mesh>& topo)
{
  Indexed_values s;
  for(const auto& p : topo.singularities) s.push_back(std::make_pair(index(p.first), p.second));
  std::sort(s.begin(), s.end());
  return singularity_list(s);
}

Json turning_numbers(const SMDF::Field_topology<Mesh>& topo)
{
  Json list = Json::array();
  for(double t : topo.generator_turning_numbers) list.push_back(t);
  return list;
}

SMDF::Svg_options svg_options(const Args& args)
{
  SMDF::Svg_options svg;
  if(!args.has("svg") && !args.has("hatching-svg") && !args.has("knot-svg") && (args.has("view") || args.has("width")))
    throw Usage_error(std::string("option --") + (args.has("view") ? "view" : "width") + " needs --svg FILE" +
                      (args.command == "rosy" ? " or --hatching-svg FILE" : ""));
  if(args.has("view")) {
    const std::string view = args.value("view");
    const std::size_t comma = view.find(',');
    const std::size_t comma2 = comma == std::string::npos ? comma : view.find(',', comma + 1);
    double a = 0, e = 0;
    const std::string axis = comma2 == std::string::npos ? "y" : view.substr(comma2 + 1);
    if(comma == std::string::npos || !parse_real(view.substr(0, comma), a) ||
       !parse_real(view.substr(comma + 1, comma2 == std::string::npos ? std::string::npos : comma2 - comma - 1), e) ||
       (axis != "x" && axis != "y" && axis != "z"))
      throw Usage_error("option --view expects 'azimuth,elevation' in degrees, optionally followed by ',x', "
                        "',y' or ',z' (the up axis; default: chosen from the mesh's bounding box), got '" + shorten(view) + "'");
    svg.up_axis = axis[0] - 'x';
    svg.azimuth = a;
    svg.elevation = e;
  }
  if(args.has("width")) {
    const long w = args.integer("width", 800);
    if(w < 1 || w > 100000) throw Usage_error("option --width expects a number of pixels in [1, 100000], got '" + args.value("width") + "'");
    svg.width = int(w);
  }
  return svg;
}

// The axis drawn pointing up when --view does not say: the thin axis of a flat object (its
// bounding box is less than half as deep along it as along the next axis), else y, the
// convention of most modelled and scanned meshes (OBJ, Stanford's and Crane's models).
int default_up_axis(const Mesh& mesh)
{
  if(num_vertices(mesh) == 0) return 1;
  const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  double extent[3];
  for(int k = 0; k < 3; ++k) extent[k] = box.max(k) - box.min(k);
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return extent[a] < extent[b]; });
  return extent[order[0]] < 0.5 * extent[order[1]] ? order[0] : 1;
}

void write_vectors(const std::string& file, const std::vector<K::Vector_3>& vectors)
{
  std::ostringstream os = number_stream();
  for(const K::Vector_3& v : vectors) os << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  write_lines_file(file, os.str());
}

void write_field_svg_file(const Args& args, const Mesh& mesh, Face_vector_property vectors, long N,
                          const SMDF::Field_topology<Mesh>& topo, const SMDF::Svg_options& svg)
{
  SMDF::Svg_options view = svg;
  if(!args.has("view")) view.up_axis = default_up_axis(mesh);
  std::ostringstream caption;
  caption << "view: azimuth " << view.azimuth << ", elevation " << view.elevation << ", " << char('x' + view.up_axis)
          << " up" << (args.has("view") ? "" : " (chosen; set with --view A,E,x|y|z)");
  view.caption = caption.str();
  std::ostringstream os;
  SMDF::write_field_svg(os, mesh, vectors, int(N), topo.singularities, view);
  write_lines_file(args.value("svg"), os.str());
}

void write_field_files(const Args& args, const Mesh& mesh, Face_vector_property vectors, long N,
                       const SMDF::Field_topology<Mesh>& topo, const SMDF::Svg_options& svg)
{
  if(args.has("svg")) write_field_svg_file(args, mesh, vectors, N, topo, svg);
  if(args.has("field-out")) {
    std::vector<K::Vector_3> v;
    for(face_descriptor f : faces(mesh)) v.push_back(get(vectors, f));
    write_vectors(args.value("field-out"), v);
  }
}

// The cones of the options: vertices with K < 2 pi (index below 1) inside, K < pi on the
// boundary (the boundary's turning angle there), each once.
std::vector<std::pair<vertex_descriptor, double>> cone_option(const Args& args, const Mesh& mesh, bool punched_holes)
{
  const Indexed_values cones = pairs_option(args, "cones", parse_angle, "'v:K,v:K,...' (K radians: decimal, p/q, pi/2, -4pi, ...)");
  const Indexed_values indices = pairs_option(args, "cone-indices", parse_number, "'v:k,...' (index k, K = 2 pi k)");
  std::vector<std::pair<vertex_descriptor, double>> out;
  std::vector<char> given(num_vertices(mesh), 0);
  auto add = [&](const char* option, std::size_t v, double K) {
    const std::string where = std::string("--") + option + ": vertex " + std::to_string(v);
    if(v >= num_vertices(mesh))
      throw Error(where + " does not exist (the mesh has " + std::to_string(num_vertices(mesh)) + " vertices)");
    const vertex_descriptor vd(static_cast<Mesh::size_type>(v));
    if(given[v]++) throw Error(where + " is given twice");
    if(halfedge(vd, mesh) == boost::graph_traits<Mesh>::null_halfedge())
      throw Error(where + " is isolated (no face)");
    if(CGAL::is_border(vd, mesh)) {
      if(!(K < CGAL_PI && K > -CGAL_PI))
        throw Error(where + " is on the boundary, where K is the boundary's turning angle and must lie in (-pi, pi), got " + format_real(K));
    } else if(!(K < 2 * CGAL_PI) && !punched_holes) {
      throw Error(where + ": cones of index 1 or more (punched holes) are not supported here");
    } else if(!std::isfinite(K)) {
      throw Error(where + ": the cone curvature must be finite");
    }
    out.emplace_back(vd, K);
  };
  for(const auto& c : cones) add("cones", c.first, c.second);
  for(const auto& c : indices) add("cone-indices", c.first, 2 * CGAL_PI * c.second);
  return out;
}

} // namespace smdf_cli
