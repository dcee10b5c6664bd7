// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf: the mesh type and the helpers shared by several subcommands (mesh loading, data files,
// vertex and face fields of a line, singularity lists, face fields and their SVG picture).
// The definitions are in common.cpp, so that the library templates they use (the mesh
// reader above all) are compiled once.

#ifndef SMDF_CLI_COMMON_H
#define SMDF_CLI_COMMON_H

#include "args.h"
#include "json.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/IO/svg_writer.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace smdf_cli {

namespace SMDF = CGAL::Surface_mesh_direction_fields;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef Mesh::Property_map<face_descriptor, double> Face_angle_property;
typedef Mesh::Property_map<face_descriptor, K::Vector_3> Face_vector_property;
typedef Mesh::Property_map<edge_descriptor, int> Edge_matching_property;   // period jump per edge
typedef Mesh::Property_map<edge_descriptor, double> Edge_length_property;

// ---- Files and their errors ---------------------------------------------------------------

// Error "<file>: <message> [<kind>]".
Error file_error(const std::string& file, const std::string& message, const char* kind);

// Error "<file>: line <line_no>: <what> [file_error]".
Error line_error(const std::string& file, std::size_t line_no, const std::string& what);

// Runs f(), turning a library Input_error into an Error that names `file`.
template <typename F>
auto on_file(const std::string& file, F f) -> decltype(f())
{
  try {
    return f();
  } catch(const SMDF::Input_error& e) {
    std::string message = e.what();
    const std::string quoted = "'" + file + "' ";   // "'f.obj' line 3: ..." -> "line 3: ..."
    if(message.compare(0, quoted.size(), quoted) == 0) message.erase(0, quoted.size());
    throw file_error(file, message, SMDF::Input_error::kind_name(e.kind()));
  }
}

// What a data file treats as a comment: a line whose first field starts with '#'
// (LINE_COMMENTS), or everything from a '#' to the end of its line (TRAILING_COMMENTS).
enum Comment_style { LINE_COMMENTS, TRAILING_COMMENTS };

// Lines of a text file split into fields; blank lines and comments are skipped. Calls
// f(line_no, fields) for every other line. An unreadable file is an Error naming it.
void for_each_data_line(const std::string& file,
                        const std::function<void(std::size_t, const std::vector<std::string>&)>& f,
                        Comment_style comments = TRAILING_COMMENTS);

// Field `field` of line `line_no` of `file` as a vertex (face) index below `n`; an Error
// "'x' is not a vertex index" or "vertex 7 does not exist (the mesh has 5 vertices)" if not.
std::size_t vertex_field(const std::string& file, std::size_t line_no, const std::string& field, std::size_t n);
std::size_t face_field(const std::string& file, std::size_t line_no, const std::string& field, std::size_t n);

// Field `field` of line `line_no` of `file` as a finite number; an Error if it is not one.
double finite_field(const std::string& file, std::size_t line_no, const std::string& field);

// Writes `text` to `file`; Error if it cannot be opened or written.
void write_lines_file(const std::string& file, const std::string& text);

// A string stream writing numbers with 17 significant digits in the C locale.
std::ostringstream number_stream();

// `d` with 17 significant digits in the C locale.
std::string format_real(double d);

// ---- Meshes -------------------------------------------------------------------------------

class Stopwatch
{
public:
  Stopwatch() : start_(clock::now()), lap_(start_) {}
  // Seconds since the previous lap (or the start).
  double lap()
  {
    const clock::time_point now = clock::now();
    const double s = std::chrono::duration<double>(now - lap_).count();
    lap_ = now;
    return s;
  }
  double total() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

private:
  typedef std::chrono::steady_clock clock;
  clock::time_point start_, lap_;
};

inline std::size_t index(vertex_descriptor v) { return std::size_t(v); }

// Reads and validates a mesh; errors name the file.
// `triangulate`: faces of more than 3 vertices are split into triangles instead of rejected
SMDF::Polygon_soup_report load_mesh(const std::string& file, Mesh& mesh, bool triangulate = false);

// "handle" or "boundary".
const char* kind_name(SMDF::Generator_kind k);

// ---- Direction fields ---------------------------------------------------------------------

// The prescribed singularities: `listed` (the pairs of --singularities) checked against a mesh
// of `nv` vertices, followed by the lines 'v k' of --singularities-file. A vertex out of range
// or given twice is an Error.
Indexed_values prescribed_singularities(const Args& args, const Indexed_values& listed, std::size_t nv);

// [{vertex, index}] in the order of `s`.
Json singularity_list(const Indexed_values& s);

// Singularities and generator turning numbers of the N-direction field given by face angles,
// read with principal matching, or with `matching` (period jumps for halfedge(e)) if given.
SMDF::Field_topology<Mesh> field_topology(const std::string& file, const Mesh& mesh,
                                          Face_angle_property angles, long N,
                                          const Edge_matching_property* matching = nullptr);

// Reads an edge-length file (--lengths): one line `i j length` per edge of `mesh` (vertex
// indices in either order); blank lines and lines starting with '#' are ignored. Every problem
// is an Error naming the file and the line.
Edge_length_property read_edge_lengths(const std::string& file, Mesh& mesh);

// --matching-out FILE: 'i j k' per interior edge, i j the vertices of halfedge(e).
void write_matching(const std::string& file, const Mesh& mesh, Edge_matching_property matching);

// The singularities of `topo` as [{vertex, index}], by vertex.
Json found_list(const SMDF::Field_topology<Mesh>& topo);

// The generator turning numbers of `topo` as an array.
Json turning_numbers(const SMDF::Field_topology<Mesh>& topo);

// --cones 'v:K,...' and --cone-indices 'v:k,...' (K = 2 pi k): vertices with K < 2 pi inside,
// K in (-pi, pi) on the boundary (the boundary's turning angle there), each once; Errors name
// the option and the vertex.
std::vector<std::pair<vertex_descriptor, double>> cone_option(const Args& args, const Mesh& mesh, bool punched_holes = false);

// The axis drawn pointing up in a picture when --view does not say (0 x, 1 y, 2 z).
int default_up_axis(const Mesh& mesh);

// The picture options of --svg: --view and --width (usage errors without --svg).
SMDF::Svg_options svg_options(const Args& args);

// Writes one line 'x y z' per vector to `file`.
void write_vectors(const std::string& file, const std::vector<K::Vector_3>& vectors);

// Writes --svg: the field and the singularities of `topo` (the view chosen from the mesh when
// --view does not say, and named in the caption).
void write_field_svg_file(const Args& args, const Mesh& mesh, Face_vector_property vectors, long N,
                          const SMDF::Field_topology<Mesh>& topo, const SMDF::Svg_options& svg);

// Writes --svg (write_field_svg_file()) and --field-out (one line 'x y z' per face), those of
// the two that are given.
void write_field_files(const Args& args, const Mesh& mesh, Face_vector_property vectors, long N,
                       const SMDF::Field_topology<Mesh>& topo, const SMDF::Svg_options& svg);

} // namespace smdf_cli

#endif // SMDF_CLI_COMMON_H
