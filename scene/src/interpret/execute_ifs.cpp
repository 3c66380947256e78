// `ifs`: an iterated function system drawn through glass::geometry's IFS model, by the guide's
// Listing 4 recursion on the modelview stack or by the chaos game.
#include "interpret/executor.h"

#include <glass/geometry/ifs.h>

namespace glass::scene {

namespace {

// Listing 4 as GL calls: glPushMatrix, glMultMatrixd(f_i), recurse, glPopMatrix; the base shape
// at depth 0 in the colour of its part (the map applied outermost).
class GlMatrixStackVisitor final : public geometry::IfsMatrixStackVisitor {
public:
  GlMatrixStackVisitor(Interpreter::Executor &executor, const geometry::IteratedFunctionSystem &system,
                       const Ifs &ifs)
      : executor_(executor), system_(system), ifs_(ifs) {}

  void pushMatrix() override { glPushMatrix(); }
  void multiplyMatrix(const geometry::Affine2 &map) override {
    glm::dmat4 m = map.toMatrix4();
    glMultMatrixd(&m[0][0]);
  }
  void popMatrix() override { glPopMatrix(); }
  void drawBase(int part) override {
    if (ifs_.partColors && part >= 0) {
      geometry::IfsColor c = geometry::partColor(system_, static_cast<std::size_t>(part));
      glColor3f(c.r, c.g, c.b);
    }
    executor_.execute(ifs_.base);
  }

private:
  Interpreter::Executor &executor_;
  const geometry::IteratedFunctionSystem &system_;
  const Ifs &ifs_;
};

} // namespace

void Interpreter::Executor::run(const Ifs &s) {
  geometry::IteratedFunctionSystem system;
  for (const IfsMap &map : s.maps) {
    geometry::IfsMap out;
    // The steps compose left to right like the GL calls they read as: translate then scale is
    // T S, which scales first.
    for (const AffineStep &step : map.steps) {
      std::vector<double> v = values(step.values);
      geometry::Affine2 m;
      switch (step.kind) {
      case AffineStep::Kind::Translate: m = geometry::Affine2::translation(v[0], v[1]); break;
      case AffineStep::Kind::Rotate: m = geometry::Affine2::rotationDegrees(v[0]); break;
      case AffineStep::Kind::Scale: m = geometry::Affine2::scaling(v[0], v[1]); break;
      case AffineStep::Kind::Shear: m = geometry::Affine2::shear(v[0]); break;
      case AffineStep::Kind::Matrix: m = geometry::Affine2::fromRows(v[0], v[1], v[2], v[3], v[4], v[5]); break;
      }
      out.transform = out.transform * m;
    }
    if (!map.color.empty()) {
      std::vector<double> c = values(map.color);
      out.color = geometry::IfsColor{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
    }
    if (map.probability) out.probability = value(*map.probability);
    system.maps.push_back(out);
  }

  // The part colours are the ifs statement's own: the current colour comes back after it.
  saveCurrentValues();
  glPushAttrib(GL_CURRENT_BIT);
  if (s.mode == Ifs::Mode::Recursive) {
    GLint depth = 0, maxDepth = 32;
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &maxDepth);
    if (depth + s.depth > maxDepth) {
      glPopAttrib();
      fail("ifs depth " + std::to_string(s.depth) + " needs " + std::to_string(s.depth) +
           " more modelview matrices, but the stack holds " + std::to_string(maxDepth) + " and " +
           std::to_string(depth) + " are in use");
    }
    GlMatrixStackVisitor visitor(*this, system, s);
    geometry::expandIfs(system, s.depth, visitor);
  } else {
    std::optional<std::vector<double>> probabilities = geometry::chaosGameProbabilities(system);
    if (!probabilities) {
      glPopAttrib();
      fail("the chaos game needs probabilities that are not negative and not all 0");
    }
    VertexTracer *tracer = options_.tracer;
    if (tracer != nullptr && tracer->pending()) tracer->capture();
    glBegin(GL_POINTS);
    int lastPart = -1;
    geometry::chaosGame(system, *probabilities, static_cast<std::uint64_t>(s.points), s.seed,
                        [&](const glm::dvec2 &point, int part) {
                          if (s.partColors && part != lastPart) {
                            geometry::IfsColor c = geometry::partColor(system, static_cast<std::size_t>(part));
                            glColor3f(c.r, c.g, c.b);
                            lastPart = part;
                            if (tracer != nullptr) {
                              const double rgba[4] = {c.r, c.g, c.b, 1.0};
                              tracer->setColor(rgba);
                            }
                          }
                          glVertex2d(point.x, point.y);
                          if (tracer != nullptr && tracer->pending()) {
                            const double v[4] = {point.x, point.y, 0.0, 1.0};
                            tracer->vertex(v, current_->where, "the chaos game of 'ifs' (map " + std::to_string(part + 1) + ")");
                          }
                        });
    glEnd();
  }
  glPopAttrib();
  resendCurrentValues();
}

} // namespace glass::scene
