// What TetGen 1.5's error codes (thrown as int by terminatetetgen) mean, for messages.
#pragma once
#include <string>

namespace cvtmesh {

// E.g. 3 -> "the boundary self-intersects (TetGen error 3)".
std::string tetgen_error(int code);

}  // namespace cvtmesh
