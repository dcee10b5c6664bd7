// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_CHARTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_CHARTS_H

// The engine of metric compensation by a polyhedron P (Lai et al. 2010, section 4.1.3.2): the
// surface cut along P's edges, every piece mapped onto its face of P (relaxed charts or Ricci
// flow segments), and the lengths of P's metric read off the charts.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/polyhedron_metric_status.h>
#include <CGAL/Surface_mesh_direction_fields/internal/chart_relaxation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/seam_relaxation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/segment_ricci_flow.h>
#include <CGAL/Surface_mesh_direction_fields/internal/polyhedron_paths.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <CGAL/boost/graph/helpers.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

namespace internal {

// What polyhedron_metric_core() knows at the end, for polyhedron_remesh(): every mesh face in the
// chart of its polyhedron face, and the paths of P's edges.
struct Polyhedron_charts
{
  std::vector<std::array<Point_2, 3>> chart;     // per mesh face: its corners in its P face's polygon
  std::vector<int> pface;                        // per mesh face: its face of P
  std::vector<std::array<int, 2>> pedges;        // P's edges (corner indices), as first met in the faces
  std::vector<std::vector<int>> paths;           // per P edge: mesh vertices from pedges[k][0] to pedges[k][1]
  std::vector<std::vector<int>> path_halfedges;  // ... and their halfedges, from paths[k][i] to paths[k][i + 1]
  std::vector<std::vector<double>> steps;        // ... and the lengths of those in the charts
  std::vector<std::vector<Point_2>> shape;       // per P face: its polygon
  bool mirrored = false;                         // the mesh's faces turn clockwise in the charts
};

// What the charts are measured against (chart_inputs()): the input's Euclidean edge lengths
// (`vertex_point_map`) and area, the relaxation steps asked, and the lengths the paths are
// shortest in (empty: the mesh's metric).
struct Chart_inputs
{
  std::vector<double> reference;
  int iterations = 0;
  int seam_rings = 8;   // relax_across_polyhedron_edges(): the bands' width in edges (0: none)
  bool ricci_segments = false;   // Lai et al.'s segments by Ricci flow instead of relaxed charts
  double area = 0;
  std::vector<double> path_metric;
};

// The metric of a polyhedron P on a closed genus-0 mesh (the engine of box_polycube_metric() and
// polyhedron_metric()): P's corners are mesh vertices, its faces cycles of corners
// (counterclockwise seen from outside). P's edges become shortest edge paths under the mesh's
// metric, the pieces between them P's faces, each embedded onto the planar polygon that
// `polygon(face, path_length)` returns (its corners counterclockwise, in the face's order; it is
// called once the paths are known, `path_length(a, b)` the length of the path between corners a
// and b) by a Tutte embedding with mean value weights, the paths placed by arc length. With
// `in.iterations` > 0, path lengths are measured in `in.reference` and the embedding is then
// relaxed towards its triangles for up to that many steps, the paths sliding along P's edges
// (relax_polyhedron_charts()). With an `in.path_metric`, the paths are shortest in it instead of
// the mesh's metric (and measured in it without relaxation). Writes
// one length per mesh edge.
template <typename TM, typename Polygon>
Polycube_metric_status polyhedron_metric_core(const Mesh_arrays<TM>& m, const std::vector<int>& corner_vertex,
                                              const std::vector<std::vector<int>>& pfaces, Polygon polygon,
                                              const Chart_inputs& in, std::vector<double>& lengths, Polyhedron_charts* charts = nullptr)
{
  const int iterations = in.iterations;
  const std::vector<double>* reference = iterations > 0 ? &in.reference : nullptr;
  const std::vector<double>* path_metric = in.path_metric.empty() ? nullptr : &in.path_metric;
  auto path_edge_length = [&](int h) { return path_metric ? (*path_metric)[std::size_t(h >> 1)] : m.edge_length(h); };
  Polycube_metric_status st;
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  // 1. and 2. the paths, and the pieces they cut, matched to P's faces
  Polyhedron_cut cut;
  if(!cut_along_polyhedron(m, corner_vertex, pfaces, path_edge_length, cut, st.message)) return st;
  st.path_edges = cut.path_edges;
  const std::vector<int>& corner_of = cut.corner_of;
  const std::vector<std::array<int, 2>>& pedges = cut.pedges;
  const std::vector<std::vector<int>>& paths = cut.paths;
  const std::vector<std::vector<int>>& path_halfedges = cut.path_halfedges;
  const std::vector<int>& region = cut.region;
  const std::vector<int>& face_of_region = cut.face_of_region;
  const std::vector<int>& region_of_face = cut.region_of_face;
  const std::size_t np = pedges.size();
  // 3. the polygons, and every path vertex placed by arc length in each face along the path
  // the paths are measured (and their vertices placed by arc length) in the reference, if any
  std::vector<std::vector<double>> along(np);
  for(std::size_t k = 0; k < np; ++k)
    for(int h : path_halfedges[k]) along[k].push_back(reference ? (*reference)[std::size_t(h >> 1)] : path_edge_length(h));
  std::vector<double> reference_length(np, 0.);
  for(std::size_t k = 0; k < np; ++k) for(double x : along[k]) reference_length[k] += x;
  auto length_between = [&](int a, int b) {
    const std::size_t k = std::size_t(cut.edge_of(a, b));
    return reference_length[k];
  };
  std::vector<std::vector<Point_2>> shape(pfaces.size());
  for(std::size_t j = 0; j < pfaces.size(); ++j) {
    shape[j] = polygon(j, length_between);
    if(shape[j].size() != pfaces[j].size()) throw Input_error(Input_error::INVALID_ARGUMENT, "a polygon of the polyhedron has the wrong number of corners");
  }
  for(std::size_t k = 0; k < np; ++k) {
    double target = 0;   // the edge's length in the polygons (the same in both faces: checked)
    int seen = 0;
    for(std::size_t j = 0; j < pfaces.size(); ++j)
      for(std::size_t i = 0; i < pfaces[j].size(); ++i) {
        const int a = pfaces[j][i], b = pfaces[j][(i + 1) % pfaces[j].size()];
        if((std::min)(a, b) != (std::min)(pedges[k][0], pedges[k][1]) || (std::max)(a, b) != (std::max)(pedges[k][0], pedges[k][1])) continue;
        const Point_2 &p = shape[j][i], &q = shape[j][(i + 1) % pfaces[j].size()];
        const double l = std::sqrt((q.x() - p.x()) * (q.x() - p.x()) + (q.y() - p.y()) * (q.y() - p.y()));
        if(seen++ && std::abs(l - target) > 1e-9 * (std::max)(l, target))
          throw Input_error(Input_error::INVALID_ARGUMENT, "two faces of the polyhedron give one edge different lengths");
        target = l;
      }
    st.max_path_stretch = (std::max)(st.max_path_stretch, (std::max)(reference_length[k] / target, target / reference_length[k]));
  }
  // per face: positions of its boundary vertices (corners and path vertices), then the Tutte embedding
  std::vector<std::array<Point_2, 3>> chart(nf);
  std::vector<char> on_path(nv, 0);
  for(const auto& p : paths) for(int v : p) on_path[std::size_t(v)] = 1;
  // The pieces are independent: embedded on two threads, the larger ones first, each to the
  // thread with less work so far (a piece writes only its own faces' charts).
  std::vector<std::string> failure(pfaces.size());
  std::vector<std::size_t> piece_faces(pfaces.size(), 0), by_size(pfaces.size());
  for(std::size_t f = 0; f < nf; ++f) ++piece_faces[std::size_t(face_of_region[std::size_t(region[f])])];
  for(std::size_t j = 0; j < by_size.size(); ++j) by_size[j] = j;
  std::stable_sort(by_size.begin(), by_size.end(), [&](std::size_t x, std::size_t y) { return piece_faces[x] > piece_faces[y]; });
  std::vector<std::size_t> share[2];
  std::size_t load[2] = {0, 0};
  for(std::size_t j : by_size) { const int t = load[1] < load[0] ? 1 : 0; share[t].push_back(j); load[t] += piece_faces[j]; }
  // With Ricci flow segments, where the path vertices lie along P's edges: the mean of the two
  // segments' parameters (Lai et al. leave the two apart; their gap is reported)
  std::vector<std::vector<double>> conformal(np);
  if(in.ricci_segments) {
    Side_parameters sides(np);
    run_on_two_threads([&](int t) {
      for(std::size_t j : share[t]) ricci_flow_segment(m, corner_vertex, cut, pfaces, shape, j, sides, failure[j]);
    }, nf >= 20000);
    for(const std::string& why : failure) if(!why.empty()) { st.message = why; return st; }
    for(std::size_t k = 0; k < np; ++k) {
      conformal[k].resize(paths[k].size());
      for(std::size_t q = 0; q < paths[k].size(); ++q) {
        conformal[k][q] = 0.5 * (sides[k][0][q] + sides[k][1][q]);
        st.max_side_parameter_gap = (std::max)(st.max_side_parameter_gap, std::abs(sides[k][0][q] - sides[k][1][q]));
      }
    }
  }
  auto embed = [&](std::size_t j) {
    const int r = region_of_face[j];
    std::map<int, Point_2> fixed;
    const std::vector<int>& fc = pfaces[j];
    for(std::size_t i = 0; i < fc.size(); ++i) {
      const int a = fc[i], b = fc[(i + 1) % fc.size()];
      const int k = cut.edge_of(a, b);
      const Point_2 &pa = shape[j][i], &pb = shape[j][(i + 1) % fc.size()];
      const std::vector<int>& p = paths[std::size_t(k)];
      const bool forward = pedges[std::size_t(k)][0] == a;
      double s = 0;
      for(std::size_t q = 0; q < p.size(); ++q) {
        if(q > 0) s += along[std::size_t(k)][q - 1];
        const double along_edge = in.ricci_segments ? conformal[std::size_t(k)][q] : s / reference_length[std::size_t(k)];
        const double t = forward ? along_edge : 1 - along_edge;
        fixed[p[q]] = Point_2((1 - t) * pa.x() + t * pb.x(), (1 - t) * pa.y() + t * pb.y());
      }
    }
    std::vector<int> column(nv, -1), unknowns;
    std::vector<int> piece;   // the mesh faces of this piece
    for(std::size_t f = 0; f < nf; ++f) {
      if(region[f] != r) continue;
      piece.push_back(int(f));
      int h = m.face_halfedge[f];
      for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
        const int v = m.source(h);
        if(!on_path[std::size_t(v)] && column[std::size_t(v)] < 0) { column[std::size_t(v)] = int(unknowns.size()); unknowns.push_back(v); }
      }
    }
    std::vector<Point_2> solved;
    // One reweighting round: it lifts the protrusions a plain Tutte embedding shrinks (without it
    // the armadillo's limbs degenerate), but further rounds, while lowering the stretch, leave the
    // as-rigid-as-possible steps more sheared triangles (Spot 433k: 71 quads with a negative
    // scaled Jacobian after ten rounds, 48 after one; Homer and the armadillo: one inverted quad
    // each at 2000 quads after ten, none after one) and take 2.8 instead of 1.1 s at 433k faces.
    // Ricci flow segments: no reweighting, a discrete harmonic map onto the polygon with the
    // sides placed conformally (close to the segment's conformal map: harmonicity does not
    // change under conformal scaling).
    const int rounds = in.ricci_segments ? 0 : (std::min)(iterations, 1);
    if(!stretch_minimizing_tutte(m, piece, column, unknowns, fixed, reference, rounds, solved, failure[j])) return;
    auto place = [&](int v) { return column[std::size_t(v)] >= 0 ? solved[std::size_t(column[std::size_t(v)])] : fixed.at(v); };
    for(int f : piece) {
      int h = m.face_halfedge[std::size_t(f)];
      for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) chart[std::size_t(f)][std::size_t(i)] = place(m.source(h));
    }
  };
  run_on_two_threads([&](int t) { for(std::size_t j : share[t]) embed(j); }, nf >= 20000);
  for(const std::string& why : failure) if(!why.empty()) { st.message = why; return st; }
  // 4. validity: every triangle non-degenerate, all on the same side (mirrored corners are fine:
  // the lengths do not see orientation); then the lengths, each edge from one of its faces
  double scale = 0;
  for(const auto& sh : shape) for(const Point_2& p : sh) scale = (std::max)(scale, std::abs(p.x()) + std::abs(p.y()));
  std::size_t positive = 0, negative = 0;
  for(std::size_t f = 0; f < nf; ++f) {
    const std::array<Point_2, 3>& c = chart[f];
    const double area = (c[1].x() - c[0].x()) * (c[2].y() - c[0].y()) - (c[2].x() - c[0].x()) * (c[1].y() - c[0].y());
    if(!(std::abs(area) > 1e-14 * scale * scale)) {
      st.message = "face " + std::to_string(f) + " is degenerate on the polyhedron (refine the mesh near the paths)";
      return st;
    }
    (area > 0 ? positive : negative) += 1;
  }
  if(positive && negative) {
    st.message = std::to_string((std::min)(positive, negative)) + " faces fold over on the polyhedron (the paths meet the corners in the wrong order)";
    return st;
  }
  std::vector<int> pface(nf);
  for(std::size_t f = 0; f < nf; ++f) pface[f] = face_of_region[std::size_t(region[f])];
  if(reference && !in.ricci_segments) {
    std::vector<int> path_of_vertex(nv, -1);
    for(std::size_t k = 0; k < np; ++k) for(std::size_t i = 1; i + 1 < paths[k].size(); ++i) path_of_vertex[std::size_t(paths[k][i])] = int(k);
    const Polyhedron_cut_view cut{&corner_of, &path_of_vertex, &pface, &pfaces, &shape, &pedges, &paths};
    std::string why;
    st.relaxation_steps = relax_polyhedron_charts(m, cut, *reference, iterations, negative ? -1. : 1., chart, why);
    if(!why.empty()) { st.message = why; return st; }
    if(!charts) {   // polyhedron_remesh() reads the charts face by face of P: only for the lengths
      st.seam_relaxed_vertices = relax_across_polyhedron_edges(m, cut, *reference, in.seam_rings, iterations, negative ? -1. : 1., chart);
    }
  }
  lengths.assign(ne, 0.);
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = m.face[2 * e] >= 0 ? int(2 * e) : int(2 * e + 1);
    const int f = m.face[std::size_t(h)];
    int g = m.face_halfedge[std::size_t(f)], k = 0;
    while(g != h) { g = m.next[std::size_t(g)]; ++k; }
    const Point_2 &p = chart[std::size_t(f)][std::size_t(k)], &q = chart[std::size_t(f)][std::size_t((k + 1) % 3)];
    lengths[e] = std::sqrt((q.x() - p.x()) * (q.x() - p.x()) + (q.y() - p.y()) * (q.y() - p.y()));
  }
  if(charts) {
    charts->chart = chart;
    charts->pface = pface;
    charts->pedges = pedges;
    charts->paths = paths;
    charts->path_halfedges = path_halfedges;
    charts->steps.assign(np, {});
    for(std::size_t k = 0; k < np; ++k)   // in the charts' lengths: where the relaxation slid them
      for(int h : path_halfedges[k]) charts->steps[k].push_back(lengths[std::size_t(h >> 1)]);
    charts->shape = shape;
    charts->mirrored = negative > 0;
  }
  st.success = true;
  return st;
}

// With `conformal_factor_map` (u, per vertex), the lengths l_ij e^((u_i + u_j) / 2) of the mesh's
// edges, l its metric: the discrete conformal scaling that compute_cone_metric() returns as u,
// on the input's edges whatever triangulation the flow ended on. Returns false without it.
template <typename TM, typename NP>
bool conformal_path_metric(const Mesh_arrays<TM>& m, const NP& np, std::vector<double>& path_metric)
{
  if constexpr(parameters::is_default_parameter<NP, internal_np::conformal_factor_t>::value) {
    return false;
  } else {
    const auto ufm = parameters::get_parameter(np, internal_np::conformal_factor);
    std::vector<double> u(m.number_of_vertices());
    for(std::size_t v = 0; v < u.size(); ++v) {
      u[v] = double(get(ufm, m.vertices[v]));
      if(!std::isfinite(u[v]))
        throw Input_error(Input_error::INVALID_ARGUMENT, "the conformal factor of vertex " + std::to_string(v) + " is not finite");
    }
    path_metric.resize(m.number_of_edges());
    for(std::size_t e = 0; e < path_metric.size(); ++e)
      path_metric[e] = m.edge_length(int(2 * e)) * std::exp(0.5 * (u[std::size_t(m.source(int(2 * e)))] + u[std::size_t(m.target[2 * e])]));
    return true;
  }
}

// The Chart_inputs of `np`: `number_of_iterations` (default 10), `vertex_point_map` and
// `conformal_factor_map`.
template <typename TM, typename NP>
Chart_inputs chart_inputs(const TM& tm, const Mesh_arrays<TM>& m, const NP& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Chart_inputs in;
  in.iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 10);
  if(in.iterations < 0) throw Input_error(Input_error::INVALID_ARGUMENT, "number_of_iterations must not be negative, got " + std::to_string(in.iterations));
  in.seam_rings = choose_parameter(get_parameter(np, internal_np::seam_relaxation_rings), 8);
  if(in.seam_rings < 0 || in.seam_rings > 1000)
    throw Input_error(Input_error::INVALID_ARGUMENT, "seam_relaxation_rings must be between 0 and 1000, got " + std::to_string(in.seam_rings));
  in.ricci_segments = choose_parameter(get_parameter(np, internal_np::segment_flattening), RELAXED_SEGMENTS) == RICCI_FLOW_SEGMENTS;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  std::vector<double>& reference = in.reference;
  reference.assign(m.number_of_edges(), 0.);
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
    const auto &p = get(vpm, m.vertices[std::size_t(m.source(int(2 * e)))]), &q = get(vpm, m.vertices[std::size_t(m.target[2 * e])]);
    reference[e] = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
  }
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
    const double a = reference[std::size_t(h0 >> 1)], b = reference[std::size_t(h1 >> 1)], c = reference[std::size_t(h2 >> 1)];
    const double s = 0.5 * (a + b + c);
    in.area += std::sqrt((std::max)(0., s * (s - a) * (s - b) * (s - c)));
  }
  conformal_path_metric(m, np, in.path_metric);
  return in;
}

template <typename TM, typename NP>
const Intrinsic_mesh<TM> genus_zero_mesh(const TM& tm, const NP& np, const char* who)
{
  Intrinsic_mesh<TM> im = get_intrinsic_mesh(tm, np);
  const Mesh_arrays<TM>& m = im.arrays();
  const Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1 || !topo.loops.empty() || m.number_of_vertices() + m.number_of_faces() != m.number_of_edges() + 2)
    throw Input_error(Input_error::INVALID_ARGUMENT, std::string(who) + " needs a closed connected mesh of genus 0");
  return im;
}

// The box's six faces (axis a, side s), corners (bit k of a corner: its side along axis k)
// counterclockwise seen from outside, and their axes in the plane.
inline void box_faces(std::vector<std::vector<int>>& faces, std::vector<std::array<int, 2>>& plane_axes)
{
  faces.clear();
  plane_axes.clear();
  for(int a = 0; a < 3; ++a)
    for(int s = 0; s < 2; ++s) {
      const int u = (a + 1) % 3, w = (a + 2) % 3;
      auto corner = [&](int bu, int bw) { return (s << a) | (bu << u) | (bw << w); };
      if(s == 1) { faces.push_back({corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)}); plane_axes.push_back({{u, w}}); }
      else { faces.push_back({corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)}); plane_axes.push_back({{w, u}}); }
    }
}

// Around every corner c of a polyhedron (faces counterclockwise seen from outside): the
// neighbour that follows q counterclockwise, turn[c][q] (-1 where q is no neighbour).
inline std::vector<std::vector<int>> corner_turns(const std::vector<std::vector<int>>& faces, int corners)
{
  std::vector<std::vector<int>> turn(std::size_t(corners), std::vector<int>(std::size_t(corners), -1));
  for(const auto& f : faces)
    for(std::size_t k = 0; k < f.size(); ++k) {   // in (p, c, q) the face turns from q to p around c
      const int p = f[(k + f.size() - 1) % f.size()], c = f[k], q = f[(k + 1) % f.size()];
      turn[std::size_t(c)][std::size_t(q)] = p;
    }
  return turn;
}

} // namespace internal

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_CHARTS_H
