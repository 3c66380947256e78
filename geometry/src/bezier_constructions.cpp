#include "glass/geometry/bezier_constructions.h"

#include <array>
#include <cmath>
#include <numbers>
#include "glass/geometry/portable_math.h"

namespace glass::geometry {
namespace {

// cos and sin, with the rounding residue of multiples of pi/2 (cos(pi/2) = 6e-17) set to 0, so
// that quarter arcs get control points like (0, -r, R) rather than (6e-17, -r, R).
double snapped(double value) { return std::abs(value) < 1e-15 ? 0.0 : value; }

}  // namespace

BezierCurve rationalQuadratic(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, double middleWeight) {
  const std::array<glm::dvec3, 3> points = {p0, p1, p2};
  const std::array<double, 3> weights = {1.0, middleWeight, 1.0};
  return BezierCurve(points, weights);
}

BezierCurve circularArc(double startAngle, double endAngle, const CirclePlacement& circle) {
  const double middle = 0.5 * (startAngle + endAngle);
  const double halfSpan = 0.5 * (endAngle - startAngle);
  const double middleWeight = portable::cos(halfSpan);
  const auto onCircle = [&](double angle, double distance) {
    return circle.center + distance * (snapped(portable::cos(angle)) * circle.xAxis + snapped(portable::sin(angle)) * circle.yAxis);
  };
  // The end tangents meet on the bisector at distance r / cos(h) from the centre.
  return rationalQuadratic(onCircle(startAngle, circle.radius), onCircle(middle, circle.radius / middleWeight),
                           onCircle(endAngle, circle.radius), middleWeight);
}

std::vector<BezierCurve> fullCircle(int arcCount, const CirclePlacement& circle) {
  std::vector<BezierCurve> arcs;
  if (arcCount < 3) return arcs;
  const double step = 2.0 * std::numbers::pi / arcCount;
  for (int k = 0; k < arcCount; ++k) arcs.push_back(circularArc(k * step, (k + 1) * step, circle));
  return arcs;
}

BezierSurface curvilinearTriangle() {
  const double s = std::numbers::sqrt2 / 2.0;
  const std::array<glm::dvec3, 6> points = {
      glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(1.0, 1.0, 0.0), glm::dvec3(0.0, 1.0, 0.0),  // u = 0: the arc
      glm::dvec3(1.0, 1.0, 0.0), glm::dvec3(1.0, 1.0, 0.0), glm::dvec3(1.0, 1.0, 0.0),  // u = 1: the corner
  };
  const std::array<double, 6> weights = {1.0, s, 1.0, 1.0, s, 1.0};
  return BezierSurface(1, 2, points, weights);
}

BezierSurface revolve(const BezierCurve& profile, double startAngle, double endAngle, const RevolutionFrame& frame) {
  // The arc on the unit circle of the frame gives the angular control "directions" and weights.
  const BezierCurve arc = circularArc(startAngle, endAngle);
  const int degreeV = profile.degree();
  std::vector<glm::dvec4> net;
  net.reserve(static_cast<std::size_t>(3 * (degreeV + 1)));
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 direction = arc.controlPoint(static_cast<std::size_t>(i));
    const glm::dvec3 radial = direction.x * frame.zeroDirection + direction.y * frame.quarterDirection;
    for (int j = 0; j <= degreeV; ++j) {
      const glm::dvec4& h = profile.homogeneousControlPoints()[static_cast<std::size_t>(j)];
      const double w = h.w;
      // The profile point (rho, height) = h.xy / w; in homogeneous form w (origin + height axis +
      // rho radial) = w origin + h.y axis + h.x radial, times the arc weight.
      const glm::dvec3 weightedPoint = w * frame.origin + h.y * frame.axis + h.x * radial;
      const double arcWeight = arc.weight(static_cast<std::size_t>(i));
      net.emplace_back(arcWeight * weightedPoint, arcWeight * w);
    }
  }
  return BezierSurface::fromHomogeneous(2, degreeV, std::move(net));
}

namespace {

BezierCurve profileSegment(double rho0, double height0, double rho1, double height1) {
  const std::array<glm::dvec3, 2> points = {glm::dvec3(rho0, height0, 0.0), glm::dvec3(rho1, height1, 0.0)};
  return BezierCurve(points);
}

// The exam torus turns about y, with phi = 0 along +z and phi = pi/2 along +x:
// (z, x, y) is right-handed, so normals point out of the tube.
RevolutionFrame examTorusFrame() {
  RevolutionFrame frame;
  frame.axis = {0.0, 1.0, 0.0};
  frame.zeroDirection = {0.0, 0.0, 1.0};
  frame.quarterDirection = {1.0, 0.0, 0.0};
  return frame;
}

}  // namespace

BezierSurface cylinderPatch(double radius, double height, double startAngle, double endAngle) {
  return revolve(profileSegment(radius, 0.0, radius, height), startAngle, endAngle);
}

BezierSurface conePatch(double radius, double height, double startAngle, double endAngle) {
  return revolve(profileSegment(radius, 0.0, 0.0, height), startAngle, endAngle);
}

BezierSurface spherePatch(double radius, double startLongitude, double endLongitude, double startLatitude,
                          double endLatitude) {
  CirclePlacement meridian;
  meridian.radius = radius;
  return revolve(circularArc(startLatitude, endLatitude, meridian), startLongitude, endLongitude);
}

std::vector<BezierSurface> spherePatches(double radius) {
  constexpr double quarter = std::numbers::pi / 2.0;
  std::vector<BezierSurface> patches;
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 2; ++l) patches.push_back(spherePatch(radius, k * quarter, (k + 1) * quarter, (l - 1) * quarter, l * quarter));
  return patches;
}

BezierSurface torusPatch(double majorRadius, double minorRadius, double startPhi, double endPhi, double startTheta,
                         double endTheta) {
  CirclePlacement tube;
  tube.center = {majorRadius, 0.0, 0.0};
  tube.radius = minorRadius;
  return revolve(circularArc(startTheta, endTheta, tube), startPhi, endPhi, examTorusFrame());
}

BezierSurface torusSixteenth(double majorRadius, double minorRadius, TorusSixteenth piece) {
  constexpr double pi = std::numbers::pi;
  return piece == TorusSixteenth::Outer ? torusPatch(majorRadius, minorRadius, 0.0, pi / 2.0, -pi / 2.0, 0.0)
                                        : torusPatch(majorRadius, minorRadius, 0.0, pi / 2.0, -pi, -pi / 2.0);
}

std::vector<BezierSurface> torusPatches(double majorRadius, double minorRadius) {
  constexpr double quarter = std::numbers::pi / 2.0;
  std::vector<BezierSurface> patches;
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 4; ++l)
      patches.push_back(torusPatch(majorRadius, minorRadius, k * quarter, (k + 1) * quarter, l * quarter - 2.0 * quarter,
                                   (l + 1) * quarter - 2.0 * quarter));
  return patches;
}

}  // namespace glass::geometry
