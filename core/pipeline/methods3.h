// The runners of the 3D methods (defined in core/pipeline/optimize.cpp), one per row of the
// method registry (core/pipeline/method_registry.cpp). Each takes validated, resolved options.
#pragma once
#include "core/pipeline/method_registry.h"

namespace cvtmesh {

void run_cvdt3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r);
void run_cvdt_swap3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r);
void run_cvdt_swap_smooth3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r);
void run_combined3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r);
void run_swap3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r);
void run_polish3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r);

}  // namespace cvtmesh
