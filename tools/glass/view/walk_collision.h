// Walking on the ground plane without passing through obstacles: the walker is a square of half
// side `radius` moving in x and z, each obstacle an axis-aligned rectangle (the footprint of a
// box), so that the walker stays at least `radius` away from every obstacle along x and along z. A
// move is swept, not sampled, so a long step cannot jump over a thin wall; when the walker meets
// an obstacle it stops at contact and keeps the part of its motion along the obstacle's side
// ("collide and slide", as first-person games move their player).
//
// Pure geometry, no window and no GL: `glass view` (view_command.cpp) calls it for each step of
// walk mode, and tests/glut/view_model_test.cpp checks it.
#pragma once

#include <vector>

namespace glass::cli::view {

// A point or a motion on the ground plane.
struct GroundPoint {
  double x = 0.0, z = 0.0;
};

// An obstacle's footprint: the rectangle [minX, maxX] x [minZ, maxZ] on the ground plane.
struct Footprint {
  double minX = 0.0, minZ = 0.0, maxX = 0.0, maxZ = 0.0;
};

// Where a walker of radius `radius` at `from` ends up when it tries to move by `motion`.
//
// The walker's centre moves along the segment from `from` to `from + motion` and is tested against
// each footprint grown by `radius` on every side (the Minkowski sum of the rectangle and the
// walker's square): the first contact stops it there, the component of the rest of the motion
// across the side it touched is dropped and the component along that side goes on, tested again
// (so it slides along a wall, and stops in a concave corner). Touching a side and moving along it
// or away from it is free. A walker that starts inside a grown footprint (placed there by a
// viewpoint) may move in any way that does not take it deeper past that footprint's nearest side,
// so it can walk out but not further in.
GroundPoint slideMove(GroundPoint from, GroundPoint motion, double radius,
                      const std::vector<Footprint> &obstacles);

} // namespace glass::cli::view
