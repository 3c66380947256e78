#include "event_dispatch.h"

#include <GL/freeglut.h>

#include "glut_state.h"
#include "popup_menu.h"
#include "presentation.h"
#include "view_key.h"
#include "window_lifecycle.h"

namespace glass::glut {

namespace {

// Runs an input callback with the window current and glutGetModifiers answering (spec 9.3: only
// inside keyboard, special and mouse callbacks).
template <class Call>
void withModifiers(Window& window, int modifiers, Call&& call) {
  makeCurrent(window);
  state().modifiers = modifiers;
  call();
  state().modifiers = -1;
}

void dispatchButton(Window& window, const InputEvent& e) {
  window.mouseX = e.x;
  window.mouseY = e.y;
  const unsigned bit = 1u << e.button;
  if (e.buttonState == GLUT_DOWN) {
    window.buttonsDown |= bit;
  } else {
    window.buttonsDown &= ~bit;
  }
  if (popupTakesButton(window, e.button, e.buttonState, e.x, e.y)) return;
  // A button with a menu attached opens it and goes to no callback (spec 6.7).
  if (e.button < 5 && window.menuOnButton[e.button] != 0) {
    if (e.buttonState == GLUT_DOWN) openPopup(window, window.menuOnButton[e.button], e.button, e.x, e.y);
    return;
  }
  if (window.callbacks.mouse) {
    withModifiers(window, e.modifiers,
                  [&] { window.callbacks.mouse(e.button, e.buttonState, e.x, e.y); });
  }
}

// freeglut: the wheel goes to glutMouseWheelFunc, or, without one, to glutMouseFunc as buttons 3
// (away from the user) and 4 (towards), pressed and released.
// As freeglut on X11: the vertical wheel (X's buttons 4 and 5) goes to the wheel callback, or,
// without one, to the mouse callback as buttons 3 (up) and 4 (down); the horizontal one (X's
// buttons 6 and 7) always to the mouse callback, as buttons 5 (left) and 6 (right).
void dispatchWheel(Window& window, const InputEvent& e) {
  const bool vertical = e.button == 0;
  if (vertical && window.callbacks.mouseWheel) {
    withModifiers(window, e.modifiers, [&] {
      window.callbacks.mouseWheel(e.button, e.buttonState, e.x, e.y);
    });
    return;
  }
  if (!window.callbacks.mouse) return;
  const int button = vertical ? (e.buttonState > 0 ? 3 : 4) : (e.buttonState < 0 ? 5 : 6);
  const int id = window.id;
  withModifiers(window, e.modifiers, [&] { window.callbacks.mouse(button, GLUT_DOWN, e.x, e.y); });
  if (Window* still = findWindow(id); still && still->callbacks.mouse) {
    withModifiers(*still, e.modifiers, [&] { still->callbacks.mouse(button, GLUT_UP, e.x, e.y); });
  }
}

void dispatchMotion(Window& window, const InputEvent& e) {
  window.mouseX = e.x;
  window.mouseY = e.y;
  if (!window.openMenus.empty()) {
    popupFollowPointer(window, e.x, e.y);
    return;
  }
  makeCurrent(window);
  if (window.buttonsDown != 0) {
    if (window.callbacks.motion) window.callbacks.motion(e.x, e.y);
  } else if (window.callbacks.passiveMotion) {
    window.callbacks.passiveMotion(e.x, e.y);
  }
}

void dispatchKey(Window& window, const InputEvent& e) {
  // A held key's repeats, dropped for every window by glutSetKeyRepeat(GLUT_KEY_REPEAT_OFF) and
  // for this one by glutIgnoreKeyRepeat (freeglut 3's rule).
  if (e.repeat && (state().keyRepeat == GLUT_KEY_REPEAT_OFF || window.ignoreKeyRepeat)) return;
  window.mouseX = e.x;
  window.mouseY = e.y;
  const WindowCallbacks& c = window.callbacks;
  const auto key = static_cast<unsigned char>(e.key);
  switch (e.kind) {
    case InputKind::Key:
      if (c.keyboard) withModifiers(window, e.modifiers, [&] { c.keyboard(key, e.x, e.y); });
      break;
    case InputKind::KeyUp:
      if (c.keyboardUp) withModifiers(window, e.modifiers, [&] { c.keyboardUp(key, e.x, e.y); });
      break;
    case InputKind::Special:
      if (c.special) withModifiers(window, e.modifiers, [&] { c.special(e.key, e.x, e.y); });
      break;
    case InputKind::SpecialUp:
      if (c.specialUp) withModifiers(window, e.modifiers, [&] { c.specialUp(e.key, e.x, e.y); });
      break;
    default: break;
  }
}

bool isPointerOrKey(InputKind kind) {
  switch (kind) {
    case InputKind::Key:
    case InputKind::KeyUp:
    case InputKind::Special:
    case InputKind::SpecialUp:
    case InputKind::Button:
    case InputKind::Wheel:
    case InputKind::Motion: return true;
    default: return false;
  }
}

// The deepest visible window at (x, y) of `window` (y down): a sub-window there, topmost first,
// or the window itself.
Window& windowAt(Window& window, int x, int y) {
  for (auto it = window.children.rbegin(); it != window.children.rend(); ++it) {
    Window* child = findWindow(*it);
    if (child && child->visible && x >= child->x && x < child->x + child->width &&
        y >= child->y && y < child->y + child->height) {
      return windowAt(*child, x - child->x, y - child->y);
    }
  }
  return window;
}

void sendEntry(int id, int state) {
  Window* window = findWindow(id);
  if (!window || !window->callbacks.entry) return;
  makeCurrent(*window);
  window->callbacks.entry(state);
}

// A pointer or key event of a top-level window with sub-windows goes to the window under the
// pointer, as X gives them to freeglut's sub-windows, in that window's coordinates: or, while a
// button pressed there is held or a pop-up opened there is open, to that window. Moving from one
// window to another tells the one left and the one entered (the entry callbacks). Returns the
// window, with e made its event; null when the entry callbacks destroyed it.
Window* windowUnderPointer(Window& top, InputEvent& e) {
  const int topId = top.id;
  if (e.kind == InputKind::Button || e.kind == InputKind::Motion) {
    top.mouseX = e.x;  // keys and the wheel are given where the pointer is, in the top's terms
    top.mouseY = e.y;
    if (top.capturedBy == 0) {
      const int over = top.pointerOver != 0 ? top.pointerOver : top.id;
      const int entered = windowAt(top, e.x, e.y).id;
      if (over != entered) {
        top.pointerOver = entered;
        sendEntry(over, GLUT_LEFT);
        sendEntry(entered, GLUT_ENTERED);
        if (!findWindow(topId)) return nullptr;
      }
    }
  }
  Window* target = findWindow(top.capturedBy);
  if (!target) target = &windowAt(top, e.x, e.y);
  int originX = 0, originY = 0;
  originInTopLevel(*target, originX, originY);
  e.window = target->id;
  e.x -= originX;
  e.y -= originY;
  return target;
}

// The event's callbacks in `window` (the one it is for).
void deliver(Window* window, const InputEvent& e);

}  // namespace

void dispatchInput(const InputEvent& given) {
  Window* window = findWindow(given.window);
  if (!window) return;
  // Input after a resize the program asked for: the system's expose of it, if any, has come.
  if (isPointerOrKey(given.kind) && given.kind != InputKind::Motion) {
    window->resizeExposeAwaited = false;
  }
  if (given.kind == InputKind::Entry && !window->children.empty()) {
    // The pointer left the top-level window from the window it was over (a sub-window, maybe),
    // or entered it: over the top-level window until it moves.
    Window* over = findWindow(window->pointerOver);
    window->pointerOver = 0;
    if (given.buttonState == GLUT_LEFT && over) return deliver(over, given);
  }
  if (!isPointerOrKey(given.kind) || window->children.empty()) return deliver(window, given);
  InputEvent e = given;
  const int topId = window->id;
  Window* target = windowUnderPointer(*window, e);
  if (!target) return;
  const int targetId = target->id;
  deliver(target, e);
  // The pointer stays with the window while a button is held or a pop-up is open there.
  Window* top = findWindow(topId);
  Window* after = findWindow(targetId);
  if (top) top->capturedBy = after && (after->buttonsDown != 0 || !after->openMenus.empty()) ? targetId : 0;
}

namespace {

void deliver(Window* window, const InputEvent& e) {
  switch (e.kind) {
    case InputKind::Key:
    case InputKind::KeyUp:
    case InputKind::Special:
    case InputKind::SpecialUp:
      // Ctrl+Alt+V is glass's, not the program's (view_key.h).
      if (!takeViewKey(*window, e)) dispatchKey(*window, e);
      return;
    case InputKind::Button: dispatchButton(*window, e); return;
    case InputKind::Wheel: dispatchWheel(*window, e); return;
    case InputKind::Motion: dispatchMotion(*window, e); return;
    case InputKind::Reshape: resizeWindow(*window, e.width, e.height); return;
    case InputKind::Moved:
      // The pointer stays where it is on the screen: in the window's coordinates it moves the
      // other way.
      window->mouseX -= e.x - window->x;
      window->mouseY -= e.y - window->y;
      window->x = e.x;
      window->y = e.y;
      if (window->parent) refreshScreen(*window);  // its parent shows it in the new place
      if (window->callbacks.position) {
        makeCurrent(*window);
        window->callbacks.position(e.x, e.y);
      }
      return;
    case InputKind::Close: closeWindowFromSystem(*window); return;
    case InputKind::Entry:
      if (window->callbacks.entry) {
        makeCurrent(*window);
        window->callbacks.entry(e.buttonState);
      }
      return;
    case InputKind::Visibility:
      window->visible = e.buttonState == GLUT_VISIBLE;
      makeCurrent(*window);
      if (window->callbacks.windowStatus) {
        window->callbacks.windowStatus(window->visible ? GLUT_FULLY_RETAINED : GLUT_HIDDEN);
      } else if (window->callbacks.visibility) {
        window->callbacks.visibility(e.buttonState);
      }
      if (window->visible) window->redisplayPending = true;
      return;
    case InputKind::Exposed:
      if (window->resizeExposeAwaited) {
        window->resizeExposeAwaited = false;
        refreshScreen(*window);
        return;
      }
      window->redisplayPending = true;
      refreshScreen(*window);
      return;
  }
}

}  // namespace

}  // namespace glass::glut
