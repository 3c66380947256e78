// How a GL entry point executes, or is compiled into a display list (spec 5.4).
//
// Every command that display lists record is written as a closure over copies of its arguments
// and handed to compileOrExecute, one line per entry point:
//
//   void glLightf(GLenum light, GLenum pname, GLfloat param) {
//     glass::gl::compileOrExecute([=](glass::gl::Context& ctx) { setLight(ctx, light, pname, &param); });
//   }
//
// compileOrExecute does nothing without a current context; between glNewList and glEndList it
// appends the closure to the list (GL_COMPILE) or appends and runs it (GL_COMPILE_AND_EXECUTE);
// otherwise it runs it now. The closure does all the command's work, error checks included
// (rejectInsideBeginEnd first, where the command is not allowed between glBegin and glEnd), so
// errors appear when the list is executed, as the specification says.
//
// Closures must own their data: copy what a pointer argument points to (glLightfv's params, for
// the number of values its pname takes) into the closure, never capture the pointer.
//
// Commands that are never compiled into lists (spec 5.4: glGet*, glIs*, glGenLists,
// glDeleteLists, glNewList, glEndList, glFinish, glFlush, glReadPixels, glPixelStore, client
// array state, glGenTextures, glDeleteTextures, ...) use executeNow or queryNow instead, which
// run at once even while a list is being compiled.
#pragma once

#include <utility>

#include "core/context.h"

namespace glass::gl {

// Appends a command to the list being compiled.
void recordListCommand(Context& ctx, ListCommand command);

// compileOrExecuteOn's work while a list is being compiled: appends the command and says whether
// it must also run now (GL_COMPILE_AND_EXECUTE). Kept out of line so that the usual case, a
// command run at once, stays a test and a call in every entry point: building the list's
// std::function inline made each glVertex, glColor and glNormal save and restore registers it
// only needs for that.
template <class Command>
[[gnu::noinline]] bool recordInList(Context& ctx, const Command& command) {
  recordListCommand(ctx, ListCommand(command));
  return ctx.lists.compileMode != GL_COMPILE;
}

// compileOrExecute on a given context, for code that already holds one (glArrayElement compiles
// the values it reads this way).
template <class Command>
inline void compileOrExecuteOn(Context& ctx, Command&& command) {
  if (ctx.lists.isCompiling()) [[unlikely]] {
    if (!recordInList(ctx, command)) return;
  }
  command(ctx);
}

template <class Command>
inline void compileOrExecute(Command&& command) {
  if (Context* ctx = currentContext()) compileOrExecuteOn(*ctx, std::forward<Command>(command));
}

template <class Command>
inline void executeNow(Command&& command) {
  if (Context* ctx = currentContext()) command(*ctx);
}

// For commands that return a value: fallback without a current context.
template <class Result, class Command>
inline Result queryNow(Result fallback, Command&& command) {
  Context* ctx = currentContext();
  return ctx ? command(*ctx) : fallback;
}

}  // namespace glass::gl
