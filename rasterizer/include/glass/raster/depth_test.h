// The depth comparison (OpenGL 1.5 spec, section 4.1.6) as the rasterizer sees it, without GL
// enums, for the early depth test of triangles (triangle.h).
#pragma once

#include <cstdint>

namespace glass::raster {

class Framebuffer;

// The fragment passes when `fragment <op> stored` holds.
enum class DepthCompare : uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

inline bool passesDepthCompare(DepthCompare compare, uint32_t fragment, uint32_t stored) {
  switch (compare) {
    case DepthCompare::Never: return false;
    case DepthCompare::Less: return fragment < stored;
    case DepthCompare::Equal: return fragment == stored;
    case DepthCompare::LessEqual: return fragment <= stored;
    case DepthCompare::Greater: return fragment > stored;
    case DepthCompare::NotEqual: return fragment != stored;
    case DepthCompare::GreaterEqual: return fragment >= stored;
    case DepthCompare::Always: return true;
  }
  return true;
}

// Early depth test: a triangle's fragments whose depth fails the comparison with the depth
// buffer are dropped before their attributes are interpolated and before the sink sees them.
// The pipeline asks for it only when a fragment that fails the depth test has no effect at all
// (the depth test is on and the stencil test, whose depth-fail operation would still write, is
// off), so the pictures are the same; what changes is that hidden fragments cost little. The
// stored values it reads are current: a batch is processed by the sink before the next block is
// tested, and a batch holds each pixel at most once.
struct EarlyDepthTest {
  const Framebuffer* buffer = nullptr;  // null: no early test
  DepthCompare compare = DepthCompare::Always;
};

}  // namespace glass::raster
