// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Flat cone metrics by discrete conformal vertex scaling (compute_cone_metric) and planar layout
// of flat disks (lay_out_disk), for Surface_mesh and Polyhedron_3. Every converged result is
// checked independently: curvature of the output metric recomputed by compute_vertex_curvatures,
// strict triangle inequalities on every face, Levi-Civita holonomy of the output metric around
// non-cone vertices = 0 mod 2pi. Cases: flat tori (generated and genus-1 shared meshes), flat
// cylinder, 8 cones of pi/2 on genus-0 meshes, one -4pi cone on genus-2 meshes, random
// chi-consistent cone sets, a rectangle from a disk (layout without flips, 4 corners),
// exact reproduction at u = 0, Gauss-Bonnet violations and other bad input.
// Cases that do not converge on the fixed triangulation must say so in the status; they are
// listed in the output as "NOT CONVERGED".
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/Eigen_sparse_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>

#include <algorithm>
#include <map>
#include <set>

#include "test_util.h"
#include "mesh_generators.h"

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

static std::vector<std::string> not_converged;

template <typename Mesh>
struct Tests
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef std::map<vertex_descriptor, double> Cones;
  std::mt19937 rng{7};

  // Checks a metric `len` on `tri` (the input mesh, or a copy of the intrinsic triangulation,
  // whose i-th vertex is the input's i-th): strict triangle inequalities, area, curvature of
  // every vertex recomputed by compute_vertex_curvatures against `target` (by vertex index),
  // Levi-Civita holonomy around non-cone interior vertices = 0 mod 2pi (sampled on large meshes)
  // and around cones = the cone's curvature. Both to 1e-9 (relative to the cone angle where it
  // exceeds 2 pi) plus the rounding level of the vertex's angle sum: the first-order change of
  // its angles, 2A d theta_m = l_m (l_m d_m - l_p cos theta_q d_p - l_q cos theta_p d_q) for
  // relative length changes d of 2^-53 (4 + max |u| of the triangle) (the documented bound
  // replaces the cosines by 1: this one is tighter).
  template <typename Tri, typename LengthMap>
  void check_metric(const Tri& tri, LengthMap len, const std::vector<double>& target, const std::vector<double>& u,
                    const std::vector<char>& is_cone, double area_in, bool converged, const std::string& what)
  {
    typedef boost::graph_traits<Tri> TGT;
    bool valid = true;
    double area = 0;
    std::vector<double> rounding(num_vertices(tri), 0.);
    auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tri);
    std::size_t i = 0;
    for(auto v : vertices(tri)) put(index, v, i++);
    for(auto f : faces(tri)) {
      typename TGT::halfedge_descriptor h = halfedge(f, tri);
      const std::array<typename TGT::halfedge_descriptor, 3> hs = {{h, next(h, tri), next(next(h, tri), tri)}};
      double l[3], um = 0;
      for(int j = 0; j < 3; ++j) {
        l[j] = get(len, edge(hs[j], tri));
        um = (std::max)(um, std::abs(u[get(index, CGAL::target(hs[j], tri))]));
      }
      if(!SMDF::is_valid_triangle(l[0], l[1], l[2])) { valid = false; continue; }
      const double a2 = 2 * SMDF::triangle_area(l[0], l[1], l[2]);
      area += a2 / 2;
      double cosine[3];   // of the angle opposite side j
      for(int j = 0; j < 3; ++j) {
        const double p = l[(j + 1) % 3], q = l[(j + 2) % 3];
        cosine[j] = (p * p + q * q - l[j] * l[j]) / (2 * p * q);
      }
      const double d = std::ldexp(4 + um, -53);
      for(int m = 0; m < 3; ++m) {   // the corner opposite side m is at the target of hs[m + 1]
        const int p = (m + 1) % 3, q = (m + 2) % 3;
        rounding[get(index, CGAL::target(hs[p], tri))] +=
            d * l[m] * (l[m] + l[p] * std::abs(cosine[q]) + l[q] * std::abs(cosine[p])) / a2;
      }
    }
    SMDF_CHECK_MSG(valid, what << ": triangle inequalities");
    // area normalisation (all test meshes have one component)
    SMDF_CHECK_MSG(std::abs(area - area_in) <= 1e-10 * area_in, what << ": total area preserved " << area_in << " " << area);
    if(!converged || !valid) return;
    auto k = get(CGAL::dynamic_vertex_property_t<double>(), tri);
    SMDF::compute_vertex_curvatures(tri, k, SMDF::parameters::edge_length_map(len));
    double kerr = 0;
    i = 0;
    for(auto v : vertices(tri)) {
      kerr = (std::max)(kerr, (std::abs(get(k, v) - target[i]) - rounding[i]) / (std::max)(1., 1 - target[i] / (2 * M_PI)));
      ++i;
    }
    SMDF_CHECK_MSG(kerr <= 1e-9, what << ": curvature of the output metric, error " << kerr);
    SMDF::Intrinsic_holonomy<Tri> hol(tri, SMDF::parameters::edge_length_map(len));
    double herr = 0;
    std::size_t n = 0, stride = (std::max<std::size_t>)(1, num_vertices(tri) / 3000);
    i = 0;
    for(auto v : vertices(tri)) {
      const std::size_t vi = i++;
      if(halfedge(v, tri) == TGT::null_halfedge() || is_border(v, tri) || (vi % stride != 0 && !is_cone[vi]))
        continue;   // isolated, boundary, or not sampled
      const double hv = hol.levi_civita_holonomy(hol.dual_cycle_around_vertex(v));
      herr = (std::max)(herr, (std::abs(smdf_test::wrap(hv - (is_cone[vi] ? target[vi] : 0.))) - rounding[vi]) /
                                  (std::max)(1., 1 - target[vi] / (2 * M_PI)));
      ++n;
    }
    SMDF_CHECK_MSG(herr <= 1e-9, what << ": holonomy around " << n << " vertices, error " << herr);
  }

  // Runs compute_cone_metric with targets `cones` (0 elsewhere) and checks the result, on the
  // input mesh or, when the flow flipped edges, on a copy of the intrinsic triangulation.
  // Returns true if it converged.
  template <typename LengthMap>
  bool run(const Mesh& mesh, const Cones& cones, LengthMap out, const std::string& what,
           int max_iterations = 200, bool flips = true, bool input_first = true)
  {
    auto tgt = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    for(auto v : vertices(mesh)) put(tgt, v, 0.);
    for(const auto& c : cones) put(tgt, c.first, c.second);
    auto ufac = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    int calls = 0, last_it = -1;
    double last_err = -1;
    SMDF::Cone_metric_status st = SMDF::compute_cone_metric(
        mesh, tgt, out,
        SMDF::parameters::conformal_factor_map(ufac).number_of_iterations(max_iterations)
            .intrinsic_edge_flips(flips).input_triangulation_first(input_first)
            .visitor([&](int it, double err) { ++calls; last_it = it; last_err = err; }));
    std::cout << what << ": converged " << st.converged << ", " << st.iterations << " iterations, error "
              << st.max_curvature_error << ", " << st.seconds << " s";
    if(st.triangulation_changed)
      std::cout << ", intrinsic triangulation (" << st.edge_flips << " flips, "
                << st.intrinsic_triangulation.number_of_new_edges() << " new edges)";
    std::cout << (st.message.empty() ? "" : ", ") << st.message << std::endl;
    SMDF_CHECK_MSG(calls == st.iterations + 1 && last_it == st.iterations, what << ": visitor calls " << calls);
    SMDF_CHECK_MSG(last_err >= 0, what << ": visitor error");
    SMDF_CHECK_MSG(flips || (st.edge_flips == 0 && !st.triangulation_changed), what << ": flips disabled");
    SMDF_CHECK_MSG(st.triangulation_changed == !st.intrinsic_triangulation.empty(), what << ": triangulation iff changed");
    if(!st.converged) {
      SMDF_CHECK_MSG(!st.message.empty(), what << ": non-convergence has a message");
      if(what.find("1 iteration") == std::string::npos) not_converged.push_back(what + ": " + st.message);
    } else {
      SMDF_CHECK_MSG(st.message.empty() && st.max_curvature_error <= 1e-10 * (1 + max_cone_angle(cones) / (2 * M_PI)), what << ": " << st.max_curvature_error);
    }
    std::vector<vertex_descriptor> vs(vertices(mesh).begin(), vertices(mesh).end());
    std::vector<double> tv, uv;
    std::vector<char> is_cone;
    for(auto v : vs) {
      tv.push_back(get(tgt, v));
      uv.push_back(get(ufac, v));
      is_cone.push_back(cones.count(v) ? 1 : 0);
    }
    auto l0 = SMDF::get_edge_length_map(mesh);
    double area_in = 0;
    for(auto f : faces(mesh)) {
      halfedge_descriptor h = halfedge(f, mesh);
      area_in += SMDF::triangle_area(get(l0, edge(h, mesh)), get(l0, edge(next(h, mesh), mesh)),
                                     get(l0, edge(next(next(h, mesh), mesh), mesh)));
    }
    double ferr = 0;   // conformal factors reproduce the lengths of the input edges
    if(!st.triangulation_changed) {
      for(auto e : edges(mesh)) {
        const double l = get(l0, e) * std::exp(0.5 * (get(ufac, source(e, mesh)) + get(ufac, target(e, mesh))));
        ferr = (std::max)(ferr, std::abs(l - get(out, e)) / l);
      }
      check_metric(mesh, out, tv, uv, is_cone, area_in, st.converged, what);
    } else {
      const SMDF::Intrinsic_triangulation& it = st.intrinsic_triangulation;
      SMDF_CHECK(it.number_of_vertices() == num_vertices(mesh) && it.number_of_faces() == num_faces(mesh));
      std::vector<edge_descriptor> es(edges(mesh).begin(), edges(mesh).end());
      std::vector<char> kept(es.size(), 0);
      bool ends_ok = true;
      for(std::size_t e = 0; e < it.number_of_edges(); ++e) {
        const long ie = it.input_edge(int(e));
        if(ie < 0) continue;
        kept[ie] = 1;
        const double l = get(l0, es[ie]) * std::exp(0.5 * (get(ufac, source(es[ie], mesh)) + get(ufac, target(es[ie], mesh))));
        ferr = (std::max)(ferr, std::abs(l - it.length(int(e))) / l);
        ferr = (std::max)(ferr, std::abs(get(out, es[ie]) - it.length(int(e))) / l);
        const std::size_t a = std::size_t(it.source(2 * int(e))), b = std::size_t(it.target(2 * int(e)));
        const vertex_descriptor c = source(es[ie], mesh), d = target(es[ie], mesh);
        ends_ok = ends_ok && ((vs[a] == c && vs[b] == d) || (vs[a] == d && vs[b] == c));
      }
      SMDF_CHECK_MSG(ends_ok, what << ": input edges of the intrinsic triangulation join the same vertices");
      bool nan_ok = true;
      for(std::size_t e = 0; e < es.size(); ++e) nan_ok = nan_ok && (kept[e] == !std::isnan(get(out, es[e])));
      SMDF_CHECK_MSG(nan_ok, what << ": output lengths NaN exactly on the flipped-away input edges");
      Surface_mesh tri;
      auto tl = tri.template add_property_map<Surface_mesh::Edge_index, double>("e:length", 0.).first;
      SMDF::copy_intrinsic_triangulation(it, mesh, tri, tl);
      SMDF_CHECK_MSG(tri.is_valid(false), what << ": copied intrinsic triangulation is a valid halfedge structure");
      check_metric(tri, tl, tv, uv, is_cone, area_in, st.converged, what + " (intrinsic)");
    }
    SMDF_CHECK_MSG(ferr < 1e-12, what << ": conformal factors give the lengths, rel. error " << ferr);
    return st.converged;
  }

  // vertex -> component (through shared edges)
  std::map<vertex_descriptor, int> components(const Mesh& mesh, int& count)
  {
    std::map<vertex_descriptor, int> comp;
    count = 0;
    for(auto v : vertices(mesh)) {
      if(comp.count(v) || halfedge(v, mesh) == GT::null_halfedge()) continue;
      std::vector<vertex_descriptor> stack(1, v);
      comp[v] = count;
      while(!stack.empty()) {
        vertex_descriptor w = stack.back();
        stack.pop_back();
        for(auto h : CGAL::halfedges_around_target(w, mesh)) {
          vertex_descriptor x = source(h, mesh);
          if(!comp.count(x)) { comp[x] = count; stack.push_back(x); }
        }
      }
      ++count;
    }
    return comp;
  }

  // Targets of the shared-mesh sweep, per component (see main()).
  Cones standard_targets(const Mesh& mesh)
  {
    int nc = 0;
    const auto comp = components(mesh, nc);
    std::vector<long> nv(nc, 0), ne(nc, 0), nf(nc, 0), nb(nc, 0);
    for(const auto& x : comp) { ++nv[x.second]; if(is_border(x.first, mesh)) ++nb[x.second]; }
    for(auto e : edges(mesh)) ++ne[comp.at(source(e, mesh))];
    for(auto f : faces(mesh)) ++nf[comp.at(target(halfedge(f, mesh), mesh))];
    Cones c;
    for(int i = 0; i < nc; ++i) {
      const long chi = nv[i] - ne[i] + nf[i];
      if(nb[i] > 0) {
        for(const auto& x : comp)
          if(x.second == i && is_border(x.first, mesh)) c[x.first] = 2 * M_PI * double(chi) / double(nb[i]);
      } else if(chi == 2) {
        const Cones e = extreme_cones(mesh, M_PI / 2, &comp, i);
        c.insert(e.begin(), e.end());
      } else if(chi < 0) {
        std::size_t best = 0;
        vertex_descriptor bv = comp.begin()->first;
        for(const auto& x : comp)
          if(x.second == i && degree(x.first, mesh) > best) { best = degree(x.first, mesh); bv = x.first; }
        c[bv] = 2 * M_PI * double(chi);
      }
    }
    return c;
  }

  std::string describe(const Mesh& mesh, const Cones& c)
  {
    std::size_t interior = 0, border = 0;
    double kmin = 0;
    for(const auto& x : c) {
      if(is_border(x.first, mesh)) ++border;
      else { ++interior; kmin = (std::min)(kmin, x.second); }
    }
    std::ostringstream os;
    if(c.empty()) os << "flat";
    else {
      os << interior << " cones";
      if(kmin < -1) os << " (min " << kmin / M_PI << " pi)";
      if(border) os << ", " << border << " boundary vertices with prescribed geodesic curvature";
    }
    return os.str();
  }

  // Cones of index >= 1 (`big`, target >= 2 pi) punched as holes: checks the status, NaN exactly
  // on the edges inside the holes, and the curvature of the output on the holed surface, recomputed
  // from the lengths: geodesic curvature (K_w + (K_v - 2 pi) / d) at the ring of each hole.
  void punched(const Mesh& mesh, const Cones& cones, const std::string& what)
  {
    auto tgt = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    for(auto v : vertices(mesh)) put(tgt, v, 0.);
    for(const auto& c : cones) put(tgt, c.first, c.second);
    auto out = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    SMDF::Cone_metric_status st = SMDF::compute_cone_metric(mesh, tgt, out);
    std::cout << what << ": converged " << st.converged << ", " << st.iterations << " iterations, error "
              << st.max_curvature_error << ", " << st.punched_vertices.size() << " hole(s)"
              << (st.triangulation_changed ? ", intrinsic triangulation" : "") << std::endl;
    std::map<vertex_descriptor, std::size_t> index;
    for(auto v : vertices(mesh)) index.emplace(v, index.size());
    std::set<vertex_descriptor> big;
    for(const auto& c : cones) if(c.second >= 2 * M_PI) big.insert(c.first);
    std::vector<std::size_t> expected;
    for(auto v : big) expected.push_back(index[v]);
    std::sort(expected.begin(), expected.end());
    SMDF_CHECK_MSG(st.converged && st.punched_vertices == expected, what << ": punched " << st.punched_vertices.size());
    if(!st.converged) return;
    std::map<vertex_descriptor, double> ring_kappa;
    for(auto v : big) {
      const double d = double(degree(v, mesh));
      for(auto h : CGAL::halfedges_around_target(v, mesh)) ring_kappa[source(h, mesh)] = (get(tgt, v) - 2 * M_PI) / d;
    }
    if(st.triangulation_changed) {   // holed intrinsic triangulation: punched vertices isolated
      Surface_mesh tri;
      auto tl = tri.add_property_map<Surface_mesh::Edge_index, double>("e:length", 0.).first;
      SMDF::copy_intrinsic_triangulation(st.intrinsic_triangulation, mesh, tri, tl);
      auto k = tri.add_property_map<Surface_mesh::Vertex_index, double>("v:k", 0.).first;
      SMDF::compute_vertex_curvatures(tri, k, SMDF::parameters::edge_length_map(tl));
      double err = 0;
      std::size_t i = 0;
      for(auto v : vertices(mesh)) {
        const Surface_mesh::Vertex_index w(Surface_mesh::size_type(i++));
        if(big.count(v)) { SMDF_CHECK(tri.is_isolated(w)); continue; }
        const double expect = get(tgt, v) + (ring_kappa.count(v) ? ring_kappa[v] : 0.);
        err = (std::max)(err, std::abs(k[w] - expect));
      }
      SMDF_CHECK_MSG(err <= 1e-9, what << ": curvature on the holed intrinsic triangulation, error " << err);
      return;
    }
    bool nan_ok = true;
    for(auto e : edges(mesh)) {
      const bool spoke = big.count(source(e, mesh)) || big.count(target(e, mesh));
      nan_ok = nan_ok && (spoke == std::isnan(get(out, e)));
    }
    SMDF_CHECK_MSG(nan_ok, what << ": NaN exactly on the edges inside the holes");
    std::map<vertex_descriptor, double> angle_sum;
    bool valid = true;
    for(auto f : faces(mesh)) {
      halfedge_descriptor h = halfedge(f, mesh);
      vertex_descriptor a = source(h, mesh), b = target(h, mesh), c = target(next(h, mesh), mesh);
      if(big.count(a) || big.count(b) || big.count(c)) continue;
      const double lab = get(out, edge(h, mesh)), lbc = get(out, edge(next(h, mesh), mesh)),
                   lca = get(out, edge(prev(h, mesh), mesh));
      valid = valid && SMDF::is_valid_triangle(lab, lbc, lca);
      angle_sum[a] += SMDF::corner_angle(lbc, lab, lca);
      angle_sum[b] += SMDF::corner_angle(lca, lab, lbc);
      angle_sum[c] += SMDF::corner_angle(lab, lbc, lca);
    }
    SMDF_CHECK_MSG(valid, what << ": triangle inequalities");
    double err = 0;
    for(const auto& x : angle_sum) {
      const bool border = is_border(x.first, mesh) || ring_kappa.count(x.first);
      const double k = (border ? M_PI : 2 * M_PI) - x.second;
      const double expect = get(tgt, x.first) + (ring_kappa.count(x.first) ? ring_kappa[x.first] : 0.);
      err = (std::max)(err, std::abs(k - expect));
    }
    SMDF_CHECK_MSG(err <= 1e-9, what << ": curvature on the holed surface, error " << err);
  }

  static double max_cone_angle(const Cones& c)
  {
    double a = 0;
    for(const auto& x : c) a = (std::max)(a, 2 * M_PI - x.second);
    return a;
  }

  Cones extreme_cones(const Mesh& mesh, double k, const std::map<vertex_descriptor, int>* comp = nullptr, int which = 0)
  {
    Cones c;
    for(int sx = -1; sx <= 1; sx += 2)
      for(int sy = -1; sy <= 1; sy += 2)
        for(int sz = -1; sz <= 1; sz += 2) {
          double best = -1e300;
          vertex_descriptor bv = GT::null_vertex();
          for(auto v : vertices(mesh)) {
            if(c.count(v) || is_border(v, mesh)) continue;
            if(comp && (!comp->count(v) || comp->at(v) != which)) continue;
            const auto& p = get(CGAL::vertex_point, mesh, v);
            const double d = sx * p.x() + sy * p.y() + sz * p.z();
            if(d > best) { best = d; bv = v; }
          }
          if(bv != GT::null_vertex()) c[bv] = k;
        }
    // fewer than 8 vertices: share 4 pi
    if(c.size() < 8)
      for(auto& x : c) x.second = 4 * M_PI / double(c.size());
    return c;
  }

  // random cones, multiples of pi/2 in [-pi, 3pi/2], summing to 2 pi chi
  Cones random_cones(const Mesh& mesh, long chi)
  {
    std::vector<vertex_descriptor> vs(vertices(mesh).begin(), vertices(mesh).end());
    std::shuffle(vs.begin(), vs.end(), rng);
    Cones c;
    long units = 4 * chi;   // in units of pi/2
    std::size_t next = 0;
    const int extra = int(rng() % 4);
    for(int i = 0; i < extra; ++i) {   // pairs that cancel: +a, -a
      const long a = 1 + long(rng() % 2);
      c[vs[next++]] = a * M_PI / 2;
      c[vs[next++]] = -a * M_PI / 2;
    }
    while(units != 0) {
      long step = units > 0 ? 1 + long(rng() % 3) : -1 - long(rng() % 2);
      if((units > 0 && step > units) || (units < 0 && step < units)) step = units;
      c[vs[next++]] = step * M_PI / 2;
      units -= step;
    }
    return c;
  }

  template <typename LengthMap>
  bool lengths_equal(const Mesh& mesh, LengthMap a)
  {
    auto l0 = SMDF::get_edge_length_map(mesh);
    for(auto e : edges(mesh)) if(get(a, e) != get(l0, e)) return false;
    return true;
  }

  void generated(const Mesh& torus, const Mesh& cyl, const std::string& suffix)
  {
    auto out = get(CGAL::dynamic_edge_property_t<double>(), torus);
    SMDF_CHECK(run(torus, Cones(), out, "generated torus, flat" + suffix));
    // exact reproduction at u = 0: targets = curvature of the input
    {
      auto k = get(CGAL::dynamic_vertex_property_t<double>(), torus);
      SMDF::compute_vertex_curvatures(torus, k);
      auto out2 = get(CGAL::dynamic_edge_property_t<double>(), torus);
      SMDF::Cone_metric_status st = SMDF::compute_cone_metric(torus, k, out2);
      SMDF_CHECK(st.converged && st.iterations == 0);
      SMDF_CHECK_MSG(lengths_equal(torus, out2), "u = 0 reproduces the input lengths exactly" << suffix);
    }
    // torus with a +pi/2 / -pi/2 pair
    {
      Cones c;
      auto it = vertices(torus).begin();
      c[*it] = M_PI / 2;
      std::advance(it, num_vertices(torus) / 2 + 7);
      c[*it] = -M_PI / 2;
      SMDF_CHECK(run(torus, c, out, "generated torus, cone pair" + suffix));
    }
    // iteration budget exhausted: reported, not hidden
    {
      Cones c;
      auto it = vertices(torus).begin();
      c[*it] = M_PI / 2;
      std::advance(it, num_vertices(torus) / 2 + 7);
      c[*it] = -M_PI / 2;
      SMDF_CHECK(!run(torus, c, out, "generated torus, cone pair, 1 iteration" + suffix, 1));
    }
    // a cone of -3.99 pi at a vertex of valence 6: not realisable by vertex scaling on this
    // triangulation (the status must say so when flips are disabled), realised with flips
    {
      Cones c;
      auto it = vertices(torus).begin();
      c[*it] = -3.99 * M_PI;
      std::advance(it, 150);
      c[*it] = 1.995 * M_PI;
      std::advance(it, 200);
      c[*it] = 1.995 * M_PI;
      auto tgt = get(CGAL::dynamic_vertex_property_t<double>(), torus);
      for(auto v : vertices(torus)) put(tgt, v, 0.);
      for(const auto& x : c) put(tgt, x.first, x.second);
      SMDF::Cone_metric_status st = SMDF::compute_cone_metric(torus, tgt, out, SMDF::parameters::intrinsic_edge_flips(false));
      std::cout << "generated torus, cone -3.99pi at valence 6, no flips: converged " << st.converged << ", "
                << st.iterations << " iterations, error " << st.max_curvature_error << ", " << st.message << std::endl;
      SMDF_CHECK_MSG(!st.converged && st.message.find("cannot carry") != std::string::npos,
                     "infeasible target reported: " << st.message);
      bool valid = true;
      for(auto f : faces(torus)) {
        halfedge_descriptor h = halfedge(f, torus);
        valid = valid && SMDF::is_valid_triangle(get(out, edge(h, torus)), get(out, edge(next(h, torus), torus)),
                                                 get(out, edge(next(next(h, torus), torus), torus)));
      }
      SMDF_CHECK_MSG(valid, "the last iterate of a failed flow is a valid metric");
      SMDF_CHECK(run(torus, c, out, "generated torus, cone -3.99pi at valence 6, with flips" + suffix));
    }
    // a cone of index +1 (a hole with geodesic boundary) and one of index -1
    {
      Cones c;
      c[*vertices(torus).begin()] = 2 * M_PI;
      c[*std::next(vertices(torus).begin(), 300)] = -2 * M_PI;
      punched(torus, c, "generated torus, cones of index +1 (hole) and -1" + suffix);
    }
    // cylinder: straight boundary loops, flat
    auto outc = get(CGAL::dynamic_edge_property_t<double>(), cyl);
    SMDF_CHECK(run(cyl, Cones(), outc, "generated cylinder, flat with geodesic boundary" + suffix));
  }

  void bad_input(const Mesh& torus, const Mesh& cyl)
  {
    auto out = get(CGAL::dynamic_edge_property_t<double>(), torus);
    auto target = get(CGAL::dynamic_vertex_property_t<double>(), torus);
    auto reset = [&]() { for(auto v : vertices(torus)) put(target, v, 0.); };
    auto expect = [&](SMDF::Input_error::Kind kind, const std::vector<std::string>& words, const std::string& what) {
      try {
        SMDF::compute_cone_metric(torus, target, out);
        SMDF_CHECK_MSG(false, what << ": no exception");
      } catch(const SMDF::Input_error& e) {
        bool has = e.kind() == kind;
        for(const auto& w : words) has = has && std::string(e.what()).find(w) != std::string::npos;
        SMDF_CHECK_MSG(has, what << ": " << e.what());
      }
    };
    reset();
    put(target, *vertices(torus).begin(), M_PI / 2);
    expect(SMDF::Input_error::INCONSISTENT_INDICES, {"Gauss-Bonnet", "1.5707963267948", "2*pi*chi = 0", "component 0"},
           "Gauss-Bonnet violation on a torus");
    reset();
    {   // two adjacent cones of index 1: their holes would overlap
      vertex_descriptor v0 = *vertices(torus).begin();
      vertex_descriptor v1 = source(halfedge(v0, torus), torus);
      put(target, v0, 2 * M_PI);
      put(target, v1, 2 * M_PI);
      put(target, *std::next(vertices(torus).begin(), 300), -4 * M_PI);
      expect(SMDF::Input_error::INVALID_ARGUMENT, {"cannot punch a hole", "another such cone"}, "adjacent cones of index 1");
    }
    reset();
    put(target, *vertices(torus).begin(), std::nan(""));
    expect(SMDF::Input_error::INVALID_ARGUMENT, {"not finite"}, "NaN target");
    reset();
    try {
      SMDF::compute_cone_metric(torus, target, out, SMDF::parameters::curvature_tolerance(-1.));
      SMDF_CHECK_MSG(false, "negative tolerance accepted");
    } catch(const SMDF::Input_error& e) { SMDF_CHECK(e.kind() == SMDF::Input_error::INVALID_ARGUMENT); }
    // lay_out_disk on a cylinder: not a disk
    auto uv = get(CGAL::dynamic_vertex_property_t<SMDF::Point_2>(), cyl);
    try {
      SMDF::lay_out_disk(cyl, SMDF::get_edge_length_map(cyl), uv);
      SMDF_CHECK_MSG(false, "lay_out_disk accepted a cylinder");
    } catch(const SMDF::Input_error& e) { SMDF_CHECK_MSG(std::string(e.what()).find("2 boundary loop") != std::string::npos, e.what()); }
  }

  // n corners of 2 pi / n at equal steps along the boundary loop, straight sides: a rectangle
  // (n = 4), an equilateral triangle (n = 3)
  void rectangle(const Mesh& mesh, const std::string& what, int n = 4)
  {
    const std::string shape = n == 4 ? ", rectangle" : n == 3 ? ", equilateral triangle" : ", polygon";
    halfedge_descriptor b = GT::null_halfedge();
    for(auto h : halfedges(mesh)) if(is_border(h, mesh)) { b = h; break; }
    std::vector<vertex_descriptor> loop;
    halfedge_descriptor h = b;
    do { loop.push_back(target(h, mesh)); h = next(h, mesh); } while(h != b);
    Cones c;
    for(int i = 0; i < n; ++i) c[loop[i * loop.size() / n]] = 2 * M_PI / n;
    auto out = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    const bool converged = run(mesh, c, out, what + shape, 200, false);
    SMDF_CHECK_MSG(converged, what << shape << ": converged without flips");
    if(!converged) return;
    auto uv = get(CGAL::dynamic_vertex_property_t<SMDF::Point_2>(), mesh);
    const bool ok = SMDF::lay_out_disk(mesh, out, uv);
    SMDF_CHECK_MSG(ok, what << ": layout without flipped triangles");
    double min_area = 1e300, lerr = 0, lmax = 0;
    for(auto f : faces(mesh)) {
      halfedge_descriptor g = halfedge(f, mesh);
      const auto& p = get(uv, source(g, mesh));
      const auto& q = get(uv, target(g, mesh));
      const auto& r = get(uv, target(next(g, mesh), mesh));
      min_area = (std::min)(min_area, CGAL::area(p, q, r));
    }
    for(auto e : edges(mesh)) {
      const double d = std::sqrt(CGAL::squared_distance(get(uv, source(e, mesh)), get(uv, target(e, mesh))));
      lerr = (std::max)(lerr, std::abs(d - get(out, e)));
      lmax = (std::max)(lmax, get(out, e));
    }
    SMDF_CHECK_MSG(min_area > 0, what << ": min signed area " << min_area);
    SMDF_CHECK_MSG(lerr <= 1e-8 * lmax * std::sqrt(double(num_faces(mesh))), what << ": layout edge length error " << lerr);
    // turning of the laid-out boundary polygon: n corners of 2 pi / n, straight elsewhere
    int corners = 0;
    std::vector<SMDF::Point_2> corner_points;
    double straight = 0, corner_err = 0;
    for(std::size_t i = 0; i < loop.size(); ++i) {
      // the border halfedges run clockwise around the disk; walk it reversed (counterclockwise)
      const auto& p = get(uv, loop[(i + 1) % loop.size()]);
      const auto& q = get(uv, loop[i]);
      const auto& r = get(uv, loop[(i + loop.size() - 1) % loop.size()]);
      const double turn = std::atan2((q.x() - p.x()) * (r.y() - q.y()) - (q.y() - p.y()) * (r.x() - q.x()),
                                     (q.x() - p.x()) * (r.x() - q.x()) + (q.y() - p.y()) * (r.y() - q.y()));
      if(std::abs(turn) > 1e-6) {
        ++corners;
        corner_err = (std::max)(corner_err, std::abs(turn - 2 * M_PI / n));
        corner_points.push_back(q);
      }
      else straight = (std::max)(straight, std::abs(turn));
    }
    SMDF_CHECK_MSG(corners == n && corner_err < 1e-7, what << shape << ": layout boundary has " << corners
                   << " corners, corner error " << corner_err << ", straight turning " << straight);
    if(n == 3 && corners == 3) {
      double side[3];
      for(int i = 0; i < 3; ++i)
        side[i] = std::sqrt(CGAL::squared_distance(corner_points[i], corner_points[(i + 1) % 3]));
      const double spread = (std::max)({side[0], side[1], side[2]}) - (std::min)({side[0], side[1], side[2]});
      SMDF_CHECK_MSG(spread <= 1e-7 * side[0], what << shape << ": sides " << side[0] << " " << side[1] << " " << side[2]);
    }
  }
};

// Other SparseCholeskySolver models (Eigen's LDLT, CGAL's Eigen_solver_traits) and a shared
// Intrinsic_mesh give the metric of the default CHOLMOD solve; the shared mesh is not rebuilt.
template <typename Mesh>
void solver_policy(const Mesh& mesh, const std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, double>& cones,
                   const std::string& what)
{
  auto tgt = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  for(auto v : vertices(mesh)) put(tgt, v, 0.);
  for(const auto& c : cones) put(tgt, c.first, c.second);
  auto ref = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  auto other = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  const SMDF::Cone_metric_status st = SMDF::compute_cone_metric(mesh, tgt, ref);
  SMDF_CHECK_MSG(st.converged, what << ": default solver converged");
  auto compare = [&](const SMDF::Cone_metric_status& s2, const char* name) {
    double d = 0;
    for(auto e : edges(mesh)) {
      const double a = get(ref, e), b = get(other, e);
      if(std::isnan(a) && std::isnan(b)) continue;
      d = (std::max)(d, std::abs(a - b) / a);
    }
    SMDF_CHECK_MSG(s2.converged && s2.max_curvature_error <= 1e-10 + s2.rounding_level && d < 1e-8,
                   what << ", " << name << ": converged " << s2.converged << ", error " << s2.max_curvature_error
                        << ", max relative length difference " << d);
  };
  compare(SMDF::compute_cone_metric(mesh, tgt, other,
              SMDF::parameters::sparse_linear_solver(SMDF::Eigen_sparse_cholesky<>())), "Eigen_sparse_cholesky");
  typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>> Traits;
  compare(SMDF::compute_cone_metric(mesh, tgt, other, SMDF::parameters::sparse_linear_solver(Traits())),
          "CGAL Eigen_solver_traits");
  const SMDF::Intrinsic_mesh<Mesh> im(mesh);
  const std::size_t builds = SMDF::internal::intrinsic_mesh_builds();
  compare(SMDF::compute_cone_metric(mesh, tgt, other, SMDF::parameters::intrinsic_mesh(im)), "shared Intrinsic_mesh");
  // the input's is not rebuilt; a punched surface (cones of index >= 1) is a new mesh with its own
  const std::size_t expected = builds + (st.punched_vertices.empty() ? 0 : 1);
  SMDF_CHECK_MSG(SMDF::internal::intrinsic_mesh_builds() == expected,
                 what << ": " << SMDF::internal::intrinsic_mesh_builds() - builds << " intrinsic meshes built with a shared one");
}

template <typename Mesh>
bool read(const std::string& file, Mesh& mesh)
{
  SMDF::read_triangle_mesh(file, mesh);
  return num_faces(mesh) > 0;
}

int main()
{
  std::cout.precision(3);
  Tests<Surface_mesh> ts;
  Tests<Polyhedron> tp;
  {
    Surface_mesh torus, cyl;
    smdf_test::soup_to_mesh(smdf_test::torus_soup(30, 20), torus);
    smdf_test::soup_to_mesh(smdf_test::cylinder_soup(30, 8), cyl);
    ts.generated(torus, cyl, "");
    ts.bad_input(torus, cyl);
    Polyhedron ptorus, pcyl;
    smdf_test::soup_to_mesh(smdf_test::torus_soup(30, 20), ptorus);
    smdf_test::soup_to_mesh(smdf_test::cylinder_soup(30, 8), pcyl);
    tp.generated(ptorus, pcyl, " (Polyhedron_3)");
    tp.bad_input(ptorus, pcyl);
  }
  const std::string dir = smdf_test::shared_data_dir();
  if(dir.empty()) {
    std::cout << "../shared/data not found: shared-mesh checks skipped" << std::endl;
    return smdf_test::finish();
  }
  const std::string md = dir + "/meshes/";
  // Every usable shared mesh (manifold, oriented, triangles, no degenerate face, at most 120k
  // faces), per component: (a) genus 1: flat; (b) genus 0: 8 cones of pi/2 at extreme vertices;
  // (c) genus g >= 2: one cone of 2 pi (2 - 2g) at the vertex of highest valence; with boundary:
  // flat inside, geodesic curvature 2 pi chi / n on each of the n boundary vertices.
  // (d) random chi-consistent cone sets on the closed single-component meshes up to 40k faces.
  for(const auto& entry : smdf_test::read_manifest(dir)) {
    if(entry.manifold != "yes" || entry.pure_tri != "yes" || entry.orientable != "yes" ||
       entry.degenerate_faces != 0 || entry.F > 120000)
      continue;
    Surface_mesh mesh;
    try { if(!read(md + entry.file, mesh)) continue; }
    catch(const SMDF::Input_error& e) { std::cout << entry.file << ": skipped, " << e.what() << std::endl; continue; }
    Tests<Surface_mesh>::Cones c = ts.standard_targets(mesh);
    auto out = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    SMDF_CHECK(ts.run(mesh, c, out, entry.file + ", " + ts.describe(mesh, c)));
    if(entry.components == 1 && entry.boundary_loops == 0 && entry.F <= 40000)
      for(int i = 0; i < 2; ++i) {
        const long chi = long(entry.V) - long(entry.E) + long(entry.F);
        const auto rc = ts.random_cones(mesh, chi);
        SMDF_CHECK(ts.run(mesh, rc, out, entry.file + ", random cones #" + std::to_string(i) + " (" + std::to_string(rc.size()) + " cones)"));
      }
  }
  {   // a single cone of index +2 on genus 0 (Lai et al. Figure 8), and +3/2 with two of +1/4
    Surface_mesh mesh;
    if(read(md + "spot_c3d.obj", mesh)) {
      Tests<Surface_mesh>::Cones c;
      c[*std::next(vertices(mesh).begin(), 100)] = 4 * M_PI;
      ts.punched(mesh, c, "spot_c3d.obj, one cone of index +2 (hole)");
      c.clear();
      c[*std::next(vertices(mesh).begin(), 100)] = 3 * M_PI;
      c[*std::next(vertices(mesh).begin(), 1500)] = M_PI / 2;
      c[*std::next(vertices(mesh).begin(), 2500)] = M_PI / 2;
      ts.punched(mesh, c, "spot_c3d.obj, cones of index +3/2 (hole), +1/4, +1/4");
    }
  }
  // Starting on the intrinsic Delaunay triangulation (input_triangulation_first(false)): the
  // same checks of the metric; Spot's input triangulation carries the 8 cones, Cheburashka's
  // does not (its flow is abandoned there), the camel head is a disk with needles.
  for(const char* file : {"spot_c3d.obj", "cheburashka_igltut.off", "camelhead_igltut.off"}) {
    Surface_mesh mesh;
    if(!read(md + file, mesh)) continue;
    const Tests<Surface_mesh>::Cones c = ts.standard_targets(mesh);
    auto out = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    SMDF_CHECK(ts.run(mesh, c, out, std::string(file) + ", " + ts.describe(mesh, c) + ", Delaunay from the start", 200,
                      true, false));
  }
  {
    Surface_mesh spot, dt;
    if(read(md + "spot_c3d.obj", spot)) solver_policy(spot, ts.extreme_cones(spot, M_PI / 2), "spot_c3d.obj, 8 cones pi/2");
    if(read(md + "double-torus_jnd.off", dt)) solver_policy(dt, ts.standard_targets(dt), "double-torus_jnd.off, one cone of -4 pi");
    Polyhedron ps;
    if(read(md + "spot_c3d.obj", ps)) {   // one cone of index +2: a hole, solved on the holed surface
      std::map<boost::graph_traits<Polyhedron>::vertex_descriptor, double> c;
      c[*std::next(vertices(ps).begin(), 100)] = 4 * M_PI;
      solver_policy(ps, c, "spot_c3d.obj (Polyhedron_3), one cone of index +2");
    }
  }
  {
    Polyhedron p;
    if(read(md + "spot_c3d.obj", p)) {
      auto out = get(CGAL::dynamic_edge_property_t<double>(), p);
      SMDF_CHECK(tp.run(p, tp.extreme_cones(p, M_PI / 2), out, "spot_c3d.obj, 8 cones pi/2 (Polyhedron_3)"));
    }
    Polyhedron e;
    if(read(md + "eight_directional.off", e)) {
      auto out = get(CGAL::dynamic_edge_property_t<double>(), e);
      SMDF_CHECK(tp.run(e, tp.standard_targets(e), out, "eight_directional.off (Polyhedron_3), " + tp.describe(e, tp.standard_targets(e))));
    }
  }
  // disks -> rectangles
  for(const std::string f : {"mushroom_cgal.off", "face_bff.obj"}) {
    Surface_mesh mesh;
    if(read(md + f, mesh)) { ts.rectangle(mesh, f); ts.rectangle(mesh, f, 3); }
  }
  {
    Polyhedron p;
    if(read(md + "mushroom_cgal.off", p)) tp.rectangle(p, "mushroom_cgal.off (Polyhedron_3)");
  }
  std::cout << not_converged.size() << " case(s) did not converge:" << std::endl;
  for(const auto& s : not_converged) std::cout << "  NOT CONVERGED: " << s << std::endl;
  return smdf_test::finish();
}
