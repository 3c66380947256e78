// The attribute stacks (OpenGL 1.5 specification, section 6.1.14): glPushAttrib/glPopAttrib save
// and restore groups of server state, glPushClientAttrib/glPopClientAttrib groups of client
// state. Each entry is a snapshot of the groups its mask names (attrib_stack.cpp).
#pragma once

#include <GL/gl.h>

#include <memory>
#include <vector>

namespace glass::gl {

struct Context;
struct StateValue;
struct AttribEntry;
struct ClientAttribEntry;

// GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH (the specification asks for 16).
inline constexpr int kMaxAttribStackDepth = 16;
inline constexpr int kMaxClientAttribStackDepth = 16;

struct AttribStackState {
  std::vector<std::shared_ptr<const AttribEntry>> server;
  std::vector<std::shared_ptr<const ClientAttribEntry>> client;
};

// glGet of the stack depths and their maxima. False when pname is not one of them.
bool queryAttribStackState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
