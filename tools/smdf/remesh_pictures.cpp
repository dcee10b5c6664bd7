// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh's pictures: see remesh_pictures.h.

#include "remesh_pictures.h"
#include "remesh_measures.h"


#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

namespace smdf_cli {

void write_remesh_svg(const Args& args, const Mesh& input, const Mesh& remesh, int N)
{
  // The remesh itself: its faces shaded and painted back to front, back faces culled, its edges
  // stroked, and its cones (vertices whose faces do not fill 2 pi in the grid's angles) marked
  // by their index K / 2 pi.
  const std::vector<double> K = grid_curvatures(remesh);
  std::vector<std::pair<vertex_descriptor, double>> marks;
  for(vertex_descriptor v : vertices(remesh)) {
    if(CGAL::is_border(v, remesh) || !(std::abs(K[index(v)]) > 1e-9)) continue;
    marks.emplace_back(v, std::round(K[index(v)] / (2 * CGAL_PI) * N) / N);
  }
  SMDF::Svg_options view = svg_options(args);
  if(!args.has("view")) view.up_axis = default_up_axis(input);
  view.edge_stroke_width = 0.5;
  view.edge_color = "#303030";
  view.singularity_radius = 4;
  std::ostringstream os;
  SMDF::write_field_svg(os, remesh, N, marks, view);
  write_lines_file(args.value("svg"), os.str());
}

void write_knot_svg(const Args& args, const Mesh& input, const Mesh& remesh)
{
  Mesh tri;
  for(vertex_descriptor v : vertices(remesh)) tri.add_vertex(remesh.point(v));
  std::vector<SMDF::Svg_stroke<Mesh>> strokes;
  auto mid = [&](halfedge_descriptor h) { return CGAL::midpoint(remesh.point(source(h, remesh)), remesh.point(target(h, remesh))); };
  auto arr = [](const K::Point_3& p) { return std::array<double, 3>{{p.x(), p.y(), p.z()}}; };
  for(face_descriptor f : faces(remesh)) {
    std::vector<halfedge_descriptor> hs;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, remesh), remesh)) hs.push_back(h);
    std::vector<face_descriptor> fan;   // triangle i: corners 0, i + 1, i + 2
    for(std::size_t i = 1; i + 1 < hs.size(); ++i)
      fan.push_back(tri.add_face(target(hs[0], remesh), target(hs[i], remesh), target(hs[i + 1], remesh)));
    K::Vector_3 c(0, 0, 0);
    for(halfedge_descriptor h : hs) c = c + (remesh.point(target(h, remesh)) - CGAL::ORIGIN) / double(hs.size());
    const K::Point_3 centre = CGAL::ORIGIN + c;
    for(std::size_t i = 0; i < hs.size(); ++i) {
      const halfedge_descriptor a = hs[i], b = hs[(i + 1) % hs.size()];   // they share target(a)
      const K::Point_3 p0 = mid(a), p2 = mid(b), corner = remesh.point(target(a, remesh));
      const K::Point_3 p1 = CGAL::midpoint(corner, centre);
      const int pieces = 8, drawn = 6;   // the last quarter is the gap where the curve passes under
      for(int k = 0; k < drawn; ++k) {
        auto at = [&](double t) {
          return CGAL::ORIGIN + ((p0 - CGAL::ORIGIN) * ((1 - t) * (1 - t)) + (p1 - CGAL::ORIGIN) * (2 * t * (1 - t)) + (p2 - CGAL::ORIGIN) * (t * t));
        };
        const K::Point_3 x = at(double(k) / pieces), y = at(double(k + 1) / pieces);
        // the fan triangle nearest to the piece's midpoint
        const K::Point_3 m = CGAL::midpoint(x, y);
        face_descriptor best = Mesh::null_face();
        double best_d = 1e300;
        for(std::size_t t = 0; t < fan.size(); ++t) {
          if(fan[t] == Mesh::null_face()) continue;
          const halfedge_descriptor th = halfedge(fan[t], tri);
          const K::Point_3 g = CGAL::centroid(tri.point(source(th, tri)), tri.point(target(th, tri)), tri.point(target(next(th, tri), tri)));
          const double d = CGAL::squared_distance(g, m);
          if(d < best_d) { best_d = d; best = fan[t]; }
        }
        if(best != Mesh::null_face()) strokes.push_back(SMDF::Svg_stroke<Mesh>{best, arr(x), arr(y)});
      }
    }
  }
  SMDF::Svg_options view = svg_options(args);
  if(!args.has("view")) view.up_axis = default_up_axis(input);
  view.edge_stroke_width = 0;
  view.face_color = "#f2ead8";
  view.glyph_color = "#6b3a1f";
  view.glyph_stroke_width = 2.2;
  std::ostringstream os;
  SMDF::write_strokes_svg(os, tri, strokes, 4, {}, view);
  write_lines_file(args.value("knot-svg"), os.str());
}

} // namespace smdf_cli
