// Pictures of a 3D IFS for `glass ifs3d render` and `animate`: a scene in the scene language
// (docs/scene-format.md) around the `ifs3d` statement, so that the command line, scene files and
// the Mesa reference draw through the same code.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "glass/geometry/ifs3d.h"

namespace glass::course {

struct Ifs3View {
  int width = 800, height = 800;
  double azimuth = 35.0;    // degrees about the vertical (y) axis, from +z towards +x
  double elevation = 25.0;  // degrees above the horizontal plane
  int depth = 3;
  int animatedMap = -1;     // 0-based; -1: the rebuild in place
  double step = 0.0;        // 0..1 along the animation
};

// Where the picture is seen from: a perspective camera looking at the centre of a box from the
// view's direction, far enough for the whole box to fit, and one directional light from above the
// viewer's left shoulder. The scene text and `glass ifs3d view`'s window use the same numbers.
struct Ifs3Camera {
  glm::dvec3 eye{0.0}, centre{0.0}, up{0.0, 1.0, 0.0};
  double fovy = 30.0, zNear = 0.1, zFar = 10.0;
  glm::dvec3 lightDirection{0.0, 0.0, 1.0};  // towards the light, in world coordinates
};
Ifs3Camera ifs3Camera(const glm::dvec3& lo, const glm::dvec3& hi, const Ifs3View& view);

// The box the picture frames: around the attractor (chaos-game points), and around the base
// polyhedron too when the view animates a map (the animation starts from it) or the system has
// no attractor to sample.
void ifs3PictureBox(const geometry::IteratedFunctionSystem3& ifs, const Ifs3View& view, glm::dvec3& lo, glm::dvec3& hi);

// The rest of the picture's set-up, shared for the same reason.
inline constexpr float kIfs3Background[3] = {0.1f, 0.1f, 0.12f};
inline constexpr float kIfs3LightDiffuse = 0.85f;
inline constexpr float kIfs3Ambient = 0.3f;

// The scene text: a perspective camera looking at the centre of the attractor from the view's
// direction, far enough for the whole attractor (and, when animating, the base polyhedron it
// starts from) to fit; one directional light from above the viewer's left shoulder; flat
// shading with colour material. `ifsPath` is written into the scene as given (no quotes in it).
std::string ifs3SceneText(const geometry::IteratedFunctionSystem3& ifs, const std::string& ifsPath, const Ifs3View& view);

// Renders the scene text to a PNG (written whole or not at all). Empty on success, else why not.
std::string renderIfs3Picture(const std::string& sceneText, const std::string& scenePath, const std::string& output);

}  // namespace glass::course
