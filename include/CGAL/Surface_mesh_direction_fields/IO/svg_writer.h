// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_SVG_WRITER_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_SVG_WRITER_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <locale>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Drawing options of write_field_svg(). Lengths in pixels unless stated otherwise; colors are
/// SVG color strings (`#rrggbb`, `#rgb`, a color name, `rgb(r,g,b)` or `none`).
struct Svg_options
{
  int width = 800;                  ///< width of the picture; the height follows from the view
  double azimuth = 30;              ///< view direction: degrees around the up axis (from the x axis when z is up, from z when y is up, from y when x is up)
  double elevation = 20;            ///< view direction: degrees above the plane orthogonal to the up axis
  int up_axis = 2;                  ///< the coordinate axis drawn pointing up: 0 (x), 1 (y) or 2 (z)
  double glyph_scale = 0.4;         ///< size of a field glyph, relative to the mean edge length
  double glyph_stroke_width = 1.2;  ///< line width of the field glyphs
  double edge_stroke_width = 0.3;   ///< line width of the mesh edges (0: no edges)
  double singularity_radius = 5;    ///< radius of the singularity markers
  std::size_t max_glyphs = 3000;    ///< glyphs are drawn on every k-th visible face so that at most this many are drawn, \f$\sqrt{k}\f$ times larger (0: no limit)
  bool legend = true;               ///< list the singularity indices (with their colors) below the mesh
  std::string face_color = "#d0d0d0";  ///< color of a face facing the light (darker when turned away)
  std::string edge_color = "#606060";  ///< color of the mesh edges
  std::string glyph_color = "#1a1a1a"; ///< color of the field glyphs
  std::string positive_color = "#d62020"; ///< color of the largest positive index (smaller ones are paler)
  std::string negative_color = "#2050d6"; ///< color of the largest negative index (smaller ones are paler)
  std::string background_color = "none";  ///< background of the picture
  std::string caption;              ///< a line of text under the picture (empty: none)
};

namespace internal {

// Tag standing for "no field" in write_field_svg().
struct No_face_field {};

// Instead of a field: line segments (x0 y0 z0 x1 y1 z1) per face index, drawn with the face so
// that the faces in front hide them (write_streamlines_svg()).
struct Svg_face_strokes
{
  std::vector<std::vector<std::array<double, 6>>> segments;
};

template <typename FaceVectorMap, typename Face>
bool svg_field_vector(const FaceVectorMap& map, const Face& f, double v[3])
{
  const auto& x = get(map, f);
  v[0] = double(x[0]);
  v[1] = double(x[1]);
  v[2] = double(x[2]);
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

template <typename Face>
bool svg_field_vector(const No_face_field&, const Face&, double*)
{
  return false;
}

// A pixel coordinate with one decimal, locale-independent, without a trailing ".0".
template <typename Face>
bool svg_field_vector(const Svg_face_strokes&, const Face&, double*)
{
  return false;
}

inline void svg_write_coordinate(std::string& out, double x)
{
  long long t = std::llround(x * 10);
  if(t < 0) { out += '-'; t = -t; }
  out += std::to_string(t / 10);
  if(t % 10) { out += '.'; out += char('0' + t % 10); }
}

// Colors end up in attribute values and CSS: reject anything that could break the markup.
inline void svg_check_color(const std::string& c, const char* name)
{
  bool ok = !c.empty() && c.size() < 64;
  for(char ch : c)
    ok = ok && ((ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                ch == '#' || ch == '(' || ch == ')' || ch == ',' || ch == '.' || ch == '%' || ch == ' ');
  if(!ok)
    throw Input_error(Input_error::INVALID_ARGUMENT,
                      std::string("Svg_options::") + name + " is not a valid SVG color: '" + c.substr(0, 40) + "'");
}

// "#rgb" or "#rrggbb" to three 0..255 values; false for other color syntaxes.
inline bool svg_parse_hex_color(const std::string& c, double rgb[3])
{
  auto hex = [](char ch) {
    if(ch >= '0' && ch <= '9') return ch - '0';
    if(ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
    if(ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
    return -1;
  };
  if(c.size() != 4 && c.size() != 7) return false;
  if(c[0] != '#') return false;
  for(std::size_t i = 1; i < c.size(); ++i)
    if(hex(c[i]) < 0) return false;
  for(int k = 0; k < 3; ++k)
    rgb[k] = c.size() == 4 ? 17.0 * hex(c[1 + k]) : 16.0 * hex(c[1 + 2 * k]) + hex(c[2 + 2 * k]);
  return true;
}

inline std::string svg_hex_color(const double rgb[3])
{
  static const char* digits = "0123456789abcdef";
  std::string s = "#";
  for(int k = 0; k < 3; ++k) {
    const int v = (std::max)(0, (std::min)(255, int(std::lround(rgb[k]))));
    s += digits[v >> 4];
    s += digits[v & 15];
  }
  return s;
}

// "+1", "-1/4", "+0.3": an index as a multiple of 1/N when it is one.
inline std::string svg_index_label(double k, int N)
{
  const double p = k * N;
  std::string s = k > 0 ? "+" : "-";
  if(std::abs(p - std::round(p)) < 1e-9 && std::abs(p) < 1e9) {
    long long a = std::llabs(std::llround(p)), b = N, x = a, y = b;
    while(y) { const long long t = x % y; x = y; y = t; }
    a /= x; b /= x;
    s += std::to_string(a);
    if(b != 1) s += "/" + std::to_string(b);
    return s;
  }
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(4);
  os << std::abs(k);
  return s + os.str();
}

// Throws Input_error for invalid options, N or singularity indices (see write_field_svg()).
template <typename Singularities>
void svg_check_options(const Svg_options& o, int N, const Singularities& singularities)
{
  auto invalid = [](const std::string& what) { throw Input_error(Input_error::INVALID_ARGUMENT, what); };
  if(o.width <= 0) invalid("Svg_options::width must be positive, got " + std::to_string(o.width));
  if(!std::isfinite(o.azimuth) || !std::isfinite(o.elevation))
    invalid("Svg_options::azimuth and elevation must be finite numbers of degrees");
  if(o.up_axis < 0 || o.up_axis > 2)
    invalid("Svg_options::up_axis must be 0, 1 or 2, got " + std::to_string(o.up_axis));
  auto check_size = [&](double x, const char* name) {
    if(!std::isfinite(x) || x < 0) invalid(std::string("Svg_options::") + name + " must be finite and non-negative");
  };
  check_size(o.glyph_scale, "glyph_scale");
  check_size(o.glyph_stroke_width, "glyph_stroke_width");
  check_size(o.edge_stroke_width, "edge_stroke_width");
  check_size(o.singularity_radius, "singularity_radius");
  internal::svg_check_color(o.face_color, "face_color");
  internal::svg_check_color(o.edge_color, "edge_color");
  internal::svg_check_color(o.glyph_color, "glyph_color");
  internal::svg_check_color(o.positive_color, "positive_color");
  internal::svg_check_color(o.negative_color, "negative_color");
  internal::svg_check_color(o.background_color, "background_color");
  if(N < 1) invalid("symmetry order N must be at least 1, got " + std::to_string(N));
  for(const auto& s : singularities)
    if(!std::isfinite(s.second)) invalid("singularity index is not finite");
}

// The orthographic camera of write_field_svg(): view direction d (towards the viewer), screen
// axes r (right) and u (up), and a fixed light from the upper left of the viewer.
struct Svg_camera
{
  double d[3], r[3], u[3], light[3];
  explicit Svg_camera(const Svg_options& o)
  {
    const double deg = CGAL_PI / 180;
    const double ca = std::cos(o.azimuth * deg), sa = std::sin(o.azimuth * deg);
    const double ce = std::cos(o.elevation * deg), se = std::sin(o.elevation * deg);
    // in coordinates (x', y', z') with z' the up axis, a cyclic permutation of (x, y, z)
    const double dp[3] = {ce * ca, ce * sa, se};
    const double rp[3] = {-sa, ca, 0};
    const double up[3] = {-se * ca, -se * sa, ce};
    for(int k = 0; k < 3; ++k) {
      const int w = (o.up_axis + 1 + k) % 3;
      d[w] = dp[k]; r[w] = rp[k]; u[w] = up[k];
    }
    // fixed light, from the upper left of the viewer
    for(int k = 0; k < 3; ++k) light[k] = d[k] + 0.5 * u[k] - 0.4 * r[k];
    const double ll = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
    for(double& x : light) x /= ll;
  }
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Writes an SVG picture of a polygon mesh (triangles, quads or any faces), of a face-based N-RoSy field on it and of its
/// singularities, as seen from the direction given by `options.azimuth` and
/// `options.elevation` (orthographic projection, `options.up_axis` pointing up).
///
/// Faces turned away from the viewer are culled; the others are painted back to front (by the
/// depth of their centroids) with flat Lambert shading. On each drawn face the field is shown at
/// the centroid by a glyph of size `options.glyph_scale` times the mean edge length, made of the
/// N directions \f$v\f$ rotated by \f$2\pi k/N\f$ about the face normal: an arrow for N = 1,
/// a line for N = 2, a cross for N = 4 (one `<line>` element per direction, or per pair of
/// opposite directions when N is even). On large meshes glyphs are drawn on every k-th visible
/// face only, so that at most `options.max_glyphs` are drawn, and are enlarged by
/// \f$\sqrt{k}\f$ to keep the field readable. Each singularity is a filled
/// circle at its vertex, drawn if one of its faces is: red for positive and blue for negative
/// indices, paler for smaller magnitudes, with an optional legend. The view box is fitted to the
/// projection of the mesh. Runs in linear time plus one sort of the faces.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, faces of any size (a polygon's normal is
///         Newell's, its glyph at the mean of its corners)
/// \tparam FaceVectorMap readable property map with `face_descriptor` keys whose values have
///         `operator[]` for the coordinates 0 to 2 (e.g. `Kernel::Vector_3`, as written by
///         `Trivial_connection::angles_to_vectors()`), a direction in (or near) the plane of the
///         face; vectors with no component in the face plane or non-finite ones are skipped.
///         Use the overload without `field` to draw the mesh and the singularities only.
///
/// \param os the output stream (the picture is written in one piece)
/// \param tm the mesh
/// \param field one 3D direction per face
/// \param N the symmetry order of the field
/// \param singularities vertices with their indices, e.g. `Field_topology::singularities`
/// \param options drawing options
/// \param np optional named parameter `vertex_point_map` (default: the mesh's points)
///
/// Throws `Input_error` (`INVALID_ARGUMENT`) for `options.width` \f$\le 0\f$, non-finite angles,
/// negative or non-finite sizes, invalid colors or `N` \f$< 1\f$, and (`INVALID_GEOMETRY`) for
/// non-finite vertex coordinates.
template <typename TriangleMesh, typename FaceVectorMap,
          typename NamedParameters = parameters::Default_named_parameters>
void write_field_svg(std::ostream& os, const TriangleMesh& tm, const FaceVectorMap& field, int N,
                     const std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                                                 double>>& singularities,
                     const Svg_options& options = Svg_options(),
                     const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  using parameters::choose_parameter;
  using parameters::get_parameter;

  const Svg_options& o = options;
  internal::svg_check_options(o, N, singularities);

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  auto fim = CGAL::get_initialized_face_index_map(tm);

  // ---- camera: view direction d (towards the viewer), screen axes r (right) and u (up), light
  const internal::Svg_camera camera(o);
  const double (&d)[3] = camera.d, (&r)[3] = camera.r, (&u)[3] = camera.u, (&light)[3] = camera.light;

  auto point = [&](vertex_descriptor v, double p[3]) {
    const auto& q = get(vpm, v);
    p[0] = CGAL::to_double(q.x());
    p[1] = CGAL::to_double(q.y());
    p[2] = CGAL::to_double(q.z());
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Input_error(Input_error::INVALID_GEOMETRY, "a vertex has non-finite coordinates");
  };
  auto dot = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  // a face's corners, its unit normal (Newell's: the area vector of a polygon of any size) and
  // its centroid; false for a degenerate face
  std::vector<std::array<double, 3>> ring;
  auto face_geometry = [&](face_descriptor f, double n[3], double c[3]) {
    ring.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      ring.emplace_back();
      point(target(h, tm), ring.back().data());
    }
    n[0] = n[1] = n[2] = c[0] = c[1] = c[2] = 0;
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const double *a = ring[i].data(), *b = ring[(i + 1) % ring.size()].data();
      n[0] += a[1] * b[2] - a[2] * b[1]; n[1] += a[2] * b[0] - a[0] * b[2]; n[2] += a[0] * b[1] - a[1] * b[0];
      for(int k = 0; k < 3; ++k) c[k] += a[k] / double(ring.size());
    }
    const double nl = std::sqrt(dot(n, n));
    if(!(nl > 0)) return false;
    for(int k = 0; k < 3; ++k) n[k] /= nl;
    return true;
  };

  // ---- projected bounding box and mean edge length
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for(vertex_descriptor v : vertices(tm)) {
    double p[3];
    point(v, p);
    const double x = dot(p, r), y = dot(p, u);
    xmin = (std::min)(xmin, x); xmax = (std::max)(xmax, x);
    ymin = (std::min)(ymin, y); ymax = (std::max)(ymax, y);
  }
  if(!(xmin <= xmax)) { xmin = xmax = ymin = ymax = 0; }
  double edge_sum = 0;
  std::size_t edge_count = 0;
  for(auto e : edges(tm)) {
    double p[3], q[3];
    point(source(halfedge(e, tm), tm), p);
    point(target(halfedge(e, tm), tm), q);
    edge_sum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    ++edge_count;
  }
  const double mean_edge = edge_count ? edge_sum / double(edge_count) : 0;

  const double W = double(o.width);
  const double margin = 0.02 * W + o.singularity_radius + o.glyph_stroke_width;
  const double extent = (std::max)(xmax - xmin, ymax - ymin);
  const double scale = extent > 0 ? ((xmax - xmin) > 0 ? (W - 2 * margin) / (xmax - xmin)
                                                        : (W - 2 * margin) / extent)
                                   : 1.0;
  const double mesh_h = (ymax - ymin) * scale + 2 * margin;
  auto sx = [&](const double* p) { return margin + (dot(p, r) - xmin) * scale; };
  auto sy = [&](const double* p) { return margin + (ymax - dot(p, u)) * scale; };

  // ---- visible faces with their depth and shade
  struct Face_item { double depth; face_descriptor f; double shade; };
  std::vector<Face_item> items;
  std::vector<double> face_depth(num_faces(tm), -std::numeric_limits<double>::infinity());
  for(face_descriptor f : faces(tm)) {
    double n[3], c[3];
    if(!face_geometry(f, n, c)) continue;   // degenerate face
    if(dot(n, d) <= 0) continue;            // back face
    const double depth = dot(c, d);
    const double lambert = (std::max)(0.0, dot(n, light));
    items.push_back(Face_item{depth, f, 0.35 + 0.65 * lambert});
    face_depth[std::size_t(get(fim, f))] = depth;
  }

  // singularity markers: painted right after the nearest of their drawn faces
  struct Marker { double depth; std::size_t singularity; };
  std::vector<Marker> markers;
  double max_index = 0;
  for(std::size_t i = 0; i < singularities.size(); ++i) {
    const vertex_descriptor v = singularities[i].first;
    max_index = (std::max)(max_index, std::abs(singularities[i].second));
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    double best = -std::numeric_limits<double>::infinity();
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm)) {
      const face_descriptor f = face(h, tm);
      if(f != GT::null_face()) best = (std::max)(best, face_depth[std::size_t(get(fim, f))]);
    }
    if(best > -std::numeric_limits<double>::infinity()) markers.push_back(Marker{best, i});
  }

  std::stable_sort(items.begin(), items.end(),
                   [](const Face_item& a, const Face_item& b) { return a.depth < b.depth; });
  std::stable_sort(markers.begin(), markers.end(),
                   [](const Marker& a, const Marker& b) { return a.depth < b.depth; });

  // every k-th visible face (in the mesh's face order) carries a glyph
  const std::size_t stride = (o.max_glyphs == 0 || items.size() <= o.max_glyphs)
                               ? 1 : (items.size() + o.max_glyphs - 1) / o.max_glyphs;
  std::vector<char> has_glyph(num_faces(tm), 0);
  if(!std::is_same<FaceVectorMap, internal::No_face_field>::value &&
     !std::is_same<FaceVectorMap, internal::Svg_face_strokes>::value) {
    std::size_t rank = 0;
    for(face_descriptor f : faces(tm)) {
      const std::size_t fi = std::size_t(get(fim, f));
      if(face_depth[fi] == -std::numeric_limits<double>::infinity()) continue;
      if(rank++ % stride == 0) has_glyph[fi] = 1;
    }
  }

  // ---- colors
  double base[3] = {208, 208, 208};
  const bool shaded = internal::svg_parse_hex_color(o.face_color, base);
  double pos[3] = {214, 32, 32}, neg[3] = {32, 80, 214};
  internal::svg_parse_hex_color(o.positive_color, pos);
  internal::svg_parse_hex_color(o.negative_color, neg);
  auto index_color = [&](double k) {
    const double* full = k > 0 ? pos : neg;
    const double s = max_index > 0 ? 0.35 + 0.65 * std::abs(k) / max_index : 1.0;
    double c[3];
    for(int j = 0; j < 3; ++j) c[j] = 235 + s * (full[j] - 235);
    return internal::svg_hex_color(c);
  };

  // legend entries: distinct indices, sorted
  std::vector<double> legend;
  if(o.legend) {
    for(const auto& s : singularities)
      if(s.second != 0) legend.push_back(s.second);
    std::sort(legend.begin(), legend.end(), [](double a, double b) { return a > b; });
    legend.erase(std::unique(legend.begin(), legend.end()), legend.end());
  }
  const double font = 12;
  const double legend_h = legend.empty() ? 0 : font + 8;
  const double caption_h = options.caption.empty() ? 0 : font + 8;
  const double H = mesh_h + legend_h + caption_h;

  // ---- output
  std::string out;
  out.reserve(items.size() * 80 + 1024);
  auto num = [&](double x) { internal::svg_write_coordinate(out, x); };
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  num(W); out += "\" height=\""; num(std::ceil(H));
  out += "\" viewBox=\"0 0 "; num(W); out += ' '; num(std::ceil(H)); out += "\">\n";
  // shades are quantised to 1/48 and written as CSS classes, which keeps large pictures small
  const int levels = 48;
  auto shade_level = [&](double shade) { return int(std::lround(shade * levels)); };
  std::vector<char> level_used(levels + 1, 0);
  for(const Face_item& it : items) level_used[std::size_t(shade_level(it.shade))] = 1;
  out += "<style>polygon{stroke:" + (o.edge_stroke_width > 0 ? o.edge_color : std::string("none")) +
         (shaded ? std::string() : ";fill:" + o.face_color) + ";stroke-width:";
  num(o.edge_stroke_width);
  out += ";stroke-linejoin:round}line{stroke:" + o.glyph_color + ";stroke-width:";
  num(o.glyph_stroke_width);
  out += ";stroke-linecap:round";
  if(N == 1) out += ";marker-end:url(#arrow)";
  out += "}circle{stroke:#000;stroke-width:";
  num(0.15 * o.singularity_radius);
  out += "}text{font:";
  num(font);
  out += "px sans-serif}";
  for(int l = 0; shaded && l <= levels; ++l) {
    if(!level_used[std::size_t(l)]) continue;
    const double c[3] = {base[0] * l / levels, base[1] * l / levels, base[2] * l / levels};
    out += "\n.s" + std::to_string(l) + "{fill:" + internal::svg_hex_color(c) + "}";
  }
  out += "</style>\n";
  if(N == 1) {
    out += "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"5\" refY=\"5\" markerWidth=\"4\" "
           "markerHeight=\"4\" orient=\"auto\"><path d=\"M0,1L10,5L0,9z\" fill=\"" + o.glyph_color +
           "\" stroke=\"none\"/></marker></defs>\n";
  }
  if(o.background_color != "none") {
    out += "<rect width=\"100%\" height=\"100%\" fill=\"" + o.background_color + "\"/>\n";
  }

  const double glyph_half = 0.5 * o.glyph_scale * mean_edge * std::sqrt(double(stride));
  std::size_t m = 0;
  auto write_markers_up_to = [&](double depth) {
    for(; m < markers.size() && markers[m].depth <= depth; ++m) {
      const auto& s = singularities[markers[m].singularity];
      double p[3];
      point(s.first, p);
      out += "<circle cx=\""; num(sx(p)); out += "\" cy=\""; num(sy(p));
      out += "\" r=\""; num(o.singularity_radius); out += "\" fill=\"" + index_color(s.second) + "\"/>\n";
    }
  };
  for(const Face_item& it : items) {
    double n[3], c[3];
    face_geometry(it.f, n, c);
    out += "<polygon ";
    if(shaded) out += "class=\"s" + std::to_string(shade_level(it.shade)) + "\" ";
    out += "points=\"";
    for(std::size_t k = 0; k < ring.size(); ++k) {
      if(k) out += ' ';
      num(sx(ring[k].data())); out += ','; num(sy(ring[k].data()));
    }
    out += "\"/>\n";

    if constexpr(std::is_same<FaceVectorMap, internal::Svg_face_strokes>::value) {
      for(const auto& g : field.segments[std::size_t(get(fim, it.f))]) {
        out += "<line x1=\""; num(sx(&g[0])); out += "\" y1=\""; num(sy(&g[0]));
        out += "\" x2=\""; num(sx(&g[3])); out += "\" y2=\""; num(sy(&g[3])); out += "\"/>\n";
      }
    }
    double v[3];
    if(has_glyph[std::size_t(get(fim, it.f))] && glyph_half > 0 && internal::svg_field_vector(field, it.f, v)) {
      const double vn = dot(v, n);
      for(int k = 0; k < 3; ++k) v[k] -= vn * n[k];      // projection on the face plane
      const double vl = std::sqrt(dot(v, v));
      if(vl > 1e-12) {
        for(double& x : v) x /= vl;
        const double w[3] = {n[1] * v[2] - n[2] * v[1], n[2] * v[0] - n[0] * v[2], n[0] * v[1] - n[1] * v[0]};
        const bool pairs = N % 2 == 0;
        const int count = pairs ? N / 2 : N;
        for(int k = 0; k < count; ++k) {
          const double a = 2 * CGAL_PI * k / N;
          const double dir[3] = {std::cos(a) * v[0] + std::sin(a) * w[0], std::cos(a) * v[1] + std::sin(a) * w[1],
                                 std::cos(a) * v[2] + std::sin(a) * w[2]};
          // N = 1 and even N: a segment centred on the centroid; odd N > 1: rays from it
          const double back = (N == 1 || pairs) ? glyph_half : 0;
          const double a0[3] = {c[0] - back * dir[0], c[1] - back * dir[1], c[2] - back * dir[2]};
          const double a1[3] = {c[0] + glyph_half * dir[0], c[1] + glyph_half * dir[1], c[2] + glyph_half * dir[2]};
          out += "<line x1=\""; num(sx(a0)); out += "\" y1=\""; num(sy(a0));
          out += "\" x2=\""; num(sx(a1)); out += "\" y2=\""; num(sy(a1)); out += "\"/>\n";
        }
      }
    }
    write_markers_up_to(it.depth);
  }
  write_markers_up_to(std::numeric_limits<double>::infinity());

  if(!legend.empty()) {
    double x = margin;
    const double y = mesh_h + legend_h / 2;
    out += "<g>\n";
    for(double k : legend) {
      const double rr = font * 0.4;
      out += "<circle cx=\""; num(x + rr); out += "\" cy=\""; num(y); out += "\" r=\""; num(rr);
      out += "\" fill=\"" + index_color(k) + "\"/>\n";
      const std::string label = internal::svg_index_label(k, N);
      out += "<text x=\""; num(x + 2 * rr + 4); out += "\" y=\""; num(y + font * 0.35);
      out += "\">" + label + "</text>\n";
      x += 2 * rr + 4 + font * 0.6 * double(label.size()) + 14;
    }
    out += "</g>\n";
  }
  if(!options.caption.empty()) {
    std::string text;
    for(char ch : options.caption) text += ch == '&' ? "&amp;" : ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : std::string(1, ch);
    out += "<text x=\""; num(margin); out += "\" y=\""; num(mesh_h + legend_h + caption_h / 2 + font * 0.35);
    out += "\" fill=\"#606060\">" + text + "</text>\n";
  }
  out += "</svg>\n";
  os.write(out.data(), std::streamsize(out.size()));
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// As write_field_svg() above, without a field: draws the shaded mesh and the singularities.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void write_field_svg(std::ostream& os, const TriangleMesh& tm, int N,
                     const std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                                                 double>>& singularities,
                     const Svg_options& options = Svg_options(),
                     const NamedParameters& np = parameters::default_values())
{
  write_field_svg(os, tm, internal::No_face_field(), N, singularities, options, np);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// A line segment drawn on a face of a mesh by write_strokes_svg(): from `a` to `b`, in 3D, on or
/// near the face.
template <typename TriangleMesh>
struct Svg_stroke
{
  typename boost::graph_traits<TriangleMesh>::face_descriptor face;   ///< the face it is drawn with
  std::array<double, 3> a, b;                                            ///< its ends
};

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Writes an SVG picture of a triangle mesh with line segments drawn on its faces: the mesh as
/// write_field_svg() draws it (culled, painted back to front), each segment drawn right after
/// its face, so that nearer parts of the surface hide the segments behind them, with
/// `options.glyph_color` and width `options.glyph_stroke_width`; and the singularities (or
/// cones, or any marked vertices with an index) as write_field_svg() draws them. `N` only
/// labels the indices in the legend (as fractions \f$k/N\f$). Used for hatching
/// (write_streamlines_svg()) and for a remesh drawn over its input (`smdf remesh --svg`).
/// Throws as write_field_svg().
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void write_strokes_svg(std::ostream& os, const TriangleMesh& tm, const std::vector<Svg_stroke<TriangleMesh>>& strokes, int N,
                       const std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>>& singularities,
                       const Svg_options& options = Svg_options(), const NamedParameters& np = parameters::default_values())
{
  auto fim = CGAL::get_initialized_face_index_map(tm);
  internal::Svg_face_strokes per_face;
  per_face.segments.resize(num_faces(tm));
  for(const auto& s : strokes)
    per_face.segments[std::size_t(get(fim, s.face))].push_back(std::array<double, 6>{{s.a[0], s.a[1], s.a[2], s.b[0], s.b[1], s.b[2]}});
  // (at least 2: strokes are lines, without the arrow heads of N = 1)
  write_field_svg(os, tm, per_face, (std::max)(N, 2), singularities, options, np);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIO
/// Writes a pen-and-ink SVG picture of streamlines on a mesh (Lai et al. 2010, Figs. 14 and
/// 15: hatching along a cross field): write_strokes_svg() with every piece of every streamline
/// (those of trace_streamlines() on the same mesh) drawn with the face it lies in. For a drawing
/// without the mesh's lines set `options.edge_stroke_width` to 0 and a light
/// `options.face_color`. Throws as write_field_svg().
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void write_streamlines_svg(std::ostream& os, const TriangleMesh& tm, const std::vector<Streamline<TriangleMesh>>& streamlines,
                           const Svg_options& options = Svg_options(), const NamedParameters& np = parameters::default_values())
{
  std::vector<Svg_stroke<TriangleMesh>> strokes;
  for(const auto& s : streamlines)
    for(std::size_t i = 0; i + 1 < s.points.size() && i < s.faces.size(); ++i)
      strokes.push_back(Svg_stroke<TriangleMesh>{s.faces[i], s.points[i], s.points[i + 1]});
  write_strokes_svg(os, tm, strokes, 2, {}, options, np);
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_SVG_WRITER_H
