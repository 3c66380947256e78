// One input event for a GLUT window, from the window system (sdl_display.cpp) or from an events
// file (event_script.cpp), before it is given to the window's callbacks (event_dispatch.cpp).
#pragma once

namespace glass::glut {

enum class InputKind {
  Key,         // key: the character (glutKeyboardFunc)
  KeyUp,       // glutKeyboardUpFunc
  Special,     // key: a GLUT_KEY_* code (glutSpecialFunc)
  SpecialUp,   // glutSpecialUpFunc
  Button,      // button (GLUT_LEFT_BUTTON, ...; 3 and 4 the wheel), buttonState GLUT_DOWN/GLUT_UP
  Wheel,       // button: the wheel, buttonState: the direction (+1 away from the user)
  Motion,      // the pointer moved (glutMotionFunc with a button down, else glutPassiveMotionFunc)
  Reshape,     // the window system changed the size to width x height
  Moved,       // to x, y on the screen
  Close,       // the window manager's close button
  Entry,       // buttonState: GLUT_ENTERED or GLUT_LEFT
  Visibility,  // buttonState: GLUT_VISIBLE or GLUT_NOT_VISIBLE
  Exposed,     // the window's content was lost and must be drawn again
};

struct InputEvent {
  InputKind kind = InputKind::Key;
  int window = 0;  // GLUT window id
  int key = 0;
  int button = 0;
  int buttonState = 0;
  int x = 0, y = 0;  // the pointer in window coordinates (y down), or the new position
  int width = 0, height = 0;
  int modifiers = 0;  // GLUT_ACTIVE_* held at the time
  bool repeat = false;  // a key's auto-repeat (its release and press), not the user's own
};

}  // namespace glass::glut
