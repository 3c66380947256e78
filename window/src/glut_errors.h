// Errors and warnings as freeglut reports them: "freeglut (program): message" on stderr, and an
// error ends the program with status 1 (freeglut's fgError and fgWarning). A handler set with
// glutInitErrorFunc or glutInitWarningFunc is called instead of printing.
#pragma once

namespace glass::glut {

struct Window;

[[noreturn]] void fatalError(const char* format, ...) __attribute__((format(printf, 1, 2)));
void warning(const char* format, ...) __attribute__((format(printf, 1, 2)));

// freeglut's FREEGLUT_EXIT_IF_NOT_INITIALISED: every GLUT call but the glutInit* family.
void requireInitialised(const char* function);

// freeglut's FREEGLUT_EXIT_IF_NO_WINDOW: the current window, or the error. Under
// GLUT_ACTION_CONTINUE_EXECUTION freeglut lets the call go on without a window; then null.
Window* requireCurrentWindow(const char* function);

// A window callback set with no current window: freeglut ignores it silently; glass ignores it
// too, with a warning, since the callback would otherwise never run without a word.
Window* windowForCallback(const char* function);

}  // namespace glass::glut
