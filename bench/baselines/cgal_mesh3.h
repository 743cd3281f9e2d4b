// CGAL 5.5's Mesh_3 from the input's boundary surface (Polyhedral_mesh_domain_with_features_3,
// sharp edges as features; make_mesh_3 with ODT, perturb and exude): a new mesh of the same domain
// at a comparable size, with a new surface mesh — the peer that, unlike the optimizers, may
// replace the surface (issue 17). One region only (CGAL's polyhedral domain has one inside).
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct CgalMesh3Options {
  double size = 0;  // facet_size, cell_size and edge_size; <= 0: the input's mean edge length
  double facet_distance = 0;  // <= 0: size / 10
  double facet_angle = 25;    // degrees
  double radius_edge_ratio = 3;
  double feature_angle = 40;  // dihedral angle (degrees) above which a surface edge is a feature
};

// Replaces `mesh` by CGAL's new mesh of the domain bounded by its boundary triangles (one region:
// the input's first region tag; every boundary triangle of surface patch 1 + i for CGAL's patch i).
// Throws InvariantError if the input has several regions or CGAL's mesh is invalid.
void cgal_mesh3(TetMesh& mesh, const CgalMesh3Options& options = {});

}  // namespace cvtmesh
