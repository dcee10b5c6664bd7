// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Metric-driven field design (Lai et al. 2010): the homotopy basis of the punctured surface, the
// holonomy group of flat cone metrics and its compatibility tests (Theorems 3.2 and 3.5), on
// flat tori made from planar lattices (whose holonomy is known exactly) and on flat cone metrics
// of shared meshes of genus 0 and 3.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/IO/svg_writer.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "test_util.h"
#include "mesh_generators.h"

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef Surface_mesh::Vertex_index Vertex;

namespace {

// Every loop is a closed dual cycle that leaves and enters the base face.
template <typename Mesh>
bool loops_are_based(const Mesh& mesh, const SMDF::Homotopy_basis<Mesh>& b)
{
  for(const auto& l : b.loops) {
    if(l.dual_cycle.empty()) return false;
    if(face(opposite(l.dual_cycle.front(), mesh), mesh) != b.base_face || face(l.dual_cycle.back(), mesh) != b.base_face)
      return false;
    for(std::size_t i = 0; i + 1 < l.dual_cycle.size(); ++i)
      if(face(l.dual_cycle[i], mesh) != face(opposite(l.dual_cycle[i + 1], mesh), mesh)) return false;
  }
  return true;
}

// The torus_soup(n, m) connectivity with the lengths of the planar lattice spanned by A (along
// i) and B (along j): a flat torus with periods n A and m B.
struct Flat_torus
{
  Surface_mesh mesh;
  Surface_mesh::Property_map<Surface_mesh::Edge_index, double> length;
};

void make_flat_torus(Flat_torus& t, std::size_t n, std::size_t m, std::complex<double> A, std::complex<double> B)
{
  smdf_test::soup_to_mesh(smdf_test::torus_soup(n, m), t.mesh);
  t.length = t.mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat", 0).first;
  for(auto e : edges(t.mesh)) {
    const std::size_t u = std::size_t(source(halfedge(e, t.mesh), t.mesh)), v = std::size_t(target(halfedge(e, t.mesh), t.mesh));
    auto wrap = [](long d, long p) { d %= p; if(d > p / 2) d -= p; if(d < -p / 2) d += p; return d; };
    const long di = wrap(long(v / m) - long(u / m), long(n)), dj = wrap(long(v % m) - long(u % m), long(m));
    t.length[e] = std::abs(double(di) * A + double(dj) * B);
  }
}

void flat_tori()
{
  typedef std::complex<double> C;
  struct Case { const char* name; C A, B; bool square, triangular; double square_spacing, triangular_spacing; };
  const Case cases[] = {{"rectangular 1 x 1.5", C(1, 0), C(0, 1.5), true, false, 30, 0},
                        {"rectangular 1 x sqrt 2", C(1, 0), C(0, std::sqrt(2.)), false, false, 0, 0},
                        {"hexagonal", C(1, 0), C(0.5, std::sqrt(3.) / 2), false, true, 0, 10}};
  for(const Case& c : cases) {
    Flat_torus t;
    make_flat_torus(t, 30, 20, c.A, c.B);
    const std::vector<Vertex> no_cones;
    const auto basis = SMDF::homotopy_basis(t.mesh, no_cones);
    SMDF_CHECK_MSG(basis.loops.size() == 2 && loops_are_based(t.mesh, basis), c.name << ": two handle loops through the base face");
    const SMDF::Holonomy_group g = SMDF::holonomy_group(t.mesh, basis, SMDF::parameters::edge_length_map(t.length));
    // rotations vanish; translations are periods p (30 A) + q (20 B) with integers p, q, not both 0
    const C P = 30. * c.A, Q = 20. * c.B;
    for(std::size_t i = 0; i < g.motions.size(); ++i) {
      const double rot = std::min(g.rotations[i], 2 * M_PI - g.rotations[i]);
      const C tr(g.motions[i].translation.x(), g.motions[i].translation.y());
      // rotate the base frame so that its translations can be compared with the lattice's: the
      // frame is that of the base face, whose first edge is one of A, B, A + B (in some order)
      double best = 1e300;
      for(C e : {c.A, c.B, c.A + c.B, -c.A, -c.B, -c.A - c.B}) {
        const C z = tr * (e / std::abs(e));   // back to lattice coordinates, for each possible first edge
        for(C zz : {z}) {
          const double q = zz.imag() / Q.imag();
          const double p = (zz.real() - q * Q.real()) / P.real();
          best = std::min(best, std::abs(zz - (std::round(p) * P + std::round(q) * Q)) + (std::abs(std::round(p)) + std::abs(std::round(q)) == 0 ? 1e9 : 0));
        }
      }
      SMDF_CHECK_MSG(rot < 1e-9 && best < 1e-8, c.name << ", loop " << i << ": rotation " << rot << ", distance of the translation to a period " << best);
    }
    SMDF_CHECK_MSG(SMDF::smallest_parallel_rosy_order(g) == 1, c.name << ": a parallel vector field exists");
    const auto sq = SMDF::tessellation_compatibility(g, SMDF::SQUARE_GRID);
    const auto tri = SMDF::tessellation_compatibility(g, SMDF::TRIANGULAR_GRID);
    SMDF_CHECK_MSG(sq.compatible == c.square, c.name << ": square grid " << sq.compatible << ", deviation " << sq.max_translation_deviation);
    SMDF_CHECK_MSG(tri.compatible == c.triangular, c.name << ": triangular grid " << tri.compatible << ", deviation " << tri.max_translation_deviation);
    if(c.square) SMDF_CHECK_MSG(std::abs(sq.spacing - c.square_spacing) < 1e-9, c.name << ": square spacing " << sq.spacing);
    if(c.triangular) SMDF_CHECK_MSG(std::abs(tri.spacing - c.triangular_spacing) < 1e-9, c.name << ": triangular spacing " << tri.spacing);
    if(!c.square) SMDF_CHECK_MSG(!sq.failing_loops.empty() && sq.max_translation_deviation > 1e-3, c.name << ": the failing loops are named");
    // the grid of a given edge length: any divisor of the spacing by a lattice vector's norm,
    // also 1000 grid edges per period (beyond the coarsest-lattice search's reach of 128), and
    // nothing else
    const SMDF::Planar_tessellation grid = c.triangular ? SMDF::TRIANGULAR_GRID : SMDF::SQUARE_GRID;
    const double s = c.square ? c.square_spacing : c.triangular ? c.triangular_spacing : 30;
    const bool fits = c.square || c.triangular;
    for(double k : {1., 2., 1000., c.triangular ? std::sqrt(3.) : std::sqrt(2.), c.triangular ? std::sqrt(7.) * 100 : std::sqrt(5.) * 100}) {
      const auto at = SMDF::tessellation_compatibility_at(g, grid, s / k);
      SMDF_CHECK_MSG(at.compatible == fits && at.spacing == s / k, c.name << ": grid of edge length " << s / k << ": " << at.compatible
                     << ", deviation " << at.max_translation_deviation);
      if(fits && k == 1000.) {   // its lines follow the periods: the coarse lattice's orientation modulo the grid's rotations
        const double step = c.triangular ? M_PI / 3 : M_PI / 2;
        const double d = std::remainder(at.orientation - (c.triangular ? tri.orientation : sq.orientation), step);
        SMDF_CHECK_MSG(std::abs(d) < 1e-9, c.name << ": orientation " << at.orientation << " against the coarse lattice's");
      }
    }
    if(fits) {
      const auto off = SMDF::tessellation_compatibility_at(g, grid, s / 7.5);
      SMDF_CHECK_MSG(!off.compatible && !off.failing_loops.empty(), c.name << ": 7.5 grid edges per period do not fit");
      // each failing loop with its amounts: the rotations fit, the translations miss the lattice
      bool amounts = off.failing_rotation_deviations.size() == off.failing_loops.size() &&
                     off.failing_translation_deviations.size() == off.failing_loops.size();
      double largest = 0;
      for(std::size_t i = 0; amounts && i < off.failing_loops.size(); ++i) {
        amounts = off.failing_rotation_deviations[i] < 1e-9 && off.failing_translation_deviations[i] > 1e-6;
        largest = (std::max)(largest, off.failing_translation_deviations[i]);
      }
      // (the status's maximum is infinite when no lattice vector has the shortest translation's norm)
      SMDF_CHECK_MSG(amounts && (std::isinf(off.max_translation_deviation) || largest >= off.max_translation_deviation - 1e-12),
                     c.name << ": every failing loop comes with its deviations, the largest at least the status's (" << largest << " against " << off.max_translation_deviation << ")");
    }
  }
}

// The vertices extreme in the given directions (distinct).
std::vector<Vertex> extreme_vertices(const Surface_mesh& mesh, const std::vector<K::Vector_3>& dirs)
{
  std::vector<Vertex> out;
  for(const auto& d : dirs) {
    Vertex best;
    double bd = -1e300;
    for(auto v : vertices(mesh)) {
      const double x = (mesh.point(v) - CGAL::ORIGIN) * d;
      if(x > bd && std::find(out.begin(), out.end(), v) == out.end()) { bd = x; best = v; }
    }
    out.push_back(best);
  }
  return out;
}

typedef Surface_mesh::Property_map<Surface_mesh::Edge_index, double> Lengths;

// Flat cone metric with the given cone curvatures, on the input triangulation.
bool flat_cone_metric(const Surface_mesh& mesh, const std::vector<std::pair<Vertex, double>>& cones, Lengths& out,
                      const std::string& name)
{
  auto K_target = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  for(auto v : vertices(mesh)) put(K_target, v, 0.);
  for(const auto& c : cones) put(K_target, c.first, c.second);
  const auto st = SMDF::compute_cone_metric(mesh, K_target, out, SMDF::parameters::intrinsic_edge_flips(false));
  SMDF_CHECK_MSG(st.converged, name << ": flat cone metric on the input triangulation: " << st.message);
  return st.converged;
}

// Invariants of every basis and group: loop count, based loops, rotations of the cone loops
// equal to the cone curvatures mod 2 pi, cone loops fixing their cone, handle loops with the
// rotation of their un-based generator (homotopic loops have the same holonomy).
void check_group(const Surface_mesh& mesh, const SMDF::Homotopy_basis<Surface_mesh>& b, const SMDF::Holonomy_group& g,
                 const std::map<Vertex, double>& curv, const Lengths& metric, const std::string& name)
{
  const auto topo = SMDF::mesh_topology(mesh);
  const long genus = topo.components[0].genus, bl = long(topo.boundary_loops.size()), n = long(b.cones.size());
  const long expected = 2 * genus + (bl > 0 ? bl - 1 + n : (n > 0 ? n - 1 : 0));
  SMDF_CHECK_MSG(long(b.loops.size()) == expected, name << ": " << b.loops.size() << " loops, expected 2g + b - 1 + n (closed: 2g + n - 1) = " << expected);
  SMDF_CHECK_MSG(loops_are_based(mesh, b), name << ": every loop leaves and enters the base face");
  SMDF::Intrinsic_holonomy<Surface_mesh> hol(mesh, SMDF::parameters::edge_length_map(metric));
  const auto gens = hol.tree_cotree_generators();
  double scale = 0;
  for(const auto& p : g.cone_positions) scale = std::max(scale, std::abs(p.x()) + std::abs(p.y()));
  for(std::size_t i = 0; i < b.loops.size(); ++i) {
    const auto& l = b.loops[i];
    if(l.kind == SMDF::CONE_LOOP) {
      const double k = curv.at(l.cone);
      const double d = std::abs(std::remainder(g.rotations[i] - k, 2 * M_PI));
      const std::size_t ci = std::size_t(std::find(b.cones.begin(), b.cones.end(), l.cone) - b.cones.begin());
      const SMDF::Point_2 p = g.cone_positions[ci], q = g.motions[i](p);
      SMDF_CHECK_MSG(d < 1e-8, name << ", cone loop " << i << ": rotation " << g.rotations[i] << " = curvature " << k << " mod 2 pi");
      SMDF_CHECK_MSG(std::hypot(q.x() - p.x(), q.y() - p.y()) < 1e-8 * (1 + scale), name << ", cone loop " << i << ": its motion fixes the developed cone");
    } else {
      const double d = std::abs(std::remainder(g.rotations[i] - hol.levi_civita_holonomy(gens[l.generator].dual_cycle), 2 * M_PI));
      SMDF_CHECK_MSG(d < 1e-8, name << ", loop " << i << ": the same rotation as its generator away from the base face");
    }
  }
}

void genus_zero(Surface_mesh& spot)
{
  // Corollary 3.3: cube-like (8 cones of pi/2) -> 4-RoSy; octahedron-like (6 of 2 pi/3) -> 3-RoSy
  const std::vector<K::Vector_3> cube = {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}};
  const std::vector<K::Vector_3> octa = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  struct Case { const char* name; const std::vector<K::Vector_3>* dirs; double curvature; int order; };
  for(const Case& c : {Case{"spot, 8 cones of pi/2", &cube, M_PI / 2, 4}, Case{"spot, 6 cones of 2 pi/3", &octa, 2 * M_PI / 3, 3}}) {
    const std::vector<Vertex> cones = extreme_vertices(spot, *c.dirs);
    std::vector<std::pair<Vertex, double>> target;
    std::map<Vertex, double> curv;
    for(Vertex v : cones) { target.emplace_back(v, c.curvature); curv[v] = c.curvature; }
    Lengths flat = spot.add_property_map<Surface_mesh::Edge_index, double>("e:flat_test", 0).first;
    if(flat_cone_metric(spot, target, flat, c.name)) {
      const auto b = SMDF::homotopy_basis(spot, cones);
      const SMDF::Holonomy_group g = SMDF::holonomy_group(spot, b, SMDF::parameters::edge_length_map(flat));
      check_group(spot, b, g, curv, flat, c.name);
      SMDF_CHECK_MSG(SMDF::smallest_parallel_rosy_order(g) == c.order, c.name << ": smallest parallel N-RoSy order " << SMDF::smallest_parallel_rosy_order(g));
      const auto r = SMDF::parallel_rosy_compatibility(g, c.order + 1);
      SMDF_CHECK_MSG(!r.compatible && !r.failing_loops.empty(), c.name << ": not " << c.order + 1 << "-RoSy, failing loops named");
      // on the embedding, the cone loops turn by the angle defect
      const SMDF::Holonomy_group ge = SMDF::holonomy_group(spot, b);
      bool ok = true;
      for(std::size_t i = 0; i < b.loops.size(); ++i)
        ok = ok && std::abs(std::remainder(ge.rotations[i] - SMDF::angle_defect(b.loops[i].cone, spot), 2 * M_PI)) < 1e-9;
      SMDF_CHECK_MSG(ok, c.name << ": on the embedding, each cone loop turns by its cone's angle defect");
    }
    spot.remove_property_map(flat);
  }
}

// The flat cone metric with curvatures `cones` on `in` (flips allowed), copied with its lengths
// onto `mesh`: the input itself, or the intrinsic triangulation the flow flipped to (same vertex
// indices). False (and a failed check) if the flow does not converge.
bool cone_metric_carrier(const Surface_mesh& in, const std::map<Vertex, double>& cones, Surface_mesh& mesh, Lengths& flat,
                         bool& flipped, const std::string& name)
{
  auto K_target = get(CGAL::dynamic_vertex_property_t<double>(), in);
  for(auto v : vertices(in)) put(K_target, v, cones.count(v) ? cones.at(v) : 0.);
  auto out = get(CGAL::dynamic_edge_property_t<double>(), in);
  const auto st = SMDF::compute_cone_metric(in, K_target, out);
  SMDF_CHECK_MSG(st.converged, name << ": flat cone metric: " << st.message);
  if(!st.converged) return false;
  flipped = st.triangulation_changed;
  if(flipped) {
    flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat_test", 0).first;
    SMDF::copy_intrinsic_triangulation(st.intrinsic_triangulation, in, mesh, flat);
  } else {
    mesh = in;
    flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat_test", 0).first;
    for(auto e : edges(mesh)) flat[e] = get(out, e);
  }
  return true;
}

void genus_three(const Surface_mesh& input, const std::string& name)
{
  // Figure 9 of Lai et al.: four cones of -pi, -3 pi, -2 pi, -2 pi (sum 2 pi chi = -8 pi). The
  // flow may flip edges: the metric then lives on an intrinsic triangulation, copied into a
  // Surface_mesh with its lengths (same vertices), on which the basis and the group are computed.
  const std::vector<Vertex> cones = extreme_vertices(input, {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}});
  const double Ks[4] = {-M_PI, -3 * M_PI, -2 * M_PI, -2 * M_PI};
  std::map<Vertex, double> curv;
  for(int i = 0; i < 4; ++i) curv[cones[std::size_t(i)]] = Ks[i];
  Surface_mesh mesh;
  Lengths flat;
  bool flipped = false;
  if(!cone_metric_carrier(input, curv, mesh, flat, flipped, name)) return;
  const auto b = SMDF::homotopy_basis(mesh, cones);   // same vertex indices as the input
  const SMDF::Holonomy_group g = SMDF::holonomy_group(mesh, b, SMDF::parameters::edge_length_map(flat));
  check_group(mesh, b, g, curv, flat, name + (flipped ? " (intrinsic triangulation)" : ""));
  std::cout << name << ": holonomy group of the flat cone metric with cones -pi, -3pi, -2pi, -2pi"
            << (flipped ? " (on its intrinsic triangulation)" : "") << "\n";
  for(std::size_t i = 0; i < b.loops.size(); ++i)
    std::cout << "  loop " << i << " (" << (b.loops[i].kind == SMDF::CONE_LOOP ? "cone" : "handle") << "): rotation "
              << std::fixed << std::setprecision(4) << g.rotations[i] / M_PI << " pi, translation ("
              << g.motions[i].translation.x() << ", " << g.motions[i].translation.y() << ")\n" << std::defaultfloat;
  const auto sq = SMDF::tessellation_compatibility(g, SMDF::SQUARE_GRID);
  std::cout << "  smallest parallel N-RoSy order: " << SMDF::smallest_parallel_rosy_order(g) << "; square grid: "
            << (sq.compatible ? "compatible" : "not compatible") << " (" << sq.failing_loops.size() << " loops fail)\n";
  SMDF_CHECK(!sq.compatible);   // the handle loops of an uncompensated metric turn by arbitrary angles
}



// The obelisk field (Lai et al. Figure 1c) by regions: on the faces below the middle cones (the
// box part: its cones are the four of pi/2) the metric carries a parallel 4-RoSy field, above
// them (the pyramid: the apex of 2 pi/3) a parallel 3-RoSy field. Each region is copied into a
// mesh of its own with the flat lengths; the middle cones are left out of both.
void obelisk_regions(const Surface_mesh& spot, const Lengths& flat, const std::vector<std::pair<Vertex, double>>& cones)
{
  double box_top = -1e300, middle_low = 1e300, middle_high = -1e300;
  for(int i = 0; i < 8; ++i) {
    const double y = spot.point(cones[std::size_t(i)].first).y();
    if(i < 4) box_top = std::max(box_top, y);
    else { middle_low = std::min(middle_low, y); middle_high = std::max(middle_high, y); }
  }
  const double apex = spot.point(cones[8].first).y();
  if(!(box_top < middle_low && middle_high < apex)) {
    std::cout << "obelisk regions: cones not separated by height, skipped" << std::endl;
    return;
  }
  const double margin = 0.02;
  struct Region { const char* name; double lo, hi; int N; };
  for(const Region& r : {Region{"box part", -1e300, middle_low - margin, 4}, Region{"pyramid", middle_high + margin, 1e300, 3}}) {
    smdf_test::Soup soup;
    std::map<Vertex, std::size_t> index;
    std::vector<Surface_mesh::Face_index> kept;
    for(auto f : faces(spot)) {
      double y = 0;
      for(auto v : vertices_around_face(halfedge(f, spot), spot)) y += spot.point(v).y() / 3;
      if(y <= r.lo || y >= r.hi) continue;
      std::vector<std::size_t> poly;
      for(auto v : vertices_around_face(halfedge(f, spot), spot)) {
        auto it = index.find(v);
        if(it == index.end()) {
          it = index.emplace(v, soup.points.size()).first;
          const auto& p = spot.point(v);
          soup.points.push_back({p.x(), p.y(), p.z()});
        }
        poly.push_back(it->second);
      }
      soup.faces.push_back(poly);
    }
    Surface_mesh part;
    smdf_test::soup_to_mesh(soup, part);
    auto len = get(CGAL::dynamic_edge_property_t<double>(), part);
    std::map<std::size_t, Vertex> back;
    for(const auto& p : index) back[p.second] = p.first;
    for(auto e : edges(part)) {
      const Vertex a = back[std::size_t(source(halfedge(e, part), part))], b = back[std::size_t(target(halfedge(e, part), part))];
      put(len, e, flat[edge(halfedge(a, b, spot).first, spot)]);
    }
    const auto topo = SMDF::mesh_topology(part);
    auto angles = get(CGAL::dynamic_face_property_t<double>(), part);
    const auto st = SMDF::parallel_rosy_field(part, r.N, angles, SMDF::parameters::edge_length_map(len));
    const auto bad = SMDF::parallel_rosy_field(part, r.N == 4 ? 3 : 4, angles, SMDF::parameters::edge_length_map(len));
    SMDF_CHECK_MSG(st.success && !bad.success, "obelisk " << r.name << " (" << num_faces(part) << " faces, " << topo.components.size()
                   << " component(s)): a parallel " << r.N << "-RoSy field and not the other one " << st.message);
  }
}

// The parallel N-RoSy field of a genus-0 flat cone metric (Corollary 3.3): read back on the
// metric, its singularities are exactly the cones with index K / 2 pi; it is the field of the
// trivial connection computed on the same metric with those indices (the adjustment angles
// vanish, DESIGN.md section 5); on the order below the smallest one the status fails.
void parallel_field(Surface_mesh& spot, const std::vector<std::pair<Vertex, double>>& cones, int N, const std::string& name)
{
  Lengths flat = spot.add_property_map<Surface_mesh::Edge_index, double>("e:flat_parallel", 0).first;
  if(flat_cone_metric(spot, cones, flat, name)) {
    auto angles = get(CGAL::dynamic_face_property_t<double>(), spot);
    const SMDF::Parallel_rosy_status st = SMDF::parallel_rosy_field(spot, N, angles, SMDF::parameters::edge_length_map(flat));
    SMDF_CHECK_MSG(st.success && st.max_deviation < 1e-8, name << ": parallel " << N << "-RoSy field, deviation " << st.max_deviation << " " << st.message);
    const auto ft = SMDF::field_singularities(spot, angles, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
    std::map<Vertex, double> got(ft.singularities.begin(), ft.singularities.end()), want;
    for(const auto& c : cones) want[c.first] = std::round(c.second / (2 * M_PI) * N) / N;
    SMDF_CHECK_MSG(got == want, name << ": read back on the metric, the singularities are the " << want.size() << " cones (found " << got.size() << ")");
    // the trivial connection on the same metric, with indices K / 2 pi: the same field
    SMDF::Trivial_connection<Surface_mesh> tc(spot, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
    for(const auto& c : cones) tc.set_singularity(c.first, want[c.first]);
    const auto tst = tc.solve();
    auto tangles = get(CGAL::dynamic_face_property_t<double>(), spot);
    tc.field_angles_from(*faces(spot).begin(), 0., tangles);
    double diff = 0;
    for(auto f : faces(spot)) diff = std::max(diff, std::abs(std::remainder(get(angles, f) - get(tangles, f), 2 * M_PI / N)));
    SMDF_CHECK_MSG(tst.success && tst.max_rotation < 1e-9 && diff < 1e-8,
                   name << ": equals the trivial connection's field on the metric (max |x| " << tst.max_rotation << ", angle difference " << diff << ")");
    // the field in 3D, read back on the embedding by principal matching: the cones again
    auto vectors = get(CGAL::dynamic_face_property_t<K::Vector_3>(), spot);
    SMDF::field_angles_to_vectors(spot, angles, vectors, SMDF::parameters::edge_length_map(flat));
    auto embedded = get(CGAL::dynamic_face_property_t<double>(), spot);
    for(auto f : faces(spot)) {
      const auto h = halfedge(f, spot);
      const K::Vector_3 e1 = spot.point(target(h, spot)) - spot.point(source(h, spot));
      const K::Vector_3 n = CGAL::cross_product(e1, spot.point(target(next(h, spot), spot)) - spot.point(source(h, spot)));
      const K::Vector_3 e2 = CGAL::cross_product(n, e1);
      const K::Vector_3 v = get(vectors, f);
      put(embedded, f, std::atan2(v * e2 / std::sqrt(e2.squared_length()), v * e1 / std::sqrt(e1.squared_length())));
    }
    const auto fe = SMDF::field_singularities(spot, embedded, SMDF::parameters::symmetry_order(N));
    std::map<Vertex, double> got_e(fe.singularities.begin(), fe.singularities.end());
    std::cout << name << ": on the embedding, principal matching reads " << got_e.size() << " singularities ("
              << (got_e == want ? "the cones" : "not only the cones") << ")" << std::endl;
    if(N == 12) obelisk_regions(spot, flat, cones);
    if(N > 1) {
      const SMDF::Parallel_rosy_status bad = SMDF::parallel_rosy_field(spot, N - 1, angles, SMDF::parameters::edge_length_map(flat));
      SMDF_CHECK_MSG(!bad.success && bad.inconsistent_edges > 0 && !bad.message.empty(), name << ": no parallel " << N - 1 << "-RoSy field");
    }
  }
  spot.remove_property_map(flat);
}


// Editing (Lai et al. 4.2) of a cross field of Spot with eight +1/4 singularities: hard direction
// constraints met to 1e-12, new values without refactoring, soft ones approached monotonically
// as the weight grows, lengths within the range of their constraints (maximum principle), and
// the read-back with the field's matching identical to the prescription after every edit.
void editing(const Surface_mesh& spot)
{
  typedef Surface_mesh::Face_index Face;
  const std::vector<Vertex> corners = extreme_vertices(spot, {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}});
  SMDF::Trivial_connection<Surface_mesh> tc(spot, SMDF::parameters::symmetry_order(4));
  std::map<Vertex, double> want;
  for(Vertex v : corners) { tc.set_singularity(v, 0.25); want[v] = 0.25; }
  SMDF_CHECK(tc.solve().success);
  auto field = get(CGAL::dynamic_face_property_t<double>(), spot);
  tc.field_angles(field);
  auto read_back = [&](const auto& angles, const std::string& what) {
    auto matching = get(CGAL::dynamic_edge_property_t<int>(), spot);
    tc.field_matching(angles, matching);
    const auto ft = SMDF::field_singularities(spot, angles, SMDF::parameters::symmetry_order(4).matching(matching));
    std::map<Vertex, double> got(ft.singularities.begin(), ft.singularities.end());
    SMDF_CHECK_MSG(got == want, "editing, " << what << ": the read-back with the field's matching is the prescription (" << got.size() << " found)");
  };
  read_back(field, "before");
  SMDF::Rosy_field_editor<Surface_mesh> editor(spot, 4, field);
  const std::vector<Face> cf = {Face(100), Face(2500), Face(4700)};
  std::vector<std::pair<Face, double>> c;
  for(std::size_t i = 0; i < cf.size(); ++i) c.emplace_back(cf[i], 0.3 + 1.1 * double(i));
  editor.set_direction_constraints(c);
  auto edited = get(CGAL::dynamic_face_property_t<double>(), spot);
  for(int round = 0; round < 2; ++round) {   // round 1: new values, same faces
    const SMDF::Field_edit_status st = editor.edit();
    SMDF_CHECK_MSG(st.success && st.max_direction_error <= 1e-12, "hard direction constraints: error " << st.max_direction_error);
    if(round == 1) SMDF_CHECK_MSG(st.factor_seconds == 0, "new constraint values reuse the factorisation");
    editor.field_angles(edited);
    read_back(edited, round == 0 ? "after a hard edit" : "after new values");
    for(auto& p : c) p.second += 0.7;
    editor.set_direction_constraints(c);
  }
  double last = 1e300;
  bool monotone = true;
  for(double lambda : {0.01, 0.1, 1., 10., 100.}) {
    editor.set_direction_constraints(c, lambda);
    const SMDF::Field_edit_status st = editor.edit();
    monotone = monotone && st.success && st.max_direction_error < last;
    last = st.max_direction_error;
    editor.field_angles(edited);
    read_back(edited, "after a soft edit, weight " + std::to_string(lambda));
  }
  SMDF_CHECK_MSG(monotone && last < 0.05, "soft direction constraints approached monotonically (error " << last << " at weight 100)");
  // lengths: hard, then soft
  const std::vector<std::pair<Face, double>> lc = {{Face(10), 0.5}, {Face(3000), 2.0}};
  editor.set_length_constraints(lc);
  SMDF::Field_edit_status st = editor.edit();
  auto lengths = get(CGAL::dynamic_face_property_t<double>(), spot);
  editor.field_lengths(lengths);
  double lo = 1e300, hi = 0;
  for(auto f : faces(spot)) { lo = std::min(lo, get(lengths, f)); hi = std::max(hi, get(lengths, f)); }
  SMDF_CHECK_MSG(st.success && st.max_length_error <= 1e-12 && lo >= 0.5 * (1 - 1e-12) && hi <= 2.0 * (1 + 1e-12),
                 "hard length constraints: error " << st.max_length_error << ", lengths in [" << lo << ", " << hi << "]");
  last = 1e300;
  monotone = true;
  for(double lambda : {0.01, 1., 100.}) {
    editor.set_length_constraints(lc, lambda);
    st = editor.edit();
    monotone = monotone && st.success && st.max_length_error < last;
    last = st.max_length_error;
  }
  SMDF_CHECK_MSG(monotone, "soft length constraints approached monotonically (error " << last << ")");
  auto throws = [](auto f) { try { f(); } catch(const SMDF::Input_error&) { return true; } return false; };
  SMDF_CHECK(throws([&] { editor.set_direction_constraints(std::vector<std::pair<Face, double>>{{Face(1), 0.}, {Face(1), 1.}}); }));
  SMDF_CHECK(throws([&] { editor.set_direction_constraints(std::vector<std::pair<Face, double>>{{Face(1), 0.}}, -1.); }));
  SMDF_CHECK(throws([&] { editor.set_length_constraints(std::vector<std::pair<Face, double>>{{Face(1), 0.}}); }));
}


// Editing the vertex field of rotation compensation (Lai et al. 4.2, at vertices, cotan
// Laplacian): hard constraints met to 1e-12 with the factorisation reused for new values, soft
// ones approached monotonically, lengths within the range of their constraints, and the face
// version read back on the metric has exactly the cones after every edit.
template <typename LengthMap, typename VertexAngles>
void vertex_editing(const Surface_mesh& mesh, const LengthMap& flat, const VertexAngles& field, const std::map<Vertex, double>& want,
                    int N, const std::string& name)
{
  const auto np = SMDF::parameters::edge_length_map(flat);
  SMDF::Rosy_vertex_field_editor<Surface_mesh> editor(mesh, N, field, np);
  auto fa = get(CGAL::dynamic_face_property_t<double>(), mesh);
  auto read_back = [&](const std::string& what) {
    editor.face_angles(fa);
    const auto ft = SMDF::field_singularities(mesh, fa, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
    std::map<Vertex, double> got(ft.singularities.begin(), ft.singularities.end());
    SMDF_CHECK_MSG(got == want, name << ", vertex editing " << what << ": the read-back is the cones (" << got.size() << " found)");
  };
  read_back("before");
  auto field_after = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  std::vector<Vertex> picks;   // three vertices away from the cones, spread over the index range
  const std::size_t nv = num_vertices(mesh);
  for(std::size_t i = 1; picks.size() < 3 && i < nv; i += nv / 4)
    if(!want.count(Vertex(Surface_mesh::size_type(i)))) picks.push_back(Vertex(Surface_mesh::size_type(i)));
  std::vector<std::pair<Vertex, double>> c;
  for(std::size_t i = 0; i < picks.size(); ++i) c.emplace_back(picks[i], get(field, picks[i]) + 0.2 * double(i + 1) / N);
  editor.set_direction_constraints(c);
  for(int round = 0; round < 2; ++round) {
    const SMDF::Field_edit_status st = editor.edit();
    SMDF_CHECK_MSG(st.success && st.max_direction_error <= 1e-12, name << ", vertex editing: hard direction error " << st.max_direction_error);
    if(round == 1) SMDF_CHECK_MSG(st.factor_seconds == 0, name << ", vertex editing: new values reuse the factorisation");
    read_back(round == 0 ? "after a hard edit" : "after new values");
    for(auto& p : c) p.second -= 0.3 / N;
    editor.set_direction_constraints(c);
  }
  double last = 1e300;
  bool monotone = true;
  for(double lambda : {0.01, 1., 100.}) {
    editor.set_direction_constraints(c, lambda);
    const SMDF::Field_edit_status st = editor.edit();
    monotone = monotone && st.success && st.max_direction_error < last;
    last = st.max_direction_error;
    read_back("after a soft edit");
  }
  SMDF_CHECK_MSG(monotone, name << ", vertex editing: soft constraints approached monotonically (" << last << " at weight 100)");
  {   // hard and soft mixed: the first met exactly, the others approached as their weight grows
    double previous = 1e300;
    bool mixed_ok = true;
    for(double lambda : {0.01, 1.}) {
      editor.set_direction_constraints(c, std::vector<double>{0., lambda, lambda});
      const SMDF::Field_edit_status st = editor.edit();
      editor.vertex_angles(field_after);
      const double hard = std::abs(std::remainder(get(field_after, c[0].first) - c[0].second, 2 * M_PI / N));
      double soft = 0;
      for(std::size_t i = 1; i < c.size(); ++i) soft = std::max(soft, std::abs(std::remainder(get(field_after, c[i].first) - c[i].second, 2 * M_PI / N)));
      mixed_ok = mixed_ok && st.success && hard <= 1e-12 && soft < previous && soft > 1e-9;
      previous = soft;
      read_back("after a mixed edit");
    }
    SMDF_CHECK_MSG(mixed_ok, name << ", vertex editing: one hard and two soft constraints, the hard one met exactly, the soft ones approached");
    bool count_refused = false;
    try { editor.set_direction_constraints(c, std::vector<double>{0., 1.}); }
    catch(const SMDF::Input_error& e) { count_refused = std::string(e.what()).find("weights for") != std::string::npos; }
    SMDF_CHECK_MSG(count_refused, name << ", vertex editing: a weight count that is not the constraint count is refused");
  }
  const std::vector<std::pair<Vertex, double>> lc = {{picks[0], 0.5}, {picks[1], 2.0}};
  editor.set_length_constraints(lc);
  const SMDF::Field_edit_status ls = editor.edit();
  auto lengths = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  editor.vertex_lengths(lengths);
  double lo = 1e300, hi = 0;
  for(auto v : vertices(mesh)) { lo = std::min(lo, get(lengths, v)); hi = std::max(hi, get(lengths, v)); }
  SMDF_CHECK_MSG(ls.success && ls.max_length_error <= 1e-12 && lo >= 0.5 * (1 - 1e-12) && hi <= 2.0 * (1 + 1e-12),
                 name << ", vertex editing: hard lengths, error " << ls.max_length_error << ", in [" << lo << ", " << hi << "]");
  bool cone_refused = false;
  try { editor.set_direction_constraints(std::vector<std::pair<Vertex, double>>{{want.begin()->first, 0.}}); }
  catch(const SMDF::Input_error& e) { cone_refused = std::string(e.what()).find("cone") != std::string::npos; }
  SMDF_CHECK_MSG(cone_refused, name << ", vertex editing: a constraint at a cone is refused");
}


// Rotation compensation (Lai et al. 4.1.3.1) on a flat cone metric of genus > 0 whose cone
// curvatures are multiples of 2 pi / N: the field is an N-RoSy field across every edge, its
// face version read back on the metric has exactly the cones as singularities, the 1-form is
// harmonic, and the trivial connection computed on the same metric with cotan weights, the
// cone indices and the turning numbers read from this field has the same read-back.
template <typename LengthMap>
void compensated(const Surface_mesh& mesh, const LengthMap& flat, const std::map<Vertex, double>& cones, int N, const std::string& name)
{
  auto va = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  auto fa = get(CGAL::dynamic_face_property_t<double>(), mesh);
  const auto np = SMDF::parameters::edge_length_map(flat);
  const SMDF::Rotation_compensation_status st = SMDF::rotation_compensated_field(mesh, N, va, fa, np);
  SMDF_CHECK_MSG(st.success && st.max_inconsistency < 1e-8 && st.max_harmonic_residual < 1e-8,
                 name << ": compensated " << N << "-RoSy field, inconsistency " << st.max_inconsistency << ", harmonic residual "
                      << st.max_harmonic_residual << " " << st.message);
  bool periods_ok = !st.periods.empty();
  for(std::size_t i = 0; i < st.periods.size(); ++i)
    periods_ok = periods_ok && std::abs(std::remainder(st.holonomy[i] + st.periods[i], 2 * M_PI / N)) < 1e-12 && std::abs(st.periods[i]) <= M_PI / N + 1e-12;
  SMDF_CHECK_MSG(periods_ok, name << ": every handle loop's holonomy plus its period is a multiple of 2 pi / N");
  {   // chosen turning numbers: one more quarter turn on the first loop, the others as before
    std::vector<double> turning;
    for(std::size_t i = 0; i < st.periods.size(); ++i) turning.push_back(std::round((st.holonomy[i] + st.periods[i]) / (2 * M_PI) * N) / N + (i == 0 ? 1. / N : 0.));
    auto va2 = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto fa2 = get(CGAL::dynamic_face_property_t<double>(), mesh);
    const auto st2 = SMDF::rotation_compensated_field(mesh, N, va2, fa2, np.generator_turning_numbers(turning));
    const auto ft2 = SMDF::field_singularities(mesh, fa2, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
    std::map<Vertex, double> got2(ft2.singularities.begin(), ft2.singularities.end()), want2;
    for(const auto& c : cones) want2[c.first] = std::round(c.second / (2 * M_PI) * N) / N;
    SMDF_CHECK_MSG(st2.success && std::abs(st2.periods[0] - st.periods[0] - 2 * M_PI / N) < 1e-9 && got2 == want2,
                   name << ": chosen turning numbers change the periods by 2 pi / N and keep the singularities");
  }
  const auto ft = SMDF::field_singularities(mesh, fa, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
  std::map<Vertex, double> got(ft.singularities.begin(), ft.singularities.end()), want;
  for(const auto& c : cones) want[c.first] = std::round(c.second / (2 * M_PI) * N) / N;
  SMDF_CHECK_MSG(got == want, name << ": the face field read back on the metric has exactly the " << want.size() << " cones (found " << got.size() << ")");
  {   // the field's own matching: the same field, read back the same with it
    auto va3 = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto fa3 = get(CGAL::dynamic_face_property_t<double>(), mesh);
    auto km = get(CGAL::dynamic_edge_property_t<int>(), mesh);
    const auto st3 = SMDF::rotation_compensated_field(mesh, N, va3, fa3, np.matching(km));
    const auto ft3 = SMDF::field_singularities(mesh, fa3, SMDF::parameters::symmetry_order(N).edge_length_map(flat).matching(km));
    std::map<Vertex, double> got3(ft3.singularities.begin(), ft3.singularities.end());
    double d = 0;
    for(auto f : faces(mesh)) d = std::max(d, std::abs(std::remainder(get(fa3, f) - get(fa, f), 2 * M_PI)));
    SMDF_CHECK_MSG(st3.success && got3 == want && d == 0 && st.max_rotation < M_PI / N,
                   name << ": with its own matching, the same field reads back the cones (largest rotation " << st.max_rotation << " rad)");
  }
  {   // the paper's construction of the harmonic forms (cut, Dirichlet jump, projection): the same field
    auto va2 = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto fa2 = get(CGAL::dynamic_face_property_t<double>(), mesh);
    const auto st2 = SMDF::rotation_compensated_field(mesh, N, va2, fa2, np.harmonic_form_construction(SMDF::CUT_AND_DIRICHLET));
    double d = 0, dp = 0;
    for(auto v : vertices(mesh))
      if(!cones.count(v)) d = std::max(d, std::abs(std::remainder(get(va, v) - get(va2, v), 2 * M_PI)));
    for(std::size_t i = 0; i < st.periods.size() && i < st2.periods.size(); ++i) dp = std::max(dp, std::abs(st.periods[i] - st2.periods[i]));
    SMDF_CHECK_MSG(st2.success && st2.max_harmonic_residual < 1e-8 && d < 1e-8 && dp < 1e-12,
                   name << ": the cut-and-Dirichlet harmonic forms give the same field (largest angle difference " << d << " rad) "
                        << st2.message);
  }
  vertex_editing(mesh, flat, va, want, N, name);
  // the vertex field pulled back to the embedding: unit vectors in the averaged tangent planes
  auto vv = get(CGAL::dynamic_vertex_property_t<K::Vector_3>(), mesh);
  SMDF::vertex_field_to_vectors(mesh, va, vv);
  double off_plane = 0, off_unit = 0;
  for(auto v : vertices(mesh)) {
    K::Vector_3 n(0, 0, 0);
    for(auto f : faces_around_target(halfedge(v, mesh), mesh)) {
      const auto h = halfedge(f, mesh);
      n = n + CGAL::cross_product(mesh.point(target(h, mesh)) - mesh.point(source(h, mesh)),
                                  mesh.point(target(next(h, mesh), mesh)) - mesh.point(source(h, mesh)));
    }
    const K::Vector_3 x = get(vv, v);
    off_plane = std::max(off_plane, std::abs(x * n) / std::sqrt(n.squared_length()));
    off_unit = std::max(off_unit, std::abs(x.squared_length() - 1));
  }
  SMDF_CHECK_MSG(off_plane < 1e-9 && off_unit < 1e-9, name << ": vertex vectors are unit and tangent (" << off_plane << ", " << off_unit << ")");
  // the trivial connection on the same metric, cotan weights (harmonic in the same sense)
  SMDF::Trivial_connection<Surface_mesh> tc(mesh, SMDF::parameters::symmetry_order(N).edge_length_map(flat).connection_weights(SMDF::COTAN_WEIGHTS));
  for(const auto& c : want) tc.set_singularity(c.first, c.second);
  for(std::size_t g = 0; g < ft.generator_turning_numbers.size(); ++g) tc.set_generator_turning_number(g, ft.generator_turning_numbers[g]);
  const auto ts = tc.solve();
  auto ta = get(CGAL::dynamic_face_property_t<double>(), mesh);
  tc.field_angles_from(*faces(mesh).begin(), get(fa, *faces(mesh).begin()), ta);
  const auto tt = SMDF::field_singularities(mesh, ta, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
  std::map<Vertex, double> tgot(tt.singularities.begin(), tt.singularities.end());
  double diff = 0;
  for(auto f : faces(mesh)) diff = std::max(diff, std::abs(std::remainder(get(fa, f) - get(ta, f), 2 * M_PI / N)));
  SMDF_CHECK_MSG(ts.success && tgot == want && tt.generator_turning_numbers == ft.generator_turning_numbers,
                 name << ": the trivial connection with the same indices and turning numbers reads back the same");
  std::cout << name << ": compensated field, " << st.periods.size() << " handle loops; largest angle difference to the trivial "
            << "connection's field " << diff << " rad (primal and dual harmonic forms)" << std::endl;
}

// The flat cone metric of `cones` on `in` on the triangulation that carries it, compensated().
void compensated_on_cone_metric(const Surface_mesh& in, const std::map<Vertex, double>& cones, int N, const std::string& name)
{
  Surface_mesh mesh;
  Lengths flat;
  bool flipped = false;
  if(cone_metric_carrier(in, cones, mesh, flat, flipped, name)) compensated(mesh, flat, cones, N, name);
}

void rotation_compensation(const Surface_mesh& g3)
{
  {   // a torus with cones of +pi/2 and -pi/2: a cross field
    Surface_mesh torus;
    smdf_test::soup_to_mesh(smdf_test::torus_soup(40, 24), torus);
    std::map<Vertex, double> cones = {{Vertex(17), M_PI / 2}, {Vertex(500), -M_PI / 2}};
    auto K_target = get(CGAL::dynamic_vertex_property_t<double>(), torus);
    for(auto v : vertices(torus)) put(K_target, v, cones.count(v) ? cones[v] : 0.);
    auto flat = get(CGAL::dynamic_edge_property_t<double>(), torus);
    const auto cm = SMDF::compute_cone_metric(torus, K_target, flat, SMDF::parameters::intrinsic_edge_flips(false));
    SMDF_CHECK_MSG(cm.converged, "torus with two cones: " << cm.message);
    if(cm.converged) compensated(torus, flat, cones, 4, "torus with cones +-pi/2");
  }
  {   // a ring of cones around the tube (+-pi/2 alternating on all 24 vertices of a meridian):
      // no loop of vertices crosses it, so the loop around the big circle must pass cones (the
      // propagation over faces serves it; loops of vertices avoiding the cones could not)
    Surface_mesh torus;
    smdf_test::soup_to_mesh(smdf_test::torus_soup(40, 24), torus);
    std::map<Vertex, double> cones;
    for(int j = 0; j < 24; ++j) cones[Vertex(j)] = (j % 2 ? -M_PI : M_PI) / 2;
    compensated_on_cone_metric(torus, cones, 4, "torus with a ring of 24 adjacent cones around the tube");
  }
  {   // the genus-3 metric of the holonomy table: cones multiples of pi, a line field
    const std::vector<Vertex> cv = extreme_vertices(g3, {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}});
    const double Ks[4] = {-M_PI, -3 * M_PI, -2 * M_PI, -2 * M_PI};
    std::map<Vertex, double> cones;
    for(int i = 0; i < 4; ++i) cones[cv[std::size_t(i)]] = Ks[i];
    compensated_on_cone_metric(g3, cones, 2, "genus3_vhacd.off, cones -pi, -3pi, -2pi, -2pi");
  }
}


// Fields parallel and orthogonal to the boundary (Lai et al. 4.3, double cover): a cross field
// on a disk with four corners of pi/2 (a rectangle), and a vector field on an annulus (flat,
// no corner); every boundary edge is checked against the field, here and in the status.
void boundary_aligned()
{
  typedef Surface_mesh::Face_index Face;
  auto check = [](const Surface_mesh& mesh, const std::map<Vertex, double>& kappa, int N, bool orthogonal, const std::string& name) {
    auto target = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    for(auto v : vertices(mesh)) put(target, v, kappa.count(v) ? kappa.at(v) : 0.);
    auto lengths = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    auto angles = get(CGAL::dynamic_face_property_t<double>(), mesh);
    const SMDF::Boundary_aligned_field_status st =
        SMDF::boundary_aligned_rosy_field(mesh, N, target, lengths, angles, SMDF::parameters::orthogonal_to_boundary(orthogonal));
    // independent check: the angle of each boundary edge in its face frame, from the output lengths
    double worst = 0;
    for(auto h : halfedges(mesh)) {
      if(!is_border(opposite(h, mesh), mesh)) continue;
      const Face f = face(h, mesh);
      double dir = 0;   // direction of h in the frame of f (x axis along halfedge(f))
      for(auto g = halfedge(f, mesh); g != h; g = next(g, mesh))
        dir += M_PI - SMDF::corner_angle(g, mesh, SMDF::parameters::edge_length_map(lengths));
      const double d = get(angles, f) - dir - (orthogonal ? M_PI / 2 : 0.);
      worst = std::max(worst, std::abs(std::remainder(d, N % 2 == 0 ? 2 * M_PI / N : M_PI / N)));   // either orientation
    }
    SMDF_CHECK_MSG(st.success && st.metric.converged && worst < 1e-6,
                   name << ": " << (orthogonal ? "orthogonal" : "parallel") << " to the boundary, deviation " << worst << " (status "
                        << st.max_boundary_deviation << ") " << st.message);
    if(!st.success) return;
    // the field read back on its metric: no singularity (no interior cone)
    const auto ft = SMDF::field_singularities(mesh, angles, SMDF::parameters::symmetry_order(N).edge_length_map(lengths));
    SMDF_CHECK_MSG(ft.singularities.empty(), name << ": no singularity inside (" << ft.singularities.size() << " found)");
  };
  {   // a disk: a grid of 16 x 12 quads, split; corners of pi/2 at the four grid corners
    smdf_test::Soup s;
    const int nx = 16, ny = 12;
    for(int i = 0; i <= nx; ++i)
      for(int j = 0; j <= ny; ++j) s.points.push_back({double(i) + 0.2 * std::sin(double(j)), double(j), 0.3 * std::sin(0.5 * i + 0.3 * j)});
    auto id = [&](int i, int j) { return std::size_t(i * (ny + 1) + j); };
    for(int i = 0; i < nx; ++i)
      for(int j = 0; j < ny; ++j) {
        if((i == nx - 1 && j == 0) || (i == 0 && j == ny - 1)) {   // the other diagonal: no ear at these corners
          s.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)}); s.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        } else {
          s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)}); s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
      }
    Surface_mesh disk;
    smdf_test::soup_to_mesh(s, disk);
    // not at the grid corners: the rectangle's corners sit at other boundary vertices
    const std::map<Vertex, double> kappa = {{Vertex(std::uint32_t(id(0, 3))), M_PI / 2}, {Vertex(std::uint32_t(id(10, 0))), M_PI / 2},
                                            {Vertex(std::uint32_t(id(nx, 8))), M_PI / 2}, {Vertex(std::uint32_t(id(5, ny))), M_PI / 2}};
    check(disk, kappa, 4, false, "disk with four corners, N = 4");
    check(disk, kappa, 4, true, "disk with four corners, N = 4");
    {   // an ear (interior edge between two boundary vertices): no trouble on genus 0 (the
        // mesh's own metric; the double cover, which would join those vertices twice, is for handles)
      smdf_test::Soup e;
      e.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
      e.faces = {{0, 1, 2}, {0, 2, 3}};
      Surface_mesh square;
      smdf_test::soup_to_mesh(e, square);
      auto target = get(CGAL::dynamic_vertex_property_t<double>(), square);
      for(auto v : vertices(square)) put(target, v, M_PI / 2);
      auto lengths = get(CGAL::dynamic_edge_property_t<double>(), square);
      auto angles = get(CGAL::dynamic_face_property_t<double>(), square);
      const auto st = SMDF::boundary_aligned_rosy_field(square, 4, target, lengths, angles);
      SMDF_CHECK_MSG(st.success && st.max_boundary_deviation < 1e-9, "a square split by its diagonal: " << st.message);
      SMDF_CHECK_MSG(std::abs(SMDF::max_boundary_deviation(square, 4, angles, SMDF::parameters::edge_length_map(lengths))) < 1e-9,
                     "a square split by its diagonal: the deviation measured again");
    }
  }
  {   // free boundary: the disk made flat with its curvature spread over the boundary (a round
      // disk); the parallel field of any N exists and has no singularity
    smdf_test::Soup s;
    for(int i = 0; i <= 12; ++i) for(int j = 0; j <= 12; ++j) s.points.push_back({double(i), double(j), 0.1 * std::sin(double(i * j))});
    for(int i = 0; i < 12; ++i) for(int j = 0; j < 12; ++j) { const std::size_t a = std::size_t(i * 13 + j); s.faces.push_back({a, a + 13, a + 14}); s.faces.push_back({a, a + 14, a + 1}); }
    Surface_mesh grid;
    smdf_test::soup_to_mesh(s, grid);
    auto target = get(CGAL::dynamic_vertex_property_t<double>(), grid);
    std::size_t nb = 0;
    for(auto v : vertices(grid)) nb += is_border(v, grid) ? 1 : 0;
    for(auto v : vertices(grid)) put(target, v, is_border(v, grid) ? 2 * M_PI / double(nb) : 0.);
    auto len = get(CGAL::dynamic_edge_property_t<double>(), grid);
    const auto cm = SMDF::compute_cone_metric(grid, target, len);
    SMDF_CHECK_MSG(cm.converged && !cm.triangulation_changed, "free boundary: round flat disk " << cm.message);
    for(int N : {1, 4, 5}) {
      auto angles = get(CGAL::dynamic_face_property_t<double>(), grid);
      const auto st = SMDF::parallel_rosy_field(grid, N, angles, SMDF::parameters::edge_length_map(len));
      const auto ft = SMDF::field_singularities(grid, angles, SMDF::parameters::symmetry_order(N).edge_length_map(len));
      SMDF_CHECK_MSG(st.success && ft.singularities.empty(), "free boundary, N = " << N << ": a parallel field without singularity");
    }
  }
  {
    Surface_mesh annulus;
    smdf_test::soup_to_mesh(smdf_test::cylinder_soup(40, 10), annulus);
    check(annulus, {}, 1, false, "annulus, N = 1");
    check(annulus, {}, 1, true, "annulus, N = 1");
  }
}


// A face field on a refinement brought back to the input (refine_at_edge_points(),
// transfer_face_field_from_refinement()): random points on random edges (border and interior,
// some edges twice), the refinement tiles every input face (areas), and a trivial connection
// with random singularities at input vertices, solved on the refinement, reads back the same
// singularities on the input faces with the transferred matching. On Surface_mesh and Polyhedron_3.
template <typename Mesh>
void refinement_transfer(const Mesh& mesh, const std::string& name, unsigned seed)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor V;
  typedef typename boost::graph_traits<Mesh>::face_descriptor F;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  std::vector<std::pair<std::size_t, double>> points;
  std::size_t border_points = 0;
  const std::size_t ne = num_edges(mesh);
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> edge_list(edges(mesh).begin(), edges(mesh).end());
  for(std::size_t e = 0; e < ne; ++e) {
    if(rng() % 20 != 0 && !(is_border(edge_list[e], mesh) && rng() % 4 == 0)) continue;
    points.emplace_back(e, unit(rng));
    if(rng() % 3 == 0) points.emplace_back(e, unit(rng));
    if(is_border(edge_list[e], mesh)) ++border_points;
  }
  Mesh refined;
  const SMDF::Delaunay_refinement_status rs = SMDF::refine_at_edge_points(mesh, points, refined);
  SMDF_CHECK_MSG(rs.success && rs.inserted.size() == points.size() && num_vertices(refined) == num_vertices(mesh) + points.size() &&
                     rs.face_origin.size() == num_faces(refined),
                 name << ": refinement at " << points.size() << " edge points (" << border_points << " edges on the border): " << rs.message);
  if(!rs.success) return;
  {   // the pieces tile each input face
    auto triangle_area = [](const auto& m, auto f) {
      const auto vpm = get(CGAL::vertex_point, m);
      const auto h = halfedge(f, m);
      return std::sqrt(CGAL::squared_area(get(vpm, source(h, m)), get(vpm, target(h, m)), get(vpm, target(next(h, m), m))));
    };
    std::vector<double> area(num_faces(mesh), 0.);
    std::size_t i = 0;
    for(F f : faces(refined)) area[rs.face_origin[i++]] += triangle_area(refined, f);
    double worst = 0;
    i = 0;
    for(F f : faces(mesh)) { const double a = triangle_area(mesh, f); worst = std::max(worst, std::abs(area[i++] - a) / a); }
    SMDF_CHECK_MSG(worst < 1e-10, name << ": the pieces tile every input face (area error " << worst << ")");
  }
  // random singularities at interior input vertices, summing to chi: the trivial connection on the refinement
  const int N = 4;
  std::vector<V> inner, inner_refined;
  {
    std::vector<V> in(vertices(mesh).begin(), vertices(mesh).end()), out(vertices(refined).begin(), vertices(refined).end());
    for(std::size_t i = 0; i < in.size(); ++i)
      if(!is_border(in[i], mesh)) { inner.push_back(in[i]); inner_refined.push_back(out[i]); }
  }
  const long chi = long(num_vertices(mesh)) - long(ne) + long(num_faces(mesh));
  std::map<std::size_t, double> want;
  long units = 0;
  const long target_units = is_closed(mesh) ? N * chi : 0;   // open: the boundary takes the rest (free turning)
  for(int k = 0; k < 6 || (is_closed(mesh) && units != target_units); ++k) {
    const long step = is_closed(mesh) && k >= 6 ? (target_units > units ? 1 : -1) : (rng() % 2 ? 1 : -1);
    const std::size_t v = rng() % inner.size();
    if(want.count(v)) continue;
    want[v] = double(step) / N;
    units += step;
  }
  SMDF::Trivial_connection<Mesh> tc(refined, SMDF::parameters::symmetry_order(N));
  for(const auto& w : want) tc.set_singularity(inner_refined[w.first], w.second);
  const SMDF::Trivial_connection_status ts = tc.solve();
  SMDF_CHECK_MSG(ts.success, name << ": trivial connection on the refinement " << ts.message);
  if(!ts.success) return;
  auto angles = get(CGAL::dynamic_face_property_t<double>(), refined);
  auto matching = get(CGAL::dynamic_edge_property_t<int>(), refined);
  tc.field_angles(angles);
  tc.field_matching(angles, matching);
  auto in_angles = get(CGAL::dynamic_face_property_t<double>(), mesh);
  auto in_matching = get(CGAL::dynamic_edge_property_t<int>(), mesh);
  const SMDF::Field_transfer_status st =
      SMDF::transfer_face_field_from_refinement(refined, mesh, rs, N, angles, matching, in_angles, in_matching);
  SMDF_CHECK_MSG(st.success, name << ": the field brought back to the input " << st.message);
  if(!st.success) return;
  const auto back = SMDF::field_singularities(mesh, in_angles, SMDF::parameters::symmetry_order(N).matching(in_matching));
  std::map<std::size_t, double> got;
  {
    std::map<V, std::size_t> id;
    for(std::size_t i = 0; i < inner.size(); ++i) id[inner[i]] = i;
    for(const auto& x : back.singularities) got[id.count(x.first) ? id[x.first] : std::size_t(-1)] = x.second;
  }
  SMDF_CHECK_MSG(got == want, name << ": the input faces read back the " << want.size() << " singularities of the refinement ("
                                   << got.size() << " found; largest turn inside an input face " << st.max_distortion << " rad)");
}

// The paper's Ricci flow (inversive distance circle packing) against vertex scaling, both on the
// input triangulation: the input metric is reproduced at u = 0, and every converged metric is
// checked by recomputing its curvature from the output lengths. Prints the comparison.
void circle_packing(const std::string& dir)
{
  auto run = [](const Surface_mesh& mesh, const std::map<Vertex, double>& cones, SMDF::Ricci_flow_scheme scheme, const std::string& name) {
    auto target = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    for(auto v : vertices(mesh)) put(target, v, cones.count(v) ? cones.at(v) : 0.);
    auto out = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    const auto st = SMDF::compute_cone_metric(mesh, target, out, SMDF::parameters::intrinsic_edge_flips(false).ricci_flow_scheme(scheme));
    if(st.converged) {
      double err = 0;
      for(auto v : vertices(mesh))
        err = std::max(err, std::abs(SMDF::angle_defect(v, mesh, SMDF::parameters::edge_length_map(out)) - get(target, v)));
      SMDF_CHECK_MSG(err < 1e-9, name << ": recomputed curvature error " << err);
    }
    return st;
  };
  struct Case { const char* file; int kind; };   // kind: 0 eight cones of pi/2, 1 flat, 2 one cone of 2 pi chi
  const Case cases[] = {{"spot_c3d.obj", 0}, {"bunny_bff.obj", 0}, {"armadillo_cgal.off", 0}, {"torus_ddg.obj", 1},
                        {"knot1_cgal.off", 1}, {"double-torus_jnd.off", 2}, {"genus3_vhacd.off", 2}};
  std::cout << "| mesh | targets | vertex scaling: converged, iterations, time | circle packing: converged, iterations, time |\n";
  int both = 0, packing = 0;
  for(const Case& c : cases) {
    Surface_mesh mesh;
    try { SMDF::read_triangle_mesh(dir + "/meshes/" + c.file, mesh); } catch(const SMDF::Input_error&) { continue; }
    std::map<Vertex, double> cones;
    const long chi = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
    if(c.kind == 0)
      for(Vertex v : extreme_vertices(mesh, {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}}))
        cones[v] = M_PI / 2;
    if(c.kind == 2) {
      Vertex best = *vertices(mesh).begin();
      for(auto v : vertices(mesh)) if(degree(v, mesh) > degree(best, mesh)) best = v;
      cones[best] = 2 * M_PI * double(chi);
    }
    const auto vs = run(mesh, cones, SMDF::VERTEX_SCALING, std::string(c.file) + ", vertex scaling");
    const auto cp = run(mesh, cones, SMDF::INVERSIVE_DISTANCE_CIRCLE_PACKING, std::string(c.file) + ", circle packing");
    both += vs.converged && cp.converged;
    packing += cp.converged;
    std::cout << "| `" << c.file << "` | " << (c.kind == 0 ? "8 x pi/2" : c.kind == 1 ? "flat" : "one cone") << " | "
              << (vs.converged ? "yes" : "no") << ", " << vs.iterations << ", " << std::setprecision(3) << vs.seconds << " s | "
              << (cp.converged ? "yes" : "no") << ", " << cp.iterations << ", " << cp.seconds << " s |" << std::setprecision(6)
              << (cp.converged ? "" : " (" + cp.message + ")") << "\n";
  }
  SMDF_CHECK_MSG(packing >= 4, "circle packing converged on " << packing << " of the meshes");
  // u = 0 reproduces the input: targets equal to the input curvatures, no iteration, same lengths
  Surface_mesh spot;
  SMDF::read_triangle_mesh(dir + "/meshes/spot_c3d.obj", spot);
  auto defects = get(CGAL::dynamic_vertex_property_t<double>(), spot);
  for(auto v : vertices(spot)) put(defects, v, SMDF::angle_defect(v, spot));
  auto out = get(CGAL::dynamic_edge_property_t<double>(), spot);
  const auto st = SMDF::compute_cone_metric(spot, defects, out, SMDF::parameters::ricci_flow_scheme(SMDF::INVERSIVE_DISTANCE_CIRCLE_PACKING));
  double d = 0;
  for(auto e : edges(spot)) d = std::max(d, std::abs(get(out, e) - std::sqrt(CGAL::squared_distance(spot.point(source(e, spot)), spot.point(target(e, spot))))));
  SMDF_CHECK_MSG(st.converged && st.iterations == 0 && d < 1e-12, "circle packing reproduces the input metric at u = 0 (" << d << ")");
}

void bad_input()
{
  Surface_mesh cyl;
  smdf_test::soup_to_mesh(smdf_test::cylinder_soup(20, 6), cyl);
  const Vertex border(0), inner(2 * 1 + 3);
  auto throws = [](auto f) { try { f(); } catch(const SMDF::Input_error& e) { return e.kind() == SMDF::Input_error::INVALID_ARGUMENT; } return false; };
  SMDF_CHECK(throws([&] { SMDF::homotopy_basis(cyl, std::vector<Vertex>{border}); }));
  SMDF_CHECK(throws([&] { SMDF::homotopy_basis(cyl, std::vector<Vertex>{Vertex(8), Vertex(8)}); }));
  SMDF_CHECK(throws([&] { SMDF::homotopy_basis(cyl, std::vector<Vertex>{Vertex(100000)}); }));
  Flat_torus t;
  make_flat_torus(t, 30, 20, {1, 0}, {0, 1});
  SMDF_CHECK(throws([&] { SMDF::parallel_rosy_compatibility(SMDF::Holonomy_group(), 0); }));
  // an annulus with two cones: 2g + b - 1 + n = 0 + 1 + 2 loops
  const auto b = SMDF::homotopy_basis(cyl, std::vector<Vertex>{Vertex(6 * 5 + 2), Vertex(6 * 12 + 3)});
  SMDF_CHECK_MSG(b.loops.size() == 3 && loops_are_based(cyl, b), "annulus with two cones: " << b.loops.size() << " loops");
  (void)inner;
  // two components
  smdf_test::Soup a = smdf_test::torus_soup(12, 8), c = smdf_test::torus_soup(12, 8);
  const std::size_t off = a.points.size();
  for(auto p : c.points) { p[0] += 10; a.points.push_back(p); }
  for(auto f : c.faces) { for(auto& v : f) v += off; a.faces.push_back(f); }
  Surface_mesh two;
  smdf_test::soup_to_mesh(a, two);
  SMDF_CHECK(throws([&] { SMDF::homotopy_basis(two, std::vector<Vertex>()); }));
  // Polyhedron_3: a torus with two cones, 2 + 1 loops
  Polyhedron p;
  smdf_test::soup_to_mesh(smdf_test::torus_soup(30, 20), p);
  std::vector<Polyhedron::Vertex_handle> pc = {std::next(p.vertices_begin(), 5), std::next(p.vertices_begin(), 300)};
  const auto pb = SMDF::homotopy_basis(p, pc);
  SMDF_CHECK_MSG(pb.loops.size() == 3 && loops_are_based(p, pb), "Polyhedron_3 torus with two cones: " << pb.loops.size() << " loops");
  const SMDF::Holonomy_group pg = SMDF::holonomy_group(p, pb);
  SMDF_CHECK(pg.motions.size() == 3 && pg.cone_positions.size() == 2);
}

// Invariants of every streamline of a face field (any mesh type): each piece lies in its face
// (in its plane, inside the triangle), runs along one of the field's N directions there, and the
// next piece is in a neighbouring face; the lengths add up; parallel samples keep apart.
template <typename Mesh, typename FaceVectorMap>
double check_streamlines(const Mesh& mesh, const FaceVectorMap& vectors, int N, const std::vector<SMDF::Streamline<Mesh>>& lines,
                         double separation, const std::string& name)
{
  typedef std::array<double, 3> V3;
  auto P = [&](typename boost::graph_traits<Mesh>::vertex_descriptor v) {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    return V3{{p.x(), p.y(), p.z()}};
  };
  auto sub = [](const V3& a, const V3& b) { return V3{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; };
  auto dot = [](const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto cross = [](const V3& a, const V3& b) { return V3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}}; };
  double worst_inside = 0, worst_direction = 0, total = 0;
  std::size_t not_adjacent = 0, length_mismatch = 0;
  for(const auto& l : lines) {
    double len = 0;
    for(std::size_t i = 0; i < l.faces.size(); ++i) {
      const auto f = l.faces[i];
      const auto h = halfedge(f, mesh);
      const V3 a = P(source(h, mesh)), b = P(target(h, mesh)), c = P(target(next(h, mesh), mesh));
      const V3 n = cross(sub(b, a), sub(c, a));
      const double area2 = std::sqrt(dot(n, n));
      for(const V3& x : {l.points[i], l.points[i + 1]}) {
        // signed barycentric coordinates and the distance to the plane, relative to the face size
        const double u = dot(cross(sub(b, x), sub(c, x)), n) / (area2 * area2), v = dot(cross(sub(c, x), sub(a, x)), n) / (area2 * area2);
        const double w = 1 - u - v, off = std::abs(dot(sub(x, a), n)) / area2 / std::sqrt(area2);
        worst_inside = std::max({worst_inside, -u, -v, -w, off});
      }
      const V3 d = sub(l.points[i + 1], l.points[i]);
      const double dl = std::sqrt(dot(d, d));
      len += dl;
      if(dl > 1e-9 * std::sqrt(area2)) {
        const auto& fv = get(vectors, f);
        V3 e{{double(fv[0]), double(fv[1]), double(fv[2])}};
        const V3 nn{{n[0] / area2, n[1] / area2, n[2] / area2}};
        const double en = dot(e, nn);
        for(int k = 0; k < 3; ++k) e[std::size_t(k)] -= en * nn[std::size_t(k)];
        const double angle = std::atan2(dot(cross(e, d), nn), dot(e, d));
        worst_direction = std::max(worst_direction, std::abs(std::remainder(angle, 2 * M_PI / N)));
      }
      if(i + 1 < l.faces.size()) {
        bool adjacent = false;
        for(auto g : halfedges_around_face(halfedge(f, mesh), mesh))
          if(!is_border(opposite(g, mesh), mesh) && face(opposite(g, mesh), mesh) == l.faces[i + 1]) adjacent = true;
        if(!adjacent) ++not_adjacent;
      }
    }
    if(std::abs(len - l.length) > 1e-9 * (1 + len)) ++length_mismatch;
    total += l.length;
  }
  SMDF_CHECK_MSG(!lines.empty() && worst_inside < 1e-7 && worst_direction < 1e-7 && not_adjacent == 0 && length_mismatch == 0,
                 name << ": " << lines.size() << " streamlines, every piece in its face (" << worst_inside << ") along the field ("
                      << worst_direction << " rad), consecutive faces adjacent (" << not_adjacent << " not), lengths ("
                      << length_mismatch << " wrong)");
  (void)separation;
  return total;
}

// principal_matching(), vertex_vectors_to_angles() and streamlines on the cross field of the
// cube-like metric of Spot, and streamlines of a vector field on a Polyhedron_3 torus.
void matching_frames_streamlines(Surface_mesh& spot, const std::vector<std::pair<Vertex, double>>& cube)
{
  Lengths flat = spot.add_property_map<Surface_mesh::Edge_index, double>("e:flat_streamlines", 0).first;
  if(!flat_cone_metric(spot, cube, flat, "spot for streamlines")) return;
  auto va = get(CGAL::dynamic_vertex_property_t<double>(), spot);
  auto fa = get(CGAL::dynamic_face_property_t<double>(), spot);
  const auto np = SMDF::parameters::edge_length_map(flat);
  const auto cs = SMDF::rotation_compensated_field(spot, 4, va, fa, np);
  SMDF_CHECK(cs.success);
  auto k = get(CGAL::dynamic_edge_property_t<int>(), spot);
  const double widest = SMDF::principal_matching(spot, fa, k, np.symmetry_order(4));
  const auto with = SMDF::field_singularities(spot, fa, np.symmetry_order(4).matching(k));
  const auto without = SMDF::field_singularities(spot, fa, np.symmetry_order(4));
  SMDF_CHECK_MSG(widest < M_PI / 4 && with.singularities == without.singularities && with.singularities.size() == cube.size(),
                 "principal_matching: read back with it as without (" << with.singularities.size() << " cones), widest rotation " << widest);
  {   // a field rotated by pi/2 on one face: principal matching jumps by one period on its edges
    auto turned = get(CGAL::dynamic_face_property_t<double>(), spot);
    for(auto f : faces(spot)) put(turned, f, get(fa, f));
    const auto f0 = *faces(spot).begin();
    put(turned, f0, get(fa, f0) + M_PI / 2);
    auto k2 = get(CGAL::dynamic_edge_property_t<int>(), spot);
    SMDF::principal_matching(spot, turned, k2, np.symmetry_order(4));
    int changed = 0;
    for(auto e : edges(spot)) changed += get(k2, e) != get(k, e);
    SMDF_CHECK_MSG(changed == 3, "a face turned by pi/2: its 3 edges change their period jump (" << changed << ")");
  }
  // vertex frames: vectors and back
  auto vv = get(CGAL::dynamic_vertex_property_t<K::Vector_3>(), spot);
  SMDF::vertex_field_to_vectors(spot, va, vv, np);
  auto back = get(CGAL::dynamic_vertex_property_t<double>(), spot);
  SMDF::vertex_vectors_to_angles(spot, vv, back, np);
  double round_trip = 0;
  for(auto v : vertices(spot)) round_trip = std::max(round_trip, std::abs(std::remainder(get(back, v) - get(va, v), 2 * M_PI)));
  SMDF_CHECK_MSG(round_trip < 1e-9, "vertex_vectors_to_angles() inverts vertex_field_to_vectors(): " << round_trip);
  // streamlines of the cross field
  auto fv = get(CGAL::dynamic_face_property_t<K::Vector_3>(), spot);
  SMDF::field_angles_to_vectors(spot, fa, fv, np);
  SMDF::Streamline_options so;
  const auto lines = SMDF::trace_streamlines(spot, fv, 4, so);
  double area = 0;
  for(auto f : faces(spot)) area += std::sqrt(CGAL::squared_area(spot.point(source(halfedge(f, spot), spot)), spot.point(target(halfedge(f, spot), spot)),
                                                                  spot.point(target(next(halfedge(f, spot), spot), spot))));
  const CGAL::Bbox_3 box = CGAL::bbox_3(spot.points().begin(), spot.points().end());
  const double sep = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) + CGAL::square(box.zmax() - box.zmin())) / 60;
  const double total = check_streamlines(spot, fv, 4, lines, sep, "spot cross field");
  // evenly spaced: two families of lines about one separation apart cover the area about
  // 2 area / sep long (each line stops at half a separation from its neighbours)
  const double coverage = total * sep / (2 * area);
  SMDF_CHECK_MSG(coverage > 0.5 && coverage < 2.5, "spot streamlines cover the surface evenly: length x separation / (2 area) = " << coverage);
  std::ostringstream svg;
  SMDF::write_streamlines_svg(svg, spot, lines);
  SMDF_CHECK(svg.str().find("<line") != std::string::npos);
  auto throws = [](auto f) { try { f(); } catch(const SMDF::Input_error& e) { return e.kind() == SMDF::Input_error::INVALID_ARGUMENT; } return false; };
  SMDF_CHECK(throws([&] { SMDF::trace_streamlines(spot, fv, 0); }));
  SMDF::Streamline_options bad;
  bad.separation = -1;
  SMDF_CHECK(throws([&] { SMDF::trace_streamlines(spot, fv, 4, bad); }));
  // Polyhedron_3: the vector field of the z axis projected on a torus lying in the xy plane
  // (zero where the face is horizontal: streamlines stop there)
  Polyhedron p;
  smdf_test::soup_to_mesh(smdf_test::torus_soup(40, 24), p);
  std::map<Polyhedron::Facet_handle, K::Vector_3> store;
  for(auto f : faces(p)) store[f] = K::Vector_3(0.3, 0.1, 1);
  const auto pv = boost::make_assoc_property_map(store);
  const auto pl = SMDF::trace_streamlines(p, pv, 1);
  check_streamlines(p, pv, 1, pl, 0, "Polyhedron_3 torus, a vector field");
  spot.remove_property_map(flat);
}

} // namespace

int main()
{
  flat_tori();
  bad_input();
  boundary_aligned();
  const std::string dir = smdf_test::shared_data_dir();
  if(dir.empty()) {
    std::cout << "../shared/data not found: shared-mesh checks skipped" << std::endl;
    return smdf_test::finish();
  }
  Surface_mesh spot, g3;
  SMDF::read_triangle_mesh(dir + "/meshes/spot_c3d.obj", spot);
  genus_zero(spot);
  {
    const std::vector<Vertex> corners = extreme_vertices(spot, {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}});
    std::vector<std::pair<Vertex, double>> cube, octa, obelisk;
    for(Vertex v : corners) cube.emplace_back(v, M_PI / 2);
    parallel_field(spot, cube, 4, "spot, cube-like metric");
    matching_frames_streamlines(spot, cube);
    for(Vertex v : extreme_vertices(spot, {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}})) octa.emplace_back(v, 2 * M_PI / 3);
    parallel_field(spot, octa, 3, "spot, octahedron-like metric");
    // the obelisk of Lai et al. (Figure 1c): a box part (four cones of pi/2 at its base), a
    // pyramid (four of pi/3 and its apex of 2 pi/3): a 12-RoSy field
    const std::vector<Vertex> ob = extreme_vertices(spot, {{1, -1, 1}, {1, -1, -1}, {-1, -1, 1}, {-1, -1, -1},
                                                           {1, 0.5, 1}, {1, 0.5, -1}, {-1, 0.5, 1}, {-1, 0.5, -1}, {0, 1, 0}});
    for(int i = 0; i < 9; ++i) obelisk.emplace_back(ob[std::size_t(i)], i < 4 ? M_PI / 2 : i < 8 ? M_PI / 3 : 2 * M_PI / 3);
    parallel_field(spot, obelisk, 12, "spot, obelisk metric");
  }
  editing(spot);
  {
    Surface_mesh holes;
    Polyhedron poly;
    SMDF::read_triangle_mesh(dir + "/meshes/holes_cgal.off", holes);
    SMDF::read_triangle_mesh(dir + "/meshes/holes_cgal.off", poly);
    for(unsigned seed : {1u, 2u}) {
      refinement_transfer(holes, "holes_cgal.off (Surface_mesh, seed " + std::to_string(seed) + ")", seed);
      refinement_transfer(poly, "holes_cgal.off (Polyhedron_3, seed " + std::to_string(seed) + ")", seed);
      refinement_transfer(spot, "spot (seed " + std::to_string(seed) + ")", seed);
    }
  }
  SMDF::read_triangle_mesh(dir + "/meshes/genus3_vhacd.off", g3);
  genus_three(g3, "genus3_vhacd.off");
  rotation_compensation(g3);
  circle_packing(dir);
  return smdf_test::finish();
}
