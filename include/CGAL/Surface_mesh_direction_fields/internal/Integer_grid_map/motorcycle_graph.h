// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_GRAPH_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_GRAPH_H

// The T-mesh of a seamless map (Campen, Bommes and Kobbelt 2015, "Quantized global
// parametrization", section 4): from every singularity and every boundary corner, its
// separatrices (the grid directions leaving it into the surface) are traced as straight lines
// through the map's triangles and across the seams, all advancing together by length, each
// stopping where it meets a line traced before it (the motorcycle graph), a singularity or the
// boundary. The lines and the boundary cut the surface into rectangles. A piece of a line between
// two consecutive nodes on it (an arc) has a length that is a linear function of the seams' small
// unknowns (translations, singularity and corner positions, boundary lines): a rounding of those
// keeps a valid map possible only if no arc's length turns negative.

#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/seam_layout.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// A real linear form in y, the small unknowns' real coordinates (2k its real part, 2k + 1 its
// imaginary part), with integer coefficients kept as doubles; terms sorted by index.
struct Linear_form
{
  std::vector<std::pair<int, double>> terms;

  // this += s * o
  void add(const Linear_form& o, double s)
  {
    std::vector<std::pair<int, double>> out;
    out.reserve(terms.size() + o.terms.size());
    std::size_t i = 0, j = 0;
    while(i < terms.size() || j < o.terms.size()) {
      if(j == o.terms.size() || (i < terms.size() && terms[i].first < o.terms[j].first)) out.push_back(terms[i++]);
      else if(i == terms.size() || o.terms[j].first < terms[i].first) { out.emplace_back(o.terms[j].first, s * o.terms[j].second); ++j; }
      else {
        const double c = terms[i].second + s * o.terms[j].second;
        if(c != 0) out.emplace_back(terms[i].first, c);
        ++i; ++j;
      }
    }
    terms.swap(out);
  }
  double operator()(const Eigen::VectorXd& y) const
  {
    double v = 0;
    for(const auto& t : terms) v += t.second * y[t.first];
    return v;
  }
};

// Re(e / d) and Im(e / d) over the small part of e, for a unit d
inline void small_part_forms(const std::vector<std::pair<int, Cplx>>& small, Cplx d, Linear_form& re, Linear_form& im)
{
  re.terms.clear(); im.terms.clear();
  std::vector<std::pair<int, Cplx>> s = small;
  std::sort(s.begin(), s.end(), [](const std::pair<int, Cplx>& a, const std::pair<int, Cplx>& b) { return a.first < b.first; });
  for(const auto& t : s) {
    const Cplx w = t.second / d;   // Re(w Y) = w_r y_2k - w_i y_2k+1, Im(w Y) = w_i y_2k + w_r y_2k+1
    const double wr = std::round(w.real()), wi = std::round(w.imag());   // Gaussian integers
    if(wr != 0) re.terms.emplace_back(2 * t.first, wr);
    if(wi != 0) re.terms.emplace_back(2 * t.first + 1, -wi);
    if(wi != 0) im.terms.emplace_back(2 * t.first, wi);
    if(wr != 0) im.terms.emplace_back(2 * t.first + 1, wr);
  }
}

// The arcs of the T-mesh: per arc, its length as a form in y.
struct Separatrix_arcs
{
  std::vector<Linear_form> forms;
  // the whole length of every boundary run between corners, and of every separatrix that ends on
  // the boundary or at a singularity: at least 1 in a map that keeps this T-mesh (two corners, a cone and the
  // boundary, or two cones would fall on one point)
  std::vector<Linear_form> spans;
  // the T-mesh as a graph, for its faces (t_mesh_faces.h): per trace its nodes in order along it,
  // each a node id (a vertex's index, or a junction's from the number of vertices on) and the
  // trace's direction there in the node's own chart (at a vertex: the angle turned from its first
  // side in the map); the length of each arc between consecutive nodes; per node id, the period of
  // those angles (2 pi, a singularity's angle in the map, 0 on the boundary: no wrap)
  struct Stop { int node; double angle; };
  std::vector<std::vector<Stop>> stops;
  std::vector<std::vector<Linear_form>> arc_of;
  std::vector<double> period;
  std::size_t traces = 0;      // separatrices traced (boundary runs between corners included)
  std::size_t junctions = 0;   // nodes where a separatrix ends on another line or on the boundary
  std::size_t crossings = 0;   // triangles crossed, summed over the separatrices
};

// Traces the T-mesh of the seamless map whose corner images are image(x) (the corner at
// source(x) in face(x)) at the small unknowns y. `expected_angle` per vertex: its total angle in
// the map (winding.h). False with a message when the map is not locally injective around a node,
// a separatrix runs into a boundary vertex, or the lines do not all end within `crossings_per_face`
// triangle crossings per face of the mesh.
template <typename TM, typename CornerImage>
bool trace_separatrix_arcs(const Mesh_arrays<TM>& m, const Topology_arrays& topo, const Seam_layout& seams, const Corner_layout& layout,
                           const std::vector<double>& expected_angle, const CornerImage& image, const Eigen::VectorXd& y,
                           Separatrix_arcs& out, std::string& message, double crossings_per_face = 20)
{
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces();
  const double quarter = CGAL_PI / 2;
  const Cplx units[4] = {Cplx(1, 0), Cplx(0, 1), Cplx(-1, 0), Cplx(0, -1)};
  auto cross = [](Cplx a, Cplx b) { return a.real() * b.imag() - a.imag() * b.real(); };
  auto axis = [&](Cplx v) { return unit_power(int(std::lround(std::arg(v) / quarter))); };
  struct Forms { Linear_form iso, offset; double offset_value = 0; };   // along in the trace's first chart = Re(P / d) - offset
  struct Segment { int trace, forms, next; Cplx a, b, dir; };
  struct Node { double along; Linear_form form; int id = -1; double angle = 0; };   // angle: NaN at a run's last corner
  // p: where the trace enters its face; at a vertex (its start) the line runs `shift` to the left
  // of p (a symbolic perturbation: no line runs along an edge or through a vertex, where two
  // lines would meet unseen, a grid-aligned mesh's common case)
  struct Trace { int face = -1, forms = -1; Cplx p, d; double shift = 0, length = 0; std::vector<Node> nodes; bool spans = false; };
  std::vector<Forms> pool;
  std::vector<Segment> segments;
  std::vector<int> head(nf, -1), border_segment(m.number_of_edges(), -1);
  std::vector<Trace> traces;
  std::vector<double> total(nv, 0.);   // the map's angle at each singularity and corner
  const std::vector<Corner_expression>& corner = layout.corner;

  // the big part of e (a boundary vertex's position along its line) divided by d: none across d
  auto big_over = [&](const Corner_expression& e, Cplx d) {
    if(e.vertex < 0) return Cplx(0, 0);
    const Cplx bd = layout.big_dir[std::size_t(e.vertex)];
    return bd == Cplx(0, 0) ? Cplx(0, 1) : e.a * bd / d;
  };
  // the motion from face(h) into face(h ^ 1): P -> r P + tau; tau's small part in tau_small
  auto transition = [&](int h, Cplx& r, Cplx& tau, std::vector<std::pair<int, Cplx>>& tau_small) {
    const int h1 = h ^ 1;
    const Cplx pa = image(h), pb = image(m.next[std::size_t(h)]), qb = image(h1), qa = image(m.next[std::size_t(h1)]);
    const Cplx ratio = (qb - qa) / (pb - pa);
    r = axis(ratio);
    if(!(std::abs(ratio - r) < 1e-6)) return false;
    tau = qa - r * pa;
    tau_small.clear();
    if(!seams.cut[std::size_t(h >> 1)]) return true;
    Corner_expression t = corner[std::size_t(m.next[std::size_t(h1)])];
    for(const auto& s : corner[std::size_t(h)].small) t.add(s.first, -r * s.second);
    for(const auto& s : t.small) if(std::abs(s.second) > 1e-9) tau_small.push_back(s);
    return true;
  };
  // the forms after the motion (r, tau) takes the direction d to r d
  std::vector<std::pair<int, Cplx>> tau_small;
  Linear_form fre, fim;
  auto moved = [&](int forms, Cplx d_new, Cplx tau) {
    if(tau_small.empty()) return forms;
    Forms f = pool[std::size_t(forms)];
    small_part_forms(tau_small, d_new, fre, fim);
    f.iso.add(fim, 1);
    f.offset.add(fre, 1);
    f.offset_value += (tau / d_new).real();
    pool.push_back(std::move(f));
    return int(pool.size()) - 1;
  };
  // the axis directions leaving vertex v into the corner x's face, strictly inside its sector
  // (on its first side too where that side is a border edge), each with the room on its left
  // before side b (cross(d, b)): the line is shifted left by less
  auto directions_in_corner = [&](int x, std::vector<std::pair<Cplx, double>>& dirs) {
    dirs.clear();
    const Cplx p = image(x), a = image(m.next[std::size_t(x)]) - p, b = image(m.prev(x)) - p;
    const bool border_first = m.face[std::size_t(x ^ 1)] < 0;
    for(const Cplx& d : units) {
      const double ca = cross(a, d), cb = cross(d, b);
      // along side a within round-off: this corner's (the line runs on its left, inside); along b: the next one's
      if(cb > 1e-12 * std::abs(b) && (border_first ? ca > 1e-9 * std::abs(a) : ca >= -1e-12 * std::abs(a)) &&
         (std::real(d * std::conj(a)) > 0 || ca > 0))
        dirs.emplace_back(d, cb);
    }
  };
  auto start_node = [&](const Corner_expression& e, Cplx p, Cplx d) {
    Node n;
    small_part_forms(e.small, d, n.form, fim);
    n.along = (p / d).real();
    return n;
  };
  // 1. the boundary runs between corners, one trace each, following the interior halfedges
  for(const auto& loop : topo.loops) {
    const int n = int(loop.size());
    int start = -1;   // x_i = loop[i] ^ 1 runs from target(loop[i]) to source(loop[i]); walk i downwards
    for(int i = 0; i < n; ++i) if(seams.boundary_corner[std::size_t(m.source(loop[std::size_t(i)] ^ 1))]) { start = i; break; }
    if(start < 0) continue;   // a loop with no corner (a closed grid line): no run to split
    int tr = -1;
    Cplx dprev;
    int xprev = -1;
    for(int s = 0; s < n; ++s) {
      const int x = loop[std::size_t(((start - s) % n + n) % n)] ^ 1;
      const Corner_expression& es = corner[std::size_t(x)];
      const Cplx d = axis(image(m.next[std::size_t(x)]) - image(x));
      if(!(std::abs(big_over(es, d).imag()) < 1e-9)) { message = "a boundary edge is off its grid line in the seamless map"; return false; }
      Forms fo;
      small_part_forms(es.small, d, fre, fo.iso);
      if(seams.boundary_corner[std::size_t(m.source(x))]) {   // a new run
        tr = int(traces.size());
        traces.emplace_back();
        traces.back().nodes.push_back(start_node(es, image(x), d));
        traces.back().nodes.back().id = m.source(x);
      } else {   // along continues through source(x): offset += Re(e2 / d2) - Re(e1 / d1)
        const Corner_expression& e1 = corner[std::size_t(m.next[std::size_t(xprev)])];
        if(!(std::abs(big_over(e1, dprev).real() - big_over(es, d).real()) < 1e-9)) {
          message = "the boundary folds back at vertex " + std::to_string(m.source(x)) + " in the seamless map";
          return false;
        }
        fo.offset = pool[std::size_t(segments[std::size_t(border_segment[std::size_t(xprev >> 1)])].forms)].offset;
        fo.offset_value = pool[std::size_t(segments[std::size_t(border_segment[std::size_t(xprev >> 1)])].forms)].offset_value;
        Linear_form a1, i1;
        small_part_forms(e1.small, dprev, a1, i1);
        fo.offset.add(fre, 1);
        fo.offset.add(a1, -1);
        fo.offset_value += (image(x) / d).real() - (image(m.next[std::size_t(xprev)]) / dprev).real();
      }
      pool.push_back(std::move(fo));
      segments.push_back(Segment{tr, int(pool.size()) - 1, -1, image(x), image(m.next[std::size_t(x)]), d});
      border_segment[std::size_t(x >> 1)] = int(segments.size()) - 1;
      const int v_end = m.target[std::size_t(x)];
      if(seams.boundary_corner[std::size_t(v_end)]) {   // the run ends at the next corner
        const Forms& fx = pool.back();
        Node e = start_node(corner[std::size_t(m.next[std::size_t(x)])], image(m.next[std::size_t(x)]), d);
        e.form.add(fx.offset, -1);
        e.along -= fx.offset_value;
        e.id = v_end;
        e.angle = std::numeric_limits<double>::quiet_NaN();   // the run arrives along the corner's last side
        traces[std::size_t(tr)].nodes.push_back(std::move(e));
        traces[std::size_t(tr)].spans = true;
      }
      xprev = x;
      dprev = d;
    }
  }
  double extent = 0;   // the map's size, for the perturbation
  for(std::size_t f = 0; f < nf; ++f) extent = (std::max)(extent, std::abs(image(m.face_halfedge[f])));
  const double shift = 1e-9 * (1 + extent);
  // 2. the separatrices of the singularities and of the corners, all started at length 0
  typedef std::pair<double, int> Event;
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> queue;
  std::vector<std::pair<Cplx, double>> dirs;
  for(std::size_t v = 0; v < nv; ++v) {
    const bool border = m.is_boundary_vertex(int(v));
    if(!(border ? seams.boundary_corner[v] : seams.singular[v])) continue;
    const int expected = int(std::lround(expected_angle[v] / quarter)) - (border ? 1 : 0);
    int found = 0;
    const int x0 = m.vertex_out[v];
    double turned = 0;   // the map's angle from the first side to corner x
    for(int x = x0;;) {
      directions_in_corner(x, dirs);
      const Cplx side_a = image(m.next[std::size_t(x)]) - image(x);
      for(const auto& dc : dirs) {
        const Cplx d = dc.first;
        Trace t;
        t.face = m.face[std::size_t(x)];
        t.p = image(x);
        t.shift = (std::min)(shift, dc.second / 2);
        t.d = d;
        Forms fo;
        Linear_form along;
        small_part_forms(corner[std::size_t(x)].small, d, along, fo.iso);
        pool.push_back(std::move(fo));
        t.forms = int(pool.size()) - 1;
        t.nodes.push_back(start_node(corner[std::size_t(x)], t.p, d));
        t.nodes.back().id = int(v);
        t.nodes.back().angle = turned + (std::max)(0., std::arg(d / side_a));
        queue.emplace(0., int(traces.size()));
        traces.push_back(std::move(t));
        ++found;
      }
      turned += std::arg((image(m.prev(x)) - image(x)) / side_a);
      const int yv = m.prev(x);
      if(m.face[std::size_t(yv ^ 1)] < 0) break;
      x = yv ^ 1;
      if(x == x0) break;
    }
    total[v] = turned;
    if(found != expected) {
      message = "the seamless map is not locally injective around vertex " + std::to_string(v) + " (" + std::to_string(found) +
                " grid directions leave it, " + std::to_string(expected) + " expected)";
      return false;
    }
  }
  out.traces = traces.size();
  int next_id = int(nv);   // junctions' node ids
  // 3. the motorcycle graph: the shortest trace advances by one triangle at a time
  const std::size_t max_crossings = std::size_t(crossings_per_face * double(nf)) + 1000;
  auto junction = [&](int hit_trace, int hit_forms, Cplx dh, Trace& t, Cplx x) {   // t ends at x on a line of direction dh
    const double s = (dh / t.d).imag();   // dh = s i d
    const Forms& ft = pool[std::size_t(t.forms)];
    const Forms& fh = pool[std::size_t(hit_forms)];
    Node e;
    e.form.add(fh.iso, -s);
    e.form.add(ft.offset, -1);
    e.along = (x / t.d).real() - ft.offset_value;
    e.id = next_id;
    e.angle = std::arg(t.d);
    t.nodes.push_back(std::move(e));
    if(hit_trace >= 0) {
      Node j;
      j.form.add(ft.iso, s);
      j.form.add(fh.offset, -1);
      j.along = (x / dh).real() - fh.offset_value;
      j.id = next_id;
      j.angle = std::arg(dh);
      traces[std::size_t(hit_trace)].nodes.push_back(std::move(j));
    }
    ++next_id;
    ++out.junctions;
  };
  while(!queue.empty()) {
    const int ti = queue.top().second;
    queue.pop();
    if(++out.crossings > max_crossings) { message = "the separatrices did not end within " + std::to_string(max_crossings) + " triangle crossings"; return false; }
    Trace& t = traces[std::size_t(ti)];
    const int f = t.face;
    const int h0 = m.face_halfedge[std::size_t(f)];
    const int hs[3] = {h0, m.next[std::size_t(h0)], m.prev(h0)};
    const Cplx P[3] = {image(hs[0]), image(hs[1]), image(hs[2])};
    const double scale = std::abs(P[1] - P[0]) + std::abs(P[2] - P[0]);
    double sg[3];
    for(int c = 0; c < 3; ++c) {   // which side of the line each corner is on; on it within round-off
      sg[c] = cross(t.d, P[c] - t.p) - t.shift;
      if(std::abs(sg[c]) < 1e-14 * scale) sg[c] = 0;
    }
    const Cplx pl = t.p + Cplx(0, t.shift) * t.d;   // on the line
    t.shift = 0;
    int a = -1;
    for(int c = 0; c < 3; ++c) if(sg[c] <= 0 && sg[(c + 1) % 3] > 0) a = c;
    if(a < 0) { message = "a separatrix left its triangle (the seamless map folds)"; return false; }
    const int b = (a + 1) % 3;
    const double lambda = sg[a] / (sg[a] - sg[b]);
    Cplx x = P[a] + lambda * (P[b] - P[a]);
    const double s_exit = ((x - pl) / t.d).real();
    // the first line of another direction crossed before the exit
    double s_hit = s_exit + 1e-12 * scale;
    int hit = -1;
    for(int si = head[std::size_t(f)]; si >= 0; si = segments[std::size_t(si)].next) {
      const Segment& S = segments[std::size_t(si)];
      const double mu = (t.d / S.dir).imag();
      if(std::abs(mu) < 0.5) continue;   // parallel
      const double s = ((S.a / S.dir).imag() - (pl / S.dir).imag()) / mu;
      if(!(s > 1e-9 * scale) || !(s < s_hit)) continue;
      const double along = ((pl + s * t.d) / S.dir).real();
      if(along < (S.a / S.dir).real() - 1e-12 * scale || along > (S.b / S.dir).real() + 1e-12 * scale) continue;
      s_hit = s;
      hit = si;
    }
    const Cplx p0 = pl;
    if(hit >= 0) {
      x = pl + s_hit * t.d;
      const Segment S = segments[std::size_t(hit)];   // a copy: the push below may move the segments
      segments.push_back(Segment{ti, t.forms, head[std::size_t(f)], p0, x, t.d});
      head[std::size_t(f)] = int(segments.size()) - 1;
      junction(S.trace, S.forms, S.dir, t, x);
      continue;
    }
    segments.push_back(Segment{ti, t.forms, head[std::size_t(f)], p0, x, t.d});
    head[std::size_t(f)] = int(segments.size()) - 1;
    t.length += s_exit;
    const int vertex_corner = lambda < 1e-9 ? a : lambda > 1 - 1e-9 ? b : -1;
    if(vertex_corner >= 0) {   // through a vertex w: on into the face whose corner at w holds d
      const int xw = hs[vertex_corner], w = m.source(xw);
      if(seams.singular[std::size_t(w)]) {   // into a singularity
        Node e = start_node(corner[std::size_t(xw)], P[vertex_corner], t.d);
        e.form.add(pool[std::size_t(t.forms)].offset, -1);
        e.along -= pool[std::size_t(t.forms)].offset_value;
        e.id = next_id++;   // its direction into the singularity is not followed: no face closes here
        e.angle = std::arg(t.d);
        t.nodes.push_back(std::move(e));
        t.spans = true;
        ++out.junctions;
        continue;
      }
      if(m.is_boundary_vertex(w)) { message = "a separatrix runs into boundary vertex " + std::to_string(w); return false; }
      int xc = xw;
      bool found = false;
      for(int step = 0; step < 1000 && !found; ++step) {
        const int yv = m.prev(xc);
        Cplx r, tau;
        if(!transition(yv, r, tau, tau_small)) { message = "a seam's motion is not a grid symmetry in the seamless map"; return false; }
        t.d *= r;
        t.forms = moved(t.forms, t.d, tau);
        xc = yv ^ 1;
        directions_in_corner(xc, dirs);
        for(const auto& dc : dirs)
          if(std::abs(dc.first - t.d) < 1e-9) { found = true; t.shift = (std::min)(shift, dc.second / 2); }
        if(xc == xw && !found) break;
      }
      if(!found) { message = "no triangle around vertex " + std::to_string(w) + " continues a separatrix"; return false; }
      t.face = m.face[std::size_t(xc)];
      t.p = image(xc);
      queue.emplace(t.length, ti);
      continue;
    }
    const int h = hs[a];   // the exit edge, from corner a to corner b
    if(m.face[std::size_t(h ^ 1)] < 0) {   // the boundary
      t.spans = true;
      const int bs = border_segment[std::size_t(h >> 1)];
      if(bs >= 0) junction(segments[std::size_t(bs)].trace, segments[std::size_t(bs)].forms, segments[std::size_t(bs)].dir, t, x);
      else {   // a loop with no corner: its line's form from the edge's corner
        const Cplx d = axis(P[b] - P[a]);
        Forms fo;
        small_part_forms(corner[std::size_t(h)].small, d, fre, fo.iso);
        pool.push_back(std::move(fo));
        junction(-1, int(pool.size()) - 1, d, t, x);
      }
      continue;
    }
    Cplx r, tau;
    if(!transition(h, r, tau, tau_small)) { message = "a seam's motion is not a grid symmetry in the seamless map"; return false; }
    t.d *= r;
    t.p = r * x + tau;
    t.forms = moved(t.forms, t.d, tau);
    t.face = m.face[std::size_t(h ^ 1)];
    queue.emplace(t.length, ti);
  }
  // 4. the arcs: consecutive nodes along each trace, checked against the seamless map; the spans:
  // first to last node of the traces that end on the boundary or at a singularity
  auto length_form = [&](const Node& from, const Node& to, Linear_form& l) {
    l = to.form;
    l.add(from.form, -1);
    const double value = to.along - from.along;
    if(std::abs(l(y) - value) <= 1e-6 * (1 + std::abs(value))) return true;
    message = "an arc of the T-mesh measures " + std::to_string(value) + " in the seamless map but its form gives " + std::to_string(l(y));
    return false;
  };
  out.period.assign(std::size_t(next_id), 2 * CGAL_PI);
  for(std::size_t v = 0; v < nv; ++v) out.period[v] = m.is_boundary_vertex(int(v)) ? 0. : total[v];
  for(Trace& t : traces) {
    std::sort(t.nodes.begin(), t.nodes.end(), [](const Node& p, const Node& q) { return p.along < q.along; });
    out.stops.emplace_back();
    out.arc_of.emplace_back();
    for(const Node& n : t.nodes)   // a run's last corner: the way back along its last side, at its whole angle
      out.stops.back().push_back({n.id, std::isnan(n.angle) ? total[std::size_t(n.id)] - CGAL_PI : n.angle});
    Linear_form l;
    for(std::size_t i = 0; i + 1 < t.nodes.size(); ++i) {
      if(!length_form(t.nodes[i], t.nodes[i + 1], l)) return false;
      out.arc_of.back().push_back(l);
      if(!l.terms.empty()) out.forms.push_back(std::move(l));
    }
    if(t.spans && t.nodes.size() >= 2) {
      if(!length_form(t.nodes.front(), t.nodes.back(), l)) return false;
      if(!l.terms.empty()) out.spans.push_back(std::move(l));
    }
  }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_GRAPH_H
