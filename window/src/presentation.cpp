#include "presentation.h"

#include <algorithm>
#include <cstring>

#include "glut_errors.h"
#include "glut_state.h"
#include "headless_run.h"
#include "popup_menu.h"
#include "sdl_display.h"

namespace glass::glut {

namespace {

// Whether the draw buffer, the context being current, includes the front buffer.
bool drawingIntoFront() {
  GLint buffer = GL_BACK;
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  return buffer == GL_FRONT || buffer == GL_FRONT_LEFT || buffer == GL_FRONT_AND_BACK || buffer == GL_LEFT;
}

}  // namespace

void presentOnFlush(GlassContext*, void* userData) {
  Window* window = findWindow(static_cast<int>(reinterpret_cast<intptr_t>(userData)));
  // A double-buffered window shows its front buffer again when it is being drawn into (as Mesa
  // shows front-buffer drawing at glFlush), else nothing until glutSwapBuffers.
  if (window && (!window->doubleBuffered || drawingIntoFront())) presentWindow(*window);
}

void presentWindow(Window& window) {
  // The front buffer: a single-buffered context's one colour buffer.
  const unsigned char* pixels = glassGetFrontBuffer(window.context);
  if (!pixels) return;
  window.shown.assign(pixels, pixels + static_cast<size_t>(window.width) * window.height * 4);
  if (window.inDisplayCallback) {
    window.presentedInDisplay = true;
  } else {
    noteFramePresented(window);
  }
  refreshScreen(window);
}

namespace {

// Copies the child's screen (RGBA8, bottom row first) into the parent's at the child's place
// (x, y from the parent's top-left corner, y down), clipped to the parent.
void drawChildOver(const Window& child, Window& parent) {
  if (child.screen.size() != static_cast<size_t>(child.width) * child.height * 4 ||
      parent.screen.size() != static_cast<size_t>(parent.width) * parent.height * 4) {
    return;
  }
  const int left = std::max(child.x, 0), right = std::min(child.x + child.width, parent.width);
  if (left >= right) return;
  for (int row = 0; row < child.height; ++row) {
    const int parentRowFromTop = child.y + (child.height - 1 - row);
    if (parentRowFromTop < 0 || parentRowFromTop >= parent.height) continue;
    const int parentRow = parent.height - 1 - parentRowFromTop;
    const unsigned char* from = child.screen.data() + (static_cast<size_t>(row) * child.width + (left - child.x)) * 4;
    unsigned char* to = parent.screen.data() + (static_cast<size_t>(parentRow) * parent.width + left) * 4;
    std::memcpy(to, from, static_cast<size_t>(right - left) * 4);
  }
}

}  // namespace

void refreshScreen(Window& window) {
  // The window's picture, its visible sub-windows' screens over it, then its pop-up.
  window.screen = window.shown;
  for (int id : window.children) {
    if (const Window* child = findWindow(id); child && child->visible) drawChildOver(*child, window);
  }
  if (!window.openMenus.empty()) drawPopupOverPicture(window);
  // A sub-window is seen through its parent's screen.
  if (Window* parent = findWindow(window.parent)) {
    refreshScreen(*parent);
  } else {
    showOnScreen(window);
  }
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
