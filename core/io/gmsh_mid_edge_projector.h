// The CAD of the current Gmsh model as a MidEdgeProjector (place_mid_edge_nodes.h): an order-2
// mesh's boundary mid-edge nodes go on the model's curves and surfaces (gmsh::model::
// getClosestPoint, the kernel's orthogonal projection). Entities that are not CAD ("Discrete
// ...", or unknown to the model) are declined. Use it while the model is current in a live
// GmshSession (cvtmesh optimize on a .geo / .step / .brep; the in-process front ends).
#pragma once
#include "core/io/place_mid_edge_nodes.h"

namespace cvtmesh {

MidEdgeProjector gmsh_cad_mid_edge_projector();

}  // namespace cvtmesh
