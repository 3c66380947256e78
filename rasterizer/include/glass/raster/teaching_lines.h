// The study guide's three line-drawing algorithms (section 2.1, Listings 1-3), generalised to all
// octants, plus GL's diamond-exit rule, each returning the grid squares it would fill. These are
// teaching and benchmarking functions: GL_LINES in the pipeline uses rasterizeLine.
//
// Every function is symmetric: swapping the endpoints gives the same set of squares (the guide's
// requirement, Figure 2.2). Ties, where two squares are equally far from the true line, are broken
// by a rule that does not depend on the direction of travel.
#pragma once

#include <vector>

namespace glass::raster {

struct GridPixel {
  int x, y;
  bool operator==(const GridPixel&) const = default;
};

// Endpoints are grid squares (integer centres). Each returns the squares from (x0, y0) to
// (x1, y1) inclusive, in order of travel from the first endpoint.
std::vector<GridPixel> lineFloat(int x0, int y0, int x1, int y1);       // Listing 1
std::vector<GridPixel> lineInteger(int x0, int y0, int x1, int y1);     // Listing 2
std::vector<GridPixel> lineBresenham(int x0, int y0, int x1, int y1);   // Listing 3
// GL's rule for a width-1 segment between square centres (x0 + 0.5, y0 + 0.5) and
// (x1 + 0.5, y1 + 0.5); like GL, it leaves out the last square.
std::vector<GridPixel> lineDiamondExit(int x0, int y0, int x1, int y1);

// Variants that write into a caller-owned buffer and return the count, for timing without
// allocation (the buffer must hold max(|dx|, |dy|) + 1 pixels).
int lineFloatInto(int x0, int y0, int x1, int y1, GridPixel* out);
int lineIntegerInto(int x0, int y0, int x1, int y1, GridPixel* out);
int lineBresenhamInto(int x0, int y0, int x1, int y1, GridPixel* out);

}  // namespace glass::raster
