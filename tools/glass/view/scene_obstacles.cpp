#include "scene_obstacles.h"

#include <GL/gl.h>
#include <glass/geometry/quaternion.h>
#include <glass/scene/frame_values.h>

#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <type_traits>

namespace glass::cli::view {

namespace {

using geometry::AxisAlignedBox;

// Replays a program's transforms the way the interpreter's GL calls build the modelview matrix
// (scene/src/interpret/execute_camera.cpp), without a GL, and collects the boxes of what it draws.
class BoxCollector {
public:
  BoxCollector(const scene::Program &program, int frame)
      : program_(program), values_(scene::evaluateParameters(program, frame)) {}

  void run(const scene::StatementList &statements) {
    for (const scene::Statement &statement : statements) {
      std::visit([this](const auto &s) { visit(s); }, statement.body);
    }
  }

  std::vector<AxisAlignedBox> boxes;

private:
  struct State {
    glm::dmat4 modelview{1.0};
    bool shadow = false; // under a shadow_matrix
  };

  double value(const scene::Number &n) const { return values_(n); }
  std::vector<double> values(const scene::Numbers &numbers) const {
    std::vector<double> v;
    v.reserve(numbers.size());
    for (const scene::Number &n : numbers) v.push_back(value(n));
    return v;
  }

  // A point of the shape's own coordinates, in world space; false when it is at infinity.
  bool toWorld(glm::dvec4 p, glm::dvec3 &world) const {
    const glm::dvec4 q = state_.modelview * p;
    if (q.w == 0.0) return false;
    world = glm::dvec3(q) / q.w;
    return std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z);
  }

  void addPoints(const std::vector<glm::dvec4> &points) {
    if (state_.shadow || points.empty()) return;
    AxisAlignedBox box;
    for (const glm::dvec4 &p : points) {
      glm::dvec3 world;
      if (!toWorld(p, world)) return;
      box.include(world);
    }
    boxes.push_back(box);
  }

  // A box of the shape's own coordinates: the world box around its eight corners.
  void addLocalBox(glm::dvec3 low, glm::dvec3 high) {
    std::vector<glm::dvec4> corners;
    for (int i = 0; i < 8; ++i) {
      corners.emplace_back(i & 1 ? high.x : low.x, i & 2 ? high.y : low.y, i & 4 ? high.z : low.z, 1.0);
    }
    addPoints(corners);
  }
  void addCentredBox(double rx, double ry, double rz) { addLocalBox({-rx, -ry, -rz}, {rx, ry, rz}); }

  static glm::dvec4 point(const std::vector<double> &v) {
    return {v[0], v.size() > 1 ? v[1] : 0.0, v.size() > 2 ? v[2] : 0.0, v.size() > 3 ? v[3] : 1.0};
  }

  void multiply(const glm::dmat4 &m) { state_.modelview = state_.modelview * m; }

  // ---- transforms ------------------------------------------------------------------------------
  void visit(const scene::LoadIdentity &) { state_.modelview = glm::dmat4(1.0); }
  void visit(const scene::Translate &s) {
    const std::vector<double> v = values(s.v);
    multiply(glm::translate(glm::dmat4(1.0), glm::dvec3(v[0], v[1], v[2])));
  }
  void rotate(double degrees, double x, double y, double z) {
    // glRotate normalises the axis (OpenGL 1.4, 2.10.2); an axis 0 0 0 turns nothing.
    const glm::dvec3 axis(x, y, z);
    const double length = std::sqrt(x * x + y * y + z * z);
    if (length == 0.0) return;
    multiply(glm::rotate(glm::dmat4(1.0), degrees * 3.14159265358979323846 / 180.0, axis / length));
  }
  void visit(const scene::Rotate &s) {
    const std::vector<double> axis = values(s.axis);
    rotate(value(s.angle), axis[0], axis[1], axis[2]);
  }
  void visit(const scene::RotateByParameter &s) {
    const std::vector<double> &r = values_.values[static_cast<std::size_t>(s.parameter)];
    rotate(r[0], r[1], r[2], r[3]);
  }
  void visit(const scene::RotateQuaternion &s) {
    const std::vector<double> q = values(s.wxyz);
    const geometry::Quaternion quaternion(q[0], q[1], q[2], q[3]);
    if (geometry::normSquared(quaternion) == 0.0) return;
    multiply(glm::dmat4(geometry::rotationMatrix(quaternion)));
  }
  void visit(const scene::Scale &s) {
    const std::vector<double> v = values(s.v);
    multiply(glm::scale(glm::dmat4(1.0), glm::dvec3(v[0], v[1], v[2])));
  }
  void visit(const scene::MultMatrix &s) {
    const std::vector<double> v = values(s.rowMajor);
    glm::dmat4 m(1.0); // glm is column-major: m[column][row]
    if (v.size() == 16) {
      for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) m[c][r] = v[static_cast<std::size_t>(r * 4 + c)];
      }
    } else if (v.size() == 6) {
      m[0][0] = v[0], m[1][0] = v[1], m[3][0] = v[2];
      m[0][1] = v[3], m[1][1] = v[4], m[3][1] = v[5];
    }
    multiply(m);
  }
  void visit(const scene::ShadowMatrix &) { state_.shadow = true; }
  void visit(const scene::Push &) { stack_.push_back(state_); }
  void visit(const scene::Pop &) {
    if (stack_.empty()) return;
    state_ = stack_.back();
    stack_.pop_back();
  }
  void visit(const scene::Instance &s) {
    if (s.definition < 0 || static_cast<std::size_t>(s.definition) >= program_.definitions.size()) return;
    if (depth_ >= 64) return; // the GL's display list nesting limit
    ++depth_;
    run(program_.definitions[static_cast<std::size_t>(s.definition)].body);
    --depth_;
  }

  // ---- geometry --------------------------------------------------------------------------------
  // Each polygon of the block (OpenGL 1.4, 2.6.1) gets its own box: a room drawn as one
  // `begin quads` is four walls, not one box around them.
  void visit(const scene::Begin &s) {
    std::vector<glm::dvec4> v;
    for (const scene::Statement &statement : s.body) {
      if (const auto *vertex = std::get_if<scene::Vertex>(&statement.body)) v.push_back(point(values(vertex->xyzw)));
    }
    const std::size_t n = v.size();
    auto polygon = [&](std::initializer_list<std::size_t> indices) {
      std::vector<glm::dvec4> points;
      for (std::size_t i : indices) points.push_back(v[i]);
      addPoints(points);
    };
    switch (s.mode) {
      case GL_TRIANGLES:
        for (std::size_t i = 0; i + 3 <= n; i += 3) polygon({i, i + 1, i + 2});
        break;
      case GL_TRIANGLE_STRIP:
        for (std::size_t i = 0; i + 3 <= n; ++i) polygon({i, i + 1, i + 2});
        break;
      case GL_TRIANGLE_FAN:
        for (std::size_t i = 1; i + 2 <= n; ++i) polygon({0, i, i + 1});
        break;
      case GL_QUADS:
        for (std::size_t i = 0; i + 4 <= n; i += 4) polygon({i, i + 1, i + 2, i + 3});
        break;
      case GL_QUAD_STRIP:
        for (std::size_t i = 0; i + 4 <= n; i += 2) polygon({i, i + 1, i + 2, i + 3});
        break;
      case GL_POLYGON:
        if (n >= 3) addPoints(v);
        break;
      default: // points and lines are not solid
        break;
    }
  }
  void visit(const scene::Rect &s) {
    const std::vector<double> c = values(s.corners);
    addLocalBox({std::min(c[0], c[2]), std::min(c[1], c[3]), 0.0}, {std::max(c[0], c[2]), std::max(c[1], c[3]), 0.0});
  }
  void visit(const scene::Mesh &s) {
    if (s.mode == GL_POINTS || s.mode == GL_LINES || s.mode == GL_LINE_STRIP || s.mode == GL_LINE_LOOP) return;
    const std::vector<double> p = values(s.positions);
    const std::size_t size = static_cast<std::size_t>(std::max(s.positionSize, 1));
    std::vector<glm::dvec4> points;
    for (std::size_t i = 0; i + size <= p.size(); i += size) {
      points.push_back(point(std::vector<double>(p.begin() + static_cast<std::ptrdiff_t>(i),
                                                 p.begin() + static_cast<std::ptrdiff_t>(i + size))));
    }
    addPoints(points);
  }
  // A rounded model lies inside its sharp one (rounding only cuts its edges), so the box of the
  // model's own triangles holds it at any radius.
  void visit(const scene::DrawModel &s) {
    if (s.model < 0 || static_cast<std::size_t>(s.model) >= program_.models.size()) return;
    std::vector<glm::dvec4> points;
    for (const scene::ModelPart &part : program_.models[static_cast<std::size_t>(s.model)].parts) {
      for (std::size_t i = 0; i + 3 <= part.positions.size(); i += 3) {
        points.emplace_back(part.positions[i], part.positions[i + 1], part.positions[i + 2], 1.0);
      }
    }
    addPoints(points);
  }
  // GLU's quadrics (GLU 1.3, 6.7): spheres about the origin, cylinders and disks along +z from z = 0.
  void visit(const scene::Sphere &s) {
    const double r = std::abs(value(s.radius));
    addCentredBox(r, r, r);
  }
  void visit(const scene::Cylinder &s) {
    const double r = std::max(std::abs(value(s.base)), std::abs(value(s.top)));
    addLocalBox({-r, -r, 0.0}, {r, r, value(s.height)});
  }
  void visit(const scene::Disk &s) {
    const double r = std::abs(value(s.outer));
    addLocalBox({-r, -r, 0.0}, {r, r, 0.0});
  }
  void visit(const scene::PartialDisk &s) {
    const double r = std::abs(value(s.outer));
    addLocalBox({-r, -r, 0.0}, {r, r, 0.0});
  }
  // freeglut 3's shapes: the cube of side `size`, spheres, the cone along +z from its base at
  // z = 0, the torus about z, the Platonic solids inside their circumscribed spheres (radius 1,
  // the dodecahedron's sqrt 3), and the teaset within its control points' boxes as
  // pipeline/src/glut/teaset_mesh.cpp scales them: the teapot of size s within x in
  // [-1.5 s, 1.7625 s], y in [-0.7875 s, 0.7875 s], z in [-s, s]; the teacup (scaled by s / 5)
  // within x and z in [-0.705 s, 0.705 s], y in [-0.3025 s, 0.3706 s]; the teaspoon within
  // x in [-0.1008 s, 0.1008 s], y in [-0.0693 s, 0.0693 s], z in [-0.1558 s, 0.705 s].
  void visit(const scene::GlutShape &s) {
    using Kind = scene::GlutShape::Kind;
    if (s.wire) return; // lines
    const std::vector<double> size = values(s.sizes);
    const double a = size.empty() ? 1.0 : std::abs(size[0]);
    const double b = size.size() > 1 ? std::abs(size[1]) : 0.0;
    switch (s.kind) {
      case Kind::Cube: addCentredBox(a / 2, a / 2, a / 2); break;
      case Kind::Sphere: addCentredBox(a, a, a); break;
      case Kind::Cone: addLocalBox({-a, -a, 0.0}, {a, a, size.size() > 1 ? size[1] : 0.0}); break;
      case Kind::Torus: addCentredBox(a + b, a + b, a); break;
      case Kind::Tetrahedron:
      case Kind::Octahedron:
      case Kind::Icosahedron: addCentredBox(1, 1, 1); break;
      case Kind::Dodecahedron: addCentredBox(std::sqrt(3.0), std::sqrt(3.0), std::sqrt(3.0)); break;
      case Kind::Teapot: addLocalBox({-1.5 * a, -0.7875 * a, -a}, {1.7625 * a, 0.7875 * a, a}); break;
      case Kind::Teacup: addLocalBox({-0.705 * a, -0.3025 * a, -0.705 * a}, {0.705 * a, 0.3706 * a, 0.705 * a}); break;
      case Kind::Teaspoon:
        addLocalBox({-0.1008 * a, -0.0693 * a, -0.1558 * a}, {0.1008 * a, 0.0693 * a, 0.705 * a});
        break;
    }
  }
  // The exam's torus about the y axis.
  void visit(const scene::ParametricTorus &s) {
    const double r = std::abs(value(s.minor)), outer = std::abs(value(s.major)) + r;
    addCentredBox(outer, r, outer);
  }
  // A Bezier patch lies in the convex hull of its control points (with positive weights).
  void visit(const scene::BezierPatch &s) {
    if (s.mode != GL_FILL) return;
    const std::vector<double> p = values(s.points);
    std::vector<glm::dvec4> points;
    for (std::size_t i = 0; i + 3 <= p.size(); i += 3) points.emplace_back(p[i], p[i + 1], p[i + 2], 1.0);
    addPoints(points);
  }

  // Everything else (state, the camera, curves, IFS) leaves the boxes alone.
  template <typename Other> void visit(const Other &) {}

  const scene::Program &program_;
  scene::FrameValues values_;
  State state_;
  std::vector<State> stack_;
  int depth_ = 0;
};

} // namespace

std::vector<AxisAlignedBox> sceneBoxes(const scene::Program &program, int frame) {
  BoxCollector collector(program, frame);
  collector.run(program.statements);
  return std::move(collector.boxes);
}

WalkGround walkGround(const std::vector<AxisAlignedBox> &boxes, const WalkerBody &body) {
  WalkGround ground;
  if (boxes.empty()) return ground;
  ground.groundY = boxes.front().min.y;
  for (const AxisAlignedBox &box : boxes) ground.groundY = std::min(ground.groundY, box.min.y);
  for (const AxisAlignedBox &box : boxes) {
    if (box.max.y > ground.groundY + body.climb && box.min.y < ground.groundY + body.eyeHeight) {
      ground.obstacles.push_back({box.min.x, box.min.z, box.max.x, box.max.z});
    }
  }
  return ground;
}

} // namespace glass::cli::view
