#include "walk_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glass::cli::view {

namespace {

enum class Axis { None, X, Z };

// The first contact of the walker's centre, moving from `from` by `motion`, with one grown
// footprint: the fraction t of the motion (0 <= t < 1 when there is a contact) and the axis of
// the side met.
struct Contact {
  double t = std::numeric_limits<double>::infinity();
  Axis axis = Axis::None;
  double side = 0.0; // the coordinate of that side along its axis
};

// A walker inside the grown box: only a motion deeper past the nearest side is stopped (at once).
Contact contactFromInside(const Footprint &g, GroundPoint from, GroundPoint motion) {
  struct Side {
    double depth, motionOutward, coordinate;
    Axis axis;
  };
  const Side sides[4] = {{from.x - g.minX, -motion.x, g.minX, Axis::X},
                         {g.maxX - from.x, motion.x, g.maxX, Axis::X},
                         {from.z - g.minZ, -motion.z, g.minZ, Axis::Z},
                         {g.maxZ - from.z, motion.z, g.maxZ, Axis::Z}};
  const Side *nearest = &sides[0];
  for (const Side &s : sides) {
    if (s.depth < nearest->depth) nearest = &s;
  }
  Contact contact;
  if (nearest->motionOutward < 0.0) {
    contact.t = 0.0;
    contact.axis = nearest->axis;
    contact.side = nearest->axis == Axis::X ? from.x : from.z; // held where it is on that axis
  }
  return contact;
}

// The slab test of a segment against a box: the segment enters the box at the latest of the
// entry times of the two slabs [minX, maxX] and [minZ, maxZ] and leaves at the earliest exit.
// Open slabs: a centre exactly on a side is outside, so touching a side does not stop a motion
// along it.
Contact contactFromOutside(const Footprint &g, GroundPoint from, GroundPoint motion) {
  double enter = -std::numeric_limits<double>::infinity();
  double leave = std::numeric_limits<double>::infinity();
  Contact contact;
  auto slab = [&](double start, double delta, double low, double high, Axis axis) {
    if (delta == 0.0) {
      if (!(start > low && start < high)) leave = -std::numeric_limits<double>::infinity();
      return;
    }
    double tLow = (low - start) / delta, tHigh = (high - start) / delta;
    double sideEntered = low;
    if (tLow > tHigh) {
      std::swap(tLow, tHigh);
      sideEntered = high;
    }
    if (tLow > enter) {
      enter = tLow;
      contact.axis = axis;
      contact.side = sideEntered;
    }
    leave = std::min(leave, tHigh);
  };
  slab(from.x, motion.x, g.minX, g.maxX, Axis::X);
  slab(from.z, motion.z, g.minZ, g.maxZ, Axis::Z);
  if (enter < leave && enter >= 0.0 && enter < 1.0) {
    contact.t = enter;
  } else {
    contact.axis = Axis::None;
  }
  return contact;
}

} // namespace

GroundPoint slideMove(GroundPoint from, GroundPoint motion, double radius,
                      const std::vector<Footprint> &obstacles) {
  if (!std::isfinite(motion.x) || !std::isfinite(motion.z) || !std::isfinite(from.x) ||
      !std::isfinite(from.z)) {
    return from;
  }
  const double r = std::isfinite(radius) ? std::max(radius, 0.0) : 0.0;
  // Each contact zeroes one axis of the motion, so after two the motion is spent; the third pass
  // only confirms that nothing is left.
  for (int pass = 0; pass < 3 && (motion.x != 0.0 || motion.z != 0.0); ++pass) {
    Contact first;
    for (const Footprint &f : obstacles) {
      const Footprint g{f.minX - r, f.minZ - r, f.maxX + r, f.maxZ + r};
      const bool inside = from.x > g.minX && from.x < g.maxX && from.z > g.minZ && from.z < g.maxZ;
      const Contact c = inside ? contactFromInside(g, from, motion) : contactFromOutside(g, from, motion);
      if (c.axis != Axis::None && c.t < first.t) first = c;
    }
    if (first.axis == Axis::None) {
      from.x += motion.x;
      from.z += motion.z;
      break;
    }
    // Up to the contact; the coordinate across the side is set to the side itself, so that
    // rounding cannot leave the walker a hair inside the obstacle.
    GroundPoint at{from.x + motion.x * first.t, from.z + motion.z * first.t};
    const double rest = 1.0 - first.t;
    GroundPoint along{motion.x * rest, motion.z * rest};
    if (first.axis == Axis::X) {
      at.x = first.side;
      along.x = 0.0;
    } else {
      at.z = first.side;
      along.z = 0.0;
    }
    from = at;
    motion = along;
  }
  return from;
}

} // namespace glass::cli::view
