// Setting callbacks (GLUT 3.7 spec 7; freeglut's additions). The window callbacks belong to the
// current window; glutIdleFunc and glutTimerFunc are in main_loop.cpp.
#include <GL/freeglut.h>

#include "glut_errors.h"
#include "glut_state.h"

using namespace glass::glut;

extern "C" {

void glutDisplayFunc(void (*callback)(void)) {
  requireInitialised("glutDisplayFunc");
  if (!callback) {
    fatalError("Fatal error in program.  NULL display callback not permitted in GLUT 3.0+ or "
               "freeglut 2.0.1+");
  }
  setWindowCallback("glutDisplayFunc", &WindowCallbacks::display, callback);
  // A window gets a display callback before it is first shown; a new one redraws it.
  if (Window* window = currentWindow()) window->redisplayPending = true;
}

void glutReshapeFunc(void (*callback)(int, int)) {
  setWindowCallback("glutReshapeFunc", &WindowCallbacks::reshape, callback);
}
void glutKeyboardFunc(void (*callback)(unsigned char, int, int)) {
  setWindowCallback("glutKeyboardFunc", &WindowCallbacks::keyboard, callback);
}
void glutKeyboardUpFunc(void (*callback)(unsigned char, int, int)) {
  setWindowCallback("glutKeyboardUpFunc", &WindowCallbacks::keyboardUp, callback);
}
void glutSpecialFunc(void (*callback)(int, int, int)) {
  setWindowCallback("glutSpecialFunc", &WindowCallbacks::special, callback);
}
void glutSpecialUpFunc(void (*callback)(int, int, int)) {
  setWindowCallback("glutSpecialUpFunc", &WindowCallbacks::specialUp, callback);
}
void glutMouseFunc(void (*callback)(int, int, int, int)) {
  setWindowCallback("glutMouseFunc", &WindowCallbacks::mouse, callback);
}
void glutMouseWheelFunc(void (*callback)(int, int, int, int)) {
  setWindowCallback("glutMouseWheelFunc", &WindowCallbacks::mouseWheel, callback);
}
void glutMotionFunc(void (*callback)(int, int)) {
  setWindowCallback("glutMotionFunc", &WindowCallbacks::motion, callback);
}
void glutPassiveMotionFunc(void (*callback)(int, int)) {
  setWindowCallback("glutPassiveMotionFunc", &WindowCallbacks::passiveMotion, callback);
}
void glutEntryFunc(void (*callback)(int)) {
  setWindowCallback("glutEntryFunc", &WindowCallbacks::entry, callback);
}
void glutVisibilityFunc(void (*callback)(int)) {
  setWindowCallback("glutVisibilityFunc", &WindowCallbacks::visibility, callback);
}
void glutWindowStatusFunc(void (*callback)(int)) {
  setWindowCallback("glutWindowStatusFunc", &WindowCallbacks::windowStatus, callback);
}
void glutPositionFunc(void (*callback)(int, int)) {
  setWindowCallback("glutPositionFunc", &WindowCallbacks::position, callback);
}
// freeglut: glutWMCloseFunc is another name for glutCloseFunc.
void glutCloseFunc(void (*callback)(void)) {
  setWindowCallback("glutCloseFunc", &WindowCallbacks::close, callback);
}
void glutWMCloseFunc(void (*callback)(void)) {
  setWindowCallback("glutWMCloseFunc", &WindowCallbacks::close, callback);
}

void glutMenuStatusFunc(void (*callback)(int, int, int)) {
  requireInitialised("glutMenuStatusFunc");
  state().menuStatus = callback;
}
void glutMenuStateFunc(void (*callback)(int)) {
  requireInitialised("glutMenuStateFunc");
  state().menuState = callback;
}

}  // extern "C"
