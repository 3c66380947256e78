// Initialisation and windows (GLUT 3.7 spec 2 and 4; freeglut's additions).
#include <GL/freeglut.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "context_version.h"
#include "framebuffer_bits.h"
#include "glut_clock.h"
#include "glut_errors.h"
#include "glut_state.h"
#include "headless_run.h"
#include "popup_menu.h"
#include "presentation.h"
#include "sdl_display.h"
#include "window_lifecycle.h"

namespace glass::glut {

namespace {

// X's geometry string, as freeglut reads -geometry: WxH, +X+Y, or both; unset parts stay.
void applyGeometry(const char* geometry) {
  State& s = state();
  int width = 0, height = 0, x = 0, y = 0;
  char xSign = '+', ySign = '+';
  const char* position = geometry;
  if (std::sscanf(geometry, "%dx%d", &width, &height) == 2) {
    if (width > 0) s.initWidth = width;
    if (height > 0) s.initHeight = height;
    position = std::strpbrk(geometry, "+-");
  }
  if (position && std::sscanf(position, "%c%d%c%d", &xSign, &x, &ySign, &y) == 4) {
    s.initX = xSign == '-' ? -x : x;
    s.initY = ySign == '-' ? -y : y;
  }
}

// freeglut's command-line options: taken out of argv, the others left in their order.
void takeOptions(int* pargc, char** argv) {
  if (!pargc || !argv) return;
  int kept = 1;
  for (int i = 1; i < *pargc; ++i) {
    const char* option = argv[i];
    if (std::strcmp(option, "-display") == 0 || std::strcmp(option, "-geometry") == 0) {
      if (i + 1 >= *pargc) {
        fatalError(std::strcmp(option, "-display") == 0
                       ? "-display parameter must be followed by display name"
                       : "-geometry parameter must be followed by window geometry settings");
      }
      if (std::strcmp(option, "-display") == 0) {
        setenv("DISPLAY", argv[i + 1], 1);
      } else {
        applyGeometry(argv[i + 1]);
      }
      ++i;
      continue;
    }
    if (std::strcmp(option, "-direct") == 0 || std::strcmp(option, "-indirect") == 0 ||
        std::strcmp(option, "-iconic") == 0 || std::strcmp(option, "-gldebug") == 0 ||
        std::strcmp(option, "-sync") == 0) {
      continue;
    }
    argv[kept++] = argv[i];
  }
  for (int i = kept; i < *pargc; ++i) argv[i] = nullptr;
  *pargc = kept;
}

// A move glass made on the system's window (into or out of full screen) is told to the position
// callback by the loop, as a move the program asks for is (SDL sends no event for either).
void reportSystemMove(Window& window) {
  int x = 0, y = 0;
  if (!systemWindowPosition(window, x, y) || (x == window.x && y == window.y)) return;
  window.requestedX = x;
  window.requestedY = y;
  window.movePending = true;
}

void freeWindow(Window& window) {
  destroySystemWindow(window);
  if (window.context) glassDestroyContext(window.context);
  if (window.menuContext) glassDestroyContext(window.menuContext);
  window.context = window.menuContext = nullptr;
}

}  // namespace

void destroyWindow(int id) {
  State& s = state();
  Window* window = findWindow(id);
  if (!window) return;
  if (window->callbacks.close) {
    void (*close)() = window->callbacks.close;
    window->callbacks.close = nullptr;  // once, even if it destroys the window itself
    const int previous = s.currentWindow;
    makeCurrent(*window);
    close();
    if (Window* restored = findWindow(previous); restored && previous != id) makeCurrent(*restored);
    window = findWindow(id);
    if (!window) return;
  }
  // Its sub-windows go with it, the topmost first.
  while (!window->children.empty()) {
    destroyWindow(window->children.back());
    window = findWindow(id);
    if (!window) return;
  }
  if (Window* parent = findWindow(window->parent)) {
    std::erase(parent->children, id);
    Window& top = topLevelOf(*parent);
    if (top.capturedBy == id) top.capturedBy = 0;
    if (top.pointerOver == id) top.pointerOver = 0;
  }
  const int parentId = window->parent;
  if (s.gameModeWindow == id) s.gameModeWindow = 0;
  const bool wasCurrent = s.currentWindow == id;
  freeWindow(*window);
  s.windows.erase(id);
  // The parent no longer shows it.
  if (Window* parent = findWindow(parentId)) refreshScreen(*parent);
  if (wasCurrent) {
    s.currentWindow = 0;
    glassMakeCurrent(nullptr);
  }
}

void closeWindowFromSystem(Window& window) {
  State& s = state();
  switch (s.actionOnWindowClose) {
    case GLUT_ACTION_GLUTMAINLOOP_RETURNS:
      destroyWindow(window.id);
      s.loopRunning = false;
      return;
    case GLUT_ACTION_CONTINUE_EXECUTION:
      destroyWindow(window.id);
      return;
    default:
      destroyWindow(window.id);
      deinitialise();
      std::exit(0);
  }
}

void deinitialise() {
  State& s = state();
  if (!s.initialised) return;
  while (!s.windows.empty()) destroyWindow(s.windows.begin()->first);
  while (!s.menus.empty()) destroyMenu(s.menus.begin()->first);
  s.timers.clear();
  closeDisplay();
  // What glutInit and glutInit* set goes; a new glutInit starts afresh, as with freeglut.
  void (*errorFunc)(const char*, va_list) = s.errorFunc;
  void (*warningFunc)(const char*, va_list) = s.warningFunc;
  s = State{};
  s.errorFunc = errorFunc;
  s.warningFunc = warningFunc;
}

}  // namespace glass::glut

using namespace glass::glut;

extern "C" {

void glutInit(int* pargc, char** argv) {
  State& s = state();
  if (s.initialised) fatalError("illegal glutInit() reinitialization attempt");
  if (pargc && *pargc > 0 && argv && argv[0]) {
    const char* slash = std::strrchr(argv[0], '/');
    s.programName = slash ? slash + 1 : argv[0];
  }
  takeOptions(pargc, argv);
  configureHeadlessRun();
  std::string failure;
  if (!openDisplay(headlessRunRequested(), failure)) {
    const char* display = std::getenv("DISPLAY");
    std::fprintf(stderr,
                 "glass: no display to open windows on (%s); to run without one, set "
                 "GLASS_GLUT_SNAPSHOT=picture.png (and GLASS_GLUT_EVENTS=file for input), see "
                 "docs/glut.md\n",
                 failure.c_str());
    fatalError("failed to open display '%s'", display ? display : "");
  }
  startClock(displayIsHeadless());
  s.initialised = true;
}

void glutInitWindowPosition(int x, int y) {
  state().initX = x;
  state().initY = y;
}

void glutInitWindowSize(int width, int height) {
  // freeglut keeps its default (300 x 300) for sizes that are not positive.
  if (width > 0 && height > 0) {
    state().initWidth = width;
    state().initHeight = height;
  }
}

void glutInitDisplayMode(unsigned int displayMode) { state().initDisplayMode = displayMode; }

void glutInitErrorFunc(void (*callback)(const char* fmt, va_list ap)) {
  state().errorFunc = callback;
}

void glutInitWarningFunc(void (*callback)(const char* fmt, va_list ap)) {
  state().warningFunc = callback;
}

}  // extern "C"

namespace glass::glut {
namespace {

// A window of the initial display mode with its context, at x, y (on the screen, or in the
// parent for a sub-window), not yet registered.
std::unique_ptr<Window> newWindow(const char* title, int x, int y, int width, int height) {
  State& s = state();
  // glass's framebuffer is RGBA; colour index and stereo visuals do not exist. A multisample
  // window is a wish: "if multisampling is not available, a non-multisampling window will
  // automatically be chosen" (GLUT 3.7, glutInitDisplayMode; freeglut tries again without it).
  if (s.initDisplayMode & (GLUT_INDEX | GLUT_STEREO)) {
    fatalError("FBConfig with necessary capabilities not found");
  }
  requireContextGlassHas();
  auto window = std::make_unique<Window>();
  window->id = s.nextWindowId++;
  window->title = title ? title : "";
  window->x = x;
  window->y = y;
  window->width = width;
  window->height = height;
  window->displayMode = s.initDisplayMode;
  window->doubleBuffered = (s.initDisplayMode & GLUT_DOUBLE) != 0;
  window->context = glassCreateContext(window->width, window->height);
  if (!window->context) {
    fatalError("Unable to create OpenGL context for a %d x %d window", window->width,
               window->height);
  }
  const AncillaryBits bits = ancillaryBitsOf(window->displayMode);
  glassSetAncillaryBuffers(window->context, bits.depth, bits.stencil, bits.accumulation);
  glassSetAlphaBitplanes(window->context, alphaBitsOf(window->displayMode));
  // GLUT_DOUBLE: a front buffer, which the window shows, and a back one, which GL draws into.
  if (window->doubleBuffered && !glassSetDoubleBuffered(window->context, 1)) {
    fatalError("Unable to create OpenGL context for a %d x %d window", window->width, window->height);
  }
  return window;
}

// Puts a sub-window on top of its siblings or under them, and shows the parent so; false for a
// top-level window.
bool restackSubWindow(Window& window, bool onTop) {
  Window* parent = findWindow(window.parent);
  if (!parent) return false;
  std::erase(parent->children, window.id);
  parent->children.insert(onTop ? parent->children.end() : parent->children.begin(), window.id);
  refreshScreen(*parent);
  return true;
}

// Registers the window, makes it current and shows its (black) picture.
int registerWindow(std::unique_ptr<Window> window) {
  State& s = state();
  glassSetFlushCallback(window->context, presentOnFlush,
                        reinterpret_cast<void*>(static_cast<intptr_t>(window->id)));
  window->shown.assign(static_cast<size_t>(window->width) * window->height * 4, 0);
  // A window that appears anywhere but at (0, 0) (of the screen, or of its parent) is told its
  // position before its first reshape, as freeglut tells it on X: it takes the window's first
  // ConfigureNotify (or a sub-window's CreateNotify) for a move from (0, 0).
  if (window->x != 0 || window->y != 0) {
    window->movePending = true;
    window->requestedX = window->x;
    window->requestedY = window->y;
  }
  Window& created = *window;
  s.windows[created.id] = std::move(window);
  makeCurrent(created);
  refreshScreen(created);
  return created.id;
}

}  // namespace

int createTopLevelWindow(const char* title, int x, int y, int width, int height, bool gameMode) {
  std::unique_ptr<Window> window = newWindow(title, x, y, width, height);
  if (!createSystemWindow(*window, gameMode)) {
    glassDestroyContext(window->context);
    fatalError("Unable to create a window: %s", "the window system refused it");
  }
  return registerWindow(std::move(window));
}

}  // namespace glass::glut

extern "C" {

int glutCreateWindow(const char* title) {
  requireInitialised("glutCreateWindow");
  const State& s = state();
  return createTopLevelWindow(title, s.initX, s.initY, s.initWidth, s.initHeight, false);
}

// GLUT 3.7 spec 4.2: a window inside `parent`, at x, y in the parent's coordinates (y down), with
// the initial display mode; it has no title and no window of its own in the window system. As
// freeglut: a parent that does not exist gives 0; a negative x or y counts from the parent's
// right or bottom edge (to the sub-window's own far edge when its size is given), and a negative
// width or height leaves that much of the parent beyond the sub-window.
int glutCreateSubWindow(int parent, int x, int y, int width, int height) {
  requireInitialised("glutCreateSubWindow");
  Window* owner = findWindow(parent);
  if (!owner) return 0;
  auto placeAlong = [](int parentSize, int& start, int& size) {
    if (start < 0) start = parentSize + start - (size >= 0 ? size : 0);
    if (size < 0) size = parentSize - start + size;
    if (size < 0) {
      start += size;
      size = -size;
    }
  };
  placeAlong(owner->width, x, width);
  placeAlong(owner->height, y, height);
  std::unique_ptr<Window> window = newWindow("", x, y, width > 0 ? width : 1, height > 0 ? height : 1);
  window->parent = parent;
  owner->children.push_back(window->id);
  return registerWindow(std::move(window));
}

void glutDestroyWindow(int window) {
  requireInitialised("glutDestroyWindow");
  destroyWindow(window);
}

void glutSetWindow(int id) {
  requireInitialised("glutSetWindow");
  Window* window = findWindow(id);
  if (!window) {
    warning("glutSetWindow(): window ID %d not found!", id);
    return;
  }
  makeCurrent(*window);
}

int glutGetWindow(void) {
  requireInitialised("glutGetWindow");
  return currentWindow() ? state().currentWindow : 0;
}

void glutSetWindowTitle(const char* title) {
  Window* window = requireCurrentWindow("glutSetWindowTitle");
  if (!window || !title) return;
  window->title = title;
  setSystemWindowTitle(*window);
}

// SDL gives windows no icon title of their own: the call is checked and has no effect.
void glutSetIconTitle(const char*) { requireCurrentWindow("glutSetIconTitle"); }

void glutReshapeWindow(int width, int height) {
  Window* window = requireCurrentWindow("glutReshapeWindow");
  if (!window) return;
  if (window->fullScreen) {
    window->fullScreen = false;
    setSystemWindowFullScreen(*window, false);
    reportSystemMove(*window);
  }
  window->requestedWidth = width > 0 ? width : 1;
  window->requestedHeight = height > 0 ? height : 1;
  setSystemWindowSize(*window, window->requestedWidth, window->requestedHeight);
}

void glutPositionWindow(int x, int y) {
  Window* window = requireCurrentWindow("glutPositionWindow");
  if (!window) return;
  // Applied now; the loop reports the move to the position callback, as freeglut does when the
  // window system confirms it (SDL sends no event for a move the program asked for).
  window->requestedX = x;
  window->requestedY = y;
  window->movePending = true;
  setSystemWindowPosition(*window, x, y);
}

void glutShowWindow(void) {
  Window* window = requireCurrentWindow("glutShowWindow");
  if (!window) return;
  window->visible = true;
  window->redisplayPending = true;
  showSystemWindow(*window, true);
  if (window->parent) refreshScreen(*window);
}

void glutHideWindow(void) {
  Window* window = requireCurrentWindow("glutHideWindow");
  if (!window) return;
  window->visible = false;
  showSystemWindow(*window, false);
  if (Window* parent = findWindow(window->parent)) refreshScreen(*parent);
}

void glutIconifyWindow(void) {
  Window* window = requireCurrentWindow("glutIconifyWindow");
  if (!window) return;
  window->visible = false;
  iconifySystemWindow(*window);
}

// A sub-window goes to the bottom (push) or the top (pop) of its siblings; a top-level window's
// push has no effect under SDL.
void glutPushWindow(void) {
  if (Window* window = requireCurrentWindow("glutPushWindow")) restackSubWindow(*window, false);
}

void glutPopWindow(void) {
  Window* window = requireCurrentWindow("glutPopWindow");
  if (window && !restackSubWindow(*window, true)) raiseSystemWindow(*window);
}

void glutFullScreen(void) {
  Window* window = requireCurrentWindow("glutFullScreen");
  if (!window || window->fullScreen || window->parent) return;  // sub-windows: as freeglut
  window->fullScreen = true;
  setSystemWindowFullScreen(*window, true);
  reportSystemMove(*window);
}

void glutLeaveFullScreen(void) {
  Window* window = requireCurrentWindow("glutLeaveFullScreen");
  if (!window || !window->fullScreen) return;
  window->fullScreen = false;
  setSystemWindowFullScreen(*window, false);
  reportSystemMove(*window);
}

void glutFullScreenToggle(void) {
  Window* window = requireCurrentWindow("glutFullScreenToggle");
  if (!window) return;
  window->fullScreen = !window->fullScreen;
  setSystemWindowFullScreen(*window, window->fullScreen);
  reportSystemMove(*window);
}

void glutPostRedisplay(void) {
  if (Window* window = requireCurrentWindow("glutPostRedisplay")) window->redisplayPending = true;
}

void glutPostWindowRedisplay(int id) {
  requireInitialised("glutPostWindowRedisplay");
  // freeglut ignores a window that does not exist.
  if (Window* window = findWindow(id)) window->redisplayPending = true;
}

// As freeglut: glFlush first (which shows a single-buffered window's picture), then a
// double-buffered window's back buffer becomes its front buffer, which it shows.
void glutSwapBuffers(void) {
  Window* window = requireCurrentWindow("glutSwapBuffers");
  glFlush();
  if (window && window->doubleBuffered) {
    glassSwapBuffers(window->context);
    presentWindow(*window);
  }
}

void glutWarpPointer(int x, int y) {
  Window* window = requireCurrentWindow("glutWarpPointer");
  if (!window) return;
  int originX = 0, originY = 0;
  originInTopLevel(*window, originX, originY);
  warpSystemPointer(topLevelOf(*window), originX + x, originY + y);
}

void glutSetCursor(int cursor) {
  Window* window = requireCurrentWindow("glutSetCursor");
  if (!window) return;
  window->cursor = cursor;
  setSystemCursor(*window, cursor);
}

void* glutGetWindowData(void) {
  Window* window = requireCurrentWindow("glutGetWindowData");
  return window ? window->userData : nullptr;
}

void glutSetWindowData(void* data) {
  if (Window* window = requireCurrentWindow("glutSetWindowData")) window->userData = data;
}

void glutExit(void) { deinitialise(); }

}  // extern "C"
