// The context a program asks for with glutInitContextVersion, glutInitContextFlags and
// glutInitContextProfile (freeglut), against the one glass has: OpenGL 1.4.
#pragma once

namespace glass::glut {

// Ends the program with freeglut's message when the asked version is above 1.4 (a core profile or
// a forward-compatible context is only asked with 3.0 and above), before a window is made.
void requireContextGlassHas();

}  // namespace glass::glut
