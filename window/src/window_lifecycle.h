// Making, destroying and closing windows, and ending GLUT (freeglut's fgDeinitialize).
#pragma once

namespace glass::glut {

struct Window;

// Makes a top-level window of the initial display mode, at x, y on the screen (negative: where
// the system puts it), current; a game mode window has no border. Returns its id.
int createTopLevelWindow(const char* title, int x, int y, int width, int height, bool gameMode);
// Destroys the window: its close callback runs first (freeglut calls it for every destruction),
// then its context and system window go.
void destroyWindow(int id);
// The window manager's close button (or an events file's `close`): the close callback, then what
// GLUT_ACTION_ON_WINDOW_CLOSE says.
void closeWindowFromSystem(Window& window);
// Destroys every window and menu and closes the display; glutInit may be called again.
void deinitialise();

}  // namespace glass::glut
