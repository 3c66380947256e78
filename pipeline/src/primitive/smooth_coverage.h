// Antialiased points and lines (GL_POINT_SMOOTH, GL_LINE_SMOOTH; spec 3.3.2, 3.4.3): their
// footprint and the coverage each fragment carries into the fragment stage, where it multiplies
// the fragment's alpha (3.11), so that blending with GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA fades
// the edges.
//
// The specification leaves the exact coverage to the implementation. glass computes it as Mesa's
// llvmpipe does (Mesa 22.3, the gallium draw module's aaline and aapoint stages), so that pictures
// agree with Mesa's:
//
// Lines. A segment from p0 to p1 (length L, direction d, unit normal n) of width w is drawn as the
// rectangle p0 - d/2 .. p1 + d/2 along d and -h .. h along n, h = 1 for w <= 1 and w/2 + 1/2
// otherwise, split into two triangles along a diagonal and filled by the triangle rule (glass
// fills both at once, as a quadrilateral with the planes of the first: TiledRasterizer::quad). A fragment
// whose centre is at distance a from the segment's midpoint along d and at distance b from the
// segment's line has coverage, with l = L/2 + 1/2,
//   c = clamp(h - |b|, 0, 1) * clamp(l - |a|, 0, 1) * min(L / l, 1)
// which is 1 across the inner w - 1 pixels, falls linearly to 0 over one pixel at each side, and
// falls from 1/2 at an endpoint to 0 half a pixel beyond it. The last factor thins segments
// shorter than a pixel: Mesa's shader caps the along term at L, but llvmpipe's pictures show the
// along term scaled by L / l instead (measured on segments of length 0.05 to 1 at sub-pixel
// offsets: every value agrees to the 8-bit step), and glass follows the pictures. Attributes are
// those of p0 on the end edge past p0 and of p1 on the one past p1, interpolated across the
// rectangle as for any triangle.
//
// Points. A point of size s is the square of half-side r around it (r = 1 for s <= 2, s/2
// otherwise; r = s/2 when the size comes from the point parameters' attenuation), split into two
// triangles; fragments whose centre q lies farther than r from the point are discarded. Mesa's
// shader was meant to fade alpha over the outermost ring, with coverage (1 - d)/(1 - k) for
// d = |q|^2/r^2 beyond k = (1 - 1/r)^2 and 1 inside, but in Mesa 22.3's NIR version the selection
// is the wrong way round: the ring keeps coverage 1 and the inner disc gets (1 - d)/(1 - k) >= 1.
// For opaque colours the colour clamp makes that 1: llvmpipe draws round points with hard edges;
// a translucent point is more opaque towards its centre. glass computes the same values (the
// alpha clamp comes with the conversion to the framebuffer's 8 bits).
#pragma once

#include <type_traits>

#include "fragment/fragment_processor.h"
#include "glass/raster/fragment.h"
#include "glass/raster/triangle.h"
#include "glass/raster/vertex.h"

namespace glass::gl {

// What the coverage of a smooth line's fragment depends on; the floats its queued triangles
// carry to the fragment stage (raster::TriangleSettings::payload).
struct SmoothLineCoverage {
  static constexpr KernelCoverage kKernelCoverage = KernelCoverage::SmoothLine;
  float midX = 0, midY = 0;        // the segment's midpoint
  float dirX = 1, dirY = 0;        // unit direction p0 -> p1
  float halfWidth = 1;             // h
  float halfLength = 0.5f;         // l = L/2 + 1/2
  float length = 0;                // L

  // Coverage of the fragment whose centre is (x, y), in [0, 1].
  float coverage(float x, float y) const;
};

struct SmoothLineShape : SmoothLineCoverage {
  // The rectangle's corners, and their order round it (kBoundary[0] to [3]), which starts at a
  // corner of the diagonal Mesa splits it along: into triangles (0, 1, 2) and (3, 1, 0), which
  // are (kBoundary[0], [1], [2]) and ([2], [3], [0]) as TiledRasterizer::quad takes them.
  raster::WindowVertex corners[4];
  static constexpr int kBoundary[4] = {0, 2, 1, 3};
};

// Builds the rectangle of a smooth segment a -> b of the given width in window coordinates
// (varyingCount varyings copied); false for a segment of zero length, which draws nothing.
// framebufferHeight: Mesa builds the corners in rows numbered from the top, which decides the
// diagonal the rectangle is split along.
bool makeSmoothLine(const raster::WindowVertex& a, const raster::WindowVertex& b, float width,
                    int framebufferHeight, int varyingCount, SmoothLineShape& shape);

// What the coverage of a smooth point's fragment depends on (as SmoothLineCoverage).
struct SmoothPointCoverage {
  static constexpr KernelCoverage kKernelCoverage = KernelCoverage::SmoothPoint;
  float x = 0, y = 0;   // the point
  float radius = 1;     // r

  // Coverage of the fragment whose centre is (x, y): Mesa's value inside the disc of radius r
  // (1, or more towards the centre), a negative value outside it (the fragment is discarded).
  float coverage(float fx, float fy) const;
};

struct SmoothPointShape : SmoothPointCoverage {
  // The square's corners, and their order round it, as SmoothLineShape's: Mesa splits it into
  // triangles (0, 1, 2) and (0, 2, 3).
  raster::WindowVertex corners[4];
  static constexpr int kBoundary[4] = {0, 1, 2, 3};
};

// The half-side r of a smooth point of the given size: perVertexSize is true when the size comes
// from the point parameters' attenuation (then r = size/2 for every size).
float smoothPointRadius(float size, bool perVertexSize);

void makeSmoothPoint(const raster::WindowVertex& v, float radius, int framebufferHeight,
                     int varyingCount, SmoothPointShape& shape);

// A fragment sink between the triangle rasterizer and the fragment stage, one per draw for each
// kind of shape: it reads the shape's Coverage from the fragments' payload (each triangle of a
// smooth line or point carries its own), computes each fragment's coverage from its pixel
// centre, drops the fragments of negative coverage, and hands the rest on with their coverage.
// That is the reference path; a covered block goes instead to the fragment stage's block kernel
// for the state and the Coverage when there is one (block_kernels.h), which does the same.
template <class Coverage>
class CoverageFilter final : public raster::FragmentSink {
 public:
  // The payload a triangle carries: the Coverage's floats.
  static constexpr int kPayloadFloats = static_cast<int>(sizeof(Coverage) / sizeof(float));
  static_assert(std::is_trivially_copyable_v<Coverage> && sizeof(Coverage) % sizeof(float) == 0 &&
                kPayloadFloats <= raster::kMaxTrianglePayload);

  explicit CoverageFilter(FragmentProcessor& next) : next_(next) {}
  void processFragments(const raster::FragmentBatch& batch) override;
  void processTriangleBlock(const raster::TriangleSetup& setup, const raster::CoveredBlock& block) override;

 private:
  FragmentProcessor& next_;
};

extern template class CoverageFilter<SmoothLineCoverage>;
extern template class CoverageFilter<SmoothPointCoverage>;

}  // namespace glass::gl
