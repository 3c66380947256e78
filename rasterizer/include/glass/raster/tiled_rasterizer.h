// Deferred rasterization in screen tiles, on several threads, with the same bytes as one thread.
//
// Primitives are not rasterized when they are submitted. Each is stored once in a "scene" and
// its index is appended to the bin of every 64 x 64 tile of the window it may touch, in
// submission order. When the scene is full, or finish() is called, the tiles are handed to a
// pool of threads: a tile is owned by one thread at a time, which runs the tile's bin in order,
// rasterizing each primitive clipped to the tile. So every pixel receives its fragments in
// submission order, whatever the number of threads, and the framebuffer ends byte for byte as
// if one thread had drawn everything in order. (The idea is Mesa llvmpipe's; the code is glass's.)
//
// Why clipping to a tile changes nothing: triangle coverage evaluates the edges and every
// attribute directly from their planes at the pixel centre (triangle_rasterize.cpp), so a pixel
// gets the same fragment whichever block of the walk holds it, and a tile's edges are multiples
// of 64 (even), so the 2x2 quads of texture level of detail stay whole in it: a tile sees exactly
// the fragments the whole triangle would give it. Lines and points are rasterized for each
// tile they touch, with the tile as their bounds: their fragments are computed from the primitive
// alone (the stipple counter runs outside the bounds too), and the bounds only select them; a
// line walks only its runs inside the tile, each found by exact integer arithmetic from the
// segment's edges (rasterizer/src/line_quad_walk.h).
//
// glClear is queued the same way (clear()): a tile runs its part of the clear in bin order, so
// the clear is shared by the threads and each tile is cleared while it is in the cache of the
// thread that draws it next.
//
// Two scenes alternate: while the pool rasterizes one, the submitting thread fills the next.
// The next scene starts only when the previous one has finished, so the order per pixel holds
// across scenes too.
//
// With one thread (no workers) a triangle, line or point whose pixels lie within a tile's size
// each way is not binned: it is drawn when it is submitted, after the bins of the tiles it
// overlaps have run, so the order per pixel holds. Binning a small primitive costs more than the
// tiles' cache gains for it; large primitives and clears are still binned, and so are small
// triangles while most of the recent ones lie in another tile than the one before them
// (scattered over the window, each drawn at once would fetch its rows from memory).
//
// The sink of a primitive is called later (or at once, as above), from any of the threads, for
// different tiles at the same time: it must not change state of its own, and whatever it reads (GL state, textures)
// must stay unchanged until finish() returns. The framebuffer the sinks write must not be read
// or written by anything else until then.
#pragma once

#include <memory>

#include "glass/raster/fragment.h"
#include "glass/raster/framebuffer.h"
#include "glass/raster/framebuffer_clear.h"
#include "glass/raster/line.h"
#include "glass/raster/triangle.h"

namespace glass::raster {

inline constexpr int kTileSize = 64;

class TiledRasterizer {
 public:
  // Tiles cover the framebuffer the sinks write (read here only to bring a tile's rows into the
  // cache before its bin runs). threadCount >= 1 threads rasterize tiles: the thread that calls
  // finish() and threadCount - 1 workers. With one thread there are no workers: the submitting
  // thread rasterizes a scene when it is full and at finish().
  TiledRasterizer(const Framebuffer& framebuffer, int threadCount);
  ~TiledRasterizer();  // finishes the queued work, then stops the workers
  TiledRasterizer(const TiledRasterizer&) = delete;
  TiledRasterizer& operator=(const TiledRasterizer&) = delete;

  int threadCount() const;

  // Queue a primitive (copied; the vertices and settings may change after the call). A triangle
  // is drawn as setupTriangle(a, b, c, settings) and rasterizeTriangle would draw it (nothing when
  // setupTriangle refuses it); each tile it touches sets it up when it runs. With one thread a
  // small primitive is drawn before the call returns (see above).
  void triangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                const TriangleSettings& settings, FragmentSink& sink);
  // A convex quadrilateral v0 v1 v2 v3 whose values are one plane (an antialiased line's or
  // point's rectangle): drawn as setupQuad and rasterizeTriangle would draw it, in one pass, when
  // quadIsConvex accepts it; otherwise as the triangles (v0, v1, v2) and (v2, v3, v0). It is
  // always binned (a thin, blended shape reads and writes pixels the tile keeps in the cache).
  void quad(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const WindowVertex& v3,
            const TriangleSettings& settings, FragmentSink& sink);
  // settings.stippleCounter, when set, is advanced now, as rasterizeLine would advance it.
  void line(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
            FragmentSink& sink);
  void point(const WindowVertex& v, const PointSettings& settings, FragmentSink& sink);
  // Queue a clear of request.rect (copied). Each tile runs its part in order with the primitives:
  // the clear is spread over the threads like the drawing, and a tile is cleared just before it
  // is drawn, while it is in the drawing thread's cache.
  void clear(const ClearRequest& request);

  // True when nothing is queued or being rasterized.
  bool idle() const;
  // True when a queued or running triangle, line or point may still call its sink; clears call
  // none, so a sink may be changed while only clears are queued.
  bool primitivesQueued() const;
  // Rasterizes everything queued; returns when every fragment has reached its sink.
  void finish();
  // Returns when no thread is rasterizing: the scene handed to the threads has finished, and
  // what is queued since stays queued. For a change of state that the queued primitives' sinks
  // read but whose old and new values give them the same results (so they need not be drawn
  // first), which must still not be written while another thread reads it.
  void waitForThreads();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace glass::raster
