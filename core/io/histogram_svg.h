// The quality histograms of one or several meshes overlaid, as an SVG picture (`cvtmesh stats
// --histogram`, `compare --save`): fraction of elements per Q bin, one outline per mesh, the
// paper's bin edges (0.3, 0.5, 0.7) marked, a legend with each mesh's count, Q_min and average.
#pragma once
#include <string>
#include <vector>

#include "core/io/atomic_file.h"
#include "core/quality/quality_histogram.h"

namespace cvtmesh {

// The SVG text (pure; what write_histogram_svg writes).
std::string histogram_svg(const std::vector<QualityHistogram>& series);

// What write_histogram_svg would refuse before any work: not a .svg, a missing directory.
// Throws OutputError.
void check_histogram_path(const std::string& path);

// Writes it atomically. Throws OutputError (cannot write, not a .svg, refused by the policy).
void write_histogram_svg(const std::vector<QualityHistogram>& series, const std::string& path,
                         const OutputPolicy& policy = {});

}  // namespace cvtmesh
