// A GL matrix stack (spec 2.11.2): glPushMatrix copies the top, glPopMatrix discards it. The
// depth is fixed at construction; push and pop report overflow and underflow instead of acting.
#pragma once

#include <cstddef>
#include <vector>

#include "core/matrix.h"

namespace glass::gl {

class MatrixStack {
 public:
  explicit MatrixStack(int maxDepth) : maxDepth_(maxDepth) {
    entries_.reserve(static_cast<std::size_t>(maxDepth));
    entries_.push_back(Matrix4::identity());
  }

  const Matrix4& top() const { return entries_.back(); }
  Matrix4& top() { return entries_.back(); }
  int depth() const { return static_cast<int>(entries_.size()); }  // 1 when nothing is pushed
  int maxDepth() const { return maxDepth_; }

  // False (and no change) when the stack is full: GL_STACK_OVERFLOW.
  bool push() {
    if (depth() >= maxDepth_) return false;
    entries_.push_back(entries_.back());
    return true;
  }
  // False (and no change) when only one matrix is left: GL_STACK_UNDERFLOW.
  bool pop() {
    if (depth() <= 1) return false;
    entries_.pop_back();
    return true;
  }

 private:
  std::vector<Matrix4> entries_;
  int maxDepth_;
};

}  // namespace glass::gl
