// The GL calls that draw the polyhedral rebuild of a 3D IFS (glass::geometry's
// polyhedralRebuild): what the scene language's `ifs3d` statement draws, and what
// `glass ifs3d view` draws in its window, so that both give the same pixels.
#pragma once

#include <vector>

#include <glass/geometry/ifs3d.h>

namespace glass::scene {

// One glBegin(GL_TRIANGLES) ... glEnd() with a glNormal3d per triangle (its face's outward
// normal, for flat shading) and, when `partColors`, a glColor3f wherever the part changes: the
// map's colour, or the palette's (light grey for the base itself, part -1). The current colour
// and normal are left as the last triangle set them.
void drawIfs3Rebuild(const geometry::IteratedFunctionSystem3 &ifs,
                     const std::vector<geometry::RebuildTriangle> &triangles, bool partColors);

} // namespace glass::scene
