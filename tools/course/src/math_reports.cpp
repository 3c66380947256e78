#include "glass/course/math_reports.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>

#include "glass/course/exact_number.h"
#include "glass/geometry/affine_decomposition.h"
#include "glass/geometry/bezier_constructions.h"
#include "glass/geometry/quaternion.h"
#include "glass/geometry/rotation.h"
#include "glass/geometry/triangle_normal.h"
#include "glass/geometry/portable_math.h"

namespace glass::course {

namespace g = glass::geometry;

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

std::string vec(const glm::dvec3& v) {
  return std::string("(") + compact(v.x) + ", " + compact(v.y) + ", " + compact(v.z) + ")";
}
std::string vecDecimal(const glm::dvec3& v) {
  return std::string("(") + decimal(v.x) + ", " + decimal(v.y) + ", " + decimal(v.z) + ")";
}

// Display width in code points, so that "√" counts once.
std::size_t displayWidth(const std::string& s) {
  std::size_t length = 0;
  for (unsigned char ch : s) length += (ch & 0xC0) != 0x80 ? 1 : 0;
  return length;
}

std::string padRight(const std::string& s, std::size_t width) {
  const std::size_t w = displayWidth(s);
  return w >= width ? s : s + std::string(width - w, ' ');
}

// The rows "[ a  b  c ]" of a matrix, columns right-aligned.
std::vector<std::string> matrixLines(const std::vector<std::vector<double>>& rows) {
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> widths;
  for (const auto& row : rows) {
    cells.emplace_back();
    for (std::size_t c = 0; c < row.size(); ++c) {
      cells.back().push_back(compact(row[c]));
      if (widths.size() <= c) widths.push_back(0);
      widths[c] = std::max(widths[c], displayWidth(cells.back().back()));
    }
  }
  std::vector<std::string> lines;
  for (const auto& row : cells) {
    std::string line = "[ ";
    for (std::size_t c = 0; c < row.size(); ++c) {
      line += std::string(widths[c] - displayWidth(row[c]), ' ') + row[c] + (c + 1 < row.size() ? "  " : " ");
    }
    lines.push_back(line + "]");
  }
  return lines;
}

// Matrices side by side, as a product is written, the label on the first row.
std::string matrices(const std::string& label, const std::vector<std::vector<std::vector<double>>>& factors,
                     const std::string& indent) {
  std::vector<std::vector<std::string>> blocks;
  std::size_t height = 0;
  for (const auto& factor : factors) {
    blocks.push_back(matrixLines(factor));
    height = std::max(height, blocks.back().size());
  }
  std::string out;
  for (std::size_t r = 0; r < height; ++r) {
    std::string line = indent + (r == 0 ? label : std::string(displayWidth(label), ' '));
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      const std::size_t width = displayWidth(blocks[b].front());
      line += padRight(r < blocks[b].size() ? blocks[b][r] : "", width) + (b + 1 < blocks.size() ? " " : "");
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  return out;
}

std::string matrix(const std::string& label, const std::vector<std::vector<double>>& rows, const std::string& indent) {
  return matrices(label, {rows}, indent);
}

std::vector<std::vector<double>> rowsOf(const glm::dmat3& m) {
  std::vector<std::vector<double>> rows(3, std::vector<double>(3));
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) rows[r][c] = m[c][r];
  return rows;
}

std::vector<std::vector<double>> rowsOf(const g::Affine2& a) {
  return {{a.m[0][0], a.m[0][1], a.m[0][2]}, {a.m[1][0], a.m[1][1], a.m[1][2]}, {0.0, 0.0, 1.0}};
}

// w + x i + y j + z k with the zero terms left out and unit coefficients unwritten.
std::string quaternion(const g::Quaternion& q) {
  std::string out;
  auto term = [&out](double value, const char* unit) {
    if (std::abs(value) < 1e-12) return;
    const bool negative = value < 0;
    std::string magnitude = compact(std::abs(value));
    if (*unit != '\0' && magnitude == "1") magnitude.clear();
    out += out.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    out += magnitude;
    if (*unit != '\0') out += magnitude.empty() ? unit : std::string(" ") + unit;
  };
  term(q.w, "");
  term(q.x, "i");
  term(q.y, "j");
  term(q.z, "k");
  return out.empty() ? "0" : out;
}

std::string degrees(double radians) { return compact(radians * kDegreesPerRadian); }

// The first non-zero component positive: the guide's answer picks (1/√2, 0, -1/√2).
glm::dvec3 canonicalSign(glm::dvec3 u) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(u[i]) > 1e-12) return u[i] < 0 ? -u : u;
  }
  return u;
}

}  // namespace

std::string rotateComposeReport(const std::vector<RotationStep>& rotations) {
  std::ostringstream out;
  if (rotations.empty()) return "No rotations given.\n";
  const std::size_t n = rotations.size();
  auto name = [](const char* letter, std::size_t i) { return std::string(letter) + std::to_string(i + 1); };
  // "R3 R2 R1": the product, right to left.
  auto product = [&](const char* letter) {
    std::string s;
    for (std::size_t i = n; i-- > 0;) s += name(letter, i) + (i > 0 ? " " : "");
    return s;
  };

  out << "Rotations, in the order they are applied:\n";
  for (std::size_t i = 0; i < n; ++i) {
    out << "  " << name("R", i) << ": " << compact(rotations[i].degrees) << " degrees about "
        << vec(rotations[i].axis) << "\n";
  }

  // (a) Matrices.
  out << "\n(a) By matrices. Equation 9 gives the matrix of each rotation:\n";
  glm::dmat3 m(1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dmat3 r = g::rotationMatrixDegrees(rotations[i].axis, rotations[i].degrees);
    out << matrix(name("R", i) + " = ", rowsOf(r), "  ");
    m = g::composeRotations(m, r);
  }
  if (n > 1) {
    out << "  The composite is M = " << product("R") << " (right to left: " << name("R", 0)
        << " acts first):\n";
  }
  out << matrix("M = ", rowsOf(m), "  ");
  auto e = [&m](int row, int column) { return m[column - 1][row - 1]; };  // 1-based, as the guide
  const double cosTheta = (e(1, 1) + e(2, 2) + e(3, 3) - 1.0) / 2.0;
  const glm::dvec3 skew{e(3, 2) - e(2, 3), e(1, 3) - e(3, 1), e(2, 1) - e(1, 2)};  // 2 sin(theta) u
  const double sinTheta = glm::length(skew) / 2.0;
  const double theta = portable::atan2(sinTheta, cosTheta);
  out << "  cos(theta) = (m11 + m22 + m33 - 1) / 2 = " << describe(cosTheta) << "\n";
  out << "  sin(theta) = |(m32 - m23, m13 - m31, m21 - m12)| / 2 = " << describe(sinTheta) << "\n";
  out << "  theta = " << degrees(theta) << " degrees\n";
  constexpr double kTiny = 1e-9;
  if (sinTheta > kTiny) {
    out << "  u = (m32 - m23, m13 - m31, m21 - m12) / (2 sin(theta)) = " << vec(skew / (2.0 * sinTheta)) << "\n";
  } else if (cosTheta > 0) {
    out << "  M is the identity: no rotation, and no axis.\n";
  } else {
    // theta = pi: M = 2 u u^T - I. The diagonal gives the squares, the off-diagonal the signs.
    out << "  At 180 degrees the skew-symmetric part vanishes and equation 9 reads M = 2 u u^T - I:\n";
    glm::dvec3 squares{(e(1, 1) + 1) / 2, (e(2, 2) + 1) / 2, (e(3, 3) + 1) / 2};
    out << "    u1^2 = (m11 + 1)/2 = " << compact(squares.x) << ",  u2^2 = (m22 + 1)/2 = "
        << compact(squares.y) << ",  u3^2 = (m33 + 1)/2 = " << compact(squares.z) << "\n";
    out << "    2 u1 u2 = m12 = " << compact(e(1, 2)) << ",  2 u1 u3 = m13 = " << compact(e(1, 3))
        << ",  2 u2 u3 = m23 = " << compact(e(2, 3)) << "\n";
    int pivot = 0;
    for (int i = 1; i < 3; ++i) pivot = squares[i] > squares[pivot] ? i : pivot;
    glm::dvec3 u(0.0);
    u[pivot] = std::sqrt(std::max(squares[pivot], 0.0));
    for (int i = 0; i < 3; ++i) {
      if (i != pivot) u[i] = e(pivot + 1, i + 1) / (2.0 * u[pivot]);
    }
    u = canonicalSign(glm::normalize(u));
    out << "    u = ±" << vec(u) << ": the sign is not unique at 180 degrees\n";
  }

  // (b) Quaternions.
  out << "\n(b) By quaternions. Equation 7, q = cos(theta/2) + sin(theta/2) u, for each rotation:\n";
  g::Quaternion q{1, 0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const g::Quaternion qi = g::rotationQuaternionDegrees(rotations[i].axis, rotations[i].degrees);
    const std::string half = compact(rotations[i].degrees / 2.0);
    out << "  " << name("q", i) << " = cos(" << half << ") + sin(" << half << ") "
        << vec(glm::normalize(rotations[i].axis)) << " = " << quaternion(qi) << "\n";
    q = g::composeRotations(q, qi);
  }
  if (n > 1) out << "  The composite is q = " << product("q") << " = " << quaternion(q) << "\n";
  const g::AxisAngle byQuaternion = g::axisAngleFromQuaternion(q);
  const double w = q.w < 0 ? -q.w : q.w;
  out << "  cos(theta/2) = " << describe(w) << (q.w < 0 ? " (of -q, the same rotation)" : "")
      << ", so theta = " << degrees(byQuaternion.angle) << " degrees";
  if (byQuaternion.angle > 0) out << ", u = Im(q) / sin(theta/2) = " << vec(byQuaternion.axis);
  out << "\n";

  // The answer, and the cross-check of (a) and (b).
  const g::AxisAngle answer = g::axisAngleFromMatrix(m);
  const glm::dmat3 fromQuaternion = g::rotationMatrix(q);
  double difference = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) difference = std::max(difference, std::abs(fromQuaternion[c][r] - m[c][r]));
  out << "\nAnswer: ";
  if (answer.angle == 0.0) {
    out << "no rotation (the identity)\n";
  } else {
    out << degrees(answer.angle) << " degrees about " << vec(answer.axis);
    if (vec(answer.axis) != vecDecimal(answer.axis)) out << " = " << vecDecimal(answer.axis);
    if (answer.angle == std::numbers::pi) out << " (or its negative: the same rotation at 180 degrees)";
    out << "\n";
  }
  out << "(a) and (b) agree: the matrix of q equals M (largest difference " << decimal(difference) << ")\n";
  return out.str();
}

std::string decomposeReport(const g::Affine2& a) {
  std::ostringstream out;
  out << matrix("A = ", rowsOf(a), "");
  const auto d = g::decomposeAffine(a);
  if (!d) {
    out << "A is not invertible (det = " << describe(a.determinant())
        << "): it flattens the plane, and no product of a rotation, shear and non-zero scalings "
           "does that.\n";
    return out.str();
  }
  const double c1x = a.m[0][0], c1y = a.m[1][0], c2x = a.m[0][1], c2y = a.m[1][1];
  out << "A = T(u) L with u = (a13, a23) = (" << compact(d->translateX) << ", " << compact(d->translateY)
      << ") (equation 3), and L the linear part\n";
  out << "Columns of L: c1 = (" << compact(c1x) << ", " << compact(c1y) << "), c2 = (" << compact(c2x) << ", "
      << compact(c2y) << "), c1 . c2 = " << compact(c1x * c2x + c1y * c2y) << "\n";
  out << "c1 = s1 (cos theta, sin theta) with theta in (-90, 90] degrees: theta = " << degrees(d->rotationRadians)
      << " degrees, s1 = " << describe(d->scaleX) << "\n";
  if (!d->needsShear) {
    out << "The columns are orthogonal, so no shear is needed: L = R(theta) S(s1, s2) with\n";
    out << "s2 = c2 . (-sin theta, cos theta) = " << describe(d->scaleY) << "\n\n";
    out << "A = T(" << compact(d->translateX) << ", " << compact(d->translateY) << ") R(" << degrees(d->rotationRadians)
        << " degrees) S(" << compact(d->scaleX) << ", " << compact(d->scaleY) << ")\n";
  } else {
    out << "The columns are not orthogonal, so L = R(theta) H(h) S(s1, s2) with the shear H(h) = [1 h; 0 1]\n"
           "(the QR factorisation of L: R(theta) times the upper triangular [s1 h s2; 0 s2]):\n";
    out << "s2 = c2 . (-sin theta, cos theta) = " << describe(d->scaleY) << "\n";
    out << "h s2 = c2 . (cos theta, sin theta) = " << describe(d->shear * d->scaleY) << ", h = " << describe(d->shear)
        << "\n\n";
    out << "A = T(" << compact(d->translateX) << ", " << compact(d->translateY) << ") R(" << degrees(d->rotationRadians)
        << " degrees) H(" << compact(d->shear) << ") S(" << compact(d->scaleX) << ", " << compact(d->scaleY) << ")\n";
  }
  std::vector<std::vector<std::vector<double>>> factors{rowsOf(g::Affine2::translation(d->translateX, d->translateY)),
                                                        rowsOf(g::Affine2::rotation(d->rotationRadians))};
  if (d->needsShear) factors.push_back(rowsOf(g::Affine2::shear(d->shear)));
  factors.push_back(rowsOf(g::Affine2::scaling(d->scaleX, d->scaleY)));
  out << matrices("  = ", factors, "");
  const g::Affine2 check = d->product();
  double difference = 0.0;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(check.m[r][c] - a.m[r][c]));
  out << "(applied right to left: scale first, then " << (d->needsShear ? "shear, then " : "")
      << "rotate, then translate; the product equals A to " << decimal(difference) << ")\n";
  return out.str();
}

std::string viewReport(const g::SphereViewProblem& problem) {
  std::ostringstream out;
  out << "Eye E = " << vec(problem.eye) << ", sphere centre C = " << vec(problem.center)
      << ", radius r = " << compact(problem.radius) << "\n";
  out << "The image should be " << compact(problem.heightShare) << " of the window's height and "
      << compact(problem.widthShare) << " of its width, with " << compact(problem.visibleFraction)
      << " of the sphere visible.\n";
  const g::SphereViewResult result = g::solveSphereView(problem);
  if (!result.solution) {
    out << "No solution: " << result.problem << ".\n";
    return out.str();
  }
  const g::SphereViewSolution& s = *result.solution;
  out << "\nd = |C - E| = " << describe(s.distance) << "\n";
  out << "The near clipping plane decides what is visible. A plane at t beyond the centre leaves a cap of\n"
         "height r - t, and a zone of a sphere has area 2 pi r times its height (Archimedes), so the cap is\n"
         "(r - t) / (2r) of the sphere: t = r (1 - 2 f) = "
      << describe(s.planeOffset) << "\n";
  out << "  zNear = d + t = " << describe(s.zNear) << "\n";
  out << "All of the cap is seen, from inside, through the opening the plane cuts; the image's outline is the\n"
         "rim of that opening, a circle of radius rho = sqrt(r^2 - t^2) = "
      << describe(s.rimRadius) << " at distance zNear.\n";
  out << "Height: the window's height at distance zNear is 2 zNear tan(fovy/2) = 2 rho / h, so\n";
  out << "  tan(fovy/2) = rho / (h zNear) = " << describe(s.rimRadius / (problem.heightShare * s.zNear))
      << ", fovy = " << decimal(s.fovyDegrees) << " degrees\n";
  out << "Width: aspect times the height is 2 rho / w, so aspect = h / w = " << describe(s.aspect)
      << " (the window must have this shape for the picture not to be stretched)\n";
  out << "Far: zFar must reach the back of the sphere, d + r = " << describe(s.backDistance)
      << "; exactly that puts the farthest point on the far\n"
         "plane, where rounding can clip it, so take more: zFar = d + 2r = "
      << describe(s.zFar) << "\n";
  out << "Any up vector not along C - E will do: the image is a circle centred in the window.\n\n";
  auto number = [](double x) { return decimal(x); };
  out << "glMatrixMode(GL_MODELVIEW);\n"
      << "glLoadIdentity();\n"
      << "gluLookAt(" << number(s.eye.x) << ", " << number(s.eye.y) << ", " << number(s.eye.z) << ",  "
      << number(s.center.x) << ", " << number(s.center.y) << ", " << number(s.center.z) << ",  "
      << number(s.up.x) << ", " << number(s.up.y) << ", " << number(s.up.z) << ");\n"
      << "glMatrixMode(GL_PROJECTION);\n"
      << "glLoadIdentity();\n"
      << "gluPerspective(" << number(s.fovyDegrees) << ", " << number(s.aspect) << ", " << number(s.zNear) << ", "
      << number(s.zFar) << ");\n";
  return out.str();
}

std::string normalReport(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& a2) {
  std::ostringstream out;
  out << "A0 = " << vec(a0) << ", A1 = " << vec(a1) << ", A2 = " << vec(a2) << "\n";
  out << "A1 - A0 = " << vec(a1 - a0) << ", A2 - A0 = " << vec(a2 - a0) << "\n";
  const auto n = g::triangleNormal(a0, a1, a2);
  if (!n) {
    out << "The points are collinear: they span no plane, and the triangle has no normal.\n";
    return out.str();
  }
  out << "n = (A1 - A0) x (A2 - A0) = " << vec(n->normal) << ", |n| = " << describe(glm::length(n->normal))
      << " (twice the area " << describe(n->area) << ")\n";
  out << "unit normal n / |n| = " << vec(n->unitNormal) << "\n";
  // The plane a x + b y + c z = d.
  std::string plane;
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const double c = n->normal[i];
    if (std::abs(c) < 1e-12) continue;
    std::string magnitude = compact(std::abs(c));
    if (magnitude == "1") magnitude.clear();
    plane += plane.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ");
    plane += magnitude + names[i];
  }
  out << "The plane through the three points: " << plane << " = " << compact(n->planeOffset) << "\n\n";
  out << "Orientation: seen from the side n points to (from A0 + n = " << vec(a0 + n->normal)
      << ", say),\n"
         "A0 -> A1 -> A2 runs counter-clockwise (the right-hand rule: fingers along A0 -> A1 -> A2, thumb\n"
         "along n). With GL's default glFrontFace(GL_CCW) that side is the front face, and n is the normal\n"
         "to give glNormal so that the front is lit. Listing the vertices as A0, A2, A1 turns n round\n"
         "and makes the other side the front.\n";
  return out.str();
}

std::string arcReport(double startDegrees, double endDegrees, double radius) {
  std::ostringstream out;
  const double sweep = endDegrees - startDegrees;
  if (!(sweep > 0.0) || sweep > 360.0 || !(radius > 0.0)) {
    return "The arc needs start < end <= start + 360 degrees and a positive radius.\n";
  }
  // One rational quadratic covers less than half a turn; split longer arcs into equal pieces.
  const int pieces = sweep < 180.0 ? 1 : static_cast<int>(std::ceil(sweep / 120.0));
  out << "The arc of the circle of radius " << compact(radius) << " about the origin from " << compact(startDegrees)
      << " to " << compact(endDegrees) << " degrees";
  if (pieces > 1) out << ", in " << pieces << " pieces of " << compact(sweep / pieces) << " degrees (one rational quadratic covers less than 180)";
  out << ".\n";
  out << "Each piece from a0 to a1 is the rational quadratic (equation 14) with end points on the circle, the\n"
         "middle control point where the end tangents meet, at r / cos(h) in the direction (a0 + a1)/2, and the\n"
         "middle weight w = cos(h), h = (a1 - a0)/2 the half angle.\n";
  g::CirclePlacement circle;
  circle.radius = radius;
  double worst = 0.0;
  for (int k = 0; k < pieces; ++k) {
    const double a0 = (startDegrees + sweep * k / pieces) / kDegreesPerRadian;
    const double a1 = (startDegrees + sweep * (k + 1) / pieces) / kDegreesPerRadian;
    const g::BezierCurve arc = g::circularArc(a0, a1, circle);
    out << "\n" << (pieces > 1 ? std::string("Piece ") + std::to_string(k + 1) + ": " : "") << "from " << degrees(a0) << " to "
        << degrees(a1) << " degrees, h = " << degrees((a1 - a0) / 2) << " degrees\n";
    out << "  i  " << padRight("control point", 22) << padRight("weight", 10)
        << "homogeneous (w x, w y, w z, w) for glMap1(GL_MAP1_VERTEX_4, ...)\n";
    for (std::size_t i = 0; i < arc.controlPointCount(); ++i) {
      const glm::dvec3 p = arc.controlPoint(i);
      const double w = arc.weight(i);
      out << "  " << i << "  " << padRight(std::string("(") + compact(p.x) + ", " + compact(p.y) + ")", 22)
          << padRight(compact(w), 10) << "(" << compact(w * p.x) << ", " << compact(w * p.y) << ", "
          << compact(w * p.z) << ", " << compact(w) << ")\n";
    }
    for (int s = 0; s <= 200; ++s) {
      const glm::dvec3 p = arc.evaluate(s / 200.0);
      worst = std::max(worst, std::abs(glm::length(p) - radius));
    }
  }
  out << "\nCheck: 201 points of each piece lie on the circle to " << decimal(worst) << ".\n";
  return out.str();
}

std::string torusPatchReport(double majorRadius, double minorRadius, bool inner) {
  std::ostringstream out;
  if (!(majorRadius > 0.0) || !(minorRadius > 0.0)) return "The radii must be positive.\n";
  const g::TorusSixteenth piece = inner ? g::TorusSixteenth::Inner : g::TorusSixteenth::Outer;
  out << "The torus x = (R + r cos theta) sin phi, y = r sin theta, z = (R + r cos theta) cos phi (the exam's).\n"
         "x >= 0 and z >= 0 give phi in [0, 90] degrees, y <= 0 gives theta in [-180, 0]: that is 1/8 of the\n"
         "torus, and half a tube circle is no single rational quadratic (its middle weight would be\n"
         "cos 90 = 0). Its "
      << (inner ? "inner" : "outer") << " half, theta in " << (inner ? "[-180, -90]" : "[-90, 0]")
      << " degrees, is the 1/16 patch:\n"
         "a rational biquadratic, u along phi (the arc about the y axis), v along theta (the tube circle),\n"
         "each control point the product of the two arcs' control points, each weight the product of\n"
         "their weights (1, 1/√2, 1).\n\n";
  // The control points are linear in R and r: read the coefficients off two evaluations.
  const g::BezierSurface a = g::torusSixteenth(2.0, 1.0, piece);
  const g::BezierSurface b = g::torusSixteenth(3.0, 1.0, piece);
  auto symbolic = [](double coefficientR, double coefficientr) {
    std::string s;
    auto add = [&s](double c, const char* name) {
      if (std::abs(c) < 1e-12) return;
      std::string magnitude = compact(std::abs(c));
      if (magnitude == "1") magnitude.clear();
      s += s.empty() ? (c < 0 ? "-" : "") : (c < 0 ? "-" : "+");
      s += magnitude + name;
    };
    add(coefficientR, "R");
    add(coefficientr, "r");
    return s.empty() ? std::string("0") : s;
  };
  const g::BezierSurface numeric = g::torusSixteenth(majorRadius, minorRadius, piece);
  out << "  i j   " << padRight("control point", 23) << padRight("weight", 9) << "for R = " << compact(majorRadius)
      << ", r = " << compact(minorRadius) << "\n";
  for (int i = 0; i <= a.degreeU(); ++i) {
    for (int j = 0; j <= a.degreeV(); ++j) {
      const glm::dvec3 pa = a.controlPoint(i, j), pb = b.controlPoint(i, j);
      const glm::dvec3 perR = pb - pa;         // coefficient of R
      const glm::dvec3 perr = pa - 2.0 * perR;  // coefficient of r (R = 2, r = 1 in a)
      const std::string point = std::string("(") + symbolic(perR.x, perr.x) + ", " + symbolic(perR.y, perr.y) + ", " +
                                symbolic(perR.z, perr.z) + ")";
      out << "  " << i << " " << j << "   " << padRight(point, 23) << padRight(compact(a.weight(i, j)), 9)
          << vecDecimal(numeric.controlPoint(i, j)) << "\n";
    }
  }
  // Check: points of the patch lie on the torus and in the region.
  double worst = 0.0;
  bool inRegion = true;
  for (int s = 0; s <= 40; ++s) {
    for (int t = 0; t <= 40; ++t) {
      const glm::dvec3 p = numeric.evaluate(s / 40.0, t / 40.0);
      const double fromAxis = std::hypot(p.x, p.z) - majorRadius;
      worst = std::max(worst, std::abs(std::hypot(fromAxis, p.y) - minorRadius));
      inRegion = inRegion && p.x >= -1e-12 && p.y <= 1e-12 && p.z >= -1e-12;
    }
  }
  out << "\nCheck: 41 x 41 points of the patch lie on the torus to " << decimal(worst) << ", and "
      << (inRegion ? "all" : "NOT all") << " satisfy x >= 0, y <= 0, z >= 0.\n";
  return out.str();
}

}  // namespace glass::course
