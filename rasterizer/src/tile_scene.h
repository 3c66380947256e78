// One scene of deferred rasterization (tiled_rasterizer.h): the primitives submitted since the
// previous scene, sorted into the bins of the 64 x 64 tiles of the window they may touch, each bin
// in submission order.
//
// A bin holds its own copy of each of its primitives, so that rasterizing a tile reads one bin
// front to back instead of gathering records from all over the scene: a small triangle touches
// one or two tiles, and reading its record from a cold, scattered place cost about as much as
// rasterizing it. Copies are compact: a primitive keeps its vertices with only as many varyings
// as it has, a triangle only the settings that change within a draw (the rest are kept once per
// draw in the scene), and runTile rebuilds the full vertices (and a triangle's setup) on its stack. The lists' memory comes from the scene's arena
// (bin_arena.h), which clear() takes back whole and keeps, so once the first frames have grown it,
// drawing allocates no memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "bin_arena.h"

#include "glass/raster/fragment.h"
#include "glass/raster/framebuffer_clear.h"
#include "glass/raster/line.h"
#include "glass/raster/triangle.h"
#include "glass/raster/tiled_rasterizer.h"
#include "hidden_block_odds.h"
#include "line_quad.h"

namespace glass::raster {

class TileScene {
 public:
  TileScene(int width, int height);

  // The triangle is set up here only as far as binning needs (its edges and box); each tile it
  // touches sets it up in full when it runs (setupTriangle), so that the planes' divisions are
  // shared by the threads instead of all falling to the submitting one.
  void addTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                   const TriangleSettings& settings, FragmentSink& sink);
  // A convex quadrilateral, binned and set up (setupQuad) likewise; `edges` are what
  // setupQuadEdges made of its corners (the caller has them: it decided by them that the corners
  // are a quadrilateral).
  void addQuad(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const WindowVertex& v3,
               const TriangleSetup& edges, const TriangleSettings& settings, FragmentSink& sink);
  // A line whose quad lineQuadOf made, to the bins of the tiles its pixels (lineQuadPixels) may
  // be in. stippleStart: the line stipple counter at the line's first fragment.
  void addLine(const LineQuad& quad, const PixelRect& pixels, const WindowVertex& a,
               const WindowVertex& b, const LineSettings& settings, int stippleStart,
               FragmentSink& sink);
  void addPoint(const WindowVertex& v, const PointSettings& settings, FragmentSink& sink);
  // The pixels of its bounds a point may touch (all that the bins it goes to cover between
  // them), generously: half its size and a margin for the snapping.
  static PixelRect pointReach(const WindowVertex& v, const PointSettings& settings);
  // A clear of the framebuffer (glClear), run in each tile of its rectangle in order with the
  // primitives, so that the tile is cleared while it is in the cache of the thread drawing it.
  void addClear(const ClearRequest& request);

  // The tiles with something in their bin; runTile(i) rasterizes the bin of the i-th of them.
  // Different tiles may run on different threads at the same time.
  int activeTileCount() const { return static_cast<int>(activeTiles_.size()); }
  void runTile(int activeIndex) const;
  PixelRect activeTileRect(int activeIndex) const {
    return tileRect(activeTiles_[static_cast<size_t>(activeIndex)]);
  }

  // Puts the active tiles in the order of their place in the window, row by row from the bottom
  // (the order of bins, not of the primitives' arrival), so that a share of the window is a run of
  // active indices: the threads share the tiles out by place (tiled_rasterizer.cpp).
  void orderActiveTilesByPlace();
  // After orderActiveTilesByPlace: the first active index whose tile comes at or after the given
  // fraction of the window's tiles in that order (activeTileCount() when none does).
  int firstActiveTileFrom(int numerator, int denominator) const;

  // The tile holding pixel (x, y) of the window, and its rectangle.
  int tileAt(int x, int y) const { return (y / kTileSize) * tilesX_ + x / kTileSize; }
  PixelRect tileRect(int tile) const;
  bool queuedIn(int tile) const { return !bins_[static_cast<size_t>(tile)].empty(); }
  // Rasterizes the tile's bin now, if it holds anything, and empties it (the tile is no longer
  // active): what is drawn in the tile next comes after everything queued in it.
  void runTileNow(int tile);
  // The tile's odds of hidden blocks, for a triangle drawn in it at once.
  HiddenBlockOdds& hiddenBlockOdds(int tile) const { return bins_[static_cast<size_t>(tile)].hiddenBlockOdds; }

  bool empty() const { return activeTiles_.empty(); }
  // Whether a triangle, line or point is queued (whose sink the tiles will call), not only clears.
  bool hasPrimitives() const { return hasPrimitives_; }
  size_t bytes() const { return bytes_; }  // about how much memory the queued primitives hold
  void clear();

 private:
  // A triangle (or quadrilateral) as it was given, for setupTriangle (setupQuad): its vertices
  // without their varyings, which follow in the bin's varyings (a's, b's, c's), and its settings:
  // those of its draw, kept once in the scene (drawSettings), and the two that change from
  // triangle to triangle of a draw. (A full copy of the settings in every record made a
  // triangle's record 136 bytes instead of 80.)
  template <int kCorners>
  struct PolygonRecord {
    FragmentSink* sink;
    float position[kCorners][4];  // x, y, z, invW of each corner
    const TriangleSettings* drawSettings;  // its frontFacing and depthBias are not used
    double depthBias;
    bool frontFacing;
  };
  using TriangleRecord = PolygonRecord<3>;
  using QuadRecord = PolygonRecord<4>;
  // A line's vertices without their varyings, which follow in the bin's varyings (a's, b's),
  // and its quad, made once when it was submitted rather than in every tile it reaches.
  struct LineRecord {
    FragmentSink* sink;
    float a[4], b[4];  // x, y, z, invW
    LineSettings settings;
    int stippleStart;
    LineQuad quad;
  };
  struct PointRecord {
    FragmentSink* sink;
    float v[4];
    PointSettings settings;
  };
  enum class Kind : uint8_t { Triangle, Quad, Line, Point, Clear };

  struct Bin {
    BinList<Kind> order;  // which list the next primitive comes from
    BinList<TriangleRecord> triangles;
    BinList<QuadRecord> quads;
    BinList<LineRecord> lines;
    BinList<PointRecord> points;
    BinList<ClearRequest> clears;
    BinList<float> varyings;  // the varyings of each primitive's vertices, in order
    // The tile's odds of hidden blocks, kept from scene to scene (runTile changes them).
    mutable HiddenBlockOdds hiddenBlockOdds;
    bool empty() const { return order.empty(); }
    void reset();
  };

  Bin& binOf(int tile);
  // Calls add(bin) for the bin of every tile the inclusive pixel range may touch.
  template <typename AddToBin>
  void forTilesIn(int64_t x0, int64_t y0, int64_t x1, int64_t y1, AddToBin add);
  void runBin(int tile) const;
  // Sets up and rasterizes a triangle's or quadrilateral's record in the tile `rect` of `bin`,
  // its varyings (and payload) taken from varyingRuns.
  template <int kCorners>
  void runPolygon(const PolygonRecord<kCorners>& r, BinList<float>::Reader& varyingRuns, const PixelRect& rect,
                  const Bin& bin) const;
  // addTriangle and addQuad: a record of the corners to the bin of every tile forTiles names
  // (forTiles(addToBin) calls addToBin(tile) for each).
  template <int kCorners, typename ForTiles>
  void addPolygon(const WindowVertex* const (&corners)[kCorners], const TriangleSettings& settings,
                  FragmentSink& sink, ForTiles forTiles);
  // Calls addToBin(tile) for the tiles a polygon of kCorners corners' box overlaps (the edges and
  // box setupTriangleEdges or setupQuadEdges made), but those no pixel centre of which is inside.
  template <int kCorners, typename AddToBin>
  void forTilesReached(const TriangleSetup& edges, AddToBin addToBin) const;
  // The one tile whose pixels a triangle's corners can reach, found from their coordinates
  // before any snapping; kNoTile when they reach no pixel of the bounds, kNoOneTile when they may
  // reach more than one tile (or cannot be rasterized: setup decides what they draw).
  static constexpr int kNoTile = -1, kNoOneTile = -2;
  int onlyTileOf(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, const PixelRect& bounds) const;
  template <int kCorners>
  BinList<PolygonRecord<kCorners>>& recordsOf(Bin& bin) {
    if constexpr (kCorners == 3) return bin.triangles; else return bin.quads;
  }
  // The scene's copy of a triangle's settings but frontFacing and depthBias (which its record
  // keeps), the payload's place left out: the last one stored when it matches, else a new one.
  const TriangleSettings& drawSettingsFor(const TriangleSettings& settings);

  int width_, height_, tilesX_, tilesY_;
  std::unique_ptr<BinArena> arena_;  // the memory of the bins' lists
  std::vector<Bin> bins_;
  std::vector<int> activeTiles_;
  const TriangleSettings* lastDrawSettings_ = nullptr;  // in the arena; null after clear()
  size_t bytes_ = 0;
  bool hasPrimitives_ = false;
};

}  // namespace glass::raster
