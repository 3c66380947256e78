// `glass ifs3d view`: the interactive part of the study guide's homework 3 as a GLUT program
// (window/, <GL/freeglut.h>): the cloud of points drawn as GL_POINTS, the polyhedral rebuild of
// the maps drawn as the scene language's `ifs3d` statement draws it, one or the other or both
// side by side, turned with the mouse by a quaternion trackball (view/trackball.h), the depth of
// the rebuild changed by keys, and each map's image of the picture's box as a wire box.
//
// The window draws with GL calls of its own, set up as the scene `glass ifs3d render` makes
// (glass/course/ifs3d_view.h), so that an unturned attractor in the window is the same picture,
// byte for byte, as `glass ifs3d render` at the same size, view and depth (tests/glut).
#include "ifs3d_view_command.h"

#include "command_registry.h"
#include "view/trackball.h"
#include "view/window_options.h"

#include <GL/freeglut.h>
#include <glass/course/ifs3d_cloud_colors.h>
#include <glass/course/ifs3d_file.h>
#include <glass/course/ifs3d_view.h>
#include <glass/course/point_cloud.h>
#include <glass/geometry/ifs3d.h>
#include <glass/geometry/quaternion.h>
#include <glass/scene/ifs3_rebuild_draw.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace glass::cli {

namespace {

namespace g = glass::geometry;

constexpr const char *kHelp = R"(usage: glass ifs3d view [FILE.ifs3] [CLOUD.txt] [options]

Homework 3 in a window: a cloud of points (CLOUD.txt, or N chaos-game points of FILE.ifs3 when no
cloud is given) and the fractal rebuilt from the maps of FILE.ifs3 as polyhedra (what
`glass ifs3d render` draws), one, the other, or both side by side.

  mouse    left drag: turn the fractal (a quaternion trackball: the point under the pointer
           follows it as on a ball); wheel: closer and farther
  keys     c the cloud, a the attractor rebuilt from the maps, b both side by side,
           + and - the depth of the rebuild, m each map's image of the picture's box (a wire
           box in the map's colour) on or off, h the cloud coloured by height or by part,
           r back to the first orientation, q or Escape quit
  menu     right button: the same choices as the keys

The cloud's colours: each point in the colour of its part, the map that made it (a chaos-game
cloud) or the map whose image of the cloud passes nearest (a cloud file shown with a .ifs3 file;
grey where no image comes near: noise, or what the maps miss); without maps, a ramp from blue
(lowest) through green and yellow to red (highest) over the height.

options:
  --points N            the chaos-game cloud's size when no cloud file is given (default 50000)
  --seed S              its seed (default 1, as `glass ifs3d points`)
  --depth N             the rebuild's depth (default 3)
  --view AZIMUTH,ELEVATION  the direction it is seen from, as `glass ifs3d render` (default 35,25)
  --show cloud|attractor|both  what the window shows first (default cloud)
  --size WxH            window size (default 640x640)
  --snapshot FILE       write the window's picture to FILE after the first frame (or after
                        the events) and exit: GLASS_GLUT_SNAPSHOT (docs/glut.md)
  --events FILE         replay input events from FILE: GLASS_GLUT_EVENTS (docs/glut.md)
  -h, --help            this help

exit status: 0 closed or snapshot written, 1 a file cannot be read, 2 bad usage

examples:
  glass ifs3d view scenes/ifs/homework3.ifs3
  glass ifs3d view cloud.txt found.ifs3 --show both
  glass ifs3d view found.ifs3 --show attractor --snapshot rebuilt.png --size 640x640
)";

enum class Shown { Cloud, Attractor, Both };

struct Ifs3Viewer {
  std::optional<g::IteratedFunctionSystem3> ifs;
  std::string title;
  std::vector<glm::dvec3> cloud;
  // The map each point belongs to (kUnexplainedPoint: none): for a chaos-game cloud the map it
  // came through last, for a file's cloud the map whose image passes nearest; empty without maps.
  std::vector<int> cloudParts;
  std::vector<glm::vec3> cloudHeightColors;  // the height ramp (ifs3d_cloud_colors.h)
  bool colorByHeight = false;
  Shown shown = Shown::Cloud;
  course::Ifs3View view{640, 640};
  glm::dvec3 lo{0.0}, hi{1.0};  // the box the picture frames
  course::Ifs3Camera camera;
  g::Quaternion orientation;  // the trackball's turn of the fractal about the box's centre
  double zoom = 1.0;          // the eye's distance as a multiple of the framing distance
  bool mapBoxes = false;
  std::vector<g::RebuildTriangle> triangles;
  int trianglesDepth = -1;
  int dragX = -1, dragY = -1;
  // The pane the drag turns in (its size): the trackball's ball is the pane's.
  int paneWidth = 1, paneHeight = 1;
};

Ifs3Viewer viewer;

// The rebuild at the view's depth, made when the depth changes. A depth whose rebuild would pass
// the triangle limit is refused with the limit's message, and the last depth stays.
void rebuildAtDepth(int depth) {
  if (!viewer.ifs || depth == viewer.trianglesDepth) return;
  std::string problem;
  std::vector<g::RebuildTriangle> triangles = g::polyhedralRebuild(*viewer.ifs, depth, g::kMaxRebuildTriangles, problem);
  if (!problem.empty()) {
    std::cerr << "glass ifs3d view: depth " << depth << ": " << problem << "\n";
    return;
  }
  viewer.triangles = std::move(triangles);
  viewer.trianglesDepth = depth;
  viewer.view.depth = depth;
}

void setTitle() {
  std::string what = viewer.shown == Shown::Cloud       ? "cloud"
                     : viewer.shown == Shown::Attractor ? "attractor"
                                                        : "cloud and attractor";
  if (viewer.shown != Shown::Cloud) what += ", depth " + std::to_string(viewer.view.depth);
  glutSetWindowTitle(("glass ifs3d view: " + viewer.title + " - " + what).c_str());
}

// The projection and camera of `glass ifs3d render`'s scene (ifs3SceneText), for a pane of
// width x height, with the eye moved along its line of sight by the zoom.
void placeCamera(int width, int height) {
  const course::Ifs3Camera &c = viewer.camera;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double zNear = viewer.zoom == 1.0 ? c.zNear : c.zNear * viewer.zoom;
  const double zFar = viewer.zoom == 1.0 ? c.zFar : c.zFar * viewer.zoom;
  gluPerspective(c.fovy, static_cast<double>(width) / height, zNear, zFar);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const glm::dvec3 eye = viewer.zoom == 1.0 ? c.eye : c.centre + (c.eye - c.centre) * viewer.zoom;
  gluLookAt(eye.x, eye.y, eye.z, c.centre.x, c.centre.y, c.centre.z, c.up.x, c.up.y, c.up.z);
}

// The state of the scene's header (ifs3SceneText): lighting, flat shading, colour material.
void setLighting() {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_FLAT);
  const glm::dvec3 &l = viewer.camera.lightDirection;
  const GLfloat position[4] = {static_cast<GLfloat>(l.x), static_cast<GLfloat>(l.y), static_cast<GLfloat>(l.z), 0.0f};
  const GLfloat diffuse[4] = {course::kIfs3LightDiffuse, course::kIfs3LightDiffuse, course::kIfs3LightDiffuse, 1.0f};
  const GLfloat ambient[4] = {course::kIfs3Ambient, course::kIfs3Ambient, course::kIfs3Ambient, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
}

// The trackball's turn about the box's centre, c - R c + R x, as one matrix: exactly the identity
// when the fractal has not been turned, which the `ifs3d` statement multiplies by too.
glm::dmat4 orientationMatrix() {
  const glm::dmat3 r = g::rotationMatrix(viewer.orientation);
  glm::dmat4 m(r);
  const glm::dvec3 c = viewer.camera.centre;
  m[3] = glm::dvec4(c - r * c, 1.0);
  return m;
}

// The colour of the points no map explains: a grey darker than any part's colour.
constexpr float kUnexplainedGrey = 0.45f;

void drawCloud() {
  glDisable(GL_LIGHTING);
  glPointSize(1.0f);
  glBegin(GL_POINTS);
  const bool byHeight = viewer.colorByHeight || viewer.cloudParts.empty();
  int lastPart = -2;
  for (std::size_t i = 0; i < viewer.cloud.size(); ++i) {
    if (byHeight) {
      const glm::vec3 &c = viewer.cloudHeightColors[i];
      glColor3f(c.r, c.g, c.b);
    } else if (viewer.cloudParts[i] != lastPart) {
      lastPart = viewer.cloudParts[i];
      if (lastPart == course::kUnexplainedPoint) {
        glColor3f(kUnexplainedGrey, kUnexplainedGrey, kUnexplainedGrey);
      } else {
        const g::IfsColor c = g::partColor3(*viewer.ifs, static_cast<std::size_t>(lastPart));
        glColor3f(c.r, c.g, c.b);
      }
    }
    glVertex3d(viewer.cloud[i].x, viewer.cloud[i].y, viewer.cloud[i].z);
  }
  glEnd();
  glEnable(GL_LIGHTING);
}

// Each map's image of the picture's box: the twelve edges of f_i(box), in the map's colour.
void drawMapBoxes() {
  glDisable(GL_LIGHTING);
  glBegin(GL_LINES);
  for (std::size_t i = 0; i < viewer.ifs->maps.size(); ++i) {
    const g::IfsColor c = g::partColor3(*viewer.ifs, i);
    glColor3f(c.r, c.g, c.b);
    const g::Affine3 &f = viewer.ifs->maps[i].transform;
    auto corner = [&](int bits) {
      return f.apply(glm::dvec3(bits & 1 ? viewer.hi.x : viewer.lo.x, bits & 2 ? viewer.hi.y : viewer.lo.y,
                                bits & 4 ? viewer.hi.z : viewer.lo.z));
    };
    for (int a = 0; a < 8; ++a) {
      for (int axis = 1; axis < 8; axis <<= 1) {
        if (a & axis) continue;  // each edge once, from its lower corner
        const glm::dvec3 p = corner(a), q = corner(a | axis);
        glVertex3d(p.x, p.y, p.z);
        glVertex3d(q.x, q.y, q.z);
      }
    }
  }
  glEnd();
  glEnable(GL_LIGHTING);
}

// One pane: what the `ifs3d` statement does (glass/scene/ifs3_rebuild_draw.h, with the current
// colour kept by glPushAttrib), or the cloud, under the trackball's turn.
void drawPane(int x, int width, int height, bool attractor) {
  glViewport(x, 0, width, height);
  placeCamera(width, height);
  setLighting();
  glPushAttrib(GL_CURRENT_BIT);
  glPushMatrix();
  const glm::dmat4 m = orientationMatrix();
  glMultMatrixd(&m[0][0]);
  if (attractor) {
    scene::drawIfs3Rebuild(*viewer.ifs, viewer.triangles, true);
  } else {
    drawCloud();
  }
  if (viewer.mapBoxes && viewer.ifs) drawMapBoxes();
  glPopMatrix();
  glPopAttrib();
}

void display() {
  const int width = glutGet(GLUT_WINDOW_WIDTH), height = std::max(1, glutGet(GLUT_WINDOW_HEIGHT));
  glClearColor(course::kIfs3Background[0], course::kIfs3Background[1], course::kIfs3Background[2], 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  if (viewer.shown == Shown::Both) {
    const int left = std::max(1, width / 2);
    drawPane(0, left, height, false);
    drawPane(left, std::max(1, width - left), height, true);
    viewer.paneWidth = left;
  } else {
    drawPane(0, std::max(1, width), height, viewer.shown == Shown::Attractor);
    viewer.paneWidth = std::max(1, width);
  }
  viewer.paneHeight = height;
  glutSwapBuffers();
}

void show(Shown what) {
  if (what != Shown::Cloud && !viewer.ifs) {
    std::cerr << "glass ifs3d view: no maps to rebuild the attractor from (name a .ifs3 file)\n";
    return;
  }
  viewer.shown = what;
  setTitle();
  glutPostRedisplay();
}

void keyboard(unsigned char key, int, int) {
  switch (key) {
    case 'c': show(Shown::Cloud); break;
    case 'a': show(Shown::Attractor); break;
    case 'b': show(Shown::Both); break;
    case '+': case '=':
    case '-':
      if (!viewer.ifs) break;
      rebuildAtDepth(std::clamp(viewer.view.depth + (key == '-' ? -1 : 1), 0, 12));
      setTitle();
      glutPostRedisplay();
      break;
    case 'm':
      if (!viewer.ifs) break;
      viewer.mapBoxes = !viewer.mapBoxes;
      glutPostRedisplay();
      break;
    case 'h':
      if (viewer.cloudParts.empty()) {
        std::cerr << "glass ifs3d view: no maps to colour the cloud's parts by (name a .ifs3 file); coloured by height\n";
        break;
      }
      viewer.colorByHeight = !viewer.colorByHeight;
      glutPostRedisplay();
      break;
    case 'r':
      viewer.orientation = {};
      viewer.zoom = 1.0;
      glutPostRedisplay();
      break;
    case 'q': case 27: glutLeaveMainLoop(); break;
    default: break;
  }
}

// The right button's menu (GLUT 3.7 section 6): the keys' choices, each entry's value the key it
// stands for, so that an entry does exactly what its key does.
void menuChoice(int key) { keyboard(static_cast<unsigned char>(key), 0, 0); }

void createMenu() {
  glutCreateMenu(menuChoice);
  glutAddMenuEntry("Cloud (c)", 'c');
  glutAddMenuEntry("Attractor rebuilt (a)", 'a');
  glutAddMenuEntry("Both side by side (b)", 'b');
  glutAddMenuEntry("Deeper (+)", '+');
  glutAddMenuEntry("Shallower (-)", '-');
  glutAddMenuEntry("Map boxes on/off (m)", 'm');
  glutAddMenuEntry("Cloud by height / by part (h)", 'h');
  glutAddMenuEntry("Reset the turn (r)", 'r');
  glutAddMenuEntry("Quit (q)", 'q');
  glutAttachMenu(GLUT_RIGHT_BUTTON);
}

void mouse(int button, int state, int x, int y) {
  if (button == GLUT_LEFT_BUTTON) {
    viewer.dragX = state == GLUT_DOWN ? x : -1;
    viewer.dragY = y;
  } else if (state == GLUT_DOWN && (button == 3 || button == 4)) {
    viewer.zoom = std::clamp(viewer.zoom * (button == 3 ? 0.9 : 1.0 / 0.9), 0.1, 10.0);
    glutPostRedisplay();
  }
}

void motion(int x, int y) {
  if (viewer.dragX < 0) return;
  // In the side-by-side view each pane is its own ball.
  const int offset = viewer.shown == Shown::Both && viewer.dragX >= viewer.paneWidth ? viewer.paneWidth : 0;
  const g::Quaternion drag = view::trackballDrag(viewer.dragX - offset, viewer.dragY, x - offset, y, viewer.paneWidth,
                                                 viewer.paneHeight);
  const course::Ifs3Camera &c = viewer.camera;
  viewer.orientation = view::turnByDrag(viewer.orientation, drag, c.eye, c.centre, c.up);
  viewer.dragX = x;
  viewer.dragY = y;
  glutPostRedisplay();
}

struct Arguments {
  std::string ifsFile, cloudFile;
  long long points = 50000;
  unsigned long long seed = 1;
};

bool parseNumberArgument(const std::string &text, long long low, long long high, long long &value) {
  char *end = nullptr;
  const long long parsed = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || parsed < low || parsed > high) return false;
  value = parsed;
  return true;
}

// Reads the command line into the viewer; an empty string when it is right, else what is wrong.
std::string readArguments(const std::vector<std::string> &args, Arguments &a) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string &arg = args[i];
    const bool hasValue = i + 1 < args.size();
    long long number = 0;
    std::string problem;
    const view::WindowOption option = view::takeWindowOption(args, i, viewer.view.width, viewer.view.height, problem);
    if (option == view::WindowOption::Bad) return problem;
    if (option == view::WindowOption::Taken) continue;
    if (arg == "--points" && hasValue) {
      if (!parseNumberArgument(args[++i], 1, 10000000, a.points)) return "--points wants a number from 1 to 10000000";
    } else if (arg == "--seed" && hasValue) {
      if (!parseNumberArgument(args[++i], 0, std::numeric_limits<long long>::max(), number)) return "--seed wants a whole number";
      a.seed = static_cast<unsigned long long>(number);
    } else if (arg == "--depth" && hasValue) {
      if (!parseNumberArgument(args[++i], 0, 12, number)) return "--depth wants a number from 0 to 12";
      viewer.view.depth = static_cast<int>(number);
    } else if (arg == "--view" && hasValue) {
      double azimuth = 0, elevation = 0;
      char end = 0;
      if (std::sscanf(args[++i].c_str(), "%lf,%lf%c", &azimuth, &elevation, &end) != 2 || !std::isfinite(azimuth) ||
          !(std::abs(elevation) < 90.0))
        return "--view takes AZIMUTH,ELEVATION in degrees, the elevation strictly between -90 and 90, like 35,25";
      viewer.view.azimuth = azimuth;
      viewer.view.elevation = elevation;
    } else if (arg == "--show" && hasValue) {
      const std::string &what = args[++i];
      if (what == "cloud") viewer.shown = Shown::Cloud;
      else if (what == "attractor") viewer.shown = Shown::Attractor;
      else if (what == "both") viewer.shown = Shown::Both;
      else return "--show wants cloud, attractor or both";
    } else if (!arg.empty() && arg[0] != '-') {
      const bool isIfs = arg.size() > 5 && arg.compare(arg.size() - 5, 5, ".ifs3") == 0;
      std::string &file = isIfs ? a.ifsFile : a.cloudFile;
      if (!file.empty()) return std::string("one ") + (isIfs ? ".ifs3 file" : "cloud") + " at a time";
      file = arg;
    } else {
      return "unknown or incomplete option '" + arg + "'";
    }
  }
  if (a.ifsFile.empty() && a.cloudFile.empty()) return "give a .ifs3 file, a cloud, or both";
  if (viewer.shown != Shown::Cloud && a.ifsFile.empty()) return "--show " + std::string(viewer.shown == Shown::Both ? "both" : "attractor") + " needs a .ifs3 file";
  return {};
}

// The cloud (a file's, or the chaos game's), the maps, and the box the picture frames: the
// attractor's box as `glass ifs3d render` frames it, or the cloud's when there are no maps.
bool loadInputs(const Arguments &a) {
  if (!a.ifsFile.empty()) {
    viewer.ifs = course::loadIfs3File(a.ifsFile, std::cerr);
    if (!viewer.ifs) return false;
    viewer.title = viewer.ifs->name.empty() ? a.ifsFile : viewer.ifs->name;
  }
  if (!a.cloudFile.empty()) {
    const course::PointCloud cloud = course::loadPointCloud(a.cloudFile);
    std::cerr << course::formatCloudMessages(cloud, a.cloudFile);
    if (!cloud.ok()) return false;
    viewer.cloud = cloud.points;
    if (viewer.ifs) {
      std::vector<g::Affine3> maps;
      for (const g::IfsMap3 &map : viewer.ifs->maps) maps.push_back(map.transform);
      viewer.cloudParts = course::cloudPartsByMaps(viewer.cloud, maps);
    }
    viewer.title = viewer.title.empty() ? a.cloudFile : viewer.title + " and " + a.cloudFile;
  } else {
    const std::optional<std::vector<double>> probabilities = g::chaosGameProbabilities3(*viewer.ifs);
    if (!probabilities) {
      std::cerr << "glass ifs3d view: " << a.ifsFile << ": the maps give no chaos game (no map keeps any volume, and no probabilities)\n";
      return false;
    }
    for (const g::IfsPoint3 &p : g::chaosGamePoints3(*viewer.ifs, *probabilities, static_cast<std::uint64_t>(a.points), a.seed)) {
      viewer.cloud.push_back(p.position);
      viewer.cloudParts.push_back(p.part);
    }
  }
  viewer.cloudHeightColors = course::heightColors(viewer.cloud);
  if (viewer.ifs) {
    course::ifs3PictureBox(*viewer.ifs, viewer.view, viewer.lo, viewer.hi);
  } else {
    viewer.lo = glm::dvec3(std::numeric_limits<double>::infinity());
    viewer.hi = -viewer.lo;
    for (const glm::dvec3 &p : viewer.cloud) {
      viewer.lo = glm::min(viewer.lo, p);
      viewer.hi = glm::max(viewer.hi, p);
    }
  }
  viewer.camera = course::ifs3Camera(viewer.lo, viewer.hi, viewer.view);
  const int depth = viewer.view.depth;
  rebuildAtDepth(depth);
  return !viewer.ifs || viewer.trianglesDepth == depth;
}

} // namespace

int runIfs3dView(const std::vector<std::string> &args) {
  if (wantsHelp(args)) {
    std::cout << kHelp;
    return kExitOk;
  }
  Arguments arguments;
  if (const std::string problem = readArguments(args, arguments); !problem.empty()) {
    std::cerr << "glass ifs3d view: " << problem << " (glass ifs3d view --help)\n";
    return kExitUsage;
  }
  if (!loadInputs(arguments)) return kExitBadInput;

  int argc = 1;
  char name[] = "glass ifs3d view";
  char *argv[] = {name, nullptr};
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
  glutInitWindowSize(viewer.view.width, viewer.view.height);
  glutCreateWindow("glass ifs3d view");
  setTitle();
  glutDisplayFunc(display);
  glutKeyboardFunc(keyboard);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  createMenu();
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
  glutMainLoop();
  return kExitOk;
}

} // namespace glass::cli
