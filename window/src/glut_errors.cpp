#include "glut_errors.h"

#include <GL/freeglut.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#include "glut_state.h"

namespace glass::glut {

namespace {

void report(void (*handler)(const char*, va_list), const char* format, va_list arguments) {
  if (handler) {
    handler(format, arguments);
    return;
  }
  std::fprintf(stderr, "freeglut ");
  if (!state().programName.empty()) std::fprintf(stderr, "(%s): ", state().programName.c_str());
  std::vfprintf(stderr, format, arguments);
  std::fprintf(stderr, "\n");
}

}  // namespace

void fatalError(const char* format, ...) {
  va_list arguments;
  va_start(arguments, format);
  report(state().errorFunc, format, arguments);
  va_end(arguments);
  // freeglut returns to its caller when a handler returns; its state is then not to be trusted,
  // so glass ends the program in both cases.
  std::exit(1);
}

void warning(const char* format, ...) {
  va_list arguments;
  va_start(arguments, format);
  report(state().warningFunc, format, arguments);
  va_end(arguments);
}

void requireInitialised(const char* function) {
  if (!state().initialised) {
    fatalError(" ERROR:  Function <%s> called without first calling 'glutInit'.", function);
  }
}

Window* requireCurrentWindow(const char* function) {
  requireInitialised(function);
  Window* window = currentWindow();
  if (!window && state().actionOnWindowClose != GLUT_ACTION_CONTINUE_EXECUTION) {
    fatalError(" ERROR:  Function <%s> called with no current window defined.", function);
  }
  return window;
}

Window* windowForCallback(const char* function) {
  requireInitialised(function);
  Window* window = currentWindow();
  if (!window) {
    warning(" WARNING:  Function <%s> called with no current window defined; the callback is "
            "ignored.",
            function);
  }
  return window;
}

}  // namespace glass::glut
