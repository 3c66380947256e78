// The callbacks of input devices glass knows none of: joysticks, spaceballs, button boxes, dials,
// tablets (GLUT 3.7 spec 7.12-7.18), freeglut's multi-pointer input, and freeglut's callbacks for
// contexts made again and for mobile applications paused and resumed. GLUT calls a device's
// callbacks only when the device exists; glutDeviceGet says that none of these does, so the
// callbacks are kept, checked like any other, and never called. glutForceJoystickFunc, which
// polls the joystick, has none to poll.
#include <GL/freeglut.h>

#include "glut_errors.h"
#include "glut_state.h"

using namespace glass::glut;

extern "C" {

void glutJoystickFunc(void (*callback)(unsigned int, int, int, int), int pollInterval) {
  if (Window* window = windowForCallback("glutJoystickFunc")) {
    window->callbacks.joystick = callback;
    window->callbacks.joystickPollInterval = pollInterval;
  }
}
void glutForceJoystickFunc(void) { requireCurrentWindow("glutForceJoystickFunc"); }
void glutSpaceballMotionFunc(void (*callback)(int, int, int)) {
  setWindowCallback("glutSpaceballMotionFunc", &WindowCallbacks::spaceballMotion, callback);
}
void glutSpaceballRotateFunc(void (*callback)(int, int, int)) {
  setWindowCallback("glutSpaceballRotateFunc", &WindowCallbacks::spaceballRotate, callback);
}
void glutSpaceballButtonFunc(void (*callback)(int, int)) {
  setWindowCallback("glutSpaceballButtonFunc", &WindowCallbacks::spaceballButton, callback);
}
void glutButtonBoxFunc(void (*callback)(int, int)) {
  setWindowCallback("glutButtonBoxFunc", &WindowCallbacks::buttonBox, callback);
}
void glutDialsFunc(void (*callback)(int, int)) { setWindowCallback("glutDialsFunc", &WindowCallbacks::dials, callback); }
void glutTabletMotionFunc(void (*callback)(int, int)) {
  setWindowCallback("glutTabletMotionFunc", &WindowCallbacks::tabletMotion, callback);
}
void glutTabletButtonFunc(void (*callback)(int, int, int, int)) {
  setWindowCallback("glutTabletButtonFunc", &WindowCallbacks::tabletButton, callback);
}
void glutMultiEntryFunc(void (*callback)(int, int)) {
  setWindowCallback("glutMultiEntryFunc", &WindowCallbacks::multiEntry, callback);
}
void glutMultiButtonFunc(void (*callback)(int, int, int, int, int)) {
  setWindowCallback("glutMultiButtonFunc", &WindowCallbacks::multiButton, callback);
}
void glutMultiMotionFunc(void (*callback)(int, int, int)) {
  setWindowCallback("glutMultiMotionFunc", &WindowCallbacks::multiMotion, callback);
}
void glutMultiPassiveFunc(void (*callback)(int, int, int)) {
  setWindowCallback("glutMultiPassiveFunc", &WindowCallbacks::multiPassive, callback);
}

void glutInitContextFunc(void (*callback)(void)) {
  requireInitialised("glutInitContextFunc");
  state().initContext = callback;
}
void glutAppStatusFunc(void (*callback)(int)) {
  requireInitialised("glutAppStatusFunc");
  state().appStatus = callback;
}

}  // extern "C"
