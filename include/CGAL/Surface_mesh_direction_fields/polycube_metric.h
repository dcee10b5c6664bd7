// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H

// Metric compensation by a polycube (Lai et al. 2010, section 4.1.3.2) for the simplest
// polycube, a box: a genus-0 surface with eight corner vertices is cut along paths between
// them into the six faces of a box, each face mapped onto a rectangle, and the metric is that
// of the box, whose holonomy lies in the square grid's symmetry group.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
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
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of box_polycube_metric().
struct Polycube_metric_status
{
  bool success = false;
  std::string message;                         ///< empty on success
  std::array<double, 3> dimensions{{0, 0, 0}}; ///< box_polycube_metric(): the box's side lengths (multiples of the edge length)
  std::size_t path_edges = 0;                  ///< mesh edges on the twelve paths between the corners
  /// the largest ratio, over the polyhedron's edges, between the path's length on the surface
  /// and the edge it is mapped to (1: no stretch along the cut)
  double max_path_stretch = 0;
  /// steps of the as-rigid-as-possible relaxation taken (0: the Tutte embedding as it is)
  int relaxation_steps = 0;
  /// vertices near the paths relaxed a second time across the polyhedron's edges, the two faces
  /// beside each edge unfolded into one plane (so that the zigzag of an edge path does not shear
  /// its triangles); 0 without relaxation and for polyhedron_remesh(), whose grid follows the paths
  std::size_t seam_relaxed_vertices = 0;
  /// with `RICCI_FLOW_SEGMENTS`: the largest difference between the places along P's edge that
  /// the two segments beside it give a path vertex, as a fraction of the edge (how far apart Lai
  /// et al.'s assembly of the segments leaves the two sides; the charts take their mean); 0 otherwise
  double max_side_parameter_gap = 0;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// How box_polycube_metric(), polyhedron_metric() and polyhedron_remesh() map the pieces of the
/// surface between P's edges (Lai et al.'s segments) onto P's faces (named parameter
/// `segment_flattening`).
enum Segment_flattening
{
  /// a stretch-minimising Tutte embedding, its sides by arc length, relaxed as rigidly as
  /// possible with the paths sliding along P's edges (the default: close to the input's own
  /// triangles, so grid cells of about the same size everywhere)
  RELAXED_SEGMENTS,
  /// Lai et al.'s step 3: each segment flattened by Ricci flow to a polygon with P's face's
  /// angles (boundary curvature \f$\pi\f$ minus the angle at P's corners, 0 elsewhere) and
  /// straight sides, the vertices of each side placed where that metric puts them (the mean of
  /// the two segments beside the path, which disagree: `max_side_parameter_gap` in the status),
  /// the inside by a Tutte embedding with the mean value weights of the mesh's metric and that
  /// boundary (a discrete harmonic map; harmonic maps do not change under conformal scaling, so
  /// with the conformal boundary it approximates the segment's conformal map onto its polygon,
  /// stretched to the polygon's sides); no relaxation. Conformal maps shrink protrusions
  /// exponentially, so the grid's cells vary in size on the surface.
  RICCI_FLOW_SEGMENTS
};

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

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Whether the polyhedron of `faces` (cycles of corner indices \f$0 \ldots 7\f$, counterclockwise
/// seen from outside, as for polyhedron_metric()) is a box: six quadrilaterals, three at every
/// corner, glued as a cube's. If so, `order[i]` is set to the corner that box_polycube_metric()
/// places at \f$(i \& 1, (i \gg 1) \& 1, (i \gg 2) \& 1)\f$, with the same faces and
/// orientation, so that a box given as a list of faces can get the box's own scaling along its
/// three axes (`smdf remesh --polycube FILE` does this).
inline bool box_corner_order(const std::vector<std::vector<int>>& faces, std::array<int, 8>& order)
{
  if(faces.size() != 6) return false;
  for(const auto& f : faces) {
    if(f.size() != 4) return false;
    for(int c : f) if(c < 0 || c > 7) return false;
  }
  std::vector<std::vector<int>> box;
  std::vector<std::array<int, 2>> axes;
  internal::box_faces(box, axes);
  const std::vector<std::vector<int>> turn = internal::corner_turns(faces, 8), box_turn = internal::corner_turns(box, 8);
  int q0 = -1;   // a neighbour of corner 0
  for(int q = 0; q < 8 && q0 < 0; ++q) if(turn[0][std::size_t(q)] >= 0) q0 = q;
  if(q0 < 0) return false;
  // corner 0 at the box's corner 0 and q0 at corner 1; the box's rotations about its diagonal
  // give the other two choices, equally good
  std::array<int, 8> o;
  o.fill(-1);
  o[0] = 0;
  int q = q0, b = 1;
  for(int k = 0; k < 3; ++k) {
    if(q < 0) return false;
    o[std::size_t(b)] = q;
    q = turn[0][std::size_t(q)];
    b = box_turn[0][std::size_t(b)];
  }
  if(q != q0) return false;   // corner 0 has three faces
  auto common = [&](int x, int y) {   // the corner other than 0 next to both
    int found = -1;
    for(int c = 1; c < 8; ++c)
      if(c != x && c != y && turn[std::size_t(c)][std::size_t(x)] >= 0 && turn[std::size_t(c)][std::size_t(y)] >= 0) {
        if(found >= 0) return -1;
        found = c;
      }
    return found;
  };
  o[3] = common(o[1], o[2]);
  o[5] = common(o[1], o[4]);
  o[6] = common(o[2], o[4]);
  std::array<char, 8> used{};
  for(int i = 0; i < 7; ++i)
    if(o[std::size_t(i)] < 0 || used[std::size_t(o[std::size_t(i)])]++) return false;
  for(int c = 0; c < 8; ++c) if(!used[std::size_t(c)]) o[7] = c;
  // every face of the box, relabelled, must be a face of the polyhedron, in the same direction
  for(const auto& bf : box) {
    bool found = false;
    for(const auto& f : faces)
      for(std::size_t r = 0; r < 4 && !found; ++r) {
        bool same = true;
        for(std::size_t k = 0; k < 4; ++k) same = same && f[(k + r) % 4] == o[std::size_t(bf[k])];
        found = same;
      }
    if(!found) return false;
  }
  order = o;
  return true;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Metric compensation with a box (Lai et al. 2010, section 4.1.3.2, for the polycube with one
/// cube): the eight `corners` of a closed genus-0 mesh (corner \f$i\f$ goes to the box corner
/// \f$(i \& 1, (i \gg 1) \& 1, (i \gg 2) \& 1)\f$) are joined by the twelve shortest edge paths
/// of the box's edges (Dijkstra, each path avoiding the earlier ones and the other corners;
/// for Lai et al. under the flat cone metric with cones of \f$\pi/2\f$ at the corners, given by
/// its conformal factors), which cut the mesh into six disks; each disk is mapped onto its face
/// of the box by a Tutte embedding with symmetrised mean value weights (Floater 2003; any
/// positive weights make it bijective onto the convex rectangle), its boundary placed by arc length on the input
/// surface along the four paths. The embedding is then made as close to an isometry of the input
/// surface as its bijectivity allows, in two stages: a second Tutte embedding whose weights are
/// divided by the L2 stretch of the first at their far ends (one round of Yoshizawa, Belyaev and
/// Seidel 2004, kept if the stretch falls; more rounds lower it further but leave the next stage
/// more sheared triangles); then as-rigid-as-possible steps (Liu et al. 2008) over all six faces
/// at once, the path vertices sliding along the box's edges (one unknown each, shared by the two
/// faces beside the path), every step cut short where a triangle would lose half its area; last,
/// the vertices within 8 edges of each path are relaxed once more in the plane where the two box
/// faces beside it are unfolded, without the path, so that its zigzag along the mesh's edges
/// does not shear the triangles beside it (`seam_relaxed_vertices` in the status). The
/// box's sides are the mean lengths on the surface of their four parallel paths, scaled so that
/// the box has the surface's area and rounded to multiples of `edge_length`. The output metric
/// (`lengths`, on `tm`'s triangulation) is the box's: flat but for cones of \f$\pi/2\f$ at the
/// corners, with cut-graph motions that are symmetries of the square grid of edge length
/// `edge_length`, so tessellate_flat_metric() accepts it.
///
/// Lai et al. flatten each disk to a rectangle by Ricci flow with corner curvatures
/// \f$\pi/2\f$ and then scale the rectangles: `segment_flattening(RICCI_FLOW_SEGMENTS)`. The two
/// sides of a path then disagree on where its vertices go (their mean is taken), and a conformal
/// map shrinks protrusions exponentially (a remesh then cuts them off). The default,
/// `RELAXED_SEGMENTS`, shares each path vertex between its two sides, which keeps the sides
/// consistent by construction, and its relaxation towards the input's own triangles gives every
/// part of the surface grid cells of about the same size: on Spot, the remesh's area is within
/// 0.5 % of the input's and every input vertex within one edge length of it, against 2.8 % and
/// up to 5 edge lengths with the plain Tutte embedding (the manual compares the two methods).
///
/// Named parameters: `edge_length_map` (the metric \f$\ell\f$ of the path lengths and of the
/// angles of the first mean value weights; default: Euclidean lengths) or `intrinsic_mesh`;
/// `conformal_factor_map` (a readable vertex map of conformal factors \f$u\f$: the paths are
/// then shortest under the lengths \f$\ell_{ij} e^{(u_i + u_j)/2}\f$ of the mesh's edges, the
/// flat cone metric of Lai et al. when \f$u\f$ is the `conformal_factor_map` output of
/// compute_cone_metric() with these cones; this works whatever triangulation the flow ended
/// on, intrinsic edge flips included, since the factors live on the vertices; a
/// `curvature_tolerance` of \f$10^{-6}\f$ is plenty for edge paths and saves a Newton step or
/// two on large meshes; default: none);
/// `number_of_iterations` (default 10: at most that many as-rigid-as-possible steps, after the
/// one reweighting round, fewer once a triangle about to fold throttles a step below 1 % of its
/// length; 0 keeps the plain Tutte embedding, the path lengths and the arc lengths then
/// in the metric of `edge_length_map`, the box's sides unscaled); `vertex_point_map` (the input
/// surface the relaxation measures against); `seam_relaxation_rings` (default 8: the width, in
/// edges, of the bands beside the paths relaxed across the box's edges; 0 leaves the paths
/// straight; on Spot at 100k faces and as many quads, 8 rings give 5 quads with a negative scaled
/// Jacobian, 4 rings 14, 16 rings 12, none 145); `segment_flattening` (default
/// `RELAXED_SEGMENTS`; `RICCI_FLOW_SEGMENTS` for Lai et al.'s segments, which ignores
/// `number_of_iterations` and `seam_relaxation_rings` but for the box's sides); and the index maps.
/// Failures (a path that cannot avoid the earlier ones, pieces that do not match the box's
/// faces, a degenerate triangle) are in the status; `Input_error` for a mesh that is not a
/// closed genus-0 surface or corners that are not eight distinct vertices.
template <typename TriangleMesh, typename EdgeLengthMap, typename NamedParameters = parameters::Default_named_parameters>
Polycube_metric_status box_polycube_metric(const TriangleMesh& tm,
                                           const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 8>& corners,
                                           double edge_length, EdgeLengthMap lengths,
                                           const NamedParameters& np = parameters::default_values())
{
  if(!(edge_length > 0) || !std::isfinite(edge_length))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the edge length must be positive, got " + std::to_string(edge_length));
  const Intrinsic_mesh<TriangleMesh> im = internal::genus_zero_mesh(tm, np, "box_polycube_metric()");
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<int> cv;
  for(const auto& v : corners) cv.push_back(m.vertex_index(v));
  std::vector<std::vector<int>> pfaces;
  std::vector<std::array<int, 2>> plane_axes;
  internal::box_faces(pfaces, plane_axes);
  const internal::Chart_inputs in = internal::chart_inputs(tm, m, np);
  std::array<double, 3> dims{{0, 0, 0}};
  bool dims_known = false;
  auto polygon = [&](std::size_t j, const std::function<double(int, int)>& path_length) {
    if(!dims_known) {   // each side: the mean of its four paths, the box scaled to the input's area, in multiples of the edge length
      std::array<double, 3> mean{{0, 0, 0}};
      for(int a = 0; a < 3; ++a)
        for(int i = 0; i < 8; ++i) if(!(i & (1 << a))) mean[std::size_t(a)] += path_length(i, i | (1 << a)) / 4;
      const double box_area = 2 * (mean[0] * mean[1] + mean[1] * mean[2] + mean[2] * mean[0]);
      const double scale = in.iterations > 0 && box_area > 0 ? std::sqrt(in.area / box_area) : 1.;
      for(int a = 0; a < 3; ++a) dims[std::size_t(a)] = edge_length * (std::max)(1., std::round(scale * mean[std::size_t(a)] / edge_length));
      dims_known = true;
    }
    const int x = plane_axes[j][0], y = plane_axes[j][1];
    std::vector<Point_2> p;
    for(int c : pfaces[j]) p.push_back(Point_2(((c >> x) & 1) * dims[std::size_t(x)], ((c >> y) & 1) * dims[std::size_t(y)]));
    return p;
  };
  std::vector<double> l;
  Polycube_metric_status st = internal::polyhedron_metric_core(m, cv, pfaces, polygon, in, l);
  st.dimensions = dims;
  if(st.success) for(std::size_t e = 0; e < l.size(); ++e) put(lengths, m.edges[e], l[e]);
  return st;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Metric compensation with a polyhedron P made of squares and equilateral triangles of side
/// `side_length` (Lai et al. 2010, section 4.1.3.2: P's vertices are the cones, its faces
/// quadrilaterals or triangles): `corners` are the mesh vertices of P's vertices, `faces` P's
/// faces as cycles of indices into `corners`, counterclockwise seen from outside. The mesh is cut
/// along shortest edge paths of P's edges and every piece embedded onto its square or triangle
/// as in box_polycube_metric(). The output metric has a cone at each of P's vertices of
/// curvature \f$2\pi\f$ minus its polygons' angles (\f$\pi/2\f$ per square, \f$\pi/3\f$ per
/// triangle): the octahedron's six cones of \f$2\pi/3\f$, an obelisk's mix. Its holonomy is in
/// the square grid's group when P has only squares, in the triangular grid's when it has only
/// triangles; a side length that is a multiple of the grid's edge length makes the cones grid
/// points. The embedding is relaxed towards the input's triangles as in box_polycube_metric()
/// (a `side_length` that gives P the surface's area suits it best). Named parameters and
/// failures as for box_polycube_metric(); `Input_error` also for a P that is not a closed
/// oriented sphere or has faces other than triangles and quadrilaterals.
template <typename TriangleMesh, typename EdgeLengthMap, typename NamedParameters = parameters::Default_named_parameters>
Polycube_metric_status polyhedron_metric(const TriangleMesh& tm,
                                         const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
                                         const std::vector<std::vector<int>>& faces, double side_length, EdgeLengthMap lengths,
                                         const NamedParameters& np = parameters::default_values())
{
  if(!(side_length > 0) || !std::isfinite(side_length))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the side length must be positive, got " + std::to_string(side_length));
  for(const auto& f : faces)
    if(f.size() != 3 && f.size() != 4)
      throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron's faces must be triangles or quadrilaterals, got one with " +
                                                           std::to_string(f.size()) + " corners");
  const Intrinsic_mesh<TriangleMesh> im = internal::genus_zero_mesh(tm, np, "polyhedron_metric()");
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<int> cv;
  for(const auto& v : corners) cv.push_back(m.vertex_index(v));
  const double L = side_length;
  auto polygon = [&](std::size_t j, const std::function<double(int, int)>&) {
    return faces[j].size() == 4 ? std::vector<Point_2>{Point_2(0, 0), Point_2(L, 0), Point_2(L, L), Point_2(0, L)}
                                : std::vector<Point_2>{Point_2(0, 0), Point_2(L, 0), Point_2(L / 2, L * std::sqrt(3.) / 2)};
  };
  std::vector<double> l;
  Polycube_metric_status st = internal::polyhedron_metric_core(m, cv, faces, polygon, internal::chart_inputs(tm, m, np), l);
  if(st.success) for(std::size_t e = 0; e < l.size(); ++e) put(lengths, m.edges[e], l[e]);
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H
