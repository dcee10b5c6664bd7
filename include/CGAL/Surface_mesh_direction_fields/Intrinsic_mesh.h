// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_MESH_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_MESH_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

namespace internal {
// Number of Intrinsic_mesh objects built from a mesh (not copies, not with_edge_lengths()), so
// that tests can check that a pipeline builds its intrinsic mesh once.
inline std::atomic<std::size_t>& intrinsic_mesh_builds()
{
  static std::atomic<std::size_t> n{0};
  return n;
}
} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// One triangle mesh under one metric, built once and shared by the algorithms of the package:
/// connectivity, edge lengths, corner angles, angle defects, connected components, boundary
/// loops, and the tree-cotree homology generators (computed on first use).
///
/// Every algorithm that needs these (`Trivial_connection`, field_singularities(),
/// `Intrinsic_holonomy`, compute_cone_metric(), ...) accepts one through the `intrinsic_mesh`
/// named parameter and otherwise builds its own, so that a pipeline such as
/// "trivial connection, then read-back" builds it once:
/// \code
/// SMDF::Trivial_connection<Mesh> tc(mesh);                      // builds one
/// ...
/// SMDF::field_singularities(mesh, angles,
///     SMDF::parameters::intrinsic_mesh(tc.intrinsic_mesh()));    // reuses it
/// \endcode
/// When an `intrinsic_mesh` is given, it replaces the `edge_length_map`, `vertex_point_map`
/// and index-map parameters of that call.
///
/// Copies are cheap and share the data (a reference-counted handle to immutable arrays); the
/// mesh must outlive every copy and must not be modified while they are in use.
/// with_edge_lengths() gives the same mesh under another metric (e.g. a flat cone metric)
/// and shares the topology and the generators.
///
/// \warning Numbers are `double` internally, whatever the kernel of the points: coordinates
/// are converted with `CGAL::to_double()` and lengths, angles and curvatures are computed in
/// double precision.
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
template <typename TriangleMesh>
class Intrinsic_mesh
{
public:
  typedef typename internal::Mesh_arrays<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename internal::Mesh_arrays<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename internal::Mesh_arrays<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename internal::Mesh_arrays<TriangleMesh>::face_descriptor face_descriptor;

  /// Builds the intrinsic mesh of `tm`. Throws `Input_error` for non-triangle faces,
  /// non-manifold vertices, non-finite or degenerate lengths, and index maps that are not
  /// bijections.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{edge_length_map}
  ///     \cgalParamDescription{the metric}
  ///     \cgalParamType{a readable property map with `edge_descriptor` keys and `double` values}
  ///     \cgalParamDefault{Euclidean lengths from `vertex_point_map`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{vertex positions (for the default metric)}
  ///     \cgalParamType{a readable property map with `vertex_descriptor` keys and 3D point values of any kernel}
  ///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits}
  ///     \cgalParamDescription{the kernel whose `Compute_squared_distance_3` gives the default metric (converted to `double` once per edge)}
  ///     \cgalParamType{a model of `Kernel`}
  ///     \cgalParamDefault{the kernel of the points of `vertex_point_map`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{numbers the vertices 0 .. n-1: the numbers used in messages and in the order of internal arrays}
  ///     \cgalParamType{a readable property map with `vertex_descriptor` keys and integer values (a bijection)}
  ///     \cgalParamDefault{the order of `vertices(tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{face_index_map, edge_index_map}
  ///     \cgalParamDescription{the same for faces and edges}
  ///     \cgalParamDefault{the order of `faces(tm)`, `edges(tm)`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Intrinsic_mesh(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
    : tm_(&tm)
  {
    auto metric = std::make_shared<Metric>(tm, np);
    shared_ = std::make_shared<Shared>(metric->arrays);
    metric_ = std::move(metric);
    ++internal::intrinsic_mesh_builds();
  }

  /// The same mesh, numbering, topology and generators under the metric `lengths` (a readable
  /// property map with `edge_descriptor` keys and `double` values). Throws `Input_error` for
  /// non-finite lengths and faces that violate the triangle inequality.
  template <typename EdgeLengthMap>
  Intrinsic_mesh with_edge_lengths(const EdgeLengthMap& lengths) const
  {
    std::vector<double> l(number_of_edges());
    for(std::size_t e = 0; e < l.size(); ++e) l[e] = double(get(lengths, arrays().edges[e]));
    for(std::size_t e = 0; e < l.size(); ++e)
      if(!std::isfinite(l[e]))
        throw Input_error(Input_error::INVALID_GEOMETRY,
                          "edge " + std::to_string(e) + " has a non-finite length");
    // copies the connectivity arrays once (linear, a memcpy); topology and generators are shared
    auto metric = std::make_shared<Metric>(metric_->arrays);
    metric->arrays.set_lengths(l);
    internal::vertex_curvatures(metric->arrays, metric->curvature);
    Intrinsic_mesh r(*this);
    r.metric_ = std::move(metric);
    return r;
  }

  /// The mesh this object was built on.
  const TriangleMesh& triangle_mesh() const { return *tm_; }
  /// `true` if this object was built on `tm` (the same object, not a copy of it).
  bool is_built_on(const TriangleMesh& tm) const { return tm_ == &tm; }

  /// The number of vertices (isolated ones included).
  std::size_t number_of_vertices() const { return arrays().number_of_vertices(); }
  /// The number of edges.
  std::size_t number_of_edges() const { return arrays().number_of_edges(); }
  /// The number of faces.
  std::size_t number_of_faces() const { return arrays().number_of_faces(); }

  /// The index of `v` (its position in the numbering, see `vertex_index_map`).
  std::size_t vertex_index(vertex_descriptor v) const { return std::size_t(arrays().vertex_index(v)); }
  /// The index of `f`.
  std::size_t face_index(face_descriptor f) const { return std::size_t(arrays().face_index(f)); }
  /// The index of `e`.
  std::size_t edge_index(edge_descriptor e) const { return std::size_t(arrays().edge_index(e, *tm_)); }
  /// The vertex of index `i`.
  vertex_descriptor vertex(std::size_t i) const { return arrays().vertices.at(i); }
  /// The face of index `i`.
  face_descriptor face(std::size_t i) const { return arrays().faces.at(i); }
  /// The edge of index `i`.
  edge_descriptor edge(std::size_t i) const { return arrays().edges.at(i); }

  /// The length of `e` in this metric.
  double edge_length(edge_descriptor e) const { return arrays().length[edge_index(e)]; }
  /// The corner angle of `face(h)` at `source(h)` (0 if `h` is a border halfedge).
  double corner_angle(halfedge_descriptor h) const { return arrays().angle[std::size_t(arrays().halfedge_index(h, *tm_))]; }
  /// The angle defect \f$2\pi - \sum\theta\f$ of an interior vertex, the geodesic curvature
  /// \f$\pi - \sum\theta\f$ of a boundary vertex, 0 for an isolated vertex.
  double vertex_curvature(vertex_descriptor v) const { return metric_->curvature[vertex_index(v)]; }

  /// The homology generators, as tree_cotree_generators() gives them (computed once, on the
  /// first call of this or of any algorithm that needs them; thread-safe).
  const std::vector<Homology_generator<TriangleMesh>>& generators() const
  {
    shared_->build_generators(arrays(), *tm_);
    return shared_->public_generators;
  }

#ifndef DOXYGEN_RUNNING
  // The arrays the algorithms run on.
  const internal::Mesh_arrays<TriangleMesh>& arrays() const { return metric_->arrays; }
  const internal::Topology_arrays& topology_arrays() const { return shared_->topology; }
  const std::vector<double>& curvatures() const { return metric_->curvature; }
  const std::vector<internal::Generator_arrays>& generator_arrays() const
  {
    shared_->build_generators(arrays(), *tm_);
    return shared_->generators;
  }
#endif

private:
  struct Metric
  {
    internal::Mesh_arrays<TriangleMesh> arrays;
    std::vector<double> curvature;
    template <typename NamedParameters>
    Metric(const TriangleMesh& tm, const NamedParameters& np) : arrays(tm, np)
    {
      internal::vertex_curvatures(arrays, curvature);
    }
    explicit Metric(const internal::Mesh_arrays<TriangleMesh>& a) : arrays(a) {}
  };
  // What does not depend on the metric.
  struct Shared
  {
    internal::Topology_arrays topology;
    std::once_flag generators_once;
    std::vector<internal::Generator_arrays> generators;
    std::vector<Homology_generator<TriangleMesh>> public_generators;

    explicit Shared(const internal::Mesh_arrays<TriangleMesh>& m) : topology(m) {}
    void build_generators(const internal::Mesh_arrays<TriangleMesh>& m, const TriangleMesh& tm)
    {
      std::call_once(generators_once, [&] {
        generators = internal::tree_cotree(m, topology);
        public_generators = internal::to_homology_generators(m, generators, tm);
      });
    }
  };

  const TriangleMesh* tm_;
  std::shared_ptr<const Metric> metric_;
  std::shared_ptr<Shared> shared_;
};

namespace internal {

// The intrinsic mesh of a call: the `intrinsic_mesh` parameter of `np` if given (it must have
// been built on `tm`), else one built from `np`.
template <typename TriangleMesh, typename NamedParameters>
Intrinsic_mesh<TriangleMesh> get_intrinsic_mesh(const TriangleMesh& tm, const NamedParameters& np)
{
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::intrinsic_mesh_t>::value) {
    const Intrinsic_mesh<TriangleMesh>& im = parameters::get_parameter(np, internal_np::intrinsic_mesh);
    if(!im.is_built_on(tm))
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "the intrinsic_mesh parameter was built on another mesh than the one passed");
    return im;
  } else {
    return Intrinsic_mesh<TriangleMesh>(tm, np);
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_MESH_H
