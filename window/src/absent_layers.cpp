// What GLUT offers for hardware glass's windows do not have, as freeglut does without it:
// overlays (GLUT 3.7 spec 5: glutLayerGet(GLUT_OVERLAY_POSSIBLE) is 0, so a program that asks
// first never establishes one; the calls do nothing and the overlay display callback is kept
// and never called), colour index maps (spec 8: glass's windows are RGBA; glutGetColor gives
// -1, as for an RGBA window) and video resizing (glutVideoResizeGet gives 0: not possible).
#include <GL/freeglut.h>

#include "glut_errors.h"
#include "glut_state.h"

using namespace glass::glut;

extern "C" {

void glutEstablishOverlay(void) { requireCurrentWindow("glutEstablishOverlay"); }
void glutRemoveOverlay(void) { requireCurrentWindow("glutRemoveOverlay"); }
void glutUseLayer(GLenum) { requireCurrentWindow("glutUseLayer"); }
void glutPostOverlayRedisplay(void) { requireCurrentWindow("glutPostOverlayRedisplay"); }
void glutPostWindowOverlayRedisplay(int) { requireInitialised("glutPostWindowOverlayRedisplay"); }
void glutShowOverlay(void) { requireCurrentWindow("glutShowOverlay"); }
void glutHideOverlay(void) { requireCurrentWindow("glutHideOverlay"); }
void glutOverlayDisplayFunc(void (*callback)(void)) {
  setWindowCallback("glutOverlayDisplayFunc", &WindowCallbacks::overlayDisplay, callback);
}

void glutSetColor(int, GLfloat, GLfloat, GLfloat) { requireCurrentWindow("glutSetColor"); }
GLfloat glutGetColor(int, int) {
  requireCurrentWindow("glutGetColor");
  return -1.0f;
}
void glutCopyColormap(int) { requireCurrentWindow("glutCopyColormap"); }

int glutVideoResizeGet(GLenum) {
  requireInitialised("glutVideoResizeGet");
  return 0;
}
void glutSetupVideoResizing(void) { requireInitialised("glutSetupVideoResizing"); }
void glutStopVideoResizing(void) { requireInitialised("glutStopVideoResizing"); }
void glutVideoResize(int, int, int, int) { requireInitialised("glutVideoResize"); }
void glutVideoPan(int, int, int, int) { requireInitialised("glutVideoPan"); }

}  // extern "C"
