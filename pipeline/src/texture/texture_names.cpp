#include "texture/texture_names.h"

namespace glass::gl {

std::shared_ptr<TextureObject> TextureNames::find(GLuint name) const {
  std::lock_guard lock(mutex_);
  const auto it = objects_.find(name);
  return it == objects_.end() ? nullptr : it->second;
}

std::shared_ptr<TextureObject> TextureNames::findOrCreate(GLuint name, GLenum target) {
  std::lock_guard lock(mutex_);
  auto& slot = objects_[name];
  if (!slot) {
    try {
      slot = std::make_shared<TextureObject>();
    } catch (...) {
      objects_.erase(name);
      throw;
    }
    slot->name = name;
    slot->target = target;
    reserved_.erase(name);
  }
  return slot;
}

bool TextureNames::isTexture(GLuint name) const {
  std::lock_guard lock(mutex_);
  return name != 0 && objects_.count(name) != 0;
}

void TextureNames::generate(GLsizei n, GLuint* names) {
  std::lock_guard lock(mutex_);
  for (GLsizei i = 0; i < n; ++i) {
    GLuint name = next_;
    while (name == 0 || objects_.count(name) != 0 || reserved_.count(name) != 0) ++name;
    reserved_.insert(name);
    next_ = name + 1;
    names[i] = name;
  }
}

std::shared_ptr<TextureObject> TextureNames::remove(GLuint name) {
  std::lock_guard lock(mutex_);
  reserved_.erase(name);
  const auto it = objects_.find(name);
  if (it == objects_.end()) return nullptr;
  std::shared_ptr<TextureObject> removed = std::move(it->second);
  objects_.erase(it);
  return removed;
}

}  // namespace glass::gl
