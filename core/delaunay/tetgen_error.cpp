#include "core/delaunay/tetgen_error.h"

namespace cvtmesh {

std::string tetgen_error(int code) {
  const char* what = "unknown failure";
  switch (code) {
    case 1:
      what = "out of memory";
      break;
    case 2:
      what = "internal error";
      break;
    case 3:
      what = "the boundary self-intersects";
      break;
    case 4:
      what = "a very small input feature (near-coincident points or edges)";
      break;
    case 5:
      what = "two nearly coincident input facets";
      break;
    case 10:
      what = "invalid input";
      break;
    default:
      break;
  }
  return std::string(what) + " (TetGen error " + std::to_string(code) + ")";
}

}  // namespace cvtmesh
