// Making, destroying and closing windows, and ending GLUT (freeglut's fgDeinitialize).
#pragma once

namespace glass::glut {

struct Window;

// Destroys the window: its close callback runs first (freeglut calls it for every destruction),
// then its context and system window go.
void destroyWindow(int id);
// The window manager's close button (or an events file's `close`): the close callback, then what
// GLUT_ACTION_ON_WINDOW_CLOSE says.
void closeWindowFromSystem(Window& window);
// Destroys every window and menu and closes the display; glutInit may be called again.
void deinitialise();

}  // namespace glass::glut
