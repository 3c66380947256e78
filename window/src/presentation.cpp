#include "presentation.h"

#include <cstring>

#include "glut_errors.h"
#include "glut_state.h"
#include "headless_run.h"
#include "popup_menu.h"
#include "sdl_display.h"

namespace glass::glut {

void presentOnFlush(GlassContext*, void* userData) {
  Window* window = findWindow(static_cast<int>(reinterpret_cast<intptr_t>(userData)));
  // A double-buffered window shows nothing until glutSwapBuffers.
  if (window && !window->doubleBuffered) presentWindow(*window);
}

void presentWindow(Window& window) {
  const unsigned char* pixels = glassGetColorBuffer(window.context);
  if (!pixels) return;
  window.shown.assign(pixels, pixels + static_cast<size_t>(window.width) * window.height * 4);
  if (window.inDisplayCallback) {
    window.presentedInDisplay = true;
  } else {
    noteFramePresented(window);
  }
  refreshScreen(window);
}

void refreshScreen(Window& window) {
  if (window.openMenus.empty()) {
    window.screen = window.shown;
  } else {
    drawPopupOverPicture(window);
  }
  showOnScreen(window);
}

void resizeWindow(Window& window, int width, int height) {
  if (width < 1) width = 1;
  if (height < 1) height = 1;
  if (width == window.width && height == window.height) return;
  if (!glassResizeContext(window.context, width, height)) {
    warning("cannot resize window %d to %d x %d (out of memory or too large)", window.id, width,
            height);
    return;
  }
  window.width = width;
  window.height = height;
  // Until the program draws again, the window shows black, as a new X window does.
  window.shown.assign(static_cast<size_t>(width) * height * 4, 0);
  closePopup(window);
  window.reshapePending = true;
  window.redisplayPending = true;
  refreshScreen(window);
}

}  // namespace glass::glut
