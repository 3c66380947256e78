// Display lists (spec 5.4): named sequences of recorded GL commands.
//
// A recorded command is a closure over copies of its arguments that performs the command on a
// context, exactly as the GL entry point does when it executes immediately. So a command behaves
// the same whether executed now or from a list, including the errors it sets. See
// lists/command_recording.h for how entry points record themselves.
#pragma once

#include <GL/gl.h>

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace glass::gl {

struct Context;

using ListCommand = std::function<void(Context&)>;

struct DisplayList {
  std::vector<ListCommand> commands;
};

// GL_MAX_LIST_NESTING: glCallList beyond this depth does nothing (spec 5.4).
inline constexpr int kMaxListNesting = 64;

// Name -> list. A name reserved by glGenLists holds an empty list. Lists are shared pointers so
// that a list being executed stays alive even if it is replaced meanwhile. Contexts created to
// share display lists (OSMesaCreateContext's sharelist) hold the same table, possibly on different
// threads at once: each operation locks it, so each is whole.
class ListTable {
 public:
  std::shared_ptr<const DisplayList> find(GLuint name) const;
  bool contains(GLuint name) const;
  void replace(GLuint name, std::shared_ptr<const DisplayList> list);
  // Deletes the names in [first, end).
  void erase(GLuint first, unsigned long long end);
  // glGenLists: the first `count` consecutive unused names after 0, reserved with empty lists;
  // 0 when there are none.
  GLuint reserve(GLuint count);

 private:
  mutable std::mutex mutex_;
  std::map<GLuint, std::shared_ptr<const DisplayList>> lists_;
};

struct DisplayListState {
  std::shared_ptr<ListTable> lists = std::make_shared<ListTable>();

  // The list being compiled between glNewList and glEndList: it replaces the old list of that
  // name only at glEndList.
  GLuint compilingName = 0;  // 0: not compiling
  GLenum compileMode = GL_COMPILE;
  std::unique_ptr<DisplayList> compiling;

  GLuint listBase = 0;       // glListBase
  int callDepth = 0;         // nesting of glCallList being executed

  bool isCompiling() const { return compilingName != 0; }
};

}  // namespace glass::gl
