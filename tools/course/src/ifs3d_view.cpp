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
#include "glass/geometry/portable_math.h"

namespace glass::course {

namespace g = glass::geometry;

namespace {

glm::dvec3 direction(double azimuthDegrees, double elevationDegrees) {
  const double az = azimuthDegrees * std::numbers::pi / 180.0, el = elevationDegrees * std::numbers::pi / 180.0;
  return {portable::cos(el) * portable::sin(az), portable::sin(el), portable::cos(el) * portable::cos(az)};
}

}  // namespace

void ifs3PictureBox(const g::IteratedFunctionSystem3& ifs, const Ifs3View& view, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(std::numeric_limits<double>::infinity());
  hi = glm::dvec3(-std::numeric_limits<double>::infinity());
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
}

Ifs3Camera ifs3Camera(const glm::dvec3& lo, const glm::dvec3& hi, const Ifs3View& view) {
  Ifs3Camera camera;
  camera.centre = (lo + hi) / 2.0;
  const double radius = std::max(glm::length(hi - lo) / 2.0, 1e-6);
  const double distance = radius / portable::sin(camera.fovy / 2.0 * std::numbers::pi / 180.0) * 1.02;
  camera.eye = camera.centre + distance * direction(view.azimuth, view.elevation);
  camera.zNear = std::max(distance - 2.0 * radius, distance * 0.01);
  camera.zFar = distance + 2.0 * radius;
  camera.lightDirection = direction(view.azimuth - 40.0, std::min(view.elevation + 35.0, 89.0));
  return camera;
}

std::string ifs3SceneText(const g::IteratedFunctionSystem3& ifs, const std::string& ifsPath, const Ifs3View& view) {
  glm::dvec3 lo, hi;
  ifs3PictureBox(ifs, view, lo, hi);
  const Ifs3Camera c = ifs3Camera(lo, hi, view);
  char text[2048];
  std::snprintf(text, sizeof text,
                "# A 3D IFS: %s\n"
                "size %d %d\n"
                "clear_color %.9g %.9g %.9g\n"
                "clear\n"
                "perspective %.0f auto %.17g %.17g\n"
                "lookat %.17g %.17g %.17g  %.17g %.17g %.17g  %.17g %.17g %.17g\n"
                "enable depth_test lighting light0 color_material normalize\n"
                "shade_model flat\n"
                "light 0 position %.17g %.17g %.17g 0 diffuse %.9g %.9g %.9g\n"
                "light_model ambient %.9g %.9g %.9g\n",
                ifs.name.empty() ? ifsPath.c_str() : ifs.name.c_str(), view.width, view.height,
                kIfs3Background[0], kIfs3Background[1], kIfs3Background[2], c.fovy, c.zNear, c.zFar, c.eye.x, c.eye.y,
                c.eye.z, c.centre.x, c.centre.y, c.centre.z, c.up.x, c.up.y, c.up.z, c.lightDirection.x,
                c.lightDirection.y, c.lightDirection.z, kIfs3LightDiffuse, kIfs3LightDiffuse, kIfs3LightDiffuse,
                kIfs3Ambient, kIfs3Ambient, kIfs3Ambient);
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
