// The memory of the tile scenes' bins (rasterizer/src/bin_arena.h): lists read back what was
// written, in the same runs, across segments and arena resets; the arena reuses its regions.
#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "bin_arena.h"

using glass::raster::BinArena;
using glass::raster::BinList;

namespace {

struct Record {  // the size of no power of two, as the scene's records
  double value[3];
  int32_t tag;
};

// Appends runs of random lengths (0 to 40, some longer than a segment) to two lists sharing an
// arena, then reads them back and compares with what was written.
void fillAndCheck(BinArena& arena, BinList<Record>& records, BinList<float>& floats, int runs) {
  std::mt19937 random(7);  // the same runs every time
  std::vector<std::vector<float>> written;
  std::uniform_int_distribution<int> length(0, 40);
  for (int r = 0; r < runs; ++r) {
    records.push(arena, Record{{r * 1.0, r * 2.0, r * 3.0}, r});
    std::vector<float> run(static_cast<size_t>(r % 97 == 0 ? 300 : length(random)));
    for (size_t i = 0; i < run.size(); ++i) run[i] = static_cast<float>(r) + static_cast<float>(i) / 512.0f;
    floats.append(arena, run.data(), run.size());
    written.push_back(run);
  }
  REQUIRE(records.size() == static_cast<size_t>(runs));
  BinList<Record>::Reader recordReader(records);
  BinList<float>::Reader floatReader(floats);
  for (int r = 0; r < runs; ++r) {
    const Record& record = *recordReader.take(1);
    CHECK(record.tag == r);
    CHECK(record.value[2] == r * 3.0);
    const std::vector<float>& run = written[static_cast<size_t>(r)];
    const float* read = floatReader.take(run.size());
    for (size_t i = 0; i < run.size(); ++i) REQUIRE(read[i] == run[i]);  // one contiguous run
  }
}

}  // namespace

TEST_CASE("bin lists read back their runs across segments and arena resets") {
  BinArena arena;
  BinList<Record> records;
  BinList<float> floats;
  fillAndCheck(arena, records, floats, 1000);
  const size_t reserved = arena.reservedBytes();
  CHECK(reserved >= 1000 * sizeof(Record));

  // A scene cleared and filled again alike: the same regions, no new memory.
  for (int scene = 0; scene < 3; ++scene) {
    records.reset();
    floats.reset();
    arena.reset();
    fillAndCheck(arena, records, floats, 1000);
    CHECK(arena.reservedBytes() == reserved);
  }

  // Emptied and filled with fewer: still correct (the first segment is sized for more).
  records.reset();
  floats.reset();
  arena.reset();
  fillAndCheck(arena, records, floats, 10);
}

TEST_CASE("a bin list refilled like the previous scene is one run of memory") {
  BinArena arena;
  BinList<Record> list;
  for (int i = 0; i < 5000; ++i) list.push(arena, Record{{}, i});  // grows through segments
  list.reset();
  arena.reset();
  const Record* previous = nullptr;
  for (int i = 0; i < 5000; ++i) {
    Record* at = list.extend(arena, 1);
    *at = Record{{}, i};
    if (previous != nullptr) REQUIRE(at == previous + 1);
    previous = at;
  }
}

TEST_CASE("the bin arena aligns its blocks to 16 bytes and serves blocks larger than a region") {
  BinArena arena;
  for (size_t bytes : {1u, 15u, 17u, 100u, 4096u}) {
    void* block = arena.allocate(bytes);
    CHECK(reinterpret_cast<uintptr_t>(block) % 16 == 0);
  }
  const size_t large = size_t{5} << 20;  // 5 MiB: more than a 2 MiB region
  auto* block = static_cast<unsigned char*>(arena.allocate(large));
  block[0] = 1;
  block[large - 1] = 2;  // the whole block is usable (ASan checks the bounds)
  CHECK(arena.reservedBytes() >= large);
  // Reset, the same large block comes from the region kept for it.
  const size_t reserved = arena.reservedBytes();
  arena.reset();
  arena.allocate(100);
  arena.allocate(large);
  CHECK(arena.reservedBytes() == reserved);
}
