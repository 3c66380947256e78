#include "bin_arena.h"

#include <new>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace glass::raster {
namespace {

constexpr size_t kRegionBytes = size_t{2} << 20;  // one 2 MiB page
constexpr size_t kAlignment = 16;

}  // namespace

BinArena::~BinArena() {
  for (const Region& region : regions_) ::operator delete(region.start, std::align_val_t{kRegionBytes});
}

void* BinArena::allocate(size_t bytes) {
  bytes = (bytes + kAlignment - 1) / kAlignment * kAlignment;
  // The next region that has room; a new one where none has (regions too small for this block
  // are passed over and used again after the next reset).
  while (current_ < regions_.size() && used_ + bytes > regions_[current_].bytes) {
    ++current_;
    used_ = 0;
  }
  if (current_ == regions_.size()) {
    const size_t size = (bytes + kRegionBytes - 1) / kRegionBytes * kRegionBytes;
    auto* start = static_cast<char*>(::operator new(size, std::align_val_t{kRegionBytes}));
#ifdef MADV_HUGEPAGE
    madvise(start, size, MADV_HUGEPAGE);  // a hint: where refused, the pages are the usual size
#endif
    regions_.push_back({start, size});
    used_ = 0;
  }
  void* block = regions_[current_].start + used_;
  used_ += bytes;
  return block;
}

void BinArena::reset() {
  current_ = 0;
  used_ = 0;
}

size_t BinArena::reservedBytes() const {
  size_t total = 0;
  for (const Region& region : regions_) total += region.bytes;
  return total;
}

}  // namespace glass::raster
