// Ctrl+Alt+V in any GLUT window: glass's teaching views (docs/teaching.md) switched at run time,
// without a line of the program changed (docs/glut.md). Each press shows the next view, in the
// order off, depth, overdraw, wireframe, normals, mipmap, off again; Ctrl+Alt+Shift+V goes
// backwards. The window's title names the view shown. GLUT programs do not see the combination:
// it goes to none of their callbacks.
#pragma once

#include <string>

#include "input_event.h"

namespace glass::glut {

struct Window;

// Whether the event is a press or release of the view key; a press switches the window's view,
// names it in the title and on stderr, and asks for the picture again.
bool takeViewKey(Window& window, const InputEvent& event);

// The title the window system shows: the program's, then "[glass: VIEW]" while a view is on.
std::string shownTitle(const Window& window);

}  // namespace glass::glut
