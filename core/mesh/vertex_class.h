// Classification of a vertex on the model: the Gmsh entity of lowest dimension it lies on.
#pragma once
#include <cstdint>

namespace cvtmesh {

struct VertexClass {
  std::int8_t dim = 3;  // 0 corner, 1 on a curve, 2 on a surface, 3 (or 2 in a 2D mesh) interior
  int entity = 0;       // Gmsh entity tag of that dimension (0 if unknown)
};

}  // namespace cvtmesh
