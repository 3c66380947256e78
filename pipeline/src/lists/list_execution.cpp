#include "lists/list_execution.h"

#include <limits>

#include "core/context.h"
#include "lists/command_recording.h"

namespace glass::gl {

void recordListCommand(Context& ctx, ListCommand command) {
  ctx.lists.compiling->commands.push_back(std::move(command));
}

void callList(Context& ctx, GLuint name) {
  DisplayListState& lists = ctx.lists;
  if (lists.callDepth >= kMaxListNesting) return;
  const auto found = lists.lists.find(name);
  if (found == lists.lists.end()) return;
  // Holding a reference keeps the list alive even if a command in it replaced it.
  const std::shared_ptr<const DisplayList> list = found->second;
  ++lists.callDepth;
  for (const ListCommand& command : list->commands) command(ctx);
  --lists.callDepth;
}

GLuint generateLists(Context& ctx, GLsizei range) {
  auto& lists = ctx.lists.lists;
  const GLuint count = static_cast<GLuint>(range);
  // The first gap of `count` unused names after 0, scanning the used names in order.
  GLuint candidate = 1;
  for (const auto& [name, list] : lists) {
    if (name < candidate) continue;
    if (name - candidate >= count) break;
    candidate = name + 1;
    if (candidate == 0) return 0;  // wrapped around: no names left
  }
  if (std::numeric_limits<GLuint>::max() - candidate < count - 1) return 0;
  auto empty = std::make_shared<const DisplayList>();
  for (GLuint i = 0; i < count; ++i) lists[candidate + i] = empty;
  return candidate;
}

}  // namespace glass::gl
