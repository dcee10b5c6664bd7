// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESH_UNTANGLING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESH_UNTANGLING_H

// Inverted faces of a remesh unfolded by moving vertices along the input surface: the
// connectivity (and so every valence and irregular vertex) stays, every moved vertex is put back
// on the input by its closest point.

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/internal/face_location.h>
#include <CGAL/Surface_mesh_direction_fields/internal/inversion.h>
#include <CGAL/Surface_mesh_direction_fields/internal/packed_lists.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of untangle_remesh().
struct Untangle_status
{
  bool success = false;              ///< no face is inverted at the end
  std::string message;               ///< empty on success
  std::size_t inverted_before = 0;   ///< faces inverted with respect to the input at the start
  std::size_t inverted_after = 0;    ///< ... and at the end (if not 0, no vertex was moved)
  std::size_t moved_vertices = 0;    ///< vertices moved along the input surface (0 unless success)
  /// of the faces still inverted, those whose corners lie where the input's normals point apart
  /// (a face across a thin part, such as an ear, or a sharp tip): no move along the surface
  /// unfolds them, a smaller edge length does
  std::size_t straddling_faces = 0;
  /// of the faces still inverted and not counted in `straddling_faces`, those next to a vertex
  /// that may not move (a cone, a border vertex)
  std::size_t faces_at_held_vertices = 0;
  int rounds = 0;                    ///< smoothing rounds taken, over both attempts (each round over a wider ring of vertices)
  /// the largest distance a vertex moved, in units of the remesh's mean edge length
  double max_displacement = 0;
  /// faces of four or more corners folded at a corner (not convex: the turn at that corner goes
  /// against the face's own area vector, the input's normals under its corners or those at the
  /// input point nearest its centroid), in the grid ...
  std::size_t folded_before = 0;
  /// ... and at the end: once no face is inverted, their corners are moved too (best effort;
  /// `success` does not depend on it)
  std::size_t folded_after = 0;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Unfolds the faces of `remesh` that are inverted with respect to the surface `input` (a face
/// is inverted when its area vector points against the input's normals at its corners, the test
/// of tessellate_flat_metric() and polyhedron_remesh(), or against the input's normal at the
/// point of the input nearest its centroid, of every input face there: a face bent over a ridge
/// or around a thin part) by moving vertices near them along the input: each round smooths the vertices within a ring of the inverted faces (one ring wider
/// each round, up to `number_of_iterations` rounds) towards the mean of their neighbours (a
/// first attempt with whole steps; if a face stays inverted, a second from the grid's positions
/// that falls back on half and quarter steps where a whole one is refused; if one still does, a
/// third that also moves the corners of each inverted face by a pattern search in the tangent
/// plane, towards fewer inverted faces around it and the worst of them facing the input
/// better), puts each one back on the input at its closest point, and keeps a move only if it inverts no face
/// around the vertex that was not inverted and does not jump to a part of the surface whose
/// normal turns away (as across a thin ear). Only positions change: faces, valences and the
/// irregular vertices are those of the grid. If some faces stay inverted, `remesh` is left as it
/// was (the status says how many would have stayed, and how many of those lie across a thin part).
/// Once none is inverted, faces of four or more corners folded at a corner (not convex: at one
/// corner the turn goes against the face's own area vector, a negative scaled Jacobian there, or
/// against the input's normals under its corners or at the point nearest its centroid, as quality
/// measures of remeshes take it) get their corners moved by the same pattern search, after steps
/// towards the neighbours' mean, a move kept only if it folds fewer faces around the vertex, or
/// as many with the worst corner around it at a larger scaled Jacobian, and inverts none. This
/// runs in two passes: first without the normals nearest the centroid, then with them, a move of
/// the second pass kept only if it also folds no more faces around the vertex by the first
/// pass's test. Best effort, reported as `folded_before` and `folded_after`. A remesh with no inverted and no
/// folded face is left as it is.
/// The input's normal under a vertex is that of the input face it lies on, searched first among
/// the faces near the one under a neighbour (a vertex off the input gets its closest face's); on
/// an input edge or vertex, the normalised sum of the unit normals of the faces around it.
///
/// This is a repair outside Lai et al.'s method. Their remesh is the grid of the metric, and
/// where one polyhedron fits the shape poorly (the bunny's ears on a box, limbs) a grid cell can
/// straddle a fold of the surface; moving a few vertices along the surface gives a valid mesh
/// whose connectivity is still the grid's.
///
/// Named parameters: `vertex_point_map` (the input's points), `vertex_is_constrained_map` (a
/// readable map of `remesh`'s vertices to `bool`: those never move, e.g. the cones; border
/// vertices never move either), `number_of_iterations` (default 8). Throws `Input_error` for an
/// empty input or a remesh whose faces have fewer than three vertices.
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Untangle_status untangle_remesh(const TriangleMesh& input, PolygonMesh& remesh, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Input_VPM;
  typedef typename boost::property_traits<Input_VPM>::value_type Input_point;
  typedef typename CGAL::Kernel_traits<Input_point>::Kernel K;
  typedef typename K::Triangle_3 Triangle;
  typedef typename std::vector<Triangle>::const_iterator Triangle_iterator;
  // triangles stored in the primitives: the tree's construction and queries read no property map
  typedef CGAL::AABB_triangle_primitive<K, Triangle_iterator, CGAL::Tag_true> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  typedef std::array<double, 3> V3;

  Untangle_status st;
  if(faces(input).first == faces(input).second) throw Input_error(Input_error::INVALID_ARGUMENT, "untangle_remesh() needs a non-empty input surface");
  for(face_descriptor f : faces(remesh))
    if(CGAL::halfedges_around_face(halfedge(f, remesh), remesh).size() < 3)
      throw Input_error(Input_error::INVALID_ARGUMENT, "untangle_remesh(): a face of the remesh has fewer than three vertices");
  const Input_VPM ivpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, input));
  const int max_rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 8);
  if(max_rounds < 0) throw Input_error(Input_error::INVALID_ARGUMENT, "number_of_iterations must not be negative");
  auto constrained = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                      CGAL::Static_boolean_property_map<vertex_descriptor, false>());
  internal::Input_faces<TriangleMesh> located(input, ivpm);
  // the remesh's vertices and faces as indices; per vertex its position, the input face it lies
  // on and the input's normal there
  auto vim = get(CGAL::dynamic_vertex_property_t<std::size_t>(), remesh);
  std::vector<vertex_descriptor> vs;
  for(vertex_descriptor v : vertices(remesh)) { put(vim, v, vs.size()); vs.push_back(v); }
  internal::Packed_lists<std::size_t> fv, vf, nb;   // per face: its vertices; per vertex: its faces, its neighbours
  std::vector<char> fixed(vs.size(), 0);
  std::vector<V3> pos(vs.size()), normal(vs.size());
  std::vector<int> under(vs.size(), -1);
  std::vector<V3> foot;   // per vertex: a point of face under[v], its closest point on the input (a query's start)
  std::vector<std::size_t> pending;   // vertices the local search did not place
  double mean_edge = 0, tol = 0;
  auto rvpm = get(CGAL::vertex_point, remesh);
  auto index_and_locate = [&] {
    fv.reserve(num_faces(remesh), 4 * num_faces(remesh));
    for(face_descriptor f : faces(remesh)) {
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, remesh), remesh)) fv.push_back(get(vim, target(h, remesh)));
      fv.close_list();
    }
    vf = fv.transposed(vs.size());
    nb.reserve(vs.size(), 2 * num_edges(remesh));
    for(vertex_descriptor v : vs) {
      fixed[get(vim, v)] = CGAL::is_border(v, remesh) || get(constrained, v);
      for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, remesh), remesh)) nb.push_back(get(vim, source(h, remesh)));
      nb.close_list();
    }
    for(std::size_t i = 0; i < vs.size(); ++i) {
      const auto& p = get(rvpm, vs[i]);
      pos[i] = V3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    }
    std::size_t edge_count = 0;
    for(std::size_t i = 0; i < vs.size(); ++i)
      for(std::size_t j : nb[i]) {
        const double d[3] = {pos[j][0] - pos[i][0], pos[j][1] - pos[i][1], pos[j][2] - pos[i][2]};
        mean_edge += std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        ++edge_count;
      }
    mean_edge /= double((std::max)(edge_count, std::size_t(1)));
    tol = 1e-7 * mean_edge;   // a vertex closer to an input face or vertex lies on it
    // the input face under every vertex, searched near the face under a neighbour, breadth first
    // over the remesh (433k vertices: a tree query each took most of the time)
    std::vector<char> queued(vs.size(), 0);
    std::vector<int> hint(vs.size(), -1);
    std::vector<std::size_t> queue;
    queue.reserve(vs.size());
    int seeds = 0;
    for(std::size_t s0 = 0; s0 < vs.size(); ++s0) {
      if(queued[s0]) continue;
      queued[s0] = 1;
      queue.push_back(s0);
      const std::size_t first = queue.size() - 1;
      for(std::size_t q = first; q < queue.size(); ++q) {
        const std::size_t i = queue[q];
        if(q == first && seeds++ < 8) {   // the first vertex of a component: every face tried
          const int f = located.nearest_face(pos[i]);
          if(located.squared_distance(pos[i], f) <= tol * tol) under[i] = f;
          hint[i] = f;
        }
        for(std::size_t j : nb[i])   // a walk from a neighbour's face, else the faces around it
          if(under[i] < 0 && hint[j] >= 0) {
            under[i] = located.walk_to(pos[i], hint[j], tol * tol);
            if(under[i] < 0) under[i] = located.face_under(pos[i], hint[j], tol * tol, 4, &hint[i]);
          }
        if(under[i] >= 0) { normal[i] = located.normal_at(pos[i], under[i], tol * tol); hint[i] = under[i]; }
        else pending.push_back(i);   // its nearest face found still guides the search for its neighbours
        for(std::size_t j : nb[i]) if(!queued[j]) { queued[j] = 1; queue.push_back(j); }
      }
    }
  };
  // The tree of the input's faces (for those vertices and for the moves) is built on the other
  // thread meanwhile, without its own search structure (queries start from a vertex's point and
  // face instead; at 433k faces that structure took longer to build than all queries).
  Tree tree;
  std::vector<Triangle> triangles;   // the input's faces, in the order of `located`
  internal::run_on_two_threads([&](int t) {
    if(t == 1) {
      triangles.reserve(located.size());
      for(std::size_t f = 0; f < located.size(); ++f) {
        const auto h = halfedge(located.face(int(f)), input);
        triangles.emplace_back(get(ivpm, source(h, input)), get(ivpm, target(h, input)), get(ivpm, target(next(h, input), input)));
      }
      tree.insert(triangles.cbegin(), triangles.cend());
      tree.build();
      tree.do_not_accelerate_distance_queries();   // queries start from a point of the surface instead
    }
    else index_and_locate();
  }, num_faces(input) >= 20000);
  // The closest point on the input to p, and the face it lies in; the search starts from vertex
  // `from`'s point on the input and its face, if any (CGAL may return that start as the answer,
  // so it must lie on the surface: `foot`, not the vertex's position, which may be off it).
  auto closest = [&](const Input_point& p, std::size_t from) {
    const auto cp = from < vs.size() && under[from] >= 0
                      ? tree.closest_point_and_primitive(p, std::make_pair(Input_point(foot[from][0], foot[from][1], foot[from][2]),
                                                                           triangles.cbegin() + std::ptrdiff_t(under[from])))
                      : tree.closest_point_and_primitive(p);
    return std::make_pair(cp.first, int(cp.second - triangles.cbegin()));
  };
  foot = pos;
  // The vertices left: breadth first again from the placed ones, the tree where the local
  // search fails once more (one failure would otherwise leave all the vertices behind it unplaced).
  {
    std::vector<char> waiting(vs.size(), 0);
    for(std::size_t i : pending) waiting[i] = 1;
    std::vector<std::size_t> queue;
    auto placed_neighbour = [&](std::size_t i) {
      for(std::size_t j : nb[i]) if(under[j] >= 0) return j;
      return vs.size();
    };
    for(std::size_t i : pending) if(placed_neighbour(i) < vs.size()) { waiting[i] = 2; queue.push_back(i); }
    for(std::size_t k = 0; k <= pending.size(); ++k) {   // the queue, then any vertex not reached from a placed one
      for(std::size_t q = 0; q < queue.size(); ++q) {
        const std::size_t i = queue[q], from = placed_neighbour(i);
        if(from < vs.size()) under[i] = located.face_under(pos[i], under[from], tol * tol, 4);
        if(under[i] < 0) {   // off the input: its closest point
          const auto cp = closest(Input_point(pos[i][0], pos[i][1], pos[i][2]), from);
          under[i] = cp.second;
          foot[i] = V3{{CGAL::to_double(cp.first.x()), CGAL::to_double(cp.first.y()), CGAL::to_double(cp.first.z())}};
        }
        normal[i] = located.normal_at(foot[i], under[i], tol * tol);
        for(std::size_t j : nb[i]) if(waiting[j] == 1) { waiting[j] = 2; queue.push_back(j); }
      }
      queue.clear();
      while(k < pending.size() && waiting[pending[k]] != 1) ++k;
      if(k < pending.size()) { waiting[pending[k]] = 2; queue.push_back(pending[k]); }
    }
  }
  // the input point nearest face f's centroid, and the input face it lies in
  auto nearest_to_centroid = [&](std::size_t f) {
    const auto c = fv[f];
    V3 centroid{{0, 0, 0}};
    for(std::size_t v : c) for(std::size_t d = 0; d < 3; ++d) centroid[d] += pos[v][d] / double(c.size());
    const auto q = closest(Input_point(centroid[0], centroid[1], centroid[2]), c[0]);
    return std::make_pair(V3{{CGAL::to_double(q.first.x()), CGAL::to_double(q.first.y()), CGAL::to_double(q.first.z())}}, q.second);
  };
  // How face f faces the input: the cosine between its area vector and the sum of the normals
  // under its corners, or the input's normals at the point nearest its centroid (of every face
  // there, on a side or corner), whichever is least (at most 0: inverted). The second sees a
  // face bent over a ridge or a thin part whose corners agree with the input but whose middle
  // does not (feline at 4,000 quads: 3 such faces, none by the corners).
  auto facing = [&](std::size_t f) {
    const auto c = fv[f];
    V3 area, sum;
    double la, lu;
    internal::area_and_normals(c.size(), [&](std::size_t k) { return pos[c[k]]; }, [&](std::size_t k) { return normal[c[k]]; }, area, sum, la, lu);
    if(!(la > 0) || !(lu > 0)) return -1.;
    const double at_corners = (area[0] * sum[0] + area[1] * sum[1] + area[2] * sum[2]) / (la * lu);
    if(at_corners <= 0) return at_corners;
    const auto q = nearest_to_centroid(f);
    return (std::min)(at_corners, located.least_dot_with_normals_at(q.first, q.second, tol * tol, V3{{area[0] / la, area[1] / la, area[2] / la}}));
  };
  auto inverted = [&](std::size_t f) { return facing(f) <= 0; };
  auto count_inverted = [&] {
    std::size_t n = 0;
    for(std::size_t f = 0; f < fv.size(); ++f) n += inverted(f);
    return n;
  };
  // an inverted face across a thin part or a tip: its corners' normals point apart
  auto straddles = [&](std::size_t f) {
    for(std::size_t a = 0; a < fv[f].size(); ++a)
      for(std::size_t b = a + 1; b < fv[f].size(); ++b) {
        const V3 &n1 = normal[fv[f][a]], &n2 = normal[fv[f][b]];
        if(n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2] < 0) return true;
      }
    return false;
  };
  auto count_straddling = [&] {
    std::size_t n = 0;
    for(std::size_t f = 0; f < fv.size(); ++f) n += inverted(f) && straddles(f);
    return n;
  };
  st.inverted_before = count_inverted();
  const std::vector<V3> start = pos, start_normal = normal;
  const std::vector<int> start_under = under;
  const std::vector<V3> start_foot = foot;
  std::vector<char> moved(vs.size(), 0);
  // One attempt from the grid's positions: up to `max_rounds` rounds, each vertex stepping to its
  // neighbours' mean, or with `fallbacks` to half or a quarter of the way when the whole step is
  // refused. Returns how many faces stay inverted.
  // How face f turns at its worst corner (at most 0: folded there): its scaled Jacobian against
  // its own area vector, the input's normals under its corners and those at the input point
  // nearest its centroid (of every input face there), the least. The last is how quality
  // measures of a remesh take it (a quad bent over a ridge can be convex by the first two: the
  // feline at 4,000 quads had a corner at -0.64 by it and none folded by the others).
  // `hard`, if given, receives the least of the first two alone (a face folded by them is also
  // not convex in the remesh's own quality measure, which the search ranks first).
  // (`at_centroid` false: the first two only, the first pass of the unfolding below)
  bool at_centroid = true;
  auto corner_turn = [&](std::size_t f, std::size_t* at = nullptr, double* hard = nullptr) {
    const auto c = fv[f];
    std::size_t worst_at = 0;
    double worst = internal::worst_corner_turn(c.size(), [&](std::size_t k) { return pos[c[k]]; }, [&](std::size_t k) { return normal[c[k]]; }, &worst_at);
    if(hard) *hard = worst;
    if(worst > 0 && at_centroid) {
      const auto q = nearest_to_centroid(f);
      const std::size_t n = c.size();
      for(std::size_t k = 0; k < n; ++k) {
        const V3 &o = pos[c[k]], &a = pos[c[(k + 1) % n]], &b = pos[c[(k + n - 1) % n]];
        const V3 u = {{a[0] - o[0], a[1] - o[1], a[2] - o[2]}}, w = {{b[0] - o[0], b[1] - o[1], b[2] - o[2]}};
        const double l = std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
        const V3 x = {{(u[1] * w[2] - u[2] * w[1]) / l, (u[2] * w[0] - u[0] * w[2]) / l, (u[0] * w[1] - u[1] * w[0]) / l}};
        const double t = located.least_dot_with_normals_at(q.first, q.second, tol * tol, x);
        if(t < worst) { worst = t; worst_at = k; }
      }
    }
    if(at) *at = worst_at;
    return worst;
  };
  auto folded_at = [&](std::size_t f, double turn) { return fv[f].size() >= 4 && turn <= 0; };
  auto folded = [&](std::size_t f) { return folded_at(f, corner_turn(f)); };
  for(std::size_t f = 0; f < fv.size(); ++f) st.folded_before += folded(f);
  // A point a short step from vertex v put back on the input: at its closest point in the face
  // a walk from the face under v reaches (the tree's answer where the walk fails), a local
  // projection that never jumps across a thin part (armadillo 400k: untangling 1.22 -> 0.98 s).
  auto project_near = [&](const V3& p, std::size_t v) {
    const int f = under[v] >= 0 ? located.walk_to(p, under[v], mean_edge * mean_edge) : -1;
    if(f < 0) return closest(Input_point(p[0], p[1], p[2]), v);
    const V3 q = located.closest_point(p, f);
    return std::make_pair(Input_point(q[0], q[1], q[2]), f);
  };
  // A pattern search for vertex v where smoothing finds no move (a face pinned by a cone at one
  // corner): steps in eight directions of the input's tangent plane, a quarter, an eighth and a
  // sixteenth of its mean edge long, each put back on the input, the best kept while it has fewer
  // inverted faces around v, or as many and the worst of them facing the input better. With
  // `unfold_corners` (no face inverted any more), also steps towards the neighbours' mean, and
  // the best kept while it has fewer inverted, then fewer folded faces around v, or as many of
  // both and the worst corner around v turning the right way more.
  auto search = [&](std::size_t v, bool unfold_corners) {
    // (worst_hard: the worst turn by the face's own area vector or the normals under its corners
    // while some face folds by those, else 0; ties in the counts go to it first, then to worst)
    auto score = [&](std::size_t& inverted_faces, double& worst_hard, double& worst) {
      inverted_faces = 0;
      std::size_t folded_faces = 0, hard_folded = 0;
      worst = 1;
      worst_hard = 0;
      for(std::size_t f : vf[v]) {
        const double c = facing(f);
        inverted_faces += c <= 0;
        if(unfold_corners) {
          double hard;
          const double t = corner_turn(f, nullptr, &hard);
          folded_faces += folded_at(f, t);
          hard_folded += folded_at(f, hard);
          worst_hard = (std::min)(worst_hard, hard);
          worst = (std::min)(worst, t);
        } else {
          worst = (std::min)(worst, c);
        }
      }
      // inverted first, then folded by the face's own area vector or the normals under its
      // corners, then folded at all
      const std::size_t base = vf[v].size() + 1;
      inverted_faces = (inverted_faces * base + hard_folded) * base + folded_faces;
    };
    double reach = 0;
    for(std::size_t w : nb[v])
      reach += std::sqrt((pos[w][0] - pos[v][0]) * (pos[w][0] - pos[v][0]) + (pos[w][1] - pos[v][1]) * (pos[w][1] - pos[v][1]) +
                         (pos[w][2] - pos[v][2]) * (pos[w][2] - pos[v][2])) / double(nb[v].size());
    std::size_t best_count;
    double best_hard, best_worst;
    score(best_count, best_hard, best_worst);
    for(int step = 0; step < (unfold_corners ? 4 : 12); ++step) {
      const V3 n = normal[v];   // a tangent frame at v
      V3 t1 = std::abs(n[0]) < 0.9 ? V3{{0, -n[2], n[1]}} : V3{{-n[2], 0, n[0]}};
      t1 = internal::normalized(t1);
      const V3 t2 = {{n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]}};
      const V3 here = pos[v], here_normal = normal[v];
      const int here_under = under[v];
      V3 best_pos = here, best_normal = here_normal;
      int best_under = here_under;
      bool improved = false;
      // one candidate: `to` put back on the input, kept if it scores better than the best so far
      auto try_point = [&](const V3& to) {
        const auto q = unfold_corners ? project_near(to, v) : closest(Input_point(to[0], to[1], to[2]), v);
        const V3 p = {{CGAL::to_double(q.first.x()), CGAL::to_double(q.first.y()), CGAL::to_double(q.first.z())}};
        const V3 m = located.normal_at(p, q.second, tol * tol);
        if(m[0] * here_normal[0] + m[1] * here_normal[1] + m[2] * here_normal[2] <= 0) return false;   // the other side of a thin part
        pos[v] = p;
        normal[v] = m;
        std::size_t count;
        double hard, worst;
        score(count, hard, worst);
        pos[v] = here;
        normal[v] = here_normal;
        if(!(count < best_count || (count == best_count && (hard > best_hard || (hard == best_hard && worst > best_worst))))) return false;
        best_count = count; best_hard = hard; best_worst = worst; best_pos = p; best_normal = m; best_under = q.second; improved = true;
        return true;
      };
      // with unfold_corners (a polish: at most 4 steps) the whole, half and quarter step towards
      // the neighbours' mean first, the first that helps taken, the pattern only if none does
      if(unfold_corners) {
        V3 mean{{0, 0, 0}};
        for(std::size_t w : nb[v]) for(int d = 0; d < 3; ++d) mean[std::size_t(d)] += pos[w][std::size_t(d)] / double(nb[v].size());
        for(double t : {1., 0.5, 0.25})
          if(try_point(V3{{here[0] + t * (mean[0] - here[0]), here[1] + t * (mean[1] - here[1]), here[2] + t * (mean[2] - here[2])}})) break;
      }
      if(!improved)
        for(double r : {0.25, 0.125, 0.0625})
          for(int k = 0; k < 8; ++k) {
            const double a = k * CGAL_PI / 4, x = r * reach * std::cos(a), y = r * reach * std::sin(a);
            try_point(V3{{here[0] + x * t1[0] + y * t2[0], here[1] + x * t1[1] + y * t2[1], here[2] + x * t1[2] + y * t2[2]}});
          }
      if(!improved) break;
      pos[v] = best_pos;
      foot[v] = best_pos;
      normal[v] = best_normal;
      under[v] = best_under;
      moved[v] = 1;
    }
  };
  auto attempt = [&](bool fallbacks, bool searching) {
    pos = start;
    normal = start_normal;
    under = start_under;
    foot = start_foot;
    std::fill(moved.begin(), moved.end(), 0);
    std::size_t left = st.inverted_before;
    for(int round = 1; round <= max_rounds && left > 0; ++round) {
      ++st.rounds;
      // the vertices within `round` rings of an inverted face
      std::vector<char> active(vs.size(), 0);
      std::vector<std::size_t> ring;
      for(std::size_t f = 0; f < fv.size(); ++f)
        if(inverted(f)) for(std::size_t v : fv[f]) if(!active[v]) { active[v] = 1; ring.push_back(v); }
      for(int r = 0; r < round; ++r) {
        const std::vector<std::size_t> last = ring;
        for(std::size_t v : last) for(std::size_t w : nb[v]) if(!active[w]) { active[w] = 1; ring.push_back(w); }
      }
      for(int sweep = 0; sweep < 10; ++sweep) {
        for(std::size_t v : ring) {
          if(fixed[v]) continue;
          V3 mean{{0, 0, 0}};
          for(std::size_t w : nb[v]) for(int d = 0; d < 3; ++d) mean[std::size_t(d)] += pos[w][std::size_t(d)] / double(nb[v].size());
          std::vector<char> was;
          for(std::size_t f : vf[v]) was.push_back(inverted(f) ? 1 : 0);
          const V3 old_pos = pos[v], old_normal = normal[v], old_foot = foot[v];
          const int old_under = under[v];
          for(double t : {1., 0.5, 0.25}) {
            if(t < 1 && !fallbacks) break;
            const auto q = closest(Input_point(old_pos[0] + t * (mean[0] - old_pos[0]), old_pos[1] + t * (mean[1] - old_pos[1]),
                                               old_pos[2] + t * (mean[2] - old_pos[2])), v);
            const V3 p = {{CGAL::to_double(q.first.x()), CGAL::to_double(q.first.y()), CGAL::to_double(q.first.z())}};
            const V3& n = located.normal_at(p, q.second, tol * tol);
            if(n[0] * old_normal[0] + n[1] * old_normal[1] + n[2] * old_normal[2] <= 0) continue;   // the other side of a thin part
            pos[v] = p;
            foot[v] = p;
            normal[v] = n;
            under[v] = q.second;
            // kept if fewer faces around v are inverted, or as many and none that was fine turned over
            std::size_t before = 0, after = 0;
            bool turned = false;
            for(std::size_t k = 0; k < vf[v].size(); ++k) {
              const bool now_inverted = inverted(vf[v][k]);
              before += std::size_t(was[k]);
              after += std::size_t(now_inverted);
              turned = turned || (!was[k] && now_inverted);
            }
            if(after < before || (after == before && !turned)) { moved[v] = 1; break; }
            pos[v] = old_pos;
            foot[v] = old_foot;
            normal[v] = old_normal;
            under[v] = old_under;
          }
        }
      }
      if(searching)
        for(std::size_t f = 0; f < fv.size(); ++f)
          if(inverted(f)) for(std::size_t v : fv[f]) if(!fixed[v]) search(v, false);
      left = count_inverted();
    }
    return left;
  };
  // Whole steps first, then with the fallbacks: each unfolds cases the other does not (whole
  // steps: Cheburashka at 8,000 quads, Spot's relaxed octahedron at 2,048 triangles; fallbacks:
  // Spot's plain octahedron at 2,048 triangles).
  std::size_t now = st.inverted_before;
  if(now > 0) now = attempt(false, false);
  if(now > 0) now = attempt(true, false);
  if(now > 0) now = attempt(true, true);
  st.inverted_after = now;
  // Then, no face inverted, the corners of the folded faces (best effort, a round at a time
  // while a round unfolds some). Only the faces around a moved vertex can change, so each round
  // looks at those alone (armadillo 400k: untangling 2.5 -> 1.2 s, two passes over all faces a round).
  // (After the attempts, counted again: an inverted quad is also folded, and the attempts'
  // moves may fold quads they do not invert.)
  st.folded_after = st.folded_before;   // a failed untangling moves nothing
  // Two passes: first the folds against the face's own area vector and the normals under its
  // corners (the remesh's own quality measure: an automatic remesh fails on them), then the
  // folds against the normals nearest the centroid too, ranked after those (a single pass with
  // both left the face at 2,500 quads with a quad folded in its own plane, which one pass without
  // the second kind unfolded).
  if(now == 0)
    for(int pass = 0; pass < 2; ++pass) {
      at_centroid = pass == 1;
      std::vector<std::size_t> fold;   // the folded faces
      for(std::size_t f = 0; f < fv.size(); ++f) if(folded(f)) fold.push_back(f);
      st.folded_after = fold.size();
      std::vector<char> tried(vs.size(), 0), listed(fv.size(), 0);
      for(int round = 0; round < max_rounds && !fold.empty(); ++round) {
        std::vector<std::size_t> touched, next;
        for(std::size_t f : fold) {
          // the corner where it folds first, then the others while it stays folded (most quads
          // unfold at that corner: armadillo 400k, untangling 0.98 -> 0.86 s)
          std::size_t at = 0;
          if(!(corner_turn(f, &at) <= 0)) continue;   // unfolded by a move around another face
          bool pinned = true;   // all its corners held: it stays as it is
          const std::size_t n = fv[f].size();
          for(std::size_t i = 0; i < n; ++i) {
            const std::size_t v = fv[f][(at + i) % n];
            pinned = pinned && fixed[v];
            if(fixed[v] || tried[v] || (i > 0 && !folded(f))) continue;
            tried[v] = 1;
            touched.push_back(v);
            search(v, true);
          }
          if(pinned && !listed[f]) { listed[f] = 1; next.push_back(f); }
        }
        for(std::size_t v : touched)
          for(std::size_t f : vf[v])
            if(!listed[f] && folded(f)) { listed[f] = 1; next.push_back(f); }
        for(std::size_t v : touched) tried[v] = 0;
        for(std::size_t f : next) listed[f] = 0;
        const bool fewer = next.size() < fold.size();
        fold.swap(next);
        st.folded_after = fold.size();
        if(!fewer) break;
      }
    }
  at_centroid = true;
  st.straddling_faces = count_straddling();
  for(std::size_t f = 0; f < fv.size(); ++f) {   // the others left inverted: next to a vertex that may not move
    if(!inverted(f) || straddles(f)) continue;
    bool held = false;
    for(std::size_t v : fv[f]) held = held || fixed[v];
    st.faces_at_held_vertices += held;
  }
  if(now > 0) {   // not all unfolded: the remesh is left as the grid made it
    pos = start;
    std::fill(moved.begin(), moved.end(), 0);
  }
  for(std::size_t i = 0; i < vs.size(); ++i) {
    if(!moved[i]) continue;
    const double d[3] = {pos[i][0] - start[i][0], pos[i][1] - start[i][1], pos[i][2] - start[i][2]};
    const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if(l == 0) continue;
    ++st.moved_vertices;
    st.max_displacement = (std::max)(st.max_displacement, l / (mean_edge > 0 ? mean_edge : 1));
    put(rvpm, vs[i], typename boost::property_traits<decltype(rvpm)>::value_type(pos[i][0], pos[i][1], pos[i][2]));
  }
  st.success = now == 0;
  if(!st.success)
    st.message = std::to_string(now) + " of " + std::to_string(st.inverted_before) + " inverted faces are still inverted after " +
                 std::to_string(st.rounds) + " rounds of moving vertices along the surface" +
                 (st.straddling_faces ? " (" + std::to_string(st.straddling_faces) + " lie across a thin part or a sharp tip, where the input's " +
                                            "normals at their corners point apart: use a smaller edge length)" : std::string()) +
                 (st.faces_at_held_vertices ? " (" + std::to_string(st.faces_at_held_vertices) + " next to a cone or border vertex, which may not move)"
                                            : std::string()) +
                 "; the remesh is left as the grid made it";
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESH_UNTANGLING_H
