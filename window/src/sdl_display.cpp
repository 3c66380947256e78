#include "sdl_display.h"

#include <GL/freeglut.h>
#include <SDL.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>

#include "glut_state.h"
#include "view_key.h"

namespace glass::glut {

namespace {

bool headless = false;

// Where each full-screen window was, and its size, to go back to when it leaves full screen.
std::map<SDL_Window*, SDL_Rect> windowedGeometry;

// The character a key press gave, kept until its release, so that glutKeyboardUpFunc gets the
// same character (SDL sends the text of a press in a separate SDL_TEXTINPUT event).
std::map<SDL_Scancode, int> characterOfPressedKey;
SDL_Scancode keyAwaitingText = SDL_SCANCODE_UNKNOWN;
// The modifiers held as of the last event translated: what a mouse, wheel or text event that
// comes after it in the queue was made with. SDL_GetModState gives them after every event SDL
// has taken from X so far, so a Shift released just after a click (both in the queue before the
// click is translated) would already be gone; X gives freeglut each event's own state. Key
// events carry the state after themselves; focus gained takes SDL's (keys pressed elsewhere).
Uint16 modifiersSoFar = KMOD_NONE;
int windowAwaitingText = 0;
bool repeatAwaitingText = false;  // the press awaiting its text is a key's auto-repeat

Window* windowOfSystemId(Uint32 sdlId) {
  SDL_Window* sdlWindow = SDL_GetWindowFromID(sdlId);
  for (auto& [id, window] : state().windows) {
    if (window->sdlWindow == sdlWindow) return window.get();
  }
  return nullptr;
}

int glutModifiersOf(Uint16 mod) {
  int modifiers = 0;
  if (mod & (KMOD_SHIFT | KMOD_CAPS)) modifiers |= GLUT_ACTIVE_SHIFT;  // "Shift or Caps Lock" (spec 7.9)
  if (mod & KMOD_CTRL) modifiers |= GLUT_ACTIVE_CTRL;
  if (mod & KMOD_ALT) modifiers |= GLUT_ACTIVE_ALT;
  if (mod & KMOD_GUI) modifiers |= GLUT_ACTIVE_SUPER;
  return modifiers;
}

// The modifier bit a modifier key itself sets (KMOD_NONE for other keys).
Uint16 ownModifierOf(SDL_Keycode key) {
  switch (key) {
    case SDLK_LSHIFT: return KMOD_LSHIFT;
    case SDLK_RSHIFT: return KMOD_RSHIFT;
    case SDLK_LCTRL: return KMOD_LCTRL;
    case SDLK_RCTRL: return KMOD_RCTRL;
    case SDLK_LALT: return KMOD_LALT;
    case SDLK_RALT: return KMOD_RALT;
    case SDLK_LGUI: return KMOD_LGUI;
    case SDLK_RGUI: return KMOD_RGUI;
    default: return KMOD_NONE;
  }
}

// The modifiers glutGetModifiers gives in the callback of a key event: those held before the
// event, as X reports them to freeglut, so pressing Shift is not yet shifted and releasing it
// still is (SDL gives the state after the event).
int glutModifiersOfKeyEvent(const SDL_KeyboardEvent& key) {
  const Uint16 own = ownModifierOf(key.keysym.sym);
  const Uint16 before = key.type == SDL_KEYDOWN ? key.keysym.mod & ~own : key.keysym.mod | own;
  return glutModifiersOf(before);
}

// The GLUT_KEY_* code of a key that goes to glutSpecialFunc, or 0 (freeglut's X11 key table).
// With Num Lock off the keypad's keys are its arrows, Home, End, Page Up and Down, Insert,
// Delete and Begin (X's KP_Up ... KP_Begin); with it on they type digits and '.'.
int specialKeyOf(SDL_Keycode key, Uint16 mod) {
  if (key >= SDLK_F1 && key <= SDLK_F12) return GLUT_KEY_F1 + (key - SDLK_F1);
  if (!(mod & KMOD_NUM)) {
    switch (key) {
      case SDLK_KP_8: return GLUT_KEY_UP;
      case SDLK_KP_2: return GLUT_KEY_DOWN;
      case SDLK_KP_4: return GLUT_KEY_LEFT;
      case SDLK_KP_6: return GLUT_KEY_RIGHT;
      case SDLK_KP_7: return GLUT_KEY_HOME;
      case SDLK_KP_1: return GLUT_KEY_END;
      case SDLK_KP_9: return GLUT_KEY_PAGE_UP;
      case SDLK_KP_3: return GLUT_KEY_PAGE_DOWN;
      case SDLK_KP_0: return GLUT_KEY_INSERT;
      case SDLK_KP_PERIOD: return GLUT_KEY_DELETE;
      case SDLK_KP_5: return GLUT_KEY_BEGIN;
      default: break;
    }
  }
  switch (key) {
    case SDLK_LEFT: return GLUT_KEY_LEFT;
    case SDLK_UP: return GLUT_KEY_UP;
    case SDLK_RIGHT: return GLUT_KEY_RIGHT;
    case SDLK_DOWN: return GLUT_KEY_DOWN;
    case SDLK_PAGEUP: return GLUT_KEY_PAGE_UP;
    case SDLK_PAGEDOWN: return GLUT_KEY_PAGE_DOWN;
    case SDLK_HOME: return GLUT_KEY_HOME;
    case SDLK_END: return GLUT_KEY_END;
    case SDLK_INSERT: return GLUT_KEY_INSERT;
    case SDLK_NUMLOCKCLEAR: return GLUT_KEY_NUM_LOCK;
    case SDLK_LSHIFT: return GLUT_KEY_SHIFT_L;
    case SDLK_RSHIFT: return GLUT_KEY_SHIFT_R;
    case SDLK_LCTRL: return GLUT_KEY_CTRL_L;
    case SDLK_RCTRL: return GLUT_KEY_CTRL_R;
    case SDLK_LALT: return GLUT_KEY_ALT_L;
    case SDLK_RALT: return GLUT_KEY_ALT_R;
    case SDLK_LGUI: return GLUT_KEY_SUPER_L;
    case SDLK_RGUI: return GLUT_KEY_SUPER_R;
    default: return 0;
  }
}

// The character of a key whose press sends no text: the control characters, and any key with
// Ctrl held, as X's XLookupString makes it from the key's symbol: '@' to '~' and space give
// their low five bits (Ctrl+A and Ctrl+a 1, Ctrl+[ 27, Ctrl+space 0), '2' 0, '3' to '7' 27 to
// 31, '8' 127, '/' 31, any other symbol itself. -1 for keys whose text comes in an
// SDL_TEXTINPUT event.
int characterWithoutText(SDL_Keycode key, Uint16 mod) {
  switch (key) {
    case SDLK_ESCAPE: return 27;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: return 13;
    case SDLK_BACKSPACE: return 8;
    case SDLK_TAB: return 9;
    case SDLK_DELETE: return 127;
    default: break;
  }
  if ((mod & KMOD_CTRL) && key >= 0 && key < 128) {
    if ((key >= '@' && key < 127) || key == ' ') return key & 0x1f;
    if (key == '2') return 0;
    if (key >= '3' && key <= '7') return key - '3' + 27;
    if (key == '8') return 127;
    if (key == '/') return '_' & 0x1f;
    return static_cast<int>(key);
  }
  return -1;
}

// The character a key's release gives (glutKeyboardUpFunc) as the modifiers held at the release
// make it, as XLookupString gives it to freeglut: Shift+B pressed, Shift let go first, then B:
// 'B' down, 'b' up; Shift+1 so: '!' down, '1' up. With Ctrl held, the control character as a
// press makes it; a letter's case follows Shift and Caps Lock;
// another printable key without Shift gives its own symbol (SDL's key code); with Shift, the
// character its press gave, since shifted symbols depend on the keyboard's layout, which SDL
// tells only as the text of a press.
int characterOfReleasedKey(const SDL_KeyboardEvent& key, int pressedCharacter) {
  const SDL_Keycode code = key.keysym.sym;
  const Uint16 mod = key.keysym.mod;
  if (mod & KMOD_CTRL) {
    if (const int control = characterWithoutText(code, mod); control >= 0) return control;
  }
  if (code >= SDLK_a && code <= SDLK_z) {
    const bool upper = ((mod & KMOD_SHIFT) != 0) != ((mod & KMOD_CAPS) != 0);
    return upper ? code - SDLK_a + 'A' : code;
  }
  const bool printable = code >= ' ' && code <= '~';
  if (printable && !(mod & (KMOD_SHIFT | KMOD_CTRL))) return code;
  return pressedCharacter;
}

// The Latin-1 character of a UTF-8 text, or -1 (GLUT's keyboard callback takes one byte).
int latin1Of(const char* text) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(text);
  if (bytes[0] < 0x80) return bytes[0] ? bytes[0] : -1;
  if ((bytes[0] & 0xe0) == 0xc0 && (bytes[1] & 0xc0) == 0x80) {
    const int code = ((bytes[0] & 0x1f) << 6) | (bytes[1] & 0x3f);
    return code < 256 ? code : -1;
  }
  return -1;
}

// Where the pointer is in the window (y down, and outside it too), as X gives it to freeglut with
// a key or wheel event. SDL's key events carry no position, and the window's record of the last
// motion is stale while the pointer has not moved over the window since it was made or moved
// (a key typed before the pointer first enters the window got 0, 0).
void pointerInWindow(const Window& window, int& x, int& y) {
  int screenX = 0, screenY = 0, windowX = 0, windowY = 0;
  SDL_GetGlobalMouseState(&screenX, &screenY);
  SDL_GetWindowPosition(window.sdlWindow, &windowX, &windowY);
  x = screenX - windowX;
  y = screenY - windowY;
}

void translateKey(const SDL_KeyboardEvent& key, Window& window, std::vector<InputEvent>& events) {
  modifiersSoFar = key.keysym.mod;
  InputEvent event;
  event.window = window.id;
  pointerInWindow(window, event.x, event.y);
  event.modifiers = glutModifiersOfKeyEvent(key);
  const bool down = key.type == SDL_KEYDOWN;
  if (down && key.repeat) {
    // X repeats a held key as a release and a press, and freeglut (as GLUT 3.7) passes both on
    // to the keyboard-up and keyboard callbacks; SDL gives only the press. Both are marked as a
    // repeat, for the window that ignores repeats (event_dispatch.cpp).
    SDL_KeyboardEvent release = key;
    release.type = SDL_KEYUP;
    release.state = SDL_RELEASED;
    const size_t first = events.size();
    translateKey(release, window, events);
    for (size_t i = first; i < events.size(); ++i) events[i].repeat = true;
    event.repeat = true;
  }
  if (down) keyAwaitingText = SDL_SCANCODE_UNKNOWN;  // a new press ends any wait for text
  if (const int special = specialKeyOf(key.keysym.sym, key.keysym.mod)) {
    event.kind = down ? InputKind::Special : InputKind::SpecialUp;
    event.key = special;
    events.push_back(event);
    return;
  }
  if (!down) {
    auto pressed = characterOfPressedKey.find(key.keysym.scancode);
    if (pressed == characterOfPressedKey.end()) return;
    event.kind = InputKind::KeyUp;
    event.key = characterOfReleasedKey(key, pressed->second);
    characterOfPressedKey.erase(pressed);
    events.push_back(event);
    return;
  }
  const int character = characterWithoutText(key.keysym.sym, key.keysym.mod);
  if (character < 0) {
    keyAwaitingText = key.keysym.scancode;
    windowAwaitingText = window.id;
    repeatAwaitingText = event.repeat;
    return;
  }
  characterOfPressedKey[key.keysym.scancode] = character;
  event.kind = InputKind::Key;
  event.key = character;
  events.push_back(event);
}

void translateText(const SDL_TextInputEvent& text, std::vector<InputEvent>& events) {
  // Text is a key's character only when its press gave none (with Ctrl, Ctrl+1's press was
  // '1' already, and SDL still sends the text "1").
  if (keyAwaitingText == SDL_SCANCODE_UNKNOWN) return;
  Window* window = findWindow(windowAwaitingText);
  const int character = latin1Of(text.text);
  if (!window || character < 0) return;
  InputEvent event;
  event.kind = InputKind::Key;
  event.window = window->id;
  event.key = character;
  pointerInWindow(*window, event.x, event.y);
  event.modifiers = glutModifiersOf(modifiersSoFar);
  event.repeat = repeatAwaitingText;
  if (keyAwaitingText != SDL_SCANCODE_UNKNOWN) characterOfPressedKey[keyAwaitingText] = character;
  keyAwaitingText = SDL_SCANCODE_UNKNOWN;
  events.push_back(event);
}

// SDL's buttons 1-3 are GLUT's left, middle and right (X numbers them the same way).
int glutButtonOf(Uint8 button) {
  switch (button) {
    case SDL_BUTTON_LEFT: return GLUT_LEFT_BUTTON;
    case SDL_BUTTON_MIDDLE: return GLUT_MIDDLE_BUTTON;
    case SDL_BUTTON_RIGHT: return GLUT_RIGHT_BUTTON;
    default: return -1;
  }
}

void translateWindowEvent(const SDL_WindowEvent& w, Window& window,
                          std::vector<InputEvent>& events) {
  if (w.event == SDL_WINDOWEVENT_FOCUS_GAINED) modifiersSoFar = static_cast<Uint16>(SDL_GetModState());
  InputEvent event;
  event.window = window.id;
  switch (w.event) {
    case SDL_WINDOWEVENT_SIZE_CHANGED:
      event.kind = InputKind::Reshape;
      event.width = w.data1;
      event.height = w.data2;
      break;
    case SDL_WINDOWEVENT_MOVED:
      event.kind = InputKind::Moved;
      event.x = w.data1;
      event.y = w.data2;
      break;
    case SDL_WINDOWEVENT_CLOSE: event.kind = InputKind::Close; break;
    case SDL_WINDOWEVENT_ENTER:
    case SDL_WINDOWEVENT_LEAVE:
      event.kind = InputKind::Entry;
      event.buttonState = w.event == SDL_WINDOWEVENT_ENTER ? GLUT_ENTERED : GLUT_LEFT;
      break;
    case SDL_WINDOWEVENT_SHOWN:
    case SDL_WINDOWEVENT_RESTORED:
    case SDL_WINDOWEVENT_HIDDEN:
    case SDL_WINDOWEVENT_MINIMIZED:
      event.kind = InputKind::Visibility;
      event.buttonState = (w.event == SDL_WINDOWEVENT_SHOWN || w.event == SDL_WINDOWEVENT_RESTORED)
                              ? GLUT_VISIBLE
                              : GLUT_NOT_VISIBLE;
      break;
    case SDL_WINDOWEVENT_EXPOSED: event.kind = InputKind::Exposed; break;
    default: return;
  }
  events.push_back(event);
}

void translate(const SDL_Event& e, std::vector<InputEvent>& events) {
  switch (e.type) {
    case SDL_KEYDOWN:
    case SDL_KEYUP:
      if (Window* window = windowOfSystemId(e.key.windowID)) translateKey(e.key, *window, events);
      return;
    case SDL_TEXTINPUT: translateText(e.text, events); return;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP: {
      Window* window = windowOfSystemId(e.button.windowID);
      const int button = glutButtonOf(e.button.button);
      if (!window || button < 0) return;
      InputEvent event;
      event.kind = InputKind::Button;
      event.window = window->id;
      event.button = button;
      event.buttonState = e.type == SDL_MOUSEBUTTONDOWN ? GLUT_DOWN : GLUT_UP;
      event.x = e.button.x;
      event.y = e.button.y;
      event.modifiers = glutModifiersOf(modifiersSoFar);
      events.push_back(event);
      return;
    }
    case SDL_MOUSEWHEEL: {
      Window* window = windowOfSystemId(e.wheel.windowID);
      if (!window || (e.wheel.y == 0 && e.wheel.x == 0)) return;
      InputEvent event;
      event.kind = InputKind::Wheel;
      event.window = window->id;
      event.button = e.wheel.y != 0 ? 0 : 1;
      const int amount = e.wheel.y != 0 ? e.wheel.y : e.wheel.x;
      event.buttonState = amount > 0 ? 1 : -1;
      pointerInWindow(*window, event.x, event.y);
      event.modifiers = glutModifiersOf(modifiersSoFar);
      events.push_back(event);
      return;
    }
    case SDL_MOUSEMOTION: {
      Window* window = windowOfSystemId(e.motion.windowID);
      if (!window) return;
      InputEvent event;
      event.kind = InputKind::Motion;
      event.window = window->id;
      event.x = e.motion.x;
      event.y = e.motion.y;
      events.push_back(event);
      return;
    }
    case SDL_WINDOWEVENT:
      if (Window* window = windowOfSystemId(e.window.windowID)) {
        translateWindowEvent(e.window, *window, events);
      }
      return;
    default: return;
  }
}

bool isHeadlessDriver(const char* driver) {
  return driver && (std::strcmp(driver, "dummy") == 0 || std::strcmp(driver, "offscreen") == 0);
}

}  // namespace

bool openDisplay(bool allowHeadless, std::string& failure) {
  // Ctrl+C ends a GLUT program at once, as it does with freeglut.
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
  // The window's surface is a plain image of the system's (X11: shared memory), not a texture of
  // an OpenGL renderer: glass needs no GPU driver to show its pictures, and making that renderer
  // would also hide and show the new window once (a spurious GLUT_NOT_VISIBLE).
  SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
  // SDL falls back to its offscreen driver by itself when there is no display; glass takes a
  // driver without a screen only when asked to (SDL_VIDEODRIVER, or the headless variables).
  const char* requested = std::getenv("SDL_VIDEODRIVER");
  const bool explicitlyHeadless = isHeadlessDriver(requested);
  const bool displayNamed = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY");
  if (!requested && !displayNamed) {
    failure = "neither DISPLAY nor WAYLAND_DISPLAY is set";
  } else if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    failure = SDL_GetError();
  } else if (isHeadlessDriver(SDL_GetCurrentVideoDriver()) && !explicitlyHeadless &&
             !allowHeadless) {
    failure = "SDL found no display";
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
  } else {
    failure.clear();
  }
  if (!failure.empty()) {
    if (!allowHeadless) return false;
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "dummy");
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
      failure = SDL_GetError();
      return false;
    }
  }
  headless = isHeadlessDriver(SDL_GetCurrentVideoDriver());
  return true;
}

void closeDisplay() {
  characterOfPressedKey.clear();
  SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

bool displayIsHeadless() { return headless; }

bool createSystemWindow(Window& window, bool borderless) {
  const int x = window.x >= 0 ? window.x : static_cast<int>(SDL_WINDOWPOS_UNDEFINED);
  const int y = window.y >= 0 ? window.y : static_cast<int>(SDL_WINDOWPOS_UNDEFINED);
  window.sdlWindow = SDL_CreateWindow(shownTitle(window).c_str(), x, y, window.width, window.height,
                                      borderless ? SDL_WINDOW_BORDERLESS : SDL_WINDOW_RESIZABLE);
  if (window.sdlWindow == nullptr) return false;
  // Where the window is (glutGet(GLUT_WINDOW_X)): the system's placement when the program asked
  // for none. A window manager that moves it later sends a move event, which updates it again.
  SDL_GetWindowPosition(window.sdlWindow, &window.x, &window.y);
  return true;
}

void destroySystemWindow(Window& window) {
  windowedGeometry.erase(window.sdlWindow);
  if (window.sdlWindow) SDL_DestroyWindow(window.sdlWindow);
  window.sdlWindow = nullptr;
}

void showOnScreen(Window& window) {
  if (!window.sdlWindow || window.screen.empty()) return;
  SDL_Surface* surface = SDL_GetWindowSurface(window.sdlWindow);
  if (!surface) return;
  // The surface may still have the old size while a resize is on its way.
  const int width = std::min(surface->w, window.width);
  const int height = std::min(surface->h, window.height);
  if (SDL_MUSTLOCK(surface)) SDL_LockSurface(surface);
  for (int row = 0; row < height; ++row) {
    // GL's rows go bottom to top; the surface's top to bottom.
    const unsigned char* source =
        window.screen.data() + static_cast<size_t>(window.height - 1 - row) * window.width * 4;
    auto* target = static_cast<unsigned char*>(surface->pixels) + static_cast<size_t>(row) * surface->pitch;
    SDL_ConvertPixels(width, 1, SDL_PIXELFORMAT_RGBA32, source, window.width * 4,
                      surface->format->format, target, surface->pitch);
  }
  if (SDL_MUSTLOCK(surface)) SDL_UnlockSurface(surface);
  SDL_UpdateWindowSurface(window.sdlWindow);
}

void setSystemWindowTitle(Window& window) {
  if (window.sdlWindow) SDL_SetWindowTitle(window.sdlWindow, shownTitle(window).c_str());
}

void setSystemWindowSize(Window& window, int width, int height) {
  if (window.sdlWindow) SDL_SetWindowSize(window.sdlWindow, width, height);
}

void setSystemWindowPosition(Window& window, int x, int y) {
  if (window.sdlWindow) SDL_SetWindowPosition(window.sdlWindow, x, y);
}

bool systemWindowPosition(const Window& window, int& x, int& y) {
  if (!window.sdlWindow) return false;
  SDL_GetWindowPosition(window.sdlWindow, &x, &y);
  return true;
}

void setSystemWindowFullScreen(Window& window, bool fullScreen) {
  SDL_Window* sdlWindow = window.sdlWindow;
  if (!sdlWindow) return;
  if (!fullScreen) {
    SDL_SetWindowFullscreen(sdlWindow, 0);
    if (auto windowed = windowedGeometry.find(sdlWindow); windowed != windowedGeometry.end()) {
      SDL_SetWindowSize(sdlWindow, windowed->second.w, windowed->second.h);
      SDL_SetWindowPosition(sdlWindow, windowed->second.x, windowed->second.y);
      windowedGeometry.erase(windowed);
    }
    return;
  }
  SDL_Rect windowed;
  SDL_GetWindowPosition(sdlWindow, &windowed.x, &windowed.y);
  SDL_GetWindowSize(sdlWindow, &windowed.w, &windowed.h);
  windowedGeometry[sdlWindow] = windowed;
  // SDL asks the window manager for full screen (X: _NET_WM_STATE_FULLSCREEN); without one that
  // does it, nothing changes on the screen, though SDL then reports the screen's size. So the
  // window is first put over the whole screen by the program itself, as freeglut does when the
  // window manager does not help (GLUT 3.7 spec 4.9: the window covers the screen).
  SDL_Rect screen;
  if (SDL_GetDisplayBounds(SDL_GetWindowDisplayIndex(sdlWindow), &screen) == 0) {
    SDL_SetWindowPosition(sdlWindow, screen.x, screen.y);
    SDL_SetWindowSize(sdlWindow, screen.w, screen.h);
  }
  SDL_SetWindowFullscreen(sdlWindow, SDL_WINDOW_FULLSCREEN_DESKTOP);
}

void showSystemWindow(Window& window, bool visible) {
  if (!window.sdlWindow) return;
  if (visible) {
    SDL_ShowWindow(window.sdlWindow);
  } else {
    SDL_HideWindow(window.sdlWindow);
  }
}

void iconifySystemWindow(Window& window) {
  if (window.sdlWindow) SDL_MinimizeWindow(window.sdlWindow);
}

void raiseSystemWindow(Window& window) {
  if (window.sdlWindow) SDL_RaiseWindow(window.sdlWindow);
}

void warpSystemPointer(Window& window, int x, int y) {
  if (window.sdlWindow) SDL_WarpMouseInWindow(window.sdlWindow, x, y);
}

void setSystemCursor(Window& window, int glutCursor) {
  static std::map<SDL_SystemCursor, SDL_Cursor*> cursors;
  if (!window.sdlWindow || headless) return;
  if (glutCursor == GLUT_CURSOR_NONE) {
    SDL_ShowCursor(SDL_DISABLE);
    return;
  }
  SDL_ShowCursor(SDL_ENABLE);
  SDL_SystemCursor shape = SDL_SYSTEM_CURSOR_ARROW;
  switch (glutCursor) {
    case GLUT_CURSOR_INFO: shape = SDL_SYSTEM_CURSOR_HAND; break;
    case GLUT_CURSOR_DESTROY: shape = SDL_SYSTEM_CURSOR_NO; break;
    case GLUT_CURSOR_WAIT: shape = SDL_SYSTEM_CURSOR_WAIT; break;
    case GLUT_CURSOR_TEXT: shape = SDL_SYSTEM_CURSOR_IBEAM; break;
    case GLUT_CURSOR_CROSSHAIR:
    case GLUT_CURSOR_FULL_CROSSHAIR: shape = SDL_SYSTEM_CURSOR_CROSSHAIR; break;
    case GLUT_CURSOR_UP_DOWN:
    case GLUT_CURSOR_TOP_SIDE:
    case GLUT_CURSOR_BOTTOM_SIDE: shape = SDL_SYSTEM_CURSOR_SIZENS; break;
    case GLUT_CURSOR_LEFT_RIGHT:
    case GLUT_CURSOR_LEFT_SIDE:
    case GLUT_CURSOR_RIGHT_SIDE: shape = SDL_SYSTEM_CURSOR_SIZEWE; break;
    case GLUT_CURSOR_TOP_LEFT_CORNER:
    case GLUT_CURSOR_BOTTOM_RIGHT_CORNER: shape = SDL_SYSTEM_CURSOR_SIZENWSE; break;
    case GLUT_CURSOR_TOP_RIGHT_CORNER:
    case GLUT_CURSOR_BOTTOM_LEFT_CORNER: shape = SDL_SYSTEM_CURSOR_SIZENESW; break;
    default: break;
  }
  SDL_Cursor*& cursor = cursors[shape];
  if (!cursor) cursor = SDL_CreateSystemCursor(shape);
  if (cursor) SDL_SetCursor(cursor);
}

void screenMode(int& bitsPerPixel, int& refreshRate) {
  SDL_DisplayMode mode;
  if (SDL_GetDesktopDisplayMode(0, &mode) != 0) {
    bitsPerPixel = refreshRate = 0;
    return;
  }
  bitsPerPixel = static_cast<int>(SDL_BITSPERPIXEL(mode.format));
  refreshRate = mode.refresh_rate;
}

void screenSize(int& width, int& height, int& widthMM, int& heightMM) {
  SDL_DisplayMode mode;
  if (SDL_GetDesktopDisplayMode(0, &mode) != 0) {
    mode.w = 0;
    mode.h = 0;
  }
  width = mode.w;
  height = mode.h;
  // SDL gives dots per inch; 25.4 mm to the inch.
  float horizontalDpi = 0, verticalDpi = 0;
  if (SDL_GetDisplayDPI(0, nullptr, &horizontalDpi, &verticalDpi) != 0 || horizontalDpi <= 0 ||
      verticalDpi <= 0) {
    horizontalDpi = verticalDpi = 96.0f;
  }
  widthMM = static_cast<int>(width * 25.4f / horizontalDpi + 0.5f);
  heightMM = static_cast<int>(height * 25.4f / verticalDpi + 0.5f);
}

void pollSystemEvents(std::vector<InputEvent>& events) {
  SDL_Event e;
  while (SDL_PollEvent(&e)) {
    // Without a display nothing real happens to the windows: input comes from the events file
    // alone, so that a headless run is the same every time.
    if (!headless) translate(e, events);
  }
}

void waitForSystemEvent(int milliseconds) {
  if (milliseconds <= 0) return;
  SDL_WaitEventTimeout(nullptr, milliseconds);
}

int systemModifiers() { return glutModifiersOf(SDL_GetModState()); }

}  // namespace glass::glut
