// The quality histograms of one or several meshes overlaid, as an SVG picture (`cvtmesh stats
// --histogram`, `compare --save`; as PNG through core/io/histogram_png.h): fraction of elements per
// Q bin, one outline per mesh, the paper's bin edges (0.3, 0.5, 0.7) marked, a legend with each
// mesh's count, Q_min and average.
#pragma once
#include <string>
#include <vector>

#include "core/io/atomic_file.h"
#include "core/quality/quality_histogram.h"

namespace cvtmesh {

// The SVG text (pure; what write_histogram_svg writes).
std::string histogram_svg(const std::vector<QualityHistogram>& series);

// What write_histogram would refuse before any work: neither .svg nor .png, a missing directory,
// a .png without its rasterizer (core/io/histogram_png.h). Throws OutputError.
void check_histogram_path(const std::string& path);

// Writes it atomically. Throws OutputError (cannot write, not a .svg, refused by the policy).
void write_histogram_svg(const std::vector<QualityHistogram>& series, const std::string& path,
                         const OutputPolicy& policy = {});

// The picture in the format of path's extension: .svg (write_histogram_svg) or .png
// (write_histogram_png). Throws OutputError.
void write_histogram(const std::vector<QualityHistogram>& series, const std::string& path,
                     const OutputPolicy& policy = {});

}  // namespace cvtmesh
