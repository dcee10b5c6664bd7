// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_READ_TRIANGLE_MESH_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_READ_TRIANGLE_MESH_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// What validate_polygon_soup() and read_triangle_mesh() found and changed.
struct Polygon_soup_report
{
  std::size_t points = 0;                 ///< number of points (vertices, in file order)
  std::size_t polygons = 0;               ///< number of polygons (faces, in file order)
  std::size_t unreferenced_points = 0;    ///< points used by no polygon (kept as isolated vertices)
  std::size_t reoriented_polygons = 0;    ///< polygons whose vertex order was reversed
  std::size_t triangulated_polygons = 0;  ///< polygons of more than 3 vertices split into triangles (`triangulate_polygons`)
};

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Checks that a polygon soup describes an orientable triangulated 2-manifold (possibly with
/// boundary, possibly with several components) and orients it consistently, keeping the order
/// of polygons and of points. Throws `Input_error` naming the first problem found, checked in
/// this order: a polygon with fewer than 3 vertices or a repeated vertex (`DEGENERATE_FACE`), an
/// index out of range (`FILE_ERROR`), an
/// edge shared by more than two polygons, which includes duplicate faces
/// (`NON_MANIFOLD_EDGE`), a component that cannot be oriented (`NON_ORIENTABLE`), a vertex
/// whose polygons form more than one fan (`NON_MANIFOLD_VERTEX`), a polygon that is not a
/// triangle (`NOT_TRIANGLE_MESH`; not checked when `triangles_only` is false).
/// Orientation follows the first polygon of each component; others are flipped to agree.
/// \tparam PolygonRange a random-access range of random-access ranges of indices (e.g.
///         `std::vector<std::vector<std::size_t>>`)
template <typename PolygonRange>
Polygon_soup_report validate_polygon_soup(std::size_t number_of_points, PolygonRange& polygons, bool triangles_only = true)
{
  Polygon_soup_report report;
  report.points = number_of_points;
  report.polygons = polygons.size();
  const std::size_t np = polygons.size();

  struct Side { std::uint64_t key; std::uint32_t poly; std::uint32_t a, b; };
  std::vector<Side> sides;
  std::vector<char> used(number_of_points, 0);
  for(std::size_t p = 0; p < np; ++p) {
    const auto& poly = polygons[p];
    const std::size_t n = poly.size();
    if(n < 3) {
      std::ostringstream os;
      os << "face " << p << " has " << n << " vertices; a face needs at least 3";
      throw Input_error(Input_error::DEGENERATE_FACE, os.str());
    }
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t a = poly[i], b = poly[(i + 1) % n];
      if(a >= number_of_points) {
        std::ostringstream os;
        os << "face " << p << " refers to vertex " << a << " but there are only "
           << number_of_points << " vertices";
        throw Input_error(Input_error::FILE_ERROR, os.str());
      }
      for(std::size_t j = 0; j < i; ++j)
        if(poly[j] == a) {
          std::ostringstream os;
          os << "face " << p << " uses vertex " << a << " twice (degenerate face)";
          throw Input_error(Input_error::DEGENERATE_FACE, os.str());
        }
      used[a] = 1;
      const std::uint64_t lo = (std::min)(a, b), hi = (std::max)(a, b);
      sides.push_back(Side{lo * number_of_points + hi, std::uint32_t(p), std::uint32_t(a), std::uint32_t(b)});
    }
  }
  report.unreferenced_points = std::size_t(std::count(used.begin(), used.end(), 0));
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return x.key < y.key; });

  // face adjacency through manifold edges; `same` = both polygons traverse the edge in the same
  // direction, so one of them must be flipped
  std::vector<std::size_t> start(np + 1, 0);
  struct Link { std::uint32_t other; bool same; };
  std::vector<std::pair<std::uint32_t, Link>> links;
  for(std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while(j < sides.size() && sides[j].key == sides[i].key) ++j;
    if(j - i > 2) {
      std::ostringstream os;
      os << "edge (" << (std::min)(sides[i].a, sides[i].b) << ", " << (std::max)(sides[i].a, sides[i].b)
         << ") is shared by " << (j - i) << " faces (non-manifold edge or duplicate face)";
      throw Input_error(Input_error::NON_MANIFOLD_EDGE, os.str());
    }
    if(j - i == 2) {
      const bool same = sides[i].a == sides[i + 1].a;
      links.push_back({sides[i].poly, Link{sides[i + 1].poly, same}});
      links.push_back({sides[i + 1].poly, Link{sides[i].poly, same}});
    }
    i = j;
  }
  for(const auto& l : links) ++start[l.first + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Link> adj(links.size());
  {
    std::vector<std::size_t> pos(start.begin(), start.end() - 1);
    for(const auto& l : links) adj[pos[l.first]++] = l.second;
  }

  std::vector<signed char> flip(np, -1);
  std::vector<std::uint32_t> stack;
  for(std::size_t r = 0; r < np; ++r) {
    if(flip[r] >= 0) continue;
    flip[r] = 0;
    stack.push_back(std::uint32_t(r));
    while(!stack.empty()) {
      const std::uint32_t p = stack.back();
      stack.pop_back();
      for(std::size_t k = start[p]; k < start[p + 1]; ++k) {
        const signed char want = static_cast<signed char>(flip[p] ^ (adj[k].same ? 1 : 0));
        if(flip[adj[k].other] < 0) { flip[adj[k].other] = want; stack.push_back(adj[k].other); }
        else if(flip[adj[k].other] != want) {
          std::ostringstream os;
          os << "the mesh is not orientable: faces " << p << " and " << adj[k].other
             << " cannot be oriented consistently (the component of face " << r
             << " is a Moebius-like surface)";
          throw Input_error(Input_error::NON_ORIENTABLE, os.str());
        }
      }
    }
  }
  for(std::size_t p = 0; p < np; ++p)
    if(flip[p]) { std::reverse(polygons[p].begin(), polygons[p].end()); ++report.reoriented_polygons; }

  // vertex fans: union the corners of two polygons at a vertex they share through an edge
  std::vector<std::size_t> corner_start(np + 1, 0);
  for(std::size_t p = 0; p < np; ++p) corner_start[p + 1] = corner_start[p] + polygons[p].size();
  std::vector<std::size_t> uf(corner_start[np]);
  std::iota(uf.begin(), uf.end(), std::size_t(0));
  auto find = [&](std::size_t x) { while(uf[x] != x) { uf[x] = uf[uf[x]]; x = uf[x]; } return x; };
  auto corner = [&](std::size_t p, std::size_t v) {
    const auto& poly = polygons[p];
    for(std::size_t i = 0; i < poly.size(); ++i) if(std::size_t(poly[i]) == v) return corner_start[p] + i;
    return std::size_t(0);
  };
  for(std::size_t i = 0; i + 1 < sides.size(); ++i) {
    if(sides[i].key != sides[i + 1].key) continue;
    for(std::size_t v : {std::size_t(sides[i].a), std::size_t(sides[i].b)}) {
      const std::size_t x = find(corner(sides[i].poly, v)), y = find(corner(sides[i + 1].poly, v));
      if(x != y) uf[x] = y;
    }
  }
  std::vector<std::size_t> fan_root(number_of_points, std::size_t(-1));
  for(std::size_t p = 0; p < np; ++p)
    for(std::size_t i = 0; i < polygons[p].size(); ++i) {
      const std::size_t v = polygons[p][i], root = find(corner_start[p] + i);
      if(fan_root[v] == std::size_t(-1)) fan_root[v] = root;
      else if(fan_root[v] != root) {
        std::ostringstream os;
        os << "vertex " << v << " is non-manifold: the faces around it form more than one fan"
           << " (pinched vertex)";
        throw Input_error(Input_error::NON_MANIFOLD_VERTEX, os.str());
      }
    }

  for(std::size_t p = 0; p < np && triangles_only; ++p)
    if(polygons[p].size() != 3) {
      std::ostringstream os;
      os << "face " << p << " has " << polygons[p].size()
         << " vertices; only triangle meshes are supported (triangulate it first)";
      throw Input_error(Input_error::NOT_TRIANGLE_MESH, os.str());
    }
  return report;
}

namespace internal {

// Wavefront OBJ reader for geometry only: `v` and `f` records (with `/`-separated texture and
// normal indices, negative relative indices and `\` line continuations); other records are
// ignored. CGAL 5.5's reader rejects files with some of these features.
template <typename Point>
void read_obj(const std::string& filename, std::vector<Point>& points,
              std::vector<std::vector<std::size_t>>& polygons)
{
  std::ifstream in(filename);
  std::string line, record;
  std::size_t line_no = 0, record_line = 0;
  auto fail = [&](const std::string& what) {
    throw Input_error(Input_error::FILE_ERROR, "'" + filename + "' line " +
                      std::to_string(record_line) + ": " + what);
  };
  while(std::getline(in, line)) {
    ++line_no;
    if(record.empty()) record_line = line_no;
    if(!line.empty() && line.back() == '\r') line.pop_back();
    if(!line.empty() && line.back() == '\\') { line.pop_back(); record += line + " "; continue; }
    record += line;
    std::istringstream is(record);
    record.clear();
    std::string key;
    if(!(is >> key) || key[0] == '#') continue;
    if(key == "v") {
      double x, y, z;
      if(!(is >> x >> y >> z)) fail("a vertex needs three coordinates");
      points.push_back(Point(x, y, z));
    } else if(key == "f") {
      std::vector<std::size_t> poly;
      std::string tok;
      while(is >> tok) {
        long idx = 0;
        try { idx = std::stol(tok.substr(0, tok.find('/'))); } catch(...) { fail("bad face index '" + tok + "'"); }
        if(idx < 0) idx += long(points.size()) + 1;
        if(idx < 1 || idx > long(points.size()))
          fail("face index " + tok + " refers to a vertex not defined before it");
        poly.push_back(std::size_t(idx - 1));
      }
      polygons.push_back(poly);
    }
  }
}

// ASCII OFF reader (headers OFF, COFF, NOFF, CNOFF, STOFF, or none; '#' comments; extra
// per-vertex and per-face values such as colours are ignored). CGAL 5.5's scanner converts a
// negative face index to an unsigned integer (undefined behaviour, found by fuzzing), so the
// package reads OFF itself and checks every count and index.
template <typename Point>
void read_off(const std::string& filename, std::vector<Point>& points,
              std::vector<std::vector<std::size_t>>& polygons)
{
  std::ifstream in(filename, std::ios::binary);
  std::string line;
  std::size_t line_no = 0;
  auto fail = [&](const std::string& what) {
    throw Input_error(Input_error::FILE_ERROR, "'" + filename + "' line " + std::to_string(line_no) + ": " + what);
  };
  // the next line with content, comments removed
  auto next_line = [&](std::istringstream& is) {
    while(std::getline(in, line)) {
      ++line_no;
      const std::size_t hash = line.find('#');
      if(hash != std::string::npos) line.erase(hash);
      if(line.find_first_not_of(" \t\r\f\v") == std::string::npos) continue;
      is.clear();
      is.str(line);
      return true;
    }
    return false;
  };
  auto count = [&](std::istringstream& is, const char* what) {
    long long n = -1;
    if(!(is >> n) || n < 0 || n > (1LL << 40)) fail(std::string("expected the number of ") + what);
    return std::size_t(n);
  };
  std::istringstream is;
  if(!next_line(is)) fail("empty file");
  std::string head;
  is >> head;
  static const char* const headers[] = {"OFF", "COFF", "NOFF", "CNOFF", "STOFF", "STCOFF", "STNOFF", "STCNOFF"};
  const bool has_header = std::find(std::begin(headers), std::end(headers), head) != std::end(headers);
  if(!has_header) {
    if(head.find("OFF") != std::string::npos) fail("unsupported OFF variant '" + head + "' (binary and 4D OFF are not read)");
    is.clear();
    is.str(line);   // a file without header starts with the counts
  }
  std::string rest;
  if(has_header && (is >> rest)) {
    if(rest == "BINARY") fail("binary OFF is not read");
    is.clear();
    is.str(line.substr(line.find(head) + head.size()));
  } else if(has_header && !next_line(is)) {
    fail("missing the counts line");
  }
  const std::size_t nv = count(is, "vertices"), nf = count(is, "faces");
  points.reserve((std::min)(nv, std::size_t(1) << 24));
  polygons.reserve((std::min)(nf, std::size_t(1) << 24));
  for(std::size_t v = 0; v < nv; ++v) {
    if(!next_line(is)) fail("the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    double x, y, z;
    if(!(is >> x >> y >> z)) fail("a vertex needs three coordinates");
    points.push_back(Point(x, y, z));
  }
  for(std::size_t f = 0; f < nf; ++f) {
    if(!next_line(is)) fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    long long k = -1;
    if(!(is >> k) || k < 1 || k > 1000000) fail("a face needs its number of vertices (at least 1)");
    std::vector<std::size_t> poly(static_cast<std::size_t>(k));
    for(auto& i : poly) {
      long long idx = -1;
      if(!(is >> idx)) fail("a face has fewer vertex indices than announced");
      if(idx < 0 || idx >= (long long)nv) fail("vertex index " + std::to_string(idx) + " out of range [0, " + std::to_string(nv) + ")");
      i = std::size_t(idx);
    }
    polygons.push_back(std::move(poly));
  }
}

inline bool is_ply_scalar_type(const std::string& t)
{
  static const char* const types[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                      "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  for(const char* known : types)
    if(t == known) return true;
  return false;
}

// Checks a PLY header before CGAL's reader sees it. CGAL 5.5
// - reads a `property` line that comes before any `element` line through back() of an empty
//   vector (undefined behaviour, found by fuzzing);
// - reads an element count of -4 as 2^64 - 4 and pushes vertices until memory runs out (found by
//   fuzzing); every element takes at least one byte, so a count above the file's size is refused;
// - accepts unknown header keywords and property types silently.
inline void check_ply_header(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary | std::ios::ate);
  const long long file_size = in ? static_cast<long long>(in.tellg()) : 0;
  in.seekg(0);
  std::string line;
  std::size_t line_no = 0;
  bool element = false;
  auto fail = [&](const std::string& what) {
    throw Input_error(Input_error::FILE_ERROR, "'" + filename + "' is not a valid PLY file: header line " +
                      std::to_string(line_no) + ": " + what);
  };
  while(std::getline(in, line) && line_no < 100000) {
    ++line_no;
    if(!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream is(line);
    std::string key;
    is >> key;
    if(line_no == 1) { if(key != "ply") fail("the first line must be 'ply'"); continue; }
    if(key == "end_header") return;
    if(key == "element") {
      std::string name, count_text, rest;
      is >> name >> count_text;
      if(name.empty() || count_text.empty() || (is >> rest)) fail("an element needs a name and a count");
      if(count_text.find_first_not_of("0123456789") != std::string::npos || count_text.size() > 18)
        fail("element count '" + count_text + "' is not a non-negative integer");
      if(std::stoll(count_text) > file_size)
        fail("element count " + count_text + " exceeds the file's size (" + std::to_string(file_size) + " bytes)");
      element = true;
      continue;
    }
    if(key == "property") {
      if(!element) fail("a property before any element");
      std::string type, count_type, index_type;
      is >> type;
      if(type == "list") {
        is >> count_type >> index_type;
        if(!is_ply_scalar_type(count_type) || !is_ply_scalar_type(index_type))
          fail("a list property needs two known types, got '" + count_type + "' and '" + index_type + "'");
      } else if(!is_ply_scalar_type(type)) {
        fail("unknown property type '" + type + "'");
      }
      continue;
    }
    if(key != "format" && key != "comment" && key != "obj_info" && !key.empty())
      fail("unknown keyword");
  }
  fail("no end_header");
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Reads a triangle mesh from an OFF, OBJ, PLY or STL file (by extension), validates it with
/// validate_polygon_soup() and builds `tm`. Vertices and faces keep their file order, so
/// vertex and face indices of the file are the indices of `vertices(tm)` and `faces(tm)` for
/// `CGAL::Surface_mesh` (unreferenced points become isolated vertices). Throws `Input_error`
/// (`FILE_ERROR` when the file cannot be opened or parsed, `INVALID_GEOMETRY` for non-finite
/// coordinates, and the errors of validate_polygon_soup()).
///
/// With `triangulate_polygons(true)` (default `false`: such a file is rejected), faces of more
/// than 3 vertices are checked like triangles, then split into triangles
/// (`CGAL::Polygon_mesh_processing::triangulate_faces()`, which triangulates each face's
/// projection on its best-fitting plane); the triangles are checked again as a soup and `tm`
/// is built from them. Vertices keep the file's order; faces do not. Throws `NOT_TRIANGLE_MESH`
/// when a polygon cannot be triangulated, and
/// the soup's errors when its triangulation is not a manifold (an edge it adds that the mesh
/// already has).
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point map
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Polygon_soup_report read_triangle_mesh(const std::string& filename, TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  const bool triangulate = parameters::choose_parameter(parameters::get_parameter(np, internal_np::triangulate_polygons), false);
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  {
    std::ifstream probe(filename);
    if(!probe) throw Input_error(Input_error::FILE_ERROR, "cannot open file '" + filename + "'");
  }
  bool ok = false;
  const std::string ext = filename.size() >= 4 ? filename.substr(filename.size() - 4) : "";
  try {
    if(ext == ".obj" || ext == ".OBJ") { internal::read_obj(filename, points, polygons); ok = true; }
    else if(ext == ".off" || ext == ".OFF") { internal::read_off(filename, points, polygons); ok = true; }
    else {
      if(ext == ".ply" || ext == ".PLY") internal::check_ply_header(filename);
      ok = CGAL::IO::read_polygon_soup(filename, points, polygons);
    }
  } catch(const Input_error&) {
    throw;
  } catch(const std::exception& e) {
    throw Input_error(Input_error::FILE_ERROR, "cannot parse '" + filename + "': " + e.what());
  }
  if(!ok)
    throw Input_error(Input_error::FILE_ERROR,
                      "cannot read '" + filename + "': unsupported extension (use .off, .obj, .ply or .stl) "
                      "or malformed content (bad header, non-numeric coordinate, index out of range, "
                      "truncated file)");
  if(polygons.empty())
    throw Input_error(Input_error::FILE_ERROR, "'" + filename + "' contains no faces");
  for(std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      throw Input_error(Input_error::INVALID_GEOMETRY,
                        "vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  Polygon_soup_report report = validate_polygon_soup(points.size(), polygons, !triangulate);
  clear(tm);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, tm);
  if(num_faces(tm) != polygons.size())
    throw Input_error(Input_error::FILE_ERROR,
                      "could not build a halfedge mesh from '" + filename + "'");
  for(const auto& p : polygons) report.triangulated_polygons += p.size() > 3;
  if(report.triangulated_polygons > 0) {
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(tm))
      throw Input_error(Input_error::NOT_TRIANGLE_MESH, "a face of more than 3 vertices of '" + filename + "' could not be triangulated");
    // the triangles as a soup, checked again: an added diagonal may be an edge the mesh has
    std::map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, std::size_t> index;
    for(auto v : vertices(tm)) index.emplace(v, index.size());
    std::vector<std::vector<std::size_t>> triangles;
    for(auto f : faces(tm)) {
      triangles.emplace_back();
      for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) triangles.back().push_back(index[v]);
    }
    validate_polygon_soup(num_vertices(tm), triangles);
    // built again from the triangles: indices without the gaps the split faces may leave
    clear(tm);
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, tm);
  }
  return report;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_READ_TRIANGLE_MESH_H
