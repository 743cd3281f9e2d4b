#include "core/swap/swap_plan.h"

namespace cvtmesh {

const char* swap_status_name(SwapStatus s) {
  switch (s) {
    case SwapStatus::kOk:
      return "ok";
    case SwapStatus::kRejected:
      return "rejected by the criterion";
    case SwapStatus::kConstrainedFace:
      return "would remove a constrained face";
    case SwapStatus::kBoundary:
      return "on the boundary";
    case SwapStatus::kMixedRegions:
      return "tets of different regions";
    case SwapStatus::kNotConvex:
      return "a new tet would be inverted or flat";
    case SwapStatus::kRingSize:
      return "unsupported number of tets around the edge";
    case SwapStatus::kInteriorVertex:
      return "a vertex lies inside the cavity";
  }
  return "?";
}

}  // namespace cvtmesh
