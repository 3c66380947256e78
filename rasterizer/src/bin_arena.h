// The memory of one tile scene's bins (tile_scene.h): a BinArena hands out memory from large
// regions by moving a cursor, and takes it all back at once when the scene is cleared, keeping the
// regions for the next scene. A bin's list (BinList) is a chain of segments from the arena: the
// first as large as the list was in the previous scene, each further one half of what the list
// has so far, so a list grows without copying what it holds.
//
// Why not std::vector: a bin's vector kept the largest capacity it ever reached, and reached it by
// doubling, each growth a copy into new memory that the system faulted in page by page; with a
// worker running, the unmapping of freed blocks also interrupted the worker's processor to flush
// its address translations. The scenes grow over the first frames of a program
// (tiled_rasterizer.cpp hands small scenes to idle workers at first), so those frames paid for it:
// at 1920 x 1080 with 150,000 small lit triangles on 2 threads, the three frames after the warm-up
// took 88 ms on average (5,800, 4,000, 2,300 page faults) against 43 ms once grown; with the
// arena 45 ms, and no faults after the warm-up. The regions are 2 MiB, aligned to 2 MiB, and on
// Linux the kernel is asked to back them with 2 MiB pages: one fault per region instead of 512.
// A short run gains most (lit_spheres, small_triangles and lines, two frames each: 1.29 -> 1.05 s
// on 1 thread, 0.94 -> 0.65 s on 2), and memory halves, since a scene's memory is what its
// largest contents needed rather than each bin's largest list ever (the benchmark's peak 158 ->
// 82 MB on 1 thread, 263 -> 124 MB on 2). Its price: once grown, frames of many small triangles
// on one thread take 2 to 4% longer (lit_spheres_indexed 61.4 -> 64.5 ms), though they run 1.5%
// fewer instructions (callgrind); not explained.
//
// One thread at a time: the submitting thread appends and clears; workers read a scene only
// while nobody appends to it (tiled_rasterizer.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace glass::raster {

class BinArena {
 public:
  BinArena() = default;
  BinArena(const BinArena&) = delete;
  BinArena& operator=(const BinArena&) = delete;
  ~BinArena();

  // `bytes` bytes aligned to 16, valid until reset().
  void* allocate(size_t bytes);
  // Takes back everything allocate() gave; the regions stay for what comes next.
  void reset();

  size_t reservedBytes() const;  // the regions' total size

 private:
  struct Region {
    char* start;
    size_t bytes;
  };
  std::vector<Region> regions_;
  size_t current_ = 0;  // the region the cursor is in (regions_.size() when there is none)
  size_t used_ = 0;     // bytes of it already handed out
};

// A list of trivially copyable T that only grows until reset(), read front to back with a
// Reader. A run of elements appended together (extend) stays contiguous.
template <typename T>
class BinList {
  static_assert(std::is_trivially_copyable_v<T> && alignof(T) <= 16);
  struct Segment;

 public:
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }

  // Room for n more elements, contiguous; the caller writes them.
  T* extend(BinArena& arena, size_t n) {
    if (n == 0) return nullptr;
    if (!hasRoom(next_, end_, n)) addSegment(arena, n);
    T* at = next_;
    next_ += n;
    size_ += n;
    return at;
  }
  void push(BinArena& arena, const T& value) { *extend(arena, 1) = value; }
  void append(BinArena& arena, const T* values, size_t n) {
    T* at = extend(arena, n);
    for (size_t i = 0; i < n; ++i) at[i] = values[i];
  }

  // Asks the memory system for the cache lines of the next n elements, when they fit in the
  // segment the list has (a hint only).
  void prefetchNext(size_t n) const {
    if (!hasRoom(next_, end_, n)) return;
    const char* next = reinterpret_cast<const char*>(next_);
    for (size_t offset = 0; offset < n * sizeof(T); offset += 64) __builtin_prefetch(next + offset, 1);
  }

  // Forgets the elements; the arena takes their memory back with its own reset(). The next
  // first segment holds as many as the list held (scenes of one program tend to be alike), so
  // that a list is mostly one run of memory, read front to back as a vector's would be.
  void reset() {
    const size_t lastSize = size_;
    *this = BinList();
    firstCapacity_ = lastSize;
  }

  // Reads the list in the order it was written, in the runs it was written in.
  class Reader {
   public:
    explicit Reader(const BinList& list) : list_(list) {
      if (list.head_ != nullptr) enter(list.head_);
    }
    // The next n elements (n as when they were appended together).
    const T* take(size_t n) {
      if (n == 0) return nullptr;
      if (!hasRoom(at_, end_, n)) enter(segment_->next);  // they were appended to the next segment
      const T* at = at_;
      at_ += n;
      return at;
    }

   private:
    void enter(const Segment* segment) {
      segment_ = segment;
      at_ = segment->data();
      end_ = segment == list_.tail_ ? list_.next_ : at_ + segment->used;
    }
    const BinList& list_;
    const Segment* segment_ = nullptr;
    const T* at_ = nullptr;
    const T* end_ = nullptr;
  };

 private:
  // A segment's elements follow its header. `used` is set when the list moves on to the next
  // segment; the last one's end is the list's next_.
  struct alignas(16) Segment {
    Segment* next;
    size_t used;
    T* data() { return reinterpret_cast<T*>(this + 1); }
    const T* data() const { return reinterpret_cast<const T*>(this + 1); }
  };
  static_assert(sizeof(Segment) == 16);

  // Whether n elements fit in [from, end), compared in bytes (an element count would take a
  // division by the element's size).
  static bool hasRoom(const T* from, const T* end, size_t n) {
    return static_cast<size_t>(reinterpret_cast<const char*>(end) - reinterpret_cast<const char*>(from)) >=
           n * sizeof(T);
  }

  void addSegment(BinArena& arena, size_t n) {
    constexpr size_t kLeast = (256 + sizeof(T) - 1) / sizeof(T);  // 256 bytes
    size_t capacity = tail_ == nullptr ? std::max(kLeast, firstCapacity_) : std::max(kLeast, capacity_ / 2);
    capacity = std::max(capacity, n);
    capacity_ += capacity;
    auto* segment = static_cast<Segment*>(arena.allocate(sizeof(Segment) + capacity * sizeof(T)));
    segment->next = nullptr;
    segment->used = 0;
    if (tail_ == nullptr) {
      head_ = segment;
    } else {
      tail_->used = static_cast<size_t>(next_ - tail_->data());
      tail_->next = segment;
    }
    tail_ = segment;
    next_ = segment->data();
    end_ = next_ + capacity;
  }

  Segment* head_ = nullptr;
  Segment* tail_ = nullptr;
  T* next_ = nullptr;  // where the next element goes, in tail_
  T* end_ = nullptr;   // the end of tail_'s room
  size_t size_ = 0;
  size_t capacity_ = 0;       // of all segments, in elements
  size_t firstCapacity_ = 0;  // at least, in elements
};

}  // namespace glass::raster
