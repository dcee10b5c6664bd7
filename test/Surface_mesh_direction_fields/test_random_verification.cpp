// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Randomised verification at scale over the shared meshes (Surface_mesh and Polyhedron_3):
// at least 1000 random trivial-connection solves (N in {1, 2, 3, 4, 6}, indices +-k/N with
// |k| <= 3 summing to the Euler characteristic, random generator turning numbers, random hard
// constraints and soft guides, cotan or unit weights), each checked by the read-back of its
// field with its own matching, the residual and the constraints, a subset against the SPQR
// minimum-norm reference; and at least 200 random cone sets for compute_cone_metric(), each
// checked by recomputing the curvature of the output metric. Prints the counts.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "test_util.h"

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

struct Counts
{
  int solves = 0, polyhedron_solves = 0, with_constraints = 0, with_guides = 0, spqr_compared = 0;
  int cone_sets = 0, cone_sets_with_flips = 0;
};

template <typename Mesh>
class Random_trials
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

public:
  Random_trials(const Mesh& mesh, const std::string& name, std::mt19937& rng, Counts& counts)
    : mesh_(mesh), name_(name), rng_(rng), counts_(counts)
  {
    for(auto v : vertices(mesh)) if(!is_border(v, mesh)) interior_.push_back(v);
    faces_.assign(faces(mesh).begin(), faces(mesh).end());
    closed_ = interior_.size() == num_vertices(mesh);
    chi_ = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  }

  // Indices k/N with 1 <= |k| <= 3 at random interior vertices, summing to chi when closed.
  std::map<vertex_descriptor, int> random_indices(int N)
  {
    std::map<vertex_descriptor, int> k;
    const int count = int(rng_() % 6);
    for(int i = 0; i < count; ++i) {
      int v = int(rng_() % 7) - 3;
      if(v == 0) v = 1;
      k[interior_[rng_() % interior_.size()]] = v;
    }
    if(closed_) {
      long sum = 0;
      for(const auto& p : k) sum += p.second;
      long deficit = chi_ * N - sum;
      while(deficit != 0) {   // +-1 steps on random vertices, keeping |k| <= 3
        const int step = deficit > 0 ? 1 : -1;
        int& kv = k[interior_[rng_() % interior_.size()]];
        if(std::abs(kv + step) > 3) continue;
        kv += step;
        deficit -= step;
      }
    }
    for(auto it = k.begin(); it != k.end();) it = it->second == 0 ? k.erase(it) : std::next(it);
    return k;
  }

  std::vector<std::pair<face_descriptor, double>> random_faces(int count)
  {
    std::vector<std::pair<face_descriptor, double>> r;
    std::vector<char> used(faces_.size(), 0);
    for(int i = 0; i < count; ++i) {
      const std::size_t f = rng_() % faces_.size();
      if(used[f]++) continue;
      r.emplace_back(faces_[f], std::uniform_real_distribution<double>(0, 2 * M_PI)(rng_));
    }
    return r;
  }

  // One object, several solves with new random data (the first solve factors it).
  void run(int solves)
  {
    const int Ns[5] = {1, 2, 3, 4, 6};
    const int N = Ns[rng_() % 5];
    const SMDF::Connection_weights w = rng_() % 2 ? SMDF::COTAN_WEIGHTS : SMDF::UNIT_WEIGHTS;
    SMDF::Trivial_connection<Mesh> tc(mesh_, SMDF::parameters::symmetry_order(N).connection_weights(w));
    // constraints and guides fixed per object (changing the constrained faces refactors)
    const auto constraints = rng_() % 3 == 0 ? random_faces(1 + int(rng_() % 3)) : decltype(random_faces(0))();
    tc.set_directional_constraints(constraints);
    std::vector<std::pair<face_descriptor, double>> guides;
    if(rng_() % 5 == 0) {
      for(const auto& g : random_faces(2 + int(rng_() % 3))) {
        bool taken = false;
        for(const auto& c : constraints) taken = taken || c.first == g.first;
        if(!taken) guides.push_back(g);
      }
      tc.set_guide_directions(guides, std::pow(10., std::uniform_real_distribution<double>(-2, 2)(rng_)));
    }
    for(int s = 0; s < solves; ++s) {
      tc.clear_singularities();
      const auto k = random_indices(N);
      for(const auto& p : k) tc.set_singularity(p.first, double(p.second) / N);
      std::vector<double> turning(tc.generators().size());
      for(std::size_t g = 0; g < turning.size(); ++g) {
        turning[g] = double(int(rng_() % 5) - 2) / N;
        tc.set_generator_turning_number(g, turning[g]);
      }
      if(!constraints.empty()) {   // new angles, same faces: no refactorisation
        auto c = constraints;
        for(auto& p : c) p.second = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng_);
        tc.set_directional_constraints(c);
        check(tc, k, turning, N, c, guides.empty() && s % 10 == 0);
      } else {
        check(tc, k, turning, N, constraints, guides.empty() && s % 10 == 0);
      }
      ++counts_.solves;
      if(std::is_same<Mesh, Polyhedron>::value) ++counts_.polyhedron_solves;
      if(!constraints.empty()) ++counts_.with_constraints;
      if(!guides.empty()) ++counts_.with_guides;
    }
  }

  // Random cone sets: multiples of pi/2 below 2 pi summing to 2 pi chi; the output metric's
  // recomputed curvature must be the target at every vertex.
  void cone_sets(int count)
  {
    for(int i = 0; i < count; ++i) {
      std::map<vertex_descriptor, int> q;   // curvature in quarter turns
      const int n = 1 + int(rng_() % 6);
      for(int c = 0; c < n; ++c) q[interior_[rng_() % interior_.size()]] = int(rng_() % 5) - 3;   // -3 .. 1
      long deficit = 4 * chi_;
      for(const auto& p : q) deficit -= p.second;
      while(deficit != 0) {
        const int step = deficit > 0 ? 1 : -1;
        int& kv = q[interior_[rng_() % interior_.size()]];
        if(kv + step > 3 || kv + step < -6) continue;
        kv += step;
        deficit -= step;
      }
      auto target = get(CGAL::dynamic_vertex_property_t<double>(), mesh_);
      for(auto v : vertices(mesh_)) put(target, v, 0.);
      for(const auto& p : q) put(target, p.first, p.second * M_PI / 2);
      auto out = get(CGAL::dynamic_edge_property_t<double>(), mesh_);
      const SMDF::Cone_metric_status st = SMDF::compute_cone_metric(mesh_, target, out);
      const std::string what = name_ + ", random cone set #" + std::to_string(i) + " (" + std::to_string(q.size()) + " cones)";
      SMDF_CHECK_MSG(st.converged, what << ": " << st.message);
      ++counts_.cone_sets;
      if(!st.converged) continue;
      // recompute the curvature from the output lengths, on the mesh or on the triangulation
      double err = 0;
      if(!st.triangulation_changed) {
        auto k = get(CGAL::dynamic_vertex_property_t<double>(), mesh_);
        SMDF::compute_vertex_curvatures(mesh_, k, SMDF::parameters::edge_length_map(out));
        for(auto v : vertices(mesh_)) err = (std::max)(err, std::abs(get(k, v) - get(target, v)));
      } else {
        ++counts_.cone_sets_with_flips;
        Surface_mesh tri;
        auto len = tri.add_property_map<Surface_mesh::Edge_index, double>("e:l", 0.).first;
        SMDF::copy_intrinsic_triangulation(st.intrinsic_triangulation, mesh_, tri, len);
        auto k = tri.add_property_map<Surface_mesh::Vertex_index, double>("v:k", 0.).first;
        SMDF::compute_vertex_curvatures(tri, k, SMDF::parameters::edge_length_map(len));
        std::size_t j = 0;
        for(auto v : vertices(mesh_)) err = (std::max)(err, std::abs(k[Surface_mesh::Vertex_index(Surface_mesh::size_type(j++))] - get(target, v)));
      }
      SMDF_CHECK_MSG(err <= 1e-9 + st.rounding_level, what << ": recomputed curvature off by " << err
                                                          << " (rounding level " << st.rounding_level << ")");
    }
  }

private:
  void check(SMDF::Trivial_connection<Mesh>& tc, const std::map<vertex_descriptor, int>& k,
             const std::vector<double>& turning, int N,
             const std::vector<std::pair<face_descriptor, double>>& constraints, bool compare_spqr)
  {
    const std::string what = name_ + ", N = " + std::to_string(N) + ", " + std::to_string(k.size()) + " singularities";
    const SMDF::Trivial_connection_status st = tc.solve();
    SMDF_CHECK_MSG(st.success && st.scaled_residual <= 1e-9, what << ": " << st.message);
    auto angles = get(CGAL::dynamic_face_property_t<double>(), mesh_);
    auto matching = get(CGAL::dynamic_edge_property_t<int>(), mesh_);
    tc.field_angles(angles, 0.7);
    const double off = tc.field_matching(angles, matching);
    SMDF_CHECK_MSG(off < 1e-8, what << ": matching off the lattice by " << off);
    const SMDF::Field_topology<Mesh> back = SMDF::field_singularities(
        mesh_, angles, SMDF::parameters::symmetry_order(N).matching(matching).intrinsic_mesh(tc.intrinsic_mesh()));
    std::map<vertex_descriptor, int> found;
    for(const auto& p : back.singularities) found[p.first] = int(std::lround(p.second * N));
    SMDF_CHECK_MSG(found == k, what << ": read back " << found.size() << " singularities with the matching");
    SMDF_CHECK_MSG(back.generator_turning_numbers == turning, what << ": turning numbers read back");
    double cerr = 0;
    for(const auto& c : constraints)
      cerr = (std::max)(cerr, std::abs(std::remainder(get(angles, c.first) - c.second, 2 * M_PI / N)));
    SMDF_CHECK_MSG(cerr < 1e-8, what << ": directional constraints met to " << cerr);
    if(!compare_spqr) return;
    // the SPQR minimum-norm reference (default weights) against the same problem on CHOLMOD
    ++counts_.spqr_compared;
    const auto np = SMDF::parameters::symmetry_order(N).intrinsic_mesh(tc.intrinsic_mesh()).rotation_limit(0);   // minimum norm
    SMDF::Trivial_connection<Mesh> ref(mesh_, np.solver(SMDF::SPQR_MINIMUM_NORM)), same(mesh_, np);
    for(SMDF::Trivial_connection<Mesh>* t : {&ref, &same}) {
      for(const auto& p : k) t->set_singularity(p.first, double(p.second) / N);
      for(std::size_t g = 0; g < turning.size(); ++g) t->set_generator_turning_number(g, turning[g]);
      t->set_directional_constraints(constraints);
    }
    const auto s1 = ref.solve(), s2 = same.solve();
    double d = 0, scale = 1;
    for(auto h : halfedges(mesh_)) {
      d = (std::max)(d, std::abs(ref.adjustment_angle(h) - same.adjustment_angle(h)));
      scale = (std::max)(scale, std::abs(ref.adjustment_angle(h)));
    }
    SMDF_CHECK_MSG(s1.success && s2.success && d <= 1e-8 * scale, what << ": CHOLMOD vs SPQR minimum norm, max |dx| = " << d);
  }

  const Mesh& mesh_;
  std::string name_;
  std::mt19937& rng_;
  Counts& counts_;
  std::vector<vertex_descriptor> interior_;
  std::vector<face_descriptor> faces_;
  bool closed_ = true;
  long chi_ = 0;
};

int main()
{
  const std::string dir = smdf_test::shared_data_dir();
  if(dir.empty()) {
    std::cout << "../shared/data not found: randomised verification skipped" << std::endl;
    return 77;
  }
  std::mt19937 rng(20261201);
  Counts counts;
  std::vector<std::string> files;
  for(const auto& e : smdf_test::read_manifest(dir))
    if(e.manifold == "yes" && e.pure_tri == "yes" && e.orientable == "yes" && e.degenerate_faces == 0 &&
       e.components == 1 && e.F <= 14000)
      files.push_back(e.file);
  std::cout << files.size() << " meshes" << std::endl;
  int cone_meshes = 0;
  for(std::size_t i = 0; i < files.size(); ++i) {
    Surface_mesh sm;
    try { SMDF::read_triangle_mesh(dir + "/meshes/" + files[i], sm); }
    catch(const SMDF::Input_error& e) { std::cout << files[i] << ": skipped, " << e.what() << std::endl; continue; }
    Random_trials<Surface_mesh> ts(sm, files[i], rng, counts);
    for(int object = 0; object < 10; ++object) ts.run(6);
    const bool closed = CGAL::is_closed(sm);
    if(closed) { ts.cone_sets(18); ++cone_meshes; }
    if(i % 3 == 0) {   // every third mesh also as a Polyhedron_3
      Polyhedron p;
      SMDF::read_triangle_mesh(dir + "/meshes/" + files[i], p);
      Random_trials<Polyhedron> tp(p, files[i] + " (Polyhedron_3)", rng, counts);
      for(int object = 0; object < 4; ++object) tp.run(6);
    }
  }
  std::cout << counts.solves << " random solves (" << counts.polyhedron_solves << " on Polyhedron_3, "
            << counts.with_constraints << " with directional constraints, " << counts.with_guides
            << " with guides, " << counts.spqr_compared << " compared with SPQR), " << counts.cone_sets
            << " random cone sets on " << cone_meshes << " closed meshes (" << counts.cone_sets_with_flips
            << " on an intrinsic triangulation)" << std::endl;
  SMDF_CHECK(counts.solves >= 1000);
  SMDF_CHECK(counts.cone_sets >= 200);
  return smdf_test::finish();
}
