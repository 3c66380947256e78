// Shapes drawn by GLU (quadrics), GLUT (solids, the teapot) and the evaluators (Bezier curves and
// patches), and the exam's torus with its texture coordinates.
#include "interpret/executor.h"

#include <cmath>
#include "glass/geometry/portable_math.h"

namespace glass::scene {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A quadric object for one shape: gluNewQuadric, the style, the drawing, gluDeleteQuadric.
class Quadric {
public:
  explicit Quadric(const QuadricStyle &style) : quadric_(gluNewQuadric()) {
    if (quadric_ == nullptr) return;
    gluQuadricDrawStyle(quadric_, style.drawStyle);
    gluQuadricNormals(quadric_, style.normals);
    gluQuadricOrientation(quadric_, style.orientation);
    gluQuadricTexture(quadric_, style.texture ? GL_TRUE : GL_FALSE);
  }
  ~Quadric() {
    if (quadric_ != nullptr) gluDeleteQuadric(quadric_);
  }
  Quadric(const Quadric &) = delete;
  Quadric &operator=(const Quadric &) = delete;
  GLUquadric *get() const { return quadric_; }

private:
  GLUquadric *quadric_;
};

} // namespace

void Interpreter::Executor::run(const Sphere &s) {
  Quadric quadric(s.style);
  if (quadric.get() == nullptr) fail("gluNewQuadric failed");
  gluSphere(quadric.get(), value(s.radius), s.slices, s.stacks);
}

void Interpreter::Executor::run(const Cylinder &s) {
  Quadric quadric(s.style);
  if (quadric.get() == nullptr) fail("gluNewQuadric failed");
  gluCylinder(quadric.get(), value(s.base), value(s.top), value(s.height), s.slices, s.stacks);
}

void Interpreter::Executor::run(const Disk &s) {
  Quadric quadric(s.style);
  if (quadric.get() == nullptr) fail("gluNewQuadric failed");
  gluDisk(quadric.get(), value(s.inner), value(s.outer), s.slices, s.loops);
}

void Interpreter::Executor::run(const PartialDisk &s) {
  Quadric quadric(s.style);
  if (quadric.get() == nullptr) fail("gluNewQuadric failed");
  gluPartialDisk(quadric.get(), value(s.inner), value(s.outer), s.slices, s.loops, value(s.start), value(s.sweep));
}

void Interpreter::Executor::run(const GlutShape &s) {
  using K = GlutShape::Kind;
  double a = s.sizes.empty() ? 0.0 : value(s.sizes[0]);
  double b = s.sizes.size() > 1 ? value(s.sizes[1]) : 0.0;
  switch (s.kind) {
  case K::Cube: s.wire ? glutWireCube(a) : glutSolidCube(a); break;
  case K::Sphere: s.wire ? glutWireSphere(a, s.slices, s.stacks) : glutSolidSphere(a, s.slices, s.stacks); break;
  case K::Cone: s.wire ? glutWireCone(a, b, s.slices, s.stacks) : glutSolidCone(a, b, s.slices, s.stacks); break;
  case K::Torus: s.wire ? glutWireTorus(a, b, s.slices, s.stacks) : glutSolidTorus(a, b, s.slices, s.stacks); break;
  case K::Teapot: s.wire ? glutWireTeapot(a) : glutSolidTeapot(a); break;
  case K::Teacup: s.wire ? glutWireTeacup(a) : glutSolidTeacup(a); break;
  case K::Teaspoon: s.wire ? glutWireTeaspoon(a) : glutSolidTeaspoon(a); break;
  case K::Tetrahedron: s.wire ? glutWireTetrahedron() : glutSolidTetrahedron(); break;
  case K::Octahedron: s.wire ? glutWireOctahedron() : glutSolidOctahedron(); break;
  case K::Dodecahedron: s.wire ? glutWireDodecahedron() : glutSolidDodecahedron(); break;
  case K::Icosahedron: s.wire ? glutWireIcosahedron() : glutSolidIcosahedron(); break;
  }
}

// The exam's torus (study guide, section 4.1, texturing):
//   x = (R + r cos t) sin p,  y = r sin t,  z = (R + r cos t) cos p,  p, t in [-pi, pi],
// with texture coordinates s = p / 2pi + 1/2, t = t / 2pi + 1/2, so that the centre of the map,
// (0.5, 0.5), lands at p = t = 0: the point (0, 0, R + r), the front of the torus seen from +z.
// Quads run counter-clockwise seen from outside, so the outside is the front face.
void Interpreter::Executor::run(const ParametricTorus &s) {
  const double major = value(s.major), minor = value(s.minor);
  if (!(major > 0.0 && minor > 0.0)) fail("the torus radii must be greater than 0");
  for (int ring = 0; ring < s.rings; ++ring) {
    glBegin(GL_QUAD_STRIP);
    for (int slice = 0; slice <= s.slices; ++slice) {
      const double p = -kPi + 2.0 * kPi * slice / s.slices;
      for (int side = 1; side >= 0; --side) {
        const double t = -kPi + 2.0 * kPi * (ring + side) / s.rings;
        glTexCoord2d(static_cast<double>(slice) / s.slices, static_cast<double>(ring + side) / s.rings);
        glNormal3d(portable::cos(t) * portable::sin(p), portable::sin(t), portable::cos(t) * portable::cos(p));
        glVertex3d((major + minor * portable::cos(t)) * portable::sin(p), minor * portable::sin(t),
                   (major + minor * portable::cos(t)) * portable::cos(p));
      }
    }
    glEnd();
  }
}

// A rational curve gives homogeneous control points (w x, w y, w z, w) to GL_MAP1_VERTEX_4.
void Interpreter::Executor::run(const BezierCurve &s) {
  std::vector<double> points = values(s.points);
  bool rational = !s.weights.empty();
  std::vector<double> control;
  for (int i = 0; i < s.order; ++i) {
    double w = rational ? value(s.weights[static_cast<std::size_t>(i)]) : 1.0;
    for (int c = 0; c < 3; ++c) control.push_back(points[static_cast<std::size_t>(3 * i + c)] * w);
    if (rational) control.push_back(w);
  }
  GLenum target = rational ? GL_MAP1_VERTEX_4 : GL_MAP1_VERTEX_3;
  glPushAttrib(GL_ENABLE_BIT | GL_EVAL_BIT);
  glMap1d(target, 0.0, 1.0, rational ? 4 : 3, s.order, control.data());
  glEnable(target);
  glMapGrid1d(s.segments, 0.0, 1.0);
  glEvalMesh1(s.mode, 0, s.segments);
  glPopAttrib();
}

void Interpreter::Executor::run(const BezierPatch &s) {
  std::vector<double> points = values(s.points);
  bool rational = !s.weights.empty();
  int size = rational ? 4 : 3;
  std::vector<double> control;
  for (int i = 0; i < s.uOrder * s.vOrder; ++i) {
    double w = rational ? value(s.weights[static_cast<std::size_t>(i)]) : 1.0;
    for (int c = 0; c < 3; ++c) control.push_back(points[static_cast<std::size_t>(3 * i + c)] * w);
    if (rational) control.push_back(w);
  }
  GLenum target = rational ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3;
  glPushAttrib(GL_ENABLE_BIT | GL_EVAL_BIT);
  // Points are listed with u running fastest: ustride is one point, vstride one row of u.
  glMap2d(target, 0.0, 1.0, size, s.uOrder, 0.0, 1.0, size * s.uOrder, s.vOrder, control.data());
  glEnable(target);
  if (s.texcoords) {
    // (s, t) = (u, v): a bilinear map from the corners of the unit square.
    static const GLdouble corners[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    glMap2d(GL_MAP2_TEXTURE_COORD_2, 0.0, 1.0, 2, 2, 0.0, 1.0, 4, 2, corners);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
  }
  if (s.autoNormal) {
    glEnable(GL_AUTO_NORMAL);
  } else {
    glDisable(GL_AUTO_NORMAL);
  }
  glMapGrid2d(s.uSegments, 0.0, 1.0, s.vSegments, 0.0, 1.0);
  glEvalMesh2(s.mode, 0, s.uSegments, 0, s.vSegments);
  glPopAttrib();
}

} // namespace glass::scene
