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
  // Holding a reference keeps the list alive even if a command in it replaced it.
  const std::shared_ptr<const DisplayList> list = lists.lists->find(name);
  if (!list) return;
  ++lists.callDepth;
  for (const ListCommand& command : list->commands) command(ctx);
  --lists.callDepth;
}

GLuint generateLists(Context& ctx, GLsizei range) {
  return ctx.lists.lists->reserve(static_cast<GLuint>(range));
}

std::shared_ptr<const DisplayList> ListTable::find(GLuint name) const {
  const std::lock_guard lock(mutex_);
  const auto found = lists_.find(name);
  return found == lists_.end() ? nullptr : found->second;
}

bool ListTable::contains(GLuint name) const {
  const std::lock_guard lock(mutex_);
  return lists_.count(name) != 0;
}

void ListTable::replace(GLuint name, std::shared_ptr<const DisplayList> list) {
  const std::lock_guard lock(mutex_);
  lists_[name] = std::move(list);
}

void ListTable::erase(GLuint first, unsigned long long end) {
  const std::lock_guard lock(mutex_);
  lists_.erase(lists_.lower_bound(first),
               end > 0xFFFFFFFFull ? lists_.end() : lists_.lower_bound(static_cast<GLuint>(end)));
}

GLuint ListTable::reserve(GLuint count) {
  const std::lock_guard lock(mutex_);
  // The first gap of `count` unused names after 0, scanning the used names in order.
  GLuint candidate = 1;
  for (const auto& [name, list] : lists_) {
    if (name < candidate) continue;
    if (name - candidate >= count) break;
    candidate = name + 1;
    if (candidate == 0) return 0;  // wrapped around: no names left
  }
  if (std::numeric_limits<GLuint>::max() - candidate < count - 1) return 0;
  auto empty = std::make_shared<const DisplayList>();
  for (GLuint i = 0; i < count; ++i) lists_[candidate + i] = empty;
  return candidate;
}

}  // namespace glass::gl
