// What the teaching tools keep for a context (a view's canvas, a frame's statistics) lives beside
// the context, not in it, so that a context without them carries nothing and the Context type
// stays as it is. The count of entries lets the per-draw lookup skip the lock in the common case
// where no context has one.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace glass::gl {

struct Context;

template <typename T>
class PerContextTable {
 public:
  T* find(const Context& ctx) {
    if (entries_.load(std::memory_order_acquire) == 0) return nullptr;
    std::lock_guard<std::mutex> lock(mutex_);
    auto found = map_.find(&ctx);
    return found == map_.end() ? nullptr : found->second.get();
  }
  // Gives ctx `value`, replacing what it had.
  T& attach(const Context& ctx, std::unique_ptr<T> value) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto [slot, added] = map_.try_emplace(&ctx);
    slot->second = std::move(value);
    if (added) entries_.fetch_add(1, std::memory_order_release);
    return *slot->second;
  }
  void detach(const Context& ctx) {
    if (entries_.load(std::memory_order_acquire) == 0) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (map_.erase(&ctx) > 0) entries_.fetch_sub(1, std::memory_order_release);
  }

 private:
  std::mutex mutex_;
  std::unordered_map<const Context*, std::unique_ptr<T>> map_;
  std::atomic<int> entries_{0};
};

}  // namespace glass::gl
