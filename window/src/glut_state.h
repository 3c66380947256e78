// The state of glass's GLUT: the windows, the menus, the callbacks that are not per window (idle,
// timers, menu status), the options, and the loop's state. One instance, used from the thread
// that called glutInit (GLUT is single-threaded, spec 1.3).
#pragma once

#include <GL/freeglut.h>
#include <glass/context.h>

#include <cstdarg>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

struct SDL_Window;

namespace glass::glut {

// The callbacks of one window (GLUT 3.7 spec 7, and freeglut's additions).
struct WindowCallbacks {
  void (*display)() = nullptr;
  void (*reshape)(int, int) = nullptr;
  void (*keyboard)(unsigned char, int, int) = nullptr;
  void (*keyboardUp)(unsigned char, int, int) = nullptr;
  void (*special)(int, int, int) = nullptr;
  void (*specialUp)(int, int, int) = nullptr;
  void (*mouse)(int, int, int, int) = nullptr;
  void (*mouseWheel)(int, int, int, int) = nullptr;
  void (*motion)(int, int) = nullptr;
  void (*passiveMotion)(int, int) = nullptr;
  void (*entry)(int) = nullptr;
  void (*visibility)(int) = nullptr;
  void (*windowStatus)(int) = nullptr;
  void (*position)(int, int) = nullptr;
  void (*close)() = nullptr;
  // Kept and never called: glass knows no such devices or layers (device_callbacks.cpp,
  // absent_layers.cpp).
  void (*joystick)(unsigned int, int, int, int) = nullptr;
  int joystickPollInterval = 0;
  void (*spaceballMotion)(int, int, int) = nullptr;
  void (*spaceballRotate)(int, int, int) = nullptr;
  void (*spaceballButton)(int, int) = nullptr;
  void (*buttonBox)(int, int) = nullptr;
  void (*dials)(int, int) = nullptr;
  void (*tabletMotion)(int, int) = nullptr;
  void (*tabletButton)(int, int, int, int) = nullptr;
  void (*multiEntry)(int, int) = nullptr;
  void (*multiButton)(int, int, int, int, int) = nullptr;
  void (*multiMotion)(int, int, int) = nullptr;
  void (*multiPassive)(int, int, int) = nullptr;
  void (*overlayDisplay)() = nullptr;
};

// The pop-up that is open in a window: the chain of menus from the one attached to the button
// down to the deepest submenu opened, each with its place in window coordinates (y down).
struct OpenMenu {
  int menu = 0;
  int x = 0, y = 0;         // top-left corner
  int highlighted = -1;     // the item under the pointer, 0-based; -1 for none
};

struct Window {
  int id = 0;
  std::string title;
  // A sub-window (glutCreateSubWindow) is a rectangle of its parent with a context of its own;
  // its parent's picture shows it over the parent's own (children later in the list on top).
  int parent = 0;                  // 0 for a top-level window
  std::vector<int> children;       // sub-windows, bottom to top
  int x = 0, y = 0;                // position on the screen (a sub-window: in its parent, y down)
  int width = 0, height = 0;
  unsigned displayMode = 0;
  bool doubleBuffered = false;
  GlassContext* context = nullptr;
  SDL_Window* sdlWindow = nullptr;  // null when there is no display (headless runs)
  WindowCallbacks callbacks;
  int menuOnButton[5] = {0, 0, 0, 0, 0};  // glutAttachMenu: the menu of each mouse button
  void* userData = nullptr;
  int cursor = GLUT_CURSOR_INHERIT;  // a new window's cursor (GLUT 3.7 spec 4.13)
  bool fullScreen = false;
  bool visible = true;
  bool ignoreKeyRepeat = false;  // glutIgnoreKeyRepeat: this window's (GLUT 3.7)

  bool redisplayPending = true;     // a new window is drawn once it is shown (spec 4.1)
  bool reshapePending = true;       // and told its size first
  bool firstPassDone = false;       // the checks freeglut makes before the first display
  int requestedWidth = 0, requestedHeight = 0;  // glutReshapeWindow, applied by the loop
  bool movePending = false;                     // glutPositionWindow, reported by the loop
  int requestedX = 0, requestedY = 0;
  // The window system's expose of a size the program asked for, still to come: the window was
  // drawn at that size already, in the pass that made the change (see runReshape).
  bool resizeExposeAwaited = false;
  bool inDisplayCallback = false;
  bool presentedInDisplay = false;  // glFlush/glFinish or glutSwapBuffers inside display

  // The picture the window shows: what the context's colour buffer held when it was last
  // presented (RGBA8, bottom row first), and what the screen shows, that picture with the open
  // pop-up menu over it.
  std::vector<unsigned char> shown;
  std::vector<unsigned char> screen;
  std::vector<OpenMenu> openMenus;  // empty when no pop-up is open
  int menuButton = -1;              // the button that opened the pop-up
  int popupOpenedAtX = 0, popupOpenedAtY = 0;
  GlassContext* menuContext = nullptr;  // where glass draws the pop-up over a copy of `shown`

  // Mouse state, for motion versus passive motion and for the keyboard callbacks' x, y.
  int mouseX = 0, mouseY = 0;
  unsigned buttonsDown = 0;
  // A top-level window's pointer: the window (itself or a sub-window) the pointer's events go
  // to while a button is held or a pop-up is open there (0: the one under the pointer), and the
  // one it was last over, for the entry callbacks.
  int capturedBy = 0;
  int pointerOver = 0;
};

struct MenuItem {
  std::string label;
  int value = 0;       // the value given to the callback, or the submenu's id
  bool isSubMenu = false;
};

struct Menu {
  int id = 0;
  void (*callback)(int) = nullptr;
  std::vector<MenuItem> items;
  void* userData = nullptr;
  void* font = nullptr;
  void (*destroy)() = nullptr;  // glutMenuDestroyFunc
};

struct Timer {
  uint64_t deadline = 0;  // in GLUT_ELAPSED_TIME milliseconds
  uint64_t order = 0;     // timers due at the same time run in the order they were set
  void (*callback)(int) = nullptr;
  int value = 0;
};

struct State {
  bool initialised = false;
  std::string programName;
  unsigned initDisplayMode = 0;  // GLUT_RGBA | GLUT_SINGLE
  int initX = -1, initY = -1;
  int initWidth = 300, initHeight = 300;

  std::map<int, std::unique_ptr<Window>> windows;
  int nextWindowId = 1;
  int currentWindow = 0;
  std::map<int, std::unique_ptr<Menu>> menus;
  int nextMenuId = 1;
  int currentMenu = 0;

  void (*idle)() = nullptr;
  void (*menuStatus)(int, int, int) = nullptr;
  void (*menuState)(int) = nullptr;
  std::vector<Timer> timers;
  uint64_t nextTimerOrder = 0;

  int actionOnWindowClose = 0;  // GLUT_ACTION_EXIT
  // glutSetOption's values that change nothing in glass but are read back as set (freeglut's
  // defaults): every context is new and direct whatever is asked.
  int renderingContext = GLUT_CREATE_NEW_CONTEXT;
  int directRendering = GLUT_TRY_DIRECT_CONTEXT;
  // GLUT_SKIP_STALE_MOTION_EVENTS: a motion event followed in the same batch by another of the
  // same window is dropped, so that a slow motion callback sees only the latest position.
  bool skipStaleMotion = false;
  int keyRepeat = GLUT_KEY_REPEAT_ON;  // glutSetKeyRepeat, for all windows (freeglut's fgState)
  bool loopRunning = false;
  int modifiers = -1;           // valid inside input callbacks only; -1 elsewhere

  // glutInitContextVersion, glutInitContextFlags, glutInitContextProfile (context_version.cpp).
  int contextMajor = 1, contextMinor = 0, contextFlags = 0, contextProfile = 0;
  // Kept and never called (device_callbacks.cpp).
  void (*initContext)() = nullptr;
  void (*appStatus)(int) = nullptr;

  // Game mode (glutGameModeString; -1: the screen's own), and its window while it is entered.
  int gameModeWidth = -1, gameModeHeight = -1, gameModeDepth = -1, gameModeRefresh = -1;
  int gameModeWindow = 0;

  void (*errorFunc)(const char*, va_list) = nullptr;
  void (*warningFunc)(const char*, va_list) = nullptr;
};

State& state();

// The window with this id, or null.
Window* findWindow(int id);
// The current window, or null.
Window* currentWindow();
Menu* findMenu(int id);

// Runs the menu's destroy callback (with the menu current) and removes it.
void destroyMenu(int id);

// Makes the window current, and its context.
void makeCurrent(Window& window);

// Stores a callback of the current window; with none, windowForCallback's warning
// (glut_errors.h).
Window* windowForCallback(const char* function);
template <class Callback>
void setWindowCallback(const char* function, Callback WindowCallbacks::*member, Callback callback) {
  if (Window* window = windowForCallback(function)) window->callbacks.*member = callback;
}

// The top-level window a window is part of (itself for a top-level window).
Window& topLevelOf(Window& window);
// Where the window's top-left corner is in its top-level window (0, 0 for a top-level window).
void originInTopLevel(const Window& window, int& x, int& y);

}  // namespace glass::glut
