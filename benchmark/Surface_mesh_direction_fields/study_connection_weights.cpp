// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Which weights should the trivial connection use by default? For every usable mesh given (one
// connected component, accepted by read_triangle_mesh()), N in {1, 2, 4, 6} and several random
// singularity sets (N |chi| indices of sign(chi) / N plus four +-1/N pairs, at random interior
// vertices), each weight rule solves with turning numbers 0 and with the smoothest ones, and
// the study records:
//   - whether the field read back by principal matching (no matching given) has exactly the
//     prescribed singularities, what any other tool would see;
//   - the largest rotation |x_e| against Levi-Civita and the edges beyond pi / N and beyond pi;
//   - two yardsticks of smoothness, the same for every rule: the energy sum x_e^2 / w_e under cotan
//     weights (clamped as COTAN_WEIGHTS, computed here from the points, independently of the
//     library) and sum x_e^2, each as the geometric mean of its ratio to the cotan rule's;
//   - the solves whose edges beyond pi a dual cycle proves unavoidable (for these turning
//     numbers, or for any), and those whose turning numbers the search below pi moved;
//   - per mesh, the mean energy with turning numbers 0 and with the smoothest ones.
// Every solve must succeed and its read-back with its own matching must equal the prescription.
// Prints Markdown tables (the manual's "Choice of weights" section). Usage:
//   study_connection_weights [--sets n] [--max-faces n] [--default-only] MESH...
// (--default-only: only the default rule, whose column is the last; the energy ratios then read 0)
// The CTest smoke run uses one small mesh and one set.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;
typedef Mesh::Edge_index Edge;

namespace {

struct Rule
{
  const char* name;
  SMDF::Connection_weights weights;
  double cap;
  double rotation_limit;   // 0: the minimum-norm connection
};

const Rule rules[] = {{"cotan", SMDF::COTAN_WEIGHTS, 10, 0},
                      {"nonnegative-cotan", SMDF::NONNEGATIVE_COTAN_WEIGHTS, 10, 0},
                      {"bounded-cotan-3", SMDF::BOUNDED_COTAN_WEIGHTS, 3, 0},
                      {"bounded-cotan-10", SMDF::BOUNDED_COTAN_WEIGHTS, 10, 0},
                      {"unit", SMDF::UNIT_WEIGHTS, 10, 0},
                      {"cotan, limit 0.8 pi", SMDF::COTAN_WEIGHTS, 10, 0.8 * M_PI},
                      {"unit, limit 0.8 pi (default)", SMDF::UNIT_WEIGHTS, 10, 0.8 * M_PI}};
constexpr int rule_count = int(sizeof(rules) / sizeof(rules[0]));
int first_rule = 0;   // --default-only: rule_count - 1
const int orders[] = {1, 2, 4, 6};

// Totals of one rule over solves.
struct Tally
{
  int solves = 0, principal_exact = 0, beyond_pi_solves = 0;
  int proven_beyond_pi = 0;       // solves where a dual cycle proves some |x_e| > pi for these turning numbers
  int proven_any_turning = 0;     // ... for any turning numbers (Trivial_connection_status::rotation_bound_any_turning)
  int turned = 0;                 // solves whose turning numbers the search for rotations below pi moved
  long beyond_half = 0, beyond_pi = 0;
  double max_rotation = 0, log_energy_ratio = 0, log_unit_energy_ratio = 0;   // sums of log(E / E of the cotan rule)
  double own_energy = 0;   // sum of the rule's own energy ||Dx||^2 (Trivial_connection_status::energy)
  void add(const Tally& t)
  {
    solves += t.solves;
    principal_exact += t.principal_exact;
    beyond_pi_solves += t.beyond_pi_solves;
    proven_beyond_pi += t.proven_beyond_pi;
    proven_any_turning += t.proven_any_turning;
    turned += t.turned;
    beyond_half += t.beyond_half;
    beyond_pi += t.beyond_pi;
    max_rotation = (std::max)(max_rotation, t.max_rotation);
    own_energy += t.own_energy;
    log_energy_ratio += t.log_energy_ratio;
    log_unit_energy_ratio += t.log_unit_energy_ratio;
  }
};

// cot-weight yardstick: w_e = (cot a + cot b) / 2 from the points, raised to 1e-3 of the mean
std::vector<double> reference_cotan_weights(const Mesh& mesh)
{
  std::vector<double> w(num_edges(mesh), 0.);
  for(Face f : faces(mesh)) {
    auto h = halfedge(f, mesh);
    for(int k = 0; k < 3; ++k, h = next(h, mesh)) {
      const K::Point_3 &a = mesh.point(source(h, mesh)), &b = mesh.point(target(h, mesh)),
                       &c = mesh.point(target(next(h, mesh), mesh));
      const K::Vector_3 u = a - c, v = b - c;
      const double cr = std::sqrt(CGAL::to_double(CGAL::cross_product(u, v).squared_length()));
      w[std::size_t(edge(h, mesh))] += 0.5 * CGAL::to_double(u * v) / cr;
    }
  }
  double sum = 0;
  int count = 0;
  for(Edge e : edges(mesh))
    if(!is_border(e, mesh) && w[std::size_t(e)] > 0 && std::isfinite(w[std::size_t(e)])) { sum += w[std::size_t(e)]; ++count; }
  const double floor = 1e-3 * (count ? sum / count : 1.);
  for(double& x : w) x = x >= floor ? x : floor;
  return w;
}

std::vector<std::pair<Vertex, double>> random_singularities(const Mesh& mesh, long chi, int N, std::mt19937& rng)
{
  std::vector<Vertex> interior;
  for(Vertex v : vertices(mesh)) if(!is_border(v, mesh) && degree(v, mesh) > 0) interior.push_back(v);   // not isolated
  std::shuffle(interior.begin(), interior.end(), rng);
  std::vector<double> idx(std::size_t(N * std::labs(chi)), chi > 0 ? 1. / N : -1. / N);
  for(int p = 0; p < 4; ++p) { idx.push_back(1. / N); idx.push_back(-1. / N); }
  std::vector<std::pair<Vertex, double>> s;
  for(std::size_t i = 0; i < idx.size() && i < interior.size(); ++i) s.emplace_back(interior[i], idx[i]);
  return s;
}

// One solve: its tally (energy ratio filled in by the caller), or an error message.
struct Outcome
{
  Tally t;
  double energy = 0, unit_energy = 0;   // sum x_e^2 / w_e (cotan yardstick), sum x_e^2
  std::string error;
};

Outcome measure(const Mesh& mesh, SMDF::Trivial_connection<Mesh>& tc, const std::vector<std::pair<Vertex, double>>& sing,
                int N, const std::vector<double>& wref)
{
  Outcome o;
  const SMDF::Trivial_connection_status st = tc.solve();
  if(!st.success) { o.error = "solve failed: " + st.message; return o; }
  auto angles = get(CGAL::dynamic_face_property_t<double>(), mesh);
  tc.field_angles(angles);
  auto matching = get(CGAL::dynamic_edge_property_t<int>(), mesh);
  tc.field_matching(angles, matching);
  std::map<Vertex, double> want(sing.begin(), sing.end());
  auto same = [&](const SMDF::Field_topology<Mesh>& ft) {
    std::map<Vertex, double> got;
    for(const auto& s : ft.singularities) got[s.first] = s.second;
    if(got.size() != want.size()) return false;
    for(const auto& p : want) {
      auto it = got.find(p.first);
      if(it == got.end() || std::abs(it->second - p.second) > 1e-9) return false;
    }
    return true;
  };
  if(!same(SMDF::field_singularities(mesh, angles, SMDF::parameters::symmetry_order(N).matching(matching)))) {
    o.error = "read-back with the field's matching differs from the prescription";
    return o;
  }
  o.t.solves = 1;
  o.t.principal_exact = same(SMDF::field_singularities(mesh, angles, SMDF::parameters::symmetry_order(N)));
  o.t.max_rotation = st.max_rotation;
  o.t.own_energy = st.energy;
  o.t.beyond_half = long(st.edges_beyond_half_period);
  o.t.beyond_pi = long(st.edges_beyond_pi);
  o.t.beyond_pi_solves = st.edges_beyond_pi > 0;
  o.t.turned = st.generators_turned_for_rotation > 0;
  if(st.edges_beyond_pi > 0) {
    o.t.proven_beyond_pi = st.rotation_lower_bound > M_PI;
    o.t.proven_any_turning = st.rotation_bound_any_turning > M_PI;
    std::cerr << "  N=" << N << ": largest rotation " << st.max_rotation << " (" << st.rotation_limit_rounds
              << " limiting rounds), lower bound for these turning numbers " << st.rotation_lower_bound
              << ", for any turning numbers " << st.rotation_bound_any_turning << "\n";
  }
  if(st.generators_turned_for_rotation > 0)
    std::cerr << "  N=" << N << ": " << st.generators_turned_for_rotation << " turning numbers moved, largest rotation "
              << st.max_rotation << "\n";
  for(Edge e : edges(mesh)) {
    if(is_border(e, mesh)) continue;
    const double x = tc.adjustment_angle(halfedge(e, mesh));
    o.energy += x * x / wref[std::size_t(e)];
    o.unit_energy += x * x;
  }
  return o;
}

std::string fixed(double x, int digits)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

// All orders, rules, sets and turning modes on one mesh.
void study_mesh(const Mesh& mesh, const std::string& name, long chi, int sets, const std::vector<double>& wref,
                Tally (&per_mesh)[2][rule_count], bool& failed)
{
  for(int N : orders) {
    std::mt19937 rng(1000u + unsigned(N));
    std::vector<std::vector<std::pair<Vertex, double>>> all_sets;
    for(int s = 0; s < sets; ++s) all_sets.push_back(random_singularities(mesh, chi, N, rng));
    std::vector<double> cotan_energy[2], cotan_unit_energy[2];
    for(int r = first_rule; r < rule_count; ++r) {
      SMDF::Trivial_connection<Mesh> tc(mesh, SMDF::parameters::symmetry_order(N)
                                                  .connection_weights(rules[r].weights)
                                                  .cotangent_cap(rules[r].cap)
                                                  .rotation_limit(rules[r].rotation_limit));
      for(int s = 0; s < sets; ++s) {
        tc.clear_singularities();
        for(const auto& p : all_sets[std::size_t(s)]) tc.set_singularity(p.first, p.second);
        for(int mode = 0; mode < 2; ++mode) {
          if(mode == 0) for(std::size_t g = 0; g < tc.generators().size(); ++g) tc.set_generator_turning_number(g, 0);
          else if(tc.generators().empty()) break;
          else tc.choose_smoothest_generator_turning_numbers();
          Outcome o = measure(mesh, tc, all_sets[std::size_t(s)], N, wref);
          if(!o.error.empty()) {
            std::cerr << name << " N=" << N << " " << rules[r].name << ": " << o.error << "\n";
            failed = true;
            continue;
          }
          if(r == 0) { cotan_energy[mode].push_back(o.energy); cotan_unit_energy[mode].push_back(o.unit_energy); }
          if(cotan_energy[mode].size() > std::size_t(s)) {
            const double ref = cotan_energy[mode][std::size_t(s)], uref = cotan_unit_energy[mode][std::size_t(s)];
            if(ref > 0 && o.energy > 0) o.t.log_energy_ratio = std::log(o.energy / ref);
            if(uref > 0 && o.unit_energy > 0) o.t.log_unit_energy_ratio = std::log(o.unit_energy / uref);
          }
          per_mesh[mode][r].add(o.t);
        }
      }
    }
  }
}

} // namespace

int main(int argc, char** argv)
{
  int sets = 3;
  std::size_t max_faces = 400000;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--sets" && i + 1 < argc) sets = std::atoi(argv[++i]);
    else if(a == "--max-faces" && i + 1 < argc) max_faces = std::size_t(std::atol(argv[++i]));
    else if(a == "--default-only") first_rule = rule_count - 1;
    else files.push_back(a);
  }
  if(files.empty() || sets < 1) {
    std::cerr << "usage: study_connection_weights [--sets n] [--max-faces n] [--default-only] MESH...\n";
    return 2;
  }
  bool failed = false;
  Tally totals[2][rule_count];   // [turning: 0 / smoothest][rule]
  std::vector<std::string> rows[2];
  std::vector<std::string> turning_rows;   // energies with turning numbers 0 and smoothest
  for(const std::string& file : files) {
    const std::string name = file.substr(file.find_last_of('/') + 1);
    Mesh mesh;
    try {
      SMDF::read_triangle_mesh(file, mesh);
    } catch(const SMDF::Input_error& e) {
      std::cerr << name << ": skipped (" << e.what() << ")\n";
      continue;
    }
    const auto topo = SMDF::mesh_topology(mesh);
    if(topo.components.size() != 1 || num_faces(mesh) > max_faces) {
      std::cerr << name << ": skipped (" << topo.components.size() << " components, " << num_faces(mesh) << " faces)\n";
      continue;
    }
    const long chi = topo.euler_characteristic();
    const std::vector<double> wref = reference_cotan_weights(mesh);
    Tally per_mesh[2][rule_count];
    try {
      study_mesh(mesh, name, chi, sets, wref, per_mesh, failed);
    } catch(const SMDF::Input_error& e) {
      std::cerr << name << ": skipped (" << e.what() << ")\n";
      continue;
    }
    for(int mode = 0; mode < 2; ++mode) {
      if(per_mesh[mode][rule_count - 1].solves == 0) continue;
      std::string row = "| `" + name + "` | " + std::to_string(num_faces(mesh)) + " | " + std::to_string(topo.components[0].genus) +
                        (topo.boundary_loops.empty() ? "" : " (" + std::to_string(topo.boundary_loops.size()) + " b.)") + " |";
      for(int r = 0; r < rule_count; ++r) {
        const Tally& t = per_mesh[mode][r];
        row += " " + std::to_string(t.principal_exact) + "/" + std::to_string(t.solves) + ", " + fixed(t.max_rotation, 2) +
               (t.beyond_pi ? " (" + std::to_string(t.beyond_pi) + " > pi)" : "") + " |";
        totals[mode][r].add(t);
      }
      rows[mode].push_back(row);
    }
    if(per_mesh[1][rule_count - 1].solves > 0) {
      std::string row = "| `" + name + "` | " + std::to_string(topo.components[0].genus) + " | " + std::to_string(topo.betti_1()) + " |";
      for(int r : {0, rule_count - 1}) {
        const Tally &z = per_mesh[0][r], &sm = per_mesh[1][r];
        if(z.solves == 0 || sm.solves == 0) { row += " |"; continue; }
        const double e0 = z.own_energy / z.solves, es = sm.own_energy / sm.solves;
        row += " " + fixed(e0, 1) + " / " + fixed(es, 1) + " (" + fixed(es / e0, 3) + ") |";
      }
      turning_rows.push_back(row);
    }
    std::cerr << name << ": done\n";
  }
  for(int mode = 0; mode < 2; ++mode) {
    std::cout << "\n### Generator turning numbers " << (mode == 0 ? "0" : "smoothest (meshes with generators)") << "\n\n";
    std::cout << "| Weights | principal read-back exact | solves with an edge > pi (proven unavoidable: for these turning numbers / for any) | solves with turning numbers moved | edges > pi/N | edges > pi | largest rotation | cotan energy ratio | unit energy ratio |\n";
    std::cout << "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for(int r = 0; r < rule_count; ++r) {
      const Tally& t = totals[mode][r];
      if(t.solves == 0) continue;
      std::cout << "| " << rules[r].name << " | " << t.principal_exact << "/" << t.solves << " ("
                << fixed(100. * t.principal_exact / t.solves, 1) << "%) | " << t.beyond_pi_solves << " (" << t.proven_beyond_pi << " / "
                << t.proven_any_turning << ") | " << t.turned << " | " << t.beyond_half
                << " | " << t.beyond_pi << " | " << fixed(t.max_rotation, 2) << " | " << fixed(std::exp(t.log_energy_ratio / t.solves), 3)
                << " | " << fixed(std::exp(t.log_unit_energy_ratio / t.solves), 3) << " |\n";
    }
    std::cout << "\nPer mesh: principal read-back exact / solves, largest rotation (rad), edges > pi.\n\n| Mesh | faces | genus |";
    for(const Rule& r : rules) std::cout << " " << r.name << " |";
    std::cout << "\n| --- | --- | --- |";
    for(int r = 0; r < rule_count; ++r) std::cout << " --- |";
    std::cout << "\n";
    for(const std::string& row : rows[mode]) std::cout << row << "\n";
  }
  std::cout << "\n### Energy with generator turning numbers 0 / smoothest\n\nMean ||Dx||^2 over the solves of each mesh (its own weights), "
               "turning numbers 0 / smoothest (ratio).\n\n| Mesh | genus | generators | "
            << rules[0].name << " | " << rules[rule_count - 1].name << " |\n| --- | --- | --- | --- | --- |\n";
  for(const std::string& row : turning_rows) std::cout << row << "\n";
  return failed ? 1 : 0;
}
