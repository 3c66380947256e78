// `glass render --trace-vertex N`: follows the N-th vertex the scene sends (counting from 0, in
// the order the GL receives them) through every stage of the fixed-function pipeline: object,
// eye, clip, normalized device and window coordinates, and its lit colour.
//
// The stages are computed here from GL state read back with glGet (matrices, viewport, depth
// range, lights, materials) by the formulas of the OpenGL 1.1 specification (sections 2.10 and
// 2.13), so the trace works on any GL. Vertices made inside GLU, GLUT or the evaluators are not
// seen by the interpreter and are not counted: the count covers vertex, rect, mesh, model and
// ifs points.
#pragma once

#include "glass/scene/source.h"

#include <array>
#include <string>

namespace glass::scene {

class VertexTracer {
public:
  explicit VertexTracer(long target) : target_(target) {}

  // True while the target vertex has not been sent yet.
  bool pending() const { return !found_; }
  // Before a primitive whose vertices may include the target (outside glBegin/glEnd, where glGet
  // is allowed): reads the state those vertices go through.
  void capture();
  // The current colour, normal and material as the interpreter sends them between captures.
  void setColor(const double rgba[4]);
  void setNormal(const double xyz[3]);
  void setMaterial(unsigned face, unsigned pname, const float *values, int count);

  // One vertex sent to the GL; `what` says which statement sent it.
  void vertex(const double xyzw[4], SourceLocation where, const std::string &what);

  long count() const { return count_; }
  bool found() const { return found_; }
  long target() const { return target_; }
  // Dividing window coordinates by this gives pixels of the final (not supersampled) image.
  void setPixelScale(int scale) { pixelScale_ = scale; }
  const std::string &report() const { return report_; }

private:
  struct Light {
    bool enabled = false;
    std::array<double, 4> ambient{}, diffuse{}, specular{}, position{};
    std::array<double, 3> spotDirection{};
    double spotExponent = 0.0, spotCutoff = 180.0;
    double constant = 1.0, linear = 0.0, quadratic = 0.0;
  };
  struct MaterialState {
    std::array<double, 4> ambient{}, diffuse{}, specular{}, emission{};
    double shininess = 0.0;
  };
  std::array<double, 4> litColor(const std::array<double, 4> &eye, const std::array<double, 3> &normal,
                                 bool back) const;
  void describe(const std::array<double, 4> &object, SourceLocation where, const std::string &what);

  long target_;
  long count_ = 0;
  bool found_ = false;
  bool captured_ = false;
  int pixelScale_ = 1;
  std::string report_;

  std::array<double, 16> modelview_{}, projection_{};
  std::array<double, 4> viewport_{};
  std::array<double, 2> depthRange_{0.0, 1.0};
  bool lighting_ = false, normalize_ = false, twoSide_ = false, localViewer_ = false;
  bool colorMaterial_ = false;
  unsigned colorMaterialFace_ = 0, colorMaterialMode_ = 0;
  std::array<double, 4> sceneAmbient_{};
  std::array<Light, 8> lights_{};
  MaterialState front_, back_;
  std::array<double, 4> color_{1.0, 1.0, 1.0, 1.0};
  std::array<double, 3> normal_{0.0, 0.0, 1.0};
};

} // namespace glass::scene
