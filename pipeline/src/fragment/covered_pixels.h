// Copies of the covered pixels of a block row (up to 8 pixels, bit i of a mask for pixel i),
// for the block kernels and their row stages: every byte read and written belongs to a covered
// pixel, since the pixels beside them in the colour, depth or stencil buffer may be another
// thread's (in the next tile) or lie past the row's end.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace glass::gl {

// Copies pixels first .. first + n - 1 (1 <= n <= 8) of kBytes bytes each in at most two
// fixed-size copies, the second overlapping the first where n is not a power of two (the
// overlap is written twice with the same values).
template <int kBytes>
void copyPixelRun(uint8_t* to, const uint8_t* from, int first, int n) {
  const auto copyAt = [&](auto pixels, int at) {
    std::memcpy(to + kBytes * at, from + kBytes * at, kBytes * decltype(pixels)::value);
  };
  if (n >= 4) {
    copyAt(std::integral_constant<int, 4>{}, first);
    copyAt(std::integral_constant<int, 4>{}, first + n - 4);
  } else if (n >= 2) {
    copyAt(std::integral_constant<int, 2>{}, first);
    copyAt(std::integral_constant<int, 2>{}, first + n - 2);
  } else {
    copyAt(std::integral_constant<int, 1>{}, first);
  }
}

// Copies pixel i (kBytes bytes at kBytes i) from `from` to `to` for each bit i of mask: a
// covered run without gaps (most rows) is one or two copies.
template <int kBytes>
void copyCoveredPixels(void* to, const void* from, unsigned mask) {
  if (mask == 0) return;
  auto* toBytes = static_cast<uint8_t*>(to);
  const auto* fromBytes = static_cast<const uint8_t*>(from);
  const int first = std::countr_zero(mask), last = std::bit_width(mask) - 1;
  if (mask >> first == (2u << (last - first)) - 1u) return copyPixelRun<kBytes>(toBytes, fromBytes, first, last - first + 1);
  for (unsigned rest = mask; rest != 0; rest &= rest - 1) {
    const int i = std::countr_zero(rest);
    std::memcpy(toBytes + kBytes * i, fromBytes + kBytes * i, kBytes);
  }
}

// 4-byte pixels: depth values and RGBA8 colours.
inline void copyCoveredWords(void* to, const void* from, unsigned mask) { copyCoveredPixels<4>(to, from, mask); }

}  // namespace glass::gl
