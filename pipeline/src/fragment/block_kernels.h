// Fast paths of the fragment stage for filled triangles (docs/pipeline.md, "Fast paths").
//
// The reference path interpolates every varying of a covered pixel into a raster::Fragment and
// runs the whole of chapter 4.1 on it (FragmentProcessor::processFragments), testing each piece
// of state per fragment. For the states most drawing uses, FragmentProcessor::prepare derives a
// key once per draw and picks a kernel compiled for it: the triangle walk's covered blocks
// (glass/raster/triangle_block.h) go straight to the kernel, which interpolates only the
// varyings the key needs and does only the work the key says. Every kernel computes each value
// with the same operations in the same order as the reference path, so it writes the same bytes;
// the test fast_paths_match_reference renders every image test program both ways and compares.
//
// GLASS_FAST_PATHS=0 in the environment switches the kernels off (the reference path draws
// everything), for that test and for anyone who suspects a kernel.
#pragma once

#include <cstdint>

#include "fragment/blend_rows.h"
#include "fragment/blending.h"
#include "fragment/kernel_texture.h"
#include "fragment/stencil_depth_tests.h"
#include "glass/raster/triangle_block.h"

namespace glass::gl {

struct Context;
struct FogState;

// What the texturing stage does for a kernel.
enum class KernelTexturing : uint8_t {
  None,      // no texturing: the colour is the interpolated primary colour
  Single2D,  // texture_hooks.h's singleTexture2D: one 2D texture on unit 0, any filter, any
             // environment but GL_COMBINE
};

// What weighs the fragments' alpha: nothing (a filled triangle), or the coverage of the
// antialiased line or point whose triangle the block belongs to (primitive/smooth_coverage.h),
// read from the triangle's payload (raster::TriangleSetup::payload). A point's fragments outside
// its disc are dropped before any test.
enum class KernelCoverage : uint8_t { None, SmoothLine, SmoothPoint };
inline constexpr int kKernelCoverageCount = 3;

// The state a kernel is compiled for. Kernels exist only for draws whose fragments need no
// per-fragment lighting, colour sum, alpha test or logic op, and write either all four colour
// channels or none; FragmentProcessor::prepare checks that.
struct BlockKernelKey {
  bool writeDepth = false;  // store the walk's depths (without the stencil test; see below)
  bool writeColor = false;
  KernelTexturing texturing = KernelTexturing::None;
  bool fog = false;  // fog_hooks.h's applyFog after texturing
  KernelCoverage coverage = KernelCoverage::None;  // after fog, as the reference path does
};

// What a kernel does with the pixels it shades, decided once per draw and read at run time
// (one test per block or row: the work they select is per pixel anyway).
//
// Without the stencil test, the depth test, when on, is the triangle walk's early test
// (glass/raster/depth_test.h), so a kernel sees only fragments that passed it and writes their
// depth when the key says so. With the stencil test on, a fragment that fails the depth test may
// still change the stencil buffer, so the walk makes no early test; the kernel then runs the
// stencil and depth tests and their writes on each covered pixel itself (stencil_depth_tests.h,
// the reference path's own function) and shades the pixels that pass.
struct KernelPixelOps {
  StencilDepthSettings tests;  // the kernel runs them when tests.stencilTest is on
  bool blend = false;  // blend with the colour buffer (blending.h) instead of replacing it
  BlendSettings blendSettings;
  BlendRow blendRow = nullptr;  // blendRowFor(blendSettings), when blending
  // ORed into every colour word stored, blended or not (storedAlphaWord, core/ancillary_buffers.h):
  // alpha 255 in a colour buffer without alpha bitplanes, 0 otherwise.
  uint32_t storedAlpha = 0;

  bool operator==(const KernelPixelOps&) const = default;
};

// Shades and writes the pixels of one covered block of a triangle (`texture` is read by the
// kernels that texture, `fog` by those that fog).
using BlockKernel = void (*)(Context& ctx, const KernelPixelOps& ops, const KernelTexture& texture, const FogState& fog,
                             const raster::TriangleSetup& setup, const raster::CoveredBlock& block);

// The kernel compiled for the key.
BlockKernel blockKernelFor(const BlockKernelKey& key);

}  // namespace glass::gl
