// The per-fragment stage (spec chapter 4.1): receives the rasterizer's fragments and applies, in
// the specification's order,
//   per-fragment lighting (GL_PHONG_WIN), texturing, colour sum, fog    (chapter 3.8-3.10)
//   antialiasing coverage times alpha (3.11; smooth points and lines)
//   scissor test      (done by the rasterizer's bounds)
//   alpha test, stencil test, depth test (and the stencil and depth writes they imply)
//   blending or logic op, then the colour write masks.
// The state it reads cannot change between glBegin and glEnd, so prepare() captures it once per
// glBegin and the per-fragment loop only tests flags.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cstdint>
#include <optional>

#include "fragment/blending.h"
#include "fragment/fog_state.h"
#include "fragment/block_kernels.h"
#include "fragment/line_kernels.h"
#include "fragment/stencil_depth_tests.h"
#include "glass/raster/fragment.h"
#include "teaching/frame_statistics.h"
#include "teaching/teaching_view.h"

namespace glass::gl {

struct Context;

class FragmentProcessor final : public raster::FragmentSink {
 public:
  // phong: the vertex stage passes eye position and normal (GL_PHONG_WIN with lighting on).
  void prepare(Context& ctx, bool phong);
  // Called for different tiles from several threads at once (tiled_rasterizer.h): it changes
  // nothing but the framebuffer's pixels of the batch.
  void processFragments(const raster::FragmentBatch& batch) override;
  // The same for fragments of an antialiased primitive: coverage[i] (smooth_coverage.h)
  // multiplies the alpha of fragment i once its colour is final (spec 3.11, "Antialiasing
  // Application").
  void processFragments(const raster::FragmentBatch& batch, const float* coverage);
  // A covered block of a triangle: the kernel prepare() chose for the draw's state
  // (block_kernels.h), or the reference path when there is none.
  void processTriangleBlock(const raster::TriangleSetup& setup,
                            const raster::CoveredBlock& block) override;
  // The block by the kernel for the state and `coverage` (other than None: the triangle
  // belongs to an antialiased line or point whose shape is its payload, and the fragments are
  // weighed by it): true when a kernel shaded it; false when none covers the state, and then
  // nothing was done (the caller, processTriangleBlock or CoverageFilter, takes the reference
  // path).
  bool shadeBlock(const raster::TriangleSetup& setup, const raster::CoveredBlock& block,
                  KernelCoverage coverage);
  // Runs of a line segment: the line kernel prepare() chose for the draw's state
  // (line_kernels.h), or the reference path when there is none.
  void processLineRuns(const raster::LineRunBatch& batch) override;

  // Texturing and per-fragment lighting read their GL state from the context for each fragment,
  // not from a copy made by prepare(): while fragments of such a draw are queued, that state
  // must not change. (Fog reads the copy in its settings.)
  bool readsContextState() const { return s_.texturing || s_.phong; }
  // Whether every fragment's colour goes to its pixel as it comes (converted to bytes) and
  // nothing else happens: fast paths allowed, and no lighting, texturing, colour sum, fog, test,
  // blending, logic op or mask. glDrawPixels's fast path writes the bytes itself then.
  bool storesColorsAsGiven() const;
  // Per-fragment lighting reads the lights and materials of the context.
  bool readsLighting() const { return s_.phong; }
  // Whether two processors treat every fragment the same way.
  bool sameSettings(const FragmentProcessor& other) const {
    return ctx_ == other.ctx_ && s_ == other.s_ && std::ranges::equal(kernels_, other.kernels_) &&
           lineKernel_ == other.lineKernel_;
  }

 private:
  // Everything prepare() takes from the GL state.
  struct Settings {
    bool phong = false;
    bool bumpMapping = false;       // GL_GLASS_bump_map perturbs the normal before Phong lighting
    bool texturing = false;
    bool secondaryVarying = false;  // separate specular colour in varyings 4-7
    bool colorSum = false;          // lit with separate specular, or unlit with GL_COLOR_SUM
    bool fog = false;
    FogState fogState;  // the fog's parameters when fog is on (a copy: queued draws keep theirs)

    bool alphaTest = false;
    GLenum alphaFunc = GL_ALWAYS;
    uint8_t alphaRefByte = 0;  // the reference as the colour buffer's 8-bit value

    StencilDepthSettings tests;

    bool blend = false;
    BlendSettings blendSettings;
    BlendFunction blendFunction = &glass::gl::blend;  // blendFunctionFor(blendSettings), or blend()
    bool logicOp = false;
    GLenum logicOpMode = GL_COPY;
    bool colorMask[4] = {true, true, true, true};
    bool writesColor = true;        // some channel unmasked and glDrawBuffer not GL_NONE
    // Every stored channel written: all four unmasked, or red, green and blue in a colour buffer
    // without alpha bitplanes (whose alpha, always 255, a write of 255 leaves as it is).
    bool allChannels = true;
    uint32_t storedAlpha = 0;  // ORed into every pixel stored (storedAlphaWord, ancillary_buffers.h)
    // GL_FRONT_AND_BACK in a double-buffered framebuffer: each fragment is written into the
    // front buffer too (fragment/buffer_selection.h), by the per-fragment path only.
    bool bothBuffers = false;

    // GLASS_VIEW=overdraw (teaching/teaching_view.h): every fragment is counted on its pixel.
    std::uint16_t* fragmentCounts = nullptr;
    int fragmentCountsWidth = 0;
    // GLASS_VIEW=normals or mipmap: every fragment written paints its pixel of the view.
    std::uint8_t* fragmentColors = nullptr;
    int fragmentColorsWidth = 0;
    TeachingView fragmentColorsView = TeachingView::Normals;
    // GLASS_STATS (teaching/frame_statistics.h): the fragments of each test are counted, and the
    // scissor test is made here instead of by the rasterizer's bounds.
    FrameStatistics* statistics = nullptr;
    bool scissorTest = false;
    int scissorX0 = 0, scissorY0 = 0, scissorX1 = 0, scissorY1 = 0;  // [x0, x1) x [y0, y1)

    bool operator==(const Settings&) const = default;
  };

  // Whether any kernel may draw: fast paths are on, no teaching view or statistics watch the
  // fragments (they see them in the reference path, teaching/teaching_hooks.h) and the
  // fragments go to one colour buffer.
  bool kernelsAllowed() const;
  // Stores a fragment's final colour into one colour buffer's pixel.
  void writeColor(const float color[4], uint8_t* pixel) const;
  // The key of the block kernels for the settings (coverage None), or none when no kernel
  // covers them (block_kernels.h).
  std::optional<BlockKernelKey> kernelKey() const;
  // The fast path's kernel for line runs with the settings, or null (line_kernels.h).
  LineKernel chooseLineKernel() const;

  Context* ctx_ = nullptr;
  Settings s_;
  // The block kernels for each KernelCoverage (filled triangles, smooth lines, smooth points).
  BlockKernel kernels_[kKernelCoverageCount] = {};
  LineKernel lineKernel_ = nullptr;
  KernelPixelOps pixelOps_;  // what kernels_ do with the pixels they shade, from s_
  KernelTexture kernelTexture_;  // the texture of a kernel that textures
  // The kernel relies on the triangle walk's early depth test (the depth test is on and not
  // GL_ALWAYS); a triangle set up without it goes the reference way.
  bool kernelNeedsEarlyDepth_ = false;
};

}  // namespace glass::gl
