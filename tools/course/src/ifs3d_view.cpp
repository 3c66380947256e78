#include "glass/course/ifs3d_view.h"

#include <glass/scene/parser.h>
#include <glass/scene/render.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace glass::course {

namespace g = glass::geometry;

namespace {

glm::dvec3 direction(double azimuthDegrees, double elevationDegrees) {
  const double az = azimuthDegrees * std::numbers::pi / 180.0, el = elevationDegrees * std::numbers::pi / 180.0;
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

}  // namespace

std::string ifs3SceneText(const g::IteratedFunctionSystem3& ifs, const std::string& ifsPath, const Ifs3View& view) {
  // The box around the attractor (chaos-game points) and around the base polyhedron when it is
  // animated, since the animation starts from it.
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  if (auto probabilities = g::chaosGameProbabilities3(ifs)) {
    for (const g::IfsPoint3& p : g::chaosGamePoints3(ifs, *probabilities, 20000, 1)) {
      lo = glm::min(lo, p.position);
      hi = glm::max(hi, p.position);
    }
  }
  if (view.animatedMap >= 0 || !(lo.x <= hi.x)) {
    for (const g::Triangle3& t : g::basePolyhedron(ifs)) {
      for (const glm::dvec3& p : {t.a, t.b, t.c}) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
  }
  const glm::dvec3 centre = (lo + hi) / 2.0;
  const double radius = std::max(glm::length(hi - lo) / 2.0, 1e-6);
  constexpr double kFieldOfView = 30.0;
  const double distance = radius / std::sin(kFieldOfView / 2.0 * std::numbers::pi / 180.0) * 1.02;
  const glm::dvec3 eye = centre + distance * direction(view.azimuth, view.elevation);
  const glm::dvec3 light = direction(view.azimuth - 40.0, std::min(view.elevation + 35.0, 89.0));
  char text[2048];
  std::snprintf(text, sizeof text,
                "# A 3D IFS: %s\n"
                "size %d %d\n"
                "clear_color 0.1 0.1 0.12\n"
                "clear\n"
                "perspective %.0f auto %.17g %.17g\n"
                "lookat %.17g %.17g %.17g  %.17g %.17g %.17g  0 1 0\n"
                "enable depth_test lighting light0 color_material normalize\n"
                "shade_model flat\n"
                "light 0 position %.17g %.17g %.17g 0 diffuse 0.85 0.85 0.85\n"
                "light_model ambient 0.3 0.3 0.3\n",
                ifs.name.empty() ? ifsPath.c_str() : ifs.name.c_str(), view.width, view.height, kFieldOfView,
                std::max(distance - 2.0 * radius, distance * 0.01), distance + 2.0 * radius, eye.x, eye.y, eye.z, centre.x,
                centre.y, centre.z, light.x, light.y, light.z);
  std::string scene = text;
  scene += "ifs3d \"" + ifsPath + "\" depth " + std::to_string(view.depth);
  if (view.animatedMap >= 0) {
    std::snprintf(text, sizeof text, " map %d step %.17g", view.animatedMap + 1, view.step);
    scene += text;
  }
  scene += '\n';
  return scene;
}

std::string renderIfs3Picture(const std::string& sceneText, const std::string& scenePath, const std::string& output) {
  scene::Diagnostics diagnostics;
  const scene::Program program = scene::parseSceneText(scenePath, sceneText, diagnostics);
  if (diagnostics.hasErrors()) return diagnostics.format();
  scene::RenderedFrame frame;
  if (!scene::renderFrame(program, 0, scene::RenderOptions{}, frame, diagnostics)) return diagnostics.format();
  std::string reason;
  if (!scene::writeImage(output, frame.image, reason)) return "cannot write " + output + ": " + reason;
  return {};
}

}  // namespace glass::course
