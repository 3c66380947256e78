// Showing a window's picture: glFlush/glFinish in a single-buffered window and glutSwapBuffers
// in a double-buffered one copy the context's colour buffer to Window::shown; the screen is that
// picture with the screens of its sub-windows over it, then the open pop-up menu. A top-level
// window's screen is what the window system shows.
#pragma once

#include <glass/context.h>

namespace glass::glut {

struct Window;

// The flush callback of every window's context (glassSetFlushCallback); userData is the window id.
void presentOnFlush(GlassContext* context, void* userData);
// Copies the colour buffer to `shown`, counts the frame and shows it.
void presentWindow(Window& window);
// Composes the screen (`shown`, the sub-windows' screens and the pop-up) and shows it, for a
// sub-window by composing its parent's again.
void refreshScreen(Window& window);
// Gives the window and its context a new size; the reshape callback runs in the next loop pass.
void resizeWindow(Window& window, int width, int height);

}  // namespace glass::glut
