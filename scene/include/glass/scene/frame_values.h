// The values of a scene's parameters at one frame: declared values, replaced by --set, or
// interpolated between the keys of `animate` (linearly for numbers, by quaternion slerp for
// rotations).
#pragma once

#include "glass/scene/program.h"

#include <vector>

namespace glass::scene {

struct FrameValues {
  // values[p] holds parameter p's numbers; a rotation is angle (degrees), axis x, y, z.
  std::vector<std::vector<double>> values;

  double operator()(const Number &n) const {
    return n.isConstant() ? n.constant
                          : values[static_cast<std::size_t>(n.parameter)][static_cast<std::size_t>(n.component)];
  }
};

FrameValues evaluateParameters(const Program &program, int frame);

// The value of one parameter at a frame (exposed for tests).
std::vector<double> parameterAt(const Parameter &parameter, double frame);

} // namespace glass::scene
