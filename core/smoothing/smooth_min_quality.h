// Optimization-based smoothing of the worst elements (Freitag & Ollivier-Gooch style): each free
// vertex of a poor tet moves to raise the minimum quality of its star (steepest ascent of the
// active worst element with a line search). A move is kept only if the star's minimum rises; no
// element is ever inverted. Topology is unchanged.
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/quality/quality.h"

namespace cvtmesh {

struct MinQualitySmoothOptions {
  Measure measure = Measure::kQ;
  double threshold = 0.4;  // vertices of tets below this quality are treated
  double target = 0.5;     // a vertex stops moving once its star's minimum reaches this
  int passes = 3;
  int max_steps = 12;  // ascent steps per vertex
};

struct MinQualitySmoothStats {
  int nb_moved = 0;
  double min_before = 0, min_after = 0;
};

MinQualitySmoothStats smooth_min_quality(TetMesh& mesh,
                                         const MinQualitySmoothOptions& options = {});

}  // namespace cvtmesh
