// The reference geometry of a model's boundary, behind one interface: the closest point on a
// surface patch or on a curve. Two implementations: the input boundary triangulation itself
// (core/boundary/discrete_boundary.h, CGAL AABB trees) and the CAD entities of a live Gmsh model
// (core/io/gmsh_cad_boundary.h). The boundary moves (core/boundary/*) see only this interface.
// In the geometry layer (no dependency) so that both core/boundary/ and core/io/ implement it.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace cvtmesh {

class BoundaryGeometry {
 public:
  virtual ~BoundaryGeometry() = default;
  // The closest point q (3 doubles) to p on surface patch `surface` (an id of this geometry:
  // see BoundaryModel::role). Returns false if the patch is unknown or the query failed.
  virtual bool closest_on_surface(int surface, const double* p, double* q) const = 0;
  // The closest point q to p on curve `curve`. false if unknown or the query failed.
  virtual bool closest_on_curve(int curve, const double* p, double* q) const = 0;
  // Distance from p to the whole reference boundary (every surface patch): the input-side term
  // of the Hausdorff distance.
  virtual double distance_to_boundary(const double* p) const = 0;
  // Whether distance_to_boundary(p) <= r; a geometry may answer it faster (the discrete one
  // stops at the first triangle within r instead of finding the closest).
  virtual bool within_distance(const double* p, double r) const {
    return distance_to_boundary(p) <= r;
  }
  // Points sampling the reference boundary (#S by 3), to measure the distance from it to the new
  // boundary (the other side of the Hausdorff distance). May be empty (then one side only).
  virtual std::vector<double> samples() const = 0;
  // "discrete" or "cad".
  virtual const char* kind() const = 0;
  // Whether the queries may run concurrently (the Gmsh API may not).
  virtual bool thread_safe() const { return true; }
};

// What a boundary vertex may do.
enum class BoundaryRole : std::int8_t {
  kInterior = 0,  // not on the boundary: the volume operators move it (vclass.dim == 3)
  kFixed = 1,     // a corner, on a locked or periodic entity, or not classifiable: never moves
  kCurve = 2,     // slides along curve `entity` of the geometry
  kSurface = 3,   // moves on surface patch `entity` of the geometry
};

struct VertexRole {
  BoundaryRole role = BoundaryRole::kInterior;
  int entity = -1;  // the geometry's curve or surface id (kCurve, kSurface)
};

// A boundary that may move: the reference geometry and what each vertex of the mesh may do.
struct BoundaryModel {
  std::shared_ptr<const BoundaryGeometry> geometry;
  std::vector<VertexRole> role;  // #V of the mesh it was built for; vertices beyond: interior
  double diagonal = 0;           // bounding-box diagonal of the input mesh
  // How far the input boundary itself is from the reference geometry: 0 for the discrete one
  // (the input triangulation is the reference); for a CAD model the input mesh's chord error
  // (its triangles' centroids and edge midpoints to their surface). The Hausdorff bound of a run
  // is on top of it: no new boundary point farther from the CAD than the input was, plus the
  // tolerance.
  double reference_deviation = 0;
  // #V by 3: the input positions (the reference boundary's own vertices for the boundary ones);
  // a vertex's new fan must pass within the Hausdorff tolerance of its input position (the
  // reference -> new side of the Hausdorff distance, checked locally at every move).
  std::vector<double> input_xyz;
  int nb_surface_vertices = 0, nb_curve_vertices = 0, nb_fixed_vertices = 0;
  // The curves' edges as vertex pairs (smaller id first, sorted), when the builder knows them
  // (the discrete geometry: its feature edges; no operator flips or splits them, so they stay the
  // curves' edges). Unknown (the CAD geometry): empty, curve_edges_known false.
  std::vector<std::array<int, 2>> curve_edges;
  bool curve_edges_known = false;

  VertexRole role_of(int v) const {
    return v < static_cast<int>(role.size()) ? role[v] : VertexRole{};
  }
  // Whether the boundary edge (a, b) may lie on a curve: one of curve_edges if they are known;
  // otherwise whenever neither end is a surface vertex.
  bool may_be_curve_edge(int a, int b) const {
    if (curve_edges_known)
      return std::binary_search(curve_edges.begin(), curve_edges.end(),
                                std::array<int, 2>{std::min(a, b), std::max(a, b)});
    return role_of(a).role != BoundaryRole::kSurface && role_of(b).role != BoundaryRole::kSurface;
  }
  bool movable(int v) const {
    const BoundaryRole r = role_of(v).role;
    return r == BoundaryRole::kCurve || r == BoundaryRole::kSurface;
  }
};

// What the builders of a BoundaryModel are told.
struct BoundaryModelOptions {
  double feature_angle = 40;         // degrees: a sharper turn across an edge is a feature
  std::vector<int> locked_surfaces;  // Gmsh surface tags whose vertices stay fixed
  std::vector<int> locked_curves;    // Gmsh curve tags whose vertices stay fixed
  // Gmsh's curves and points where the surface is smooth (no turn above feature_angle across
  // them, e.g. the patch boundaries of a reparametrized STL) are not features: the patches on
  // both sides are one, and their vertices move on it (their triangles keep their surface tags;
  // the curve's line elements follow the vertices). false (default): every Gmsh curve is kept.
  // (Discrete geometry only.)
  bool free_smooth_curves = false;
};

}  // namespace cvtmesh
