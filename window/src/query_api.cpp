// State queries and options (GLUT 3.7 spec 9; freeglut's glutSetOption).
#include <GL/freeglut.h>

#include <cstring>
#include <optional>

#include "framebuffer_bits.h"
#include "glut_clock.h"
#include "glut_errors.h"
#include "glut_state.h"
#include "sdl_display.h"

using namespace glass::glut;

namespace {

// The answer to a query about `window`, or nothing when glutGet has no such query (a position
// may be negative, so no value can mean that).
std::optional<int> windowQuery(const Window& window, GLenum query) {
  switch (query) {
    case GLUT_WINDOW_X: return window.x;
    case GLUT_WINDOW_Y: return window.y;
    case GLUT_WINDOW_WIDTH: return window.width;
    case GLUT_WINDOW_HEIGHT: return window.height;
    case GLUT_WINDOW_BUFFER_SIZE: return 3 * kColorBits + alphaBitsOf(window.displayMode);
    case GLUT_WINDOW_STENCIL_SIZE: return ancillaryBitsOf(window.displayMode).stencil;
    case GLUT_WINDOW_DEPTH_SIZE: return ancillaryBitsOf(window.displayMode).depth;
    case GLUT_WINDOW_RED_SIZE:
    case GLUT_WINDOW_GREEN_SIZE:
    case GLUT_WINDOW_BLUE_SIZE: return kColorBits;
    case GLUT_WINDOW_ALPHA_SIZE: return alphaBitsOf(window.displayMode);
    case GLUT_WINDOW_ACCUM_RED_SIZE:
    case GLUT_WINDOW_ACCUM_GREEN_SIZE:
    case GLUT_WINDOW_ACCUM_BLUE_SIZE:
    case GLUT_WINDOW_ACCUM_ALPHA_SIZE: return ancillaryBitsOf(window.displayMode).accumulation;
    case GLUT_WINDOW_DOUBLEBUFFER: return window.doubleBuffered ? 1 : 0;
    case GLUT_WINDOW_RGBA: return 1;
    case GLUT_WINDOW_PARENT: return window.parent;
    case GLUT_WINDOW_NUM_CHILDREN: return static_cast<int>(window.children.size());
    case GLUT_WINDOW_COLORMAP_SIZE:
    case GLUT_WINDOW_NUM_SAMPLES:
    case GLUT_WINDOW_STEREO: return 0;
    case GLUT_WINDOW_CURSOR: return window.cursor;
    case GLUT_WINDOW_FORMAT_ID: return 0;
    case GLUT_FULL_SCREEN: return window.fullScreen ? 1 : 0;
    case GLUT_WINDOW_BORDER_WIDTH:
    case GLUT_WINDOW_HEADER_HEIGHT: return 0;
    default: return std::nullopt;
  }
}

}  // namespace

extern "C" {

int glutGet(GLenum query) {
  State& s = state();
  // freeglut answers these before glutInit.
  switch (query) {
    case GLUT_INIT_STATE: return s.initialised ? 1 : 0;
    case GLUT_ELAPSED_TIME: return s.initialised ? static_cast<int>(elapsedMilliseconds()) : 0;
    case GLUT_VERSION: return 30200;  // the freeglut version whose interface glass follows
    default: break;
  }
  requireInitialised("glutGet");
  switch (query) {
    case GLUT_SCREEN_WIDTH:
    case GLUT_SCREEN_HEIGHT:
    case GLUT_SCREEN_WIDTH_MM:
    case GLUT_SCREEN_HEIGHT_MM: {
      int width = 0, height = 0, widthMM = 0, heightMM = 0;
      screenSize(width, height, widthMM, heightMM);
      return query == GLUT_SCREEN_WIDTH    ? width
             : query == GLUT_SCREEN_HEIGHT ? height
             : query == GLUT_SCREEN_WIDTH_MM ? widthMM
                                             : heightMM;
    }
    case GLUT_MENU_NUM_ITEMS: {
      const Menu* menu = findMenu(s.currentMenu);
      return menu ? static_cast<int>(menu->items.size()) : 0;
    }
    case GLUT_DISPLAY_MODE_POSSIBLE:  // exactly as asked: glutCreateWindow makes a multisample
                                      // wish a window without multisampling
      return (s.initDisplayMode & (GLUT_INDEX | GLUT_STEREO | GLUT_MULTISAMPLE)) ? 0 : 1;
    case GLUT_INIT_WINDOW_X: return s.initX;
    case GLUT_INIT_WINDOW_Y: return s.initY;
    case GLUT_INIT_WINDOW_WIDTH: return s.initWidth;
    case GLUT_INIT_WINDOW_HEIGHT: return s.initHeight;
    case GLUT_INIT_DISPLAY_MODE: return static_cast<int>(s.initDisplayMode);
    case GLUT_INIT_MAJOR_VERSION: return s.contextMajor;
    case GLUT_INIT_MINOR_VERSION: return s.contextMinor;
    case GLUT_INIT_FLAGS: return s.contextFlags;
    case GLUT_INIT_PROFILE: return s.contextProfile;
    case GLUT_ACTION_ON_WINDOW_CLOSE: return s.actionOnWindowClose;
    case GLUT_RENDERING_CONTEXT: return s.renderingContext;
    case GLUT_DIRECT_RENDERING: return s.directRendering;
    case GLUT_SKIP_STALE_MOTION_EVENTS: return s.skipStaleMotion ? 1 : 0;
    default: break;
  }
  const Window* window = currentWindow();
  if (!window) return query >= GLUT_WINDOW_X && query <= GLUT_WINDOW_FORMAT_ID ? 0 : -1;
  const std::optional<int> answer = windowQuery(*window, query);
  if (answer) return *answer;
  warning("glutGet(): missing enum handle %d", static_cast<int>(query));
  return -1;
}

int glutDeviceGet(GLenum query) {
  requireInitialised("glutDeviceGet");
  switch (query) {
    case GLUT_HAS_KEYBOARD:
    case GLUT_HAS_MOUSE: return 1;
    case GLUT_NUM_MOUSE_BUTTONS: return 3;
    case GLUT_DEVICE_IGNORE_KEY_REPEAT: {
      const Window* window = currentWindow();
      return window && window->ignoreKeyRepeat ? 1 : 0;
    }
    case GLUT_DEVICE_KEY_REPEAT: return state().keyRepeat;
    // No spaceball, dial and button box, tablet or joystick.
    default: return 0;
  }
}

int glutGetModifiers(void) {
  requireInitialised("glutGetModifiers");
  if (state().modifiers < 0) {
    warning("glutGetModifiers() called outside an input callback");
    return 0;
  }
  return state().modifiers;
}

// No overlays (freeglut has none either).
int glutLayerGet(GLenum query) {
  requireInitialised("glutLayerGet");
  switch (query) {
    case GLUT_TRANSPARENT_INDEX: return -1;
    default: return 0;
  }
}

// GLUT 3.7 spec 9.4: whether the current window's context has the extension, a whole word of
// GL_EXTENSIONS.
int glutExtensionSupported(const char* extension) {
  requireInitialised("glutExtensionSupported");
  if (!extension || !*extension || std::strchr(extension, ' ') || !currentWindow()) return 0;
  const char* all = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  const size_t length = std::strlen(extension);
  for (const char* at = all; at && (at = std::strstr(at, extension)) != nullptr; at += length) {
    const bool starts = at == all || at[-1] == ' ';
    const bool ends = at[length] == ' ' || at[length] == '\0';
    if (starts && ends) return 1;
  }
  return 0;
}

// GLUT 3.7 (glutIgnoreKeyRepeat(3GLUT)): whether the current window gets a held key's repeats.
void glutIgnoreKeyRepeat(int ignore) {
  if (Window* window = requireCurrentWindow("glutIgnoreKeyRepeat")) {
    window->ignoreKeyRepeat = ignore != 0;
  }
}

// Key repeat on or off for every window, as freeglut 3 does it: the system's repeats still come,
// and GLUT drops them (the default is on).
void glutSetKeyRepeat(int repeatMode) {
  requireInitialised("glutSetKeyRepeat");
  switch (repeatMode) {
    case GLUT_KEY_REPEAT_OFF: state().keyRepeat = GLUT_KEY_REPEAT_OFF; break;
    case GLUT_KEY_REPEAT_ON:
    case GLUT_KEY_REPEAT_DEFAULT: state().keyRepeat = GLUT_KEY_REPEAT_ON; break;
    default: fatalError("Invalid glutSetKeyRepeat mode: %d", repeatMode);
  }
}

// GLUT 3.7 spec 9.5: prints the GL errors of the current window's context.
void glutReportErrors(void) {
  requireInitialised("glutReportErrors");
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
    warning("GL error: %s", reinterpret_cast<const char*>(gluErrorString(error)));
  }
}

void glutSetOption(GLenum option, int value) {
  requireInitialised("glutSetOption");
  State& s = state();
  switch (option) {
    case GLUT_INIT_WINDOW_X: s.initX = value; break;
    case GLUT_INIT_WINDOW_Y: s.initY = value; break;
    case GLUT_INIT_WINDOW_WIDTH: s.initWidth = value; break;
    case GLUT_INIT_WINDOW_HEIGHT: s.initHeight = value; break;
    case GLUT_INIT_DISPLAY_MODE: s.initDisplayMode = static_cast<unsigned>(value); break;
    case GLUT_ACTION_ON_WINDOW_CLOSE: s.actionOnWindowClose = value; break;
    case GLUT_RENDERING_CONTEXT: s.renderingContext = value; break;
    case GLUT_DIRECT_RENDERING: s.directRendering = value; break;
    case GLUT_SKIP_STALE_MOTION_EVENTS: s.skipStaleMotion = value != 0; break;
    default: warning("glutSetOption(): missing enum handle %d", static_cast<int>(option)); break;
  }
}

}  // extern "C"
