// How often, lately, the triangle walk has found a small triangle's block hidden in one tile
// (triangle_rasterize.cpp, "Hidden blocks"): it decides which blocks are tested, never what is
// drawn.
//
// The test costs about a fifth of what a hidden block's rows cost, so it pays where more than
// about one block in five is hidden (lit_spheres: 45% of its blocks, small_triangles: 3%). The
// score rises by 4 for a hidden block and falls by 1 for a visible one (it holds where one block
// in five is hidden); every block is tested while it is above 8, one in sixteen otherwise, to
// notice when hidden blocks come.
#pragma once

#include <algorithm>

namespace glass::raster {

struct HiddenBlockOdds {
  int score = 0;
  unsigned untested = 0;
  bool worthTesting() { return score > 8 || (++untested & 15u) == 0; }
  void record(bool hidden) { score = hidden ? std::min(score + 4, 64) : std::max(score - 1, 0); }
};

}  // namespace glass::raster
