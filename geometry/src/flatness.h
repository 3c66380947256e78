// The flatness tests that stop adaptive subdivision (see tessellation.h for the bounds they give).
// Private to the library.
#pragma once

#include "glass/geometry/bezier_curve.h"
#include "glass/geometry/bezier_surface.h"
#include "glass/geometry/tessellation.h"

namespace glass::geometry::detail {

// True when the piece of a patch may be drawn as triangles between its corners (and the vertices
// its neighbours put on its sides) under the criterion.
bool isFlatEnough(const BezierSurface& piece, const AdaptiveOptions& options);
// True when the piece of a curve may be drawn as its chord.
bool isFlatEnough(const BezierCurve& piece, const AdaptiveOptions& options);

}  // namespace glass::geometry::detail
