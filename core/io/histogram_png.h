// The quality histogram picture (core/io/histogram_svg.h) as a PNG: our SVG rasterized by
// librsvg's `rsvg-convert` (Debian package librsvg2-bin), run as a child process. It renders the
// SVG's text with the system's fonts (fontconfig); ImageMagick's SVG reader does not work under
// Debian's default policy, and a PNG drawn by us would need a font of its own.
#pragma once
#include <string>
#include <vector>

#include "core/io/atomic_file.h"
#include "core/quality/quality_histogram.h"

namespace cvtmesh {

// The rasterizer's path: $CVTMESH_RSVG_CONVERT if set (a path or a name; empty: none), else
// rsvg-convert found in $PATH; "" if there is none.
std::string histogram_png_rasterizer();

// Throws OutputError naming `path` and the missing program (and its Debian package) if there is
// no rasterizer: what write_histogram_png would refuse before any work.
void check_histogram_png(const std::string& path);

// Writes the PNG (760 x 440 pixels, white background) atomically: the SVG goes to a temporary
// file, rsvg-convert writes the temporary of `path`, which is renamed only if it is a PNG.
// Throws OutputError (no rasterizer, it failed -- its message is quoted --, cannot write).
void write_histogram_png(const std::vector<QualityHistogram>& series, const std::string& path,
                         const OutputPolicy& policy = {});

}  // namespace cvtmesh
