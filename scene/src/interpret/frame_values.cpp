#include "glass/scene/frame_values.h"

#include <glass/geometry/quaternion.h>
#include <glass/geometry/rotation.h>

#include <cmath>

namespace glass::scene {

namespace {

// Rotation keys are angle-axis; interpolation goes through unit quaternions (study guide 2.3.3,
// equation 7) and slerp, which turns at a constant rate along the shorter arc.
std::vector<double> slerpRotation(const std::vector<double> &a, const std::vector<double> &b, double t) {
  geometry::Quaternion qa = geometry::rotationQuaternionDegrees({a[1], a[2], a[3]}, a[0]);
  geometry::Quaternion qb = geometry::rotationQuaternionDegrees({b[1], b[2], b[3]}, b[0]);
  geometry::AxisAngle result = geometry::axisAngleFromQuaternion(geometry::slerp(qa, qb, t));
  const double degrees = result.angle * (180.0 / 3.14159265358979323846);
  return {degrees, result.axis.x, result.axis.y, result.axis.z};
}

} // namespace

std::vector<double> parameterAt(const Parameter &parameter, double frame) {
  const std::vector<Keyframe> &keys = parameter.keys;
  if (keys.empty()) return parameter.value;
  if (frame <= keys.front().frame) return keys.front().value;
  if (frame >= keys.back().frame) return keys.back().value;
  std::size_t next = 1;
  while (keys[next].frame < frame) ++next;
  const Keyframe &k0 = keys[next - 1];
  const Keyframe &k1 = keys[next];
  double t = (frame - k0.frame) / (k1.frame - k0.frame);
  if (parameter.kind == Parameter::Kind::Rotation) return slerpRotation(k0.value, k1.value, t);
  std::vector<double> value(k0.value.size());
  for (std::size_t i = 0; i < value.size(); ++i) value[i] = k0.value[i] + t * (k1.value[i] - k0.value[i]);
  return value;
}

FrameValues evaluateParameters(const Program &program, int frame) {
  FrameValues values;
  for (const Parameter &parameter : program.parameters) {
    values.values.push_back(parameterAt(parameter, static_cast<double>(frame)));
  }
  return values;
}

} // namespace glass::scene
