// An SVG picture of a planar triangle mesh, each triangle filled with a colour for its quality
// (the paper's Q by default), the constrained edges drawn thicker, with a colour bar.
#pragma once
#include <string>

#include "core/io/atomic_file.h"
#include "core/mesh/tri_mesh2.h"
#include "core/quality/quality.h"

namespace cvtmesh {

struct SvgOptions {
  double width = 800;             // picture width in px (height follows the mesh's aspect)
  Measure measure = Measure::kQ;  // colour: kQ / kRadiusRatio in [q_low, 1], angles in degrees
  double q_low = 0.5;             // quality mapped to the "worst" colour (and below)
  double q_high = 1.0;            // quality mapped to the "best" colour
  bool colour_bar = true;
  std::string title;  // drawn above the mesh if not empty
  OutputPolicy policy{
      .force = true, .input_path = {}, .in_place = false};  // replace existing files
};

// Writes mesh to path (atomically). Throws OutputError if it cannot be written.
void write_svg(const TriMesh2& mesh, const std::string& path, const SvgOptions& options = {});

}  // namespace cvtmesh
