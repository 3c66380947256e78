// Giving input events to the window's callbacks, and to its pop-up menu first when one is open
// or attached to the button (GLUT 3.7 spec 6-7).
#pragma once

#include "input_event.h"

namespace glass::glut {

void dispatchInput(const InputEvent& event);

}  // namespace glass::glut
