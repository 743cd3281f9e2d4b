// A .msh saved by Gmsh with physical groups holds only the elements of those groups: boundary
// triangles (lines in 2D) of surfaces outside every group are not in the file, although their
// nodes are, classified on their entities. This restores them in the current Gmsh model.
#pragma once

namespace cvtmesh {

// For the current Gmsh model and mesh dimension dim (3: tets, 2: triangles): every face (edge)
// of the simplices that lies on the domain boundary or between two volumes (surfaces) and is
// not an element yet becomes a triangle (line) element on the surface (curve) it belongs to: the
// entity its nodes are classified on, or, for a facet whose nodes all lie on curves and points,
// the boundary entity of its volume whose closure holds them. New elements get fresh tags.
// Facets with nothing to go by (a file with tets only, no surface entities) go to a new entity,
// and the nodes are then reclassified from the elements (gmsh reclassifyNodes).
// Returns the number of facets added. Requires a live GmshSession.
long add_missing_facets(int dim);

}  // namespace cvtmesh
