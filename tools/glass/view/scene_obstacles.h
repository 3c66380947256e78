// What a walker collides with in a scene (`glass view`'s walk mode): the world-space bounding
// boxes of what the scene draws, and from them the footprints that stand in the walker's way.
//
// World space is the space the scene's `lookat` is written in: the viewer's camera replaces that
// statement, so every transform after it (translate, rotate, scale, matrix, push/pop, instances)
// takes a shape's own coordinates to world space. docs/glut.md ("Walking and collisions") lists
// which statements give boxes.
#pragma once

#include "walk_collision.h"

#include <glass/geometry/axis_aligned_box.h>
#include <glass/scene/program.h>

#include <vector>

namespace glass::cli::view {

// The bounding boxes, in world space, of the solid things frame `frame` of the program draws:
// one box per polygon of a `begin`/`end` block (triangles, quads, strips, fans, polygons) and per
// `rect`; one box per mesh, model, quadric, GLUT shape, parametric torus and Bezier patch (its
// control points). Points, lines, curves, IFS drawings and anything drawn under a
// `shadow_matrix` (a shadow lies on a surface, it is not a solid) give none.
std::vector<geometry::AxisAlignedBox> sceneBoxes(const scene::Program &program, int frame);

// The walker's body, in scene units.
struct WalkerBody {
  double radius = 0.3;    // how close the eye comes to an obstacle, along x and along z
  double eyeHeight = 1.6; // the eye above the ground
  double climb = 0.3;     // what it steps over: things that reach no higher above the ground
};

// The ground the walker stands on and what stands in its way there.
struct WalkGround {
  double groundY = 0.0; // the lowest point of the scene (its boxes' smallest y)
  std::vector<Footprint> obstacles;
};

// The footprints (x and z extent) of the boxes that reach into the walker's body: higher than
// groundY + climb and lower than groundY + eyeHeight. A floor (no higher than `climb`) and what
// hangs above the eye (a lamp) are not obstacles.
WalkGround walkGround(const std::vector<geometry::AxisAlignedBox> &boxes, const WalkerBody &body);

} // namespace glass::cli::view
