// `glass view`: a scene file in a GLUT window (window/, <GL/freeglut.h>), with a camera of the
// viewer's own (examine and walk modes, walking with collisions, five viewpoints, perspective or
// orthographic, field of view), the teaching views, the shade model, wireframe, lights on and
// off, the rounding radius, animation, a right-button menu, and live reload.
#include "command_registry.h"
#include "view/scene_obstacles.h"
#include "view/scene_overrides.h"
#include "view/window_options.h"

#include <GL/freeglut.h>
#include <glass/scene/parser.h>
#include <glass/scene/render.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#include "glass/geometry/portable_math.h"

namespace glass::cli {

namespace {

constexpr const char *kHelp = R"(usage: glass view SCENE [options]

Shows a scene file (docs/scene-format.md) in a window, redrawn when the file or a file it
includes changes. The frame time is in the title bar.

  mouse    left drag: orbit around the scene's centre (examine) or turn (walk);
           wheel: closer and farther; right button: the menu (viewpoints, examine or walk,
           projection, views, shade model, wireframe, each light on or off, play, reload)
  keys     e examine, w walk, 1-5 viewpoints (1 is the scene's own camera), o orthographic or
           perspective, + and - the field of view, v the next view (colour, depth, overdraw,
           wireframe), R and r the rounding radius of rounded models up and down, c print the
           camera as scene statements, space play or pause the animation, F5 reload, q or
           Escape quit;
           walk: arrow keys move and turn at eye height, Page Up and Page Down look up and
           down; walls and objects stop the walker, who slides along them (docs/glut.md)

options:
  --size WxH            window size (default: the scene's `size`)
  --snapshot FILE       write the window's picture to FILE after the first frame (or after
                        the events) and exit: GLASS_GLUT_SNAPSHOT (docs/glut.md)
  --events FILE         replay input events from FILE: GLASS_GLUT_EVENTS (docs/glut.md)
  -h, --help            this help

exit status: 0 closed or snapshot written, 1 the scene cannot be read, 2 bad usage

examples:
  glass view scenes/room.scene
  glass view scenes/lighting.scene --snapshot lit.png --events keys.txt
)";

constexpr double kPi = 3.14159265358979323846;
double radians(double degrees) { return degrees * kPi / 180.0; }

enum class Mode { Examine, Walk };

// Menu values.
enum MenuValue {
  kViewpoint1 = 1,  // .. kViewpoint1 + 4
  kExamine = 10,
  kWalk,
  kPerspective,
  kOrthographic,
  kWiderView,
  kNarrowerView,
  kColorView = 20,  // .. + 3, in scene::View order
  kPlayPause = 30,
  kReload,
  kQuit,
  kShadeScene = 40, // .. + 3, in view::ShadeChoice order
  kWireframe = 50,
  kLight0 = 60,     // .. + 7, the light's number
};

// Each R or r press changes the rounding radius by this much (scene units).
constexpr double kRoundingStep = 0.02;

struct Viewer {
  std::string path;
  scene::Program program;
  bool haveProgram = false;
  std::vector<std::pair<std::string, std::filesystem::file_time_type>> watched;
  int width = 0, height = 0;
  scene::View view = scene::View::Color;
  int frame = 0;
  bool playing = false;

  scene::SceneCamera sceneCamera;  // from the first frame drawn
  bool sceneCameraKnown = false;
  Mode mode = Mode::Examine;
  int viewpoint = 1;
  scene::ViewCamera camera;        // what is drawn
  double centre[3] = {0, 0, 0};
  double distance = 5, yaw = 0, pitch = 0;  // examine: the eye around the centre
  double heading = 0, lookPitch = 0;        // walk: where the eye looks
  int dragX = -1, dragY = -1;

  view::SceneOverrides overrides;  // the menu's shade model, wireframe and lights, R and r
  int roundingSteps = 0;           // R minus r presses: roundingChange in kRoundingStep steps
  int lastRoundingPress = 0;       // +1 or -1 until the frame after an R or r is drawn
  std::vector<view::SceneLight> lights;
  int lightsMenu = 0, mainMenu = 0;
  // The program with the overrides made, for overriddenFrame; rebuilt when either changes.
  scene::Program overridden;
  bool overriddenValid = false;
  int overriddenFrame = -1;
  // Draws the program of programToDraw(), keeping its context, textures and compiled
  // definitions from frame to frame; made again when that program changes.
  std::unique_ptr<scene::FrameRenderer> renderer;

  const view::WalkerBody body;
};

Viewer viewer;

// The eye of the examine mode, on a sphere around the centre.
void placeExamineEye() {
  scene::ViewCamera &c = viewer.camera;
  const double cp = portable::cos(radians(viewer.pitch));
  c.eye[0] = viewer.centre[0] + viewer.distance * cp * portable::sin(radians(viewer.yaw));
  c.eye[1] = viewer.centre[1] + viewer.distance * portable::sin(radians(viewer.pitch));
  c.eye[2] = viewer.centre[2] + viewer.distance * cp * portable::cos(radians(viewer.yaw));
  std::copy(viewer.centre, viewer.centre + 3, c.centre);
  c.up[0] = 0;
  c.up[1] = 1;
  c.up[2] = 0;
}

// The point the walking eye looks at: one unit ahead along the heading, tilted by lookPitch.
void placeWalkTarget() {
  scene::ViewCamera &c = viewer.camera;
  const double cp = portable::cos(radians(viewer.lookPitch));
  c.centre[0] = c.eye[0] + cp * portable::sin(radians(viewer.heading));
  c.centre[1] = c.eye[1] + portable::sin(radians(viewer.lookPitch));
  c.centre[2] = c.eye[2] + cp * portable::cos(radians(viewer.heading));
}

// Viewpoint 1 is the scene's own lookat; 2-5 look at its centre from the front, the right, above
// and a corner, at the scene camera's distance.
void chooseViewpoint(int number) {
  viewer.viewpoint = number;
  viewer.mode = Mode::Examine;
  const scene::SceneCamera &s = viewer.sceneCamera;
  viewer.camera.zNear = s.hasPerspective ? s.zNear : 0.1; // walking may have moved it closer
  const double *look = s.lookAt;
  std::copy(look + 3, look + 6, viewer.centre);
  const double dx = look[0] - look[3], dy = look[1] - look[4], dz = look[2] - look[5];
  viewer.distance = std::max(1e-3, std::sqrt(dx * dx + dy * dy + dz * dz));
  if (number == 1) {
    std::copy(look, look + 9, viewer.camera.eye);  // eye, centre and up are consecutive
    std::copy(look + 3, look + 6, viewer.camera.centre);
    std::copy(look + 6, look + 9, viewer.camera.up);
    viewer.yaw = portable::atan2(dx, dz) * 180.0 / kPi;
    viewer.pitch = portable::asin(std::clamp(dy / viewer.distance, -1.0, 1.0)) * 180.0 / kPi;
    return;
  }
  static const double angles[5][2] = {{0, 0}, {0, 0}, {90, 0}, {0, 89}, {45, 35}};
  viewer.yaw = angles[number - 1][0];
  viewer.pitch = angles[number - 1][1];
  placeExamineEye();
}

// The walking eye stands eyeHeight above the scene's ground (scene_obstacles.h).
view::WalkGround walkGround() {
  return view::walkGround(view::sceneBoxes(viewer.program, viewer.frame), viewer.body);
}

void startWalking() {
  viewer.mode = Mode::Walk;
  scene::ViewCamera &c = viewer.camera;
  const double dx = c.centre[0] - c.eye[0], dz = c.centre[2] - c.eye[2];
  viewer.heading = portable::atan2(dx, dz) * 180.0 / kPi;
  viewer.lookPitch = 0;
  c.eye[1] = walkGround().groundY + viewer.body.eyeHeight;
  c.up[0] = 0;
  c.up[1] = 1;
  c.up[2] = 0;
  placeWalkTarget();
}

// The near plane while walking: close enough that its corners stay within the walker's radius
// of the eye, so that a wall the walker stands at cannot be cut open by it. A corner of the
// near plane at distance n is n sqrt(1 + t^2 (1 + a^2)) from the eye, t = tan(fovy / 2) and a
// the aspect ratio.
double walkingNearPlane(int width, int height) {
  const double t = portable::tan(radians(viewer.camera.fovy) / 2);
  const double a = height > 0 ? static_cast<double>(width) / height : 1.0;
  const double inside = 0.9 * viewer.body.radius / std::sqrt(1 + t * t * (1 + a * a));
  return std::min(viewer.sceneCamera.hasPerspective ? viewer.sceneCamera.zNear : 0.1, inside);
}

// The program drawn: the scene's, or a copy with the viewer's overrides.
const scene::Program &programToDraw() {
  if (!viewer.overrides.any()) return viewer.program;
  if (!viewer.overriddenValid || viewer.overriddenFrame != viewer.frame) {
    viewer.renderer.reset();
    viewer.overridden = view::withOverrides(viewer.program, viewer.overrides, viewer.frame);
    viewer.overriddenValid = true;
    viewer.overriddenFrame = viewer.frame;
  }
  return viewer.overridden;
}

void overridesChanged() {
  viewer.overriddenValid = false;
  viewer.renderer.reset();
}

bool readScene() {
  scene::Diagnostics diagnostics;
  scene::Program program = scene::parseSceneFile(viewer.path, diagnostics);
  if (diagnostics.hasErrors()) {
    // The last good picture stays.
    diagnostics.print(std::cerr);
    return false;
  }
  diagnostics.print(std::cerr);
  viewer.program = std::move(program);
  viewer.haveProgram = true;
  overridesChanged();
  viewer.frame = std::min(viewer.frame, viewer.program.frames - 1);
  viewer.watched.clear();
  for (const std::string &file : viewer.program.sources->paths()) {
    std::error_code ec;
    viewer.watched.emplace_back(file, std::filesystem::last_write_time(file, ec));
  }
  return true;
}

// The frame drawn by the scene library into an image (in a context of its own, kept from frame
// to frame), then into the window with glDrawPixels.
void display() {
  const auto start = std::chrono::steady_clock::now();
  const int window = glutGetWindow();
  scene::RenderOptions options;
  options.width = glutGet(GLUT_WINDOW_WIDTH);
  options.height = glutGet(GLUT_WINDOW_HEIGHT);
  options.view = viewer.view;
  scene::SceneCamera seen;
  options.sceneCamera = &seen;
  if (viewer.mode == Mode::Walk) viewer.camera.zNear = walkingNearPlane(options.width, options.height);
  options.camera = viewer.sceneCameraKnown ? &viewer.camera : nullptr;
  scene::RenderedFrame rendered;
  scene::Diagnostics diagnostics;
  bool drawn = false;
  if (viewer.haveProgram) {
    const scene::Program &program = programToDraw();
    if (!viewer.renderer) viewer.renderer = std::make_unique<scene::FrameRenderer>(program);
    drawn = viewer.renderer->render(viewer.frame, options, rendered, diagnostics);
  }
  glutSetWindow(window);  // the renderer drew in a context of its own
  if (!drawn && viewer.lastRoundingPress != 0) {
    // A radius the model cannot take (docs/scene-format.md, `round`): said on stderr, then back
    // to the last radius it took; the picture shown stays.
    diagnostics.print(std::cerr);
    viewer.roundingSteps -= viewer.lastRoundingPress;
    viewer.lastRoundingPress = 0;
    viewer.overrides.roundingChange = viewer.roundingSteps * kRoundingStep;
    overridesChanged();
    glutPostRedisplay();
    return;
  }
  viewer.lastRoundingPress = 0;
  if (!drawn) {
    diagnostics.print(std::cerr);
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
    return;
  }
  if (!viewer.sceneCameraKnown && seen.hasLookAt) {
    viewer.sceneCamera = seen;
    viewer.sceneCameraKnown = true;
    viewer.camera.fovy = seen.hasPerspective ? seen.fovy : 45.0;
    viewer.camera.zNear = seen.hasPerspective ? seen.zNear : 0.1;
    viewer.camera.zFar = seen.hasPerspective ? seen.zFar : 1000.0;
    chooseViewpoint(1);
  }
  const scene::Image &image = rendered.image;
  // The image's rows go top to bottom, GL's bottom to top.
  std::vector<unsigned char> rows(image.rgba.size());
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    std::copy_n(image.rgba.begin() + static_cast<std::ptrdiff_t>(y * rowBytes), rowBytes,
                rows.begin() + static_cast<std::ptrdiff_t>((image.height - 1 - y) * rowBytes));
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  glutSwapBuffers();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  char title[512];
  std::snprintf(title, sizeof title, "glass view: %s - %.1f ms", viewer.path.c_str(), ms);
  glutSetWindowTitle(title);
}

void redraw() { glutPostRedisplay(); }

void zoom(double factor) {
  if (viewer.mode != Mode::Examine) return;
  viewer.distance = std::max(1e-3, viewer.distance * factor);
  placeExamineEye();
  redraw();
}

void changeFieldOfView(double degrees) {
  viewer.camera.fovy = std::clamp(viewer.camera.fovy + degrees, 5.0, 150.0);
  redraw();
}

void setProjection(bool orthographic) {
  viewer.camera.orthographic = orthographic;
  // The same height at the centre as the perspective view shows there.
  viewer.camera.halfHeight = viewer.distance * portable::tan(radians(viewer.camera.fovy) / 2);
  redraw();
}

// A step of walk mode: turned by `turn` degrees, then `forward` steps (1/20 of the scene
// camera's distance to its centre each) along the heading, stopped by the scene's obstacles and
// sliding along them (view/walk_collision.h).
void walk(double forward, double turn) {
  scene::ViewCamera &c = viewer.camera;
  viewer.heading += turn;
  if (forward != 0.0) {
    const double step = forward * std::max(viewer.distance, 1e-3) / 20;
    const view::GroundPoint motion{step * portable::sin(radians(viewer.heading)),
                                   step * portable::cos(radians(viewer.heading))};
    const view::GroundPoint at =
        view::slideMove({c.eye[0], c.eye[2]}, motion, viewer.body.radius, walkGround().obstacles);
    c.eye[0] = at.x;
    c.eye[2] = at.z;
  }
  placeWalkTarget();
  redraw();
}

// The camera as scene statements (docs/scene-format.md), to paste into a scene file: the
// projection with the current field of view and planes, and the lookat.
void printCamera() {
  const scene::ViewCamera &c = viewer.camera;
  const int width = glutGet(GLUT_WINDOW_WIDTH), height = glutGet(GLUT_WINDOW_HEIGHT);
  if (c.orthographic) {
    const double halfWidth = c.halfHeight * (height > 0 ? static_cast<double>(width) / height : 1.0);
    std::printf("ortho %.17g %.17g %.17g %.17g %.17g %.17g\n", -halfWidth, halfWidth, -c.halfHeight,
                c.halfHeight, c.zNear, c.zFar);
  } else {
    std::printf("perspective %.17g auto %.17g %.17g\n", c.fovy, c.zNear, c.zFar);
  }
  std::printf("lookat %.17g %.17g %.17g  %.17g %.17g %.17g  %.17g %.17g %.17g\n", c.eye[0], c.eye[1],
              c.eye[2], c.centre[0], c.centre[1], c.centre[2], c.up[0], c.up[1], c.up[2]);
  std::fflush(stdout);
}

// The labels of the menu entries that switch something on and off say its state.
void labelSwitches() {
  const int current = glutGetMenu();
  glutSetMenu(viewer.mainMenu);
  glutChangeToMenuEntry(7, viewer.overrides.wireframe ? "Wireframe: on" : "Wireframe: off", kWireframe);
  glutSetMenu(viewer.lightsMenu);
  while (glutGet(GLUT_MENU_NUM_ITEMS) > 0) glutRemoveMenuItem(1);
  for (const view::SceneLight &light : viewer.lights) {
    const bool off = std::count(viewer.overrides.lightsOff.begin(), viewer.overrides.lightsOff.end(), light.number) > 0;
    const std::string label = "Light " + std::to_string(light.number) + " (" + light.kind + "): " + (off ? "off" : "on");
    glutAddMenuEntry(label.c_str(), kLight0 + light.number);
  }
  if (viewer.lights.empty()) glutAddMenuEntry("(the scene has no lights)", 0);
  if (current > 0) glutSetMenu(current);
}

void switchLight(int number) {
  std::vector<int> &off = viewer.overrides.lightsOff;
  if (std::erase(off, number) == 0) off.push_back(number);
  overridesChanged();
  labelSwitches();
}

// R and r: every rounded model's radius up or down by kRoundingStep, not below 0. A radius the
// model cannot take is reported by the frame (file:line:col) and taken back (display()).
void changeRounding(int press) {
  if (!view::hasRoundedModels(viewer.program)) {
    std::cerr << "glass view: the scene has no rounded model (model ... round R)\n";
    return;
  }
  viewer.roundingSteps += press;
  viewer.lastRoundingPress = press;
  viewer.overrides.roundingChange = viewer.roundingSteps * kRoundingStep;
  overridesChanged();
}

void choose(int value) {
  if (value >= kViewpoint1 && value < kViewpoint1 + 5) {
    if (viewer.sceneCameraKnown) chooseViewpoint(value - kViewpoint1 + 1);
  } else if (value >= kColorView && value < kColorView + 4) {
    viewer.view = static_cast<scene::View>(value - kColorView);
  } else {
    switch (value) {
      case kExamine:
        if (viewer.sceneCameraKnown) chooseViewpoint(viewer.viewpoint);
        break;
      case kWalk:
        if (viewer.sceneCameraKnown) startWalking();
        break;
      case kPerspective: setProjection(false); break;
      case kOrthographic: setProjection(true); break;
      case kWiderView: changeFieldOfView(5); break;
      case kNarrowerView: changeFieldOfView(-5); break;
      case kPlayPause: viewer.playing = !viewer.playing; break;
      case kReload:
        if (readScene()) {
          viewer.lights = view::sceneLights(viewer.program);
          labelSwitches();
        }
        break;
      case kShadeScene:
      case kShadeScene + 1:
      case kShadeScene + 2:
      case kShadeScene + 3:
        viewer.overrides.shade = static_cast<view::ShadeChoice>(value - kShadeScene);
        overridesChanged();
        break;
      case kWireframe:
        viewer.overrides.wireframe = !viewer.overrides.wireframe;
        overridesChanged();
        labelSwitches();
        break;
      case kQuit: glutLeaveMainLoop(); break;
      default:
        if (value >= kLight0 && value < kLight0 + 8) switchLight(value - kLight0);
        break;
    }
  }
  redraw();
}

void keyboard(unsigned char key, int, int) {
  switch (key) {
    case 'e': choose(kExamine); break;
    case 'w': choose(kWalk); break;
    case '1': case '2': case '3': case '4': case '5': choose(kViewpoint1 + (key - '1')); break;
    case 'o': choose(viewer.camera.orthographic ? kPerspective : kOrthographic); break;
    case '+': choose(kWiderView); break;
    case '-': choose(kNarrowerView); break;
    case 'v': choose(kColorView + (static_cast<int>(viewer.view) + 1) % 4); break;
    case ' ': choose(kPlayPause); break;
    case 'R': changeRounding(1); redraw(); break;
    case 'r': changeRounding(-1); redraw(); break;
    case 'c': printCamera(); break;
    case 'q': case 27: choose(kQuit); break;
    default: break;
  }
}

void special(int key, int, int) {
  if (key == GLUT_KEY_F5) choose(kReload);
  if (viewer.mode != Mode::Walk) return;
  switch (key) {
    case GLUT_KEY_UP: walk(1, 0); break;
    case GLUT_KEY_DOWN: walk(-1, 0); break;
    case GLUT_KEY_LEFT: walk(0, 5); break;
    case GLUT_KEY_RIGHT: walk(0, -5); break;
    case GLUT_KEY_PAGE_UP:
      viewer.lookPitch = std::min(viewer.lookPitch + 5, 85.0);
      placeWalkTarget();
      redraw();
      break;
    case GLUT_KEY_PAGE_DOWN:
      viewer.lookPitch = std::max(viewer.lookPitch - 5, -85.0);
      placeWalkTarget();
      redraw();
      break;
    default: break;
  }
}

void mouse(int button, int state, int x, int y) {
  if (button == GLUT_LEFT_BUTTON) {
    viewer.dragX = state == GLUT_DOWN ? x : -1;
    viewer.dragY = y;
  } else if (state == GLUT_DOWN && (button == 3 || button == 4)) {
    zoom(button == 3 ? 0.9 : 1.0 / 0.9);  // the wheel, as GLUT gives it
  }
}

void motion(int x, int y) {
  if (viewer.dragX < 0 || !viewer.sceneCameraKnown) return;
  const double dx = x - viewer.dragX, dy = y - viewer.dragY;
  viewer.dragX = x;
  viewer.dragY = y;
  if (viewer.mode == Mode::Examine) {
    viewer.yaw -= dx * 0.5;
    viewer.pitch = std::clamp(viewer.pitch + dy * 0.5, -89.0, 89.0);
    placeExamineEye();
  } else {
    viewer.heading -= dx * 0.5;
    viewer.lookPitch = std::clamp(viewer.lookPitch - dy * 0.5, -85.0, 85.0);
    placeWalkTarget();
  }
  redraw();
}

// Every quarter second: reload when a file of the scene changed; the next frame when playing.
void tick(int) {
  bool changed = false;
  for (const auto &[file, time] : viewer.watched) {
    std::error_code ec;
    if (std::filesystem::last_write_time(file, ec) != time) changed = true;
  }
  if (changed && readScene()) {
    viewer.lights = view::sceneLights(viewer.program);
    labelSwitches();
    redraw();
  }
  if (viewer.playing && viewer.haveProgram && viewer.program.frames > 1) {
    viewer.frame = (viewer.frame + 1) % viewer.program.frames;
    redraw();
  }
  glutTimerFunc(250, tick, 0);
}

void buildMenu() {
  const int viewpoints = glutCreateMenu(choose);
  for (int i = 0; i < 5; ++i) {
    const std::string label = i == 0 ? "1 the scene's camera" : std::to_string(i + 1) +
        (i == 1 ? " front" : i == 2 ? " right" : i == 3 ? " top" : " corner");
    glutAddMenuEntry(label.c_str(), kViewpoint1 + i);
  }
  const int projection = glutCreateMenu(choose);
  glutAddMenuEntry("Perspective", kPerspective);
  glutAddMenuEntry("Orthographic", kOrthographic);
  glutAddMenuEntry("Wider field (+)", kWiderView);
  glutAddMenuEntry("Narrower field (-)", kNarrowerView);
  const int views = glutCreateMenu(choose);
  glutAddMenuEntry("Colour", kColorView);
  glutAddMenuEntry("Depth", kColorView + 1);
  glutAddMenuEntry("Overdraw", kColorView + 2);
  glutAddMenuEntry("Wireframe", kColorView + 3);
  const int shading = glutCreateMenu(choose);
  glutAddMenuEntry("The scene's own", kShadeScene);
  glutAddMenuEntry("Flat", kShadeScene + 1);
  glutAddMenuEntry("Smooth (Gouraud)", kShadeScene + 2);
  glutAddMenuEntry("Phong (per pixel)", kShadeScene + 3);
  viewer.lightsMenu = glutCreateMenu(choose);
  viewer.mainMenu = glutCreateMenu(choose);
  glutAddSubMenu("Viewpoint", viewpoints);
  glutAddMenuEntry("Examine", kExamine);
  glutAddMenuEntry("Walk", kWalk);
  glutAddSubMenu("Projection", projection);
  glutAddSubMenu("View", views);
  glutAddSubMenu("Shade model", shading);
  glutAddMenuEntry("Wireframe: off", kWireframe); // entry 7: labelSwitches() keeps its label
  glutAddSubMenu("Lights", viewer.lightsMenu);
  glutAddMenuEntry("Play / pause", kPlayPause);
  glutAddMenuEntry("Reload", kReload);
  glutAddMenuEntry("Quit", kQuit);
  glutAttachMenu(GLUT_RIGHT_BUTTON);
  viewer.lights = view::sceneLights(viewer.program);
  labelSwitches();
}

int runView(const std::vector<std::string> &args) {
  if (wantsHelp(args)) {
    std::cout << kHelp;
    return kExitOk;
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string &arg = args[i];
    std::string problem;
    const view::WindowOption option = view::takeWindowOption(args, i, viewer.width, viewer.height, problem);
    if (option == view::WindowOption::Bad) {
      std::cerr << "glass view: " << problem << "\n";
      return kExitUsage;
    }
    if (option == view::WindowOption::Taken) continue;
    if (!arg.empty() && arg[0] != '-' && viewer.path.empty()) {
      viewer.path = arg;
    } else {
      std::cerr << "glass view: unknown or incomplete option '" << arg << "' (glass view --help)\n";
      return kExitUsage;
    }
  }
  if (viewer.path.empty()) {
    std::cerr << "glass view: which scene? (glass view --help)\n";
    return kExitUsage;
  }
  if (!readScene()) return kExitBadInput;

  int argc = 1;
  char name[] = "glass view";
  char *argv[] = {name, nullptr};
  glutInit(&argc, argv);
  // The buffers glass render draws a scene with: alpha bitplanes (for dst_alpha blending) and a
  // stencil buffer besides the depth buffer, so that the window shows the same picture.
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_ALPHA | GLUT_DEPTH | GLUT_STENCIL);
  glutInitWindowSize(viewer.width > 0 ? viewer.width : viewer.program.width,
                     viewer.height > 0 ? viewer.height : viewer.program.height);
  glutCreateWindow(("glass view: " + viewer.path).c_str());
  glutDisplayFunc(display);
  glutKeyboardFunc(keyboard);
  glutSpecialFunc(special);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  buildMenu();
  glutTimerFunc(250, tick, 0);
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
  glutMainLoop();
  return kExitOk;
}

const bool registered =
    registerCommand({"view", "show a scene file in a window: examine, walk, viewpoints, menu, live reload", runView});

} // namespace

} // namespace glass::cli
