#include "tile_scene.h"

#include <algorithm>
#include <cmath>

#include "edge_functions.h"
#include "line_section.h"
#include "glass/raster/tiled_rasterizer.h"
#include "subpixel.h"

namespace glass::raster {
namespace {

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// The pixels a point may touch lie within `reach` pixels of its window position: half the
// (rounded) size, plus a margin for the snapping to 1/256 pixel. Being generous only costs a bin
// entry that draws nothing. (Lines are binned by their quad's pixels, lineQuadPixels.)
double reachOf(float size) { return std::ceil(std::max(1.0f, size)) * 0.5 + 2.0; }

// floor(v), clamped to +-2^31 so that it is defined for every double: converting NaN, an infinity
// or a value beyond int64_t's range is undefined behaviour. NaN gives the low end. The callers
// clamp the result to the framebuffer, far inside this range.
int64_t floorToPixel(double v) {
  constexpr double kFar = 2147483648.0;  // 2^31
  if (!(v > -kFar)) return -static_cast<int64_t>(kFar);
  if (!(v < kFar)) return static_cast<int64_t>(kFar);
  return static_cast<int64_t>(std::floor(v));
}

WindowVertex rebuildVertex(const float position[4], const float* varyings, int count) {
  WindowVertex v;
  v.x = position[0];
  v.y = position[1];
  v.z = position[2];
  v.invW = position[3];
  std::copy(varyings, varyings + count, v.varyings);
  return v;
}

// The pixels [x0, x1) x [y0, y1) of `bounds` within `reach` pixels of the window positions
// from (x0, y0) to (x1, y1); empty when there are none.
PixelRect reachRect(double x0, double y0, double x1, double y1, double reach, const PixelRect& bounds) {
  const int64_t left = std::max<int64_t>(floorToPixel(x0 - reach), bounds.x0);
  const int64_t bottom = std::max<int64_t>(floorToPixel(y0 - reach), bounds.y0);
  const int64_t right = std::min<int64_t>(floorToPixel(x1 + reach) + 1, bounds.x1);
  const int64_t top = std::min<int64_t>(floorToPixel(y1 + reach) + 1, bounds.y1);
  if (left >= right || bottom >= top) return PixelRect{};
  return PixelRect{static_cast<int>(left), static_cast<int>(bottom), static_cast<int>(right), static_cast<int>(top)};
}

}  // namespace

PixelRect TileScene::pointReach(const WindowVertex& v, const PointSettings& settings) {
  return reachRect(v.x, v.y, v.x, v.y, reachOf(settings.size), settings.bounds);
}

void TileScene::Bin::reset() {
  order.reset();
  triangles.reset();
  quads.reset();
  lines.reset();
  points.reset();
  clears.reset();
  varyings.reset();
}

TileScene::TileScene(int width, int height)
    : width_(width),
      height_(height),
      tilesX_((width + kTileSize - 1) / kTileSize),
      tilesY_((height + kTileSize - 1) / kTileSize),
      arena_(std::make_unique<BinArena>()),
      bins_(static_cast<size_t>(tilesX_) * static_cast<size_t>(tilesY_)) {}

PixelRect TileScene::tileRect(int tile) const {
  const int x0 = (tile % tilesX_) * kTileSize, y0 = (tile / tilesX_) * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, width_), std::min(y0 + kTileSize, height_)};
}

TileScene::Bin& TileScene::binOf(int tile) {
  Bin& bin = bins_[static_cast<size_t>(tile)];
  if (bin.empty()) activeTiles_.push_back(tile);
  return bin;
}

template <typename AddToBin>
void TileScene::forTilesIn(int64_t x0, int64_t y0, int64_t x1, int64_t y1, AddToBin add) {
  x0 = std::max<int64_t>(x0, 0);
  y0 = std::max<int64_t>(y0, 0);
  x1 = std::min<int64_t>(x1, width_ - 1);
  y1 = std::min<int64_t>(y1, height_ - 1);
  if (x0 > x1 || y0 > y1) return;
  for (int64_t ty = y0 / kTileSize; ty <= y1 / kTileSize; ++ty)
    for (int64_t tx = x0 / kTileSize; tx <= x1 / kTileSize; ++tx)
      add(binOf(static_cast<int>(ty * tilesX_ + tx)));
}

const TriangleSettings& TileScene::drawSettingsFor(const TriangleSettings& settings) {
  const int varyingCount = std::clamp(settings.varyingCount, 0, kMaxVaryings);
  const int payloadCount = settings.payload != nullptr ? std::clamp(settings.payloadCount, 0, kMaxTrianglePayload) : 0;
  const TriangleSettings* last = lastDrawSettings_;
  if (last != nullptr && last->bounds.x0 == settings.bounds.x0 && last->bounds.y0 == settings.bounds.y0 &&
      last->bounds.x1 == settings.bounds.x1 && last->bounds.y1 == settings.bounds.y1 &&
      last->varyingCount == varyingCount && last->perspectiveCorrect == settings.perspectiveCorrect &&
      last->earlyDepth.buffer == settings.earlyDepth.buffer && last->earlyDepth.compare == settings.earlyDepth.compare &&
      last->depthUsed == settings.depthUsed && last->payloadCount == payloadCount)
    return *last;
  auto* stored = static_cast<TriangleSettings*>(arena_->allocate(sizeof(TriangleSettings)));
  *stored = settings;
  stored->varyingCount = varyingCount;
  stored->payloadCount = payloadCount;
  stored->payload = nullptr;  // runBin points it at the bin's copy
  bytes_ += sizeof(TriangleSettings);
  lastDrawSettings_ = stored;
  return *stored;
}

int TileScene::onlyTileOf(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                          const PixelRect& bounds) const {
  for (const WindowVertex* v : {&a, &b, &c})
    if (!isRasterizableCoordinate(v->x) || !isRasterizableCoordinate(v->y)) return kNoOneTile;
  // The pixels whose centres the snapped corners can reach: pixel i is covered only when its
  // centre i + 0.5 lies within the snapped corners' range, and snapping moves a corner by 1/512
  // of a pixel at most, so from floor(min - 0.5 - 1/256) to floor(max - 0.5 + 1/256) (a little
  // more than it takes). The sums are exact in double (the coordinates are within 2^19, with
  // float's 24 bits), so the truncation of the sum with 2^20 is the floor.
  const auto floorOf = [](float v, double offset) {
    return static_cast<int>(static_cast<double>(v) + offset + double(1 << 20)) - (1 << 20);
  };
  constexpr double kLow = -0.5 - 1.0 / 256.0, kHigh = -0.5 + 1.0 / 256.0;
  const int x0 = std::max(bounds.x0, floorOf(std::min(std::min(a.x, b.x), c.x), kLow));
  const int y0 = std::max(bounds.y0, floorOf(std::min(std::min(a.y, b.y), c.y), kLow));
  const int x1 = std::min(bounds.x1 - 1, floorOf(std::max(std::max(a.x, b.x), c.x), kHigh));
  const int y1 = std::min(bounds.y1 - 1, floorOf(std::max(std::max(a.y, b.y), c.y), kHigh));
  if (x0 > x1 || y0 > y1) return kNoTile;
  // Here 0 <= x0 <= x1 and 0 <= y0 <= y1 (the bounds lie in the window).
  const unsigned tileX = static_cast<unsigned>(x0) / kTileSize, tileY = static_cast<unsigned>(y0) / kTileSize;
  if (tileX != static_cast<unsigned>(x1) / kTileSize || tileY != static_cast<unsigned>(y1) / kTileSize)
    return kNoOneTile;
  return static_cast<int>(tileY) * tilesX_ + static_cast<int>(tileX);
}

void TileScene::addTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                            const TriangleSettings& settings, FragmentSink& sink) {
  // A triangle whose pixels can only be in one tile goes to that tile's bin without being set
  // up here at all (most triangles of a mesh): the tile sets it up in full when it runs, and
  // finds there whether it covers anything (if it has no area, or its pixels are all outside
  // the bounds, it draws nothing there as it would draw nothing here).
  const int tile = onlyTileOf(a, b, c, settings.bounds);
  if (tile == kNoTile) return;
  if (tile != kNoOneTile) {
    return addPolygon<3>({&a, &b, &c}, settings, sink, [&](auto addToBin) { addToBin(tile); });
  }
  TriangleSetup edges;  // the edge functions and the box alone
  if (!setupTriangleEdges(a, b, c, settings.bounds, edges)) return;
  addPolygon<3>({&a, &b, &c}, settings, sink, [&](auto addToBin) { forTilesReached<3>(edges, addToBin); });
}

void TileScene::addQuad(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                        const WindowVertex& v3, const TriangleSetup& edges, const TriangleSettings& settings,
                        FragmentSink& sink) {
  addPolygon<4>({&v0, &v1, &v2, &v3}, settings, sink, [&](auto addToBin) { forTilesReached<4>(edges, addToBin); });
}

template <int kCorners, typename AddToBin>
void TileScene::forTilesReached(const TriangleSetup& edges, AddToBin addToBin) const {
  const PixelRect& box = edges.box;
  const int firstTileX = box.x0 / kTileSize, lastTileX = (box.x1 - 1) / kTileSize;
  const int firstTileY = box.y0 / kTileSize, lastTileY = (box.y1 - 1) / kTileSize;
  // A box within one tile goes to that tile's bin as it is.
  if (firstTileX == lastTileX && firstTileY == lastTileY) return addToBin(firstTileY * tilesX_ + firstTileX);
  // Otherwise to the tiles its box overlaps, except those no pixel centre of which is inside:
  // the coverage walk would reject every block of such a tile anyway. This matters for large
  // triangles, whose box holds many tiles the triangle misses.
  const PixelEdgeFunctions<kCorners> edgeFunctions(edges);
  for (int ty = firstTileY; ty <= lastTileY; ++ty)
    for (int tx = firstTileX; tx <= lastTileX; ++tx)
      if (!edgeFunctions.rejects(tx * kTileSize, ty * kTileSize, kTileSize, kTileSize)) addToBin(ty * tilesX_ + tx);
}

template <int kCorners, typename ForTiles>
void TileScene::addPolygon(const WindowVertex* const (&corners)[kCorners], const TriangleSettings& settings,
                           FragmentSink& sink, ForTiles forTiles) {
  hasPrimitives_ = true;
  PolygonRecord<kCorners> r;
  r.sink = &sink;
  for (int i = 0; i < kCorners; ++i) {
    const WindowVertex& v = *corners[i];
    const float position[4] = {v.x, v.y, v.z, v.invW};
    std::copy(position, position + 4, r.position[i]);
  }
  r.drawSettings = &drawSettingsFor(settings);
  r.depthBias = settings.depthBias;
  r.frontFacing = settings.frontFacing;
  const size_t n = static_cast<size_t>(r.drawSettings->varyingCount);
  const size_t payload = static_cast<size_t>(r.drawSettings->payloadCount);

  const auto addToBin = [&](int tile) {
    Bin& bin = binOf(tile);
    bin.order.push(*arena_, kCorners == 3 ? Kind::Triangle : Kind::Quad);
    auto& records = recordsOf<kCorners>(bin);
    records.push(*arena_, r);
    // The corners' varyings in one run, then the payload, as runTile takes them.
    float* varyings = bin.varyings.extend(*arena_, kCorners * n + payload);
    for (int i = 0; i < kCorners; ++i) std::copy(corners[i]->varyings, corners[i]->varyings + n, varyings + i * n);
    std::copy(settings.payload, settings.payload + payload, varyings + kCorners * n);
    // A new record lands on cache lines nobody has touched yet, and with hundreds of bins filled
    // in turn each write would otherwise wait for its line; by the time the bin's next
    // primitive arrives, the lines are there.
    records.prefetchNext(1);
    bin.varyings.prefetchNext(kCorners * n + payload);
    bytes_ += 1 + sizeof r + sizeof(float) * (kCorners * n + payload);
  };
  forTiles(addToBin);
}

void TileScene::addLine(const LineQuad& quad, const PixelRect& pixels, const WindowVertex& a,
                        const WindowVertex& b, const LineSettings& settings, int stippleStart,
                        FragmentSink& sink) {
  hasPrimitives_ = true;
  const int n = std::clamp(settings.varyingCount, 0, kMaxVaryings);
  forTilesIn(pixels.x0, pixels.y0, int64_t{pixels.x1} - 1, int64_t{pixels.y1} - 1,
             [&](Bin& bin) {
               bin.order.push(*arena_, Kind::Line);
               // Written in place, field by field: a record made on the stack and copied into
               // each bin was read back with wide loads right after its narrow stores, and each
               // such load waited for the stores to drain (a store-forwarding stall per bin).
               LineRecord& r = *bin.lines.extend(*arena_, 1);
               r.sink = &sink;
               r.a[0] = a.x, r.a[1] = a.y, r.a[2] = a.z, r.a[3] = a.invW;
               r.b[0] = b.x, r.b[1] = b.y, r.b[2] = b.z, r.b[3] = b.invW;
               r.settings = settings;
               r.settings.varyingCount = n;
               r.settings.stippleCounter = nullptr;
               r.stippleStart = stippleStart;
               r.quad = quad;
               // Both vertices' varyings in one run, as runTile takes them.
               float* varyings = bin.varyings.extend(*arena_, 2 * static_cast<size_t>(n));
               std::copy(a.varyings, a.varyings + n, varyings);
               std::copy(b.varyings, b.varyings + n, varyings + n);
               bytes_ += 1 + sizeof(LineRecord) + 2 * sizeof(float) * static_cast<size_t>(n);
             });
}

void TileScene::addPoint(const WindowVertex& v, const PointSettings& settings, FragmentSink& sink) {
  if (!isRasterizableCoordinate(v.x) || !isRasterizableCoordinate(v.y)) return;  // as rasterizePoint
  hasPrimitives_ = true;
  PointRecord r;
  r.sink = &sink;
  const float position[4] = {v.x, v.y, v.z, v.invW};
  std::copy(position, position + 4, r.v);
  r.settings = settings;
  r.settings.varyingCount = std::clamp(settings.varyingCount, 0, kMaxVaryings);
  const int n = r.settings.varyingCount;

  const PixelRect reach = pointReach(v, settings);
  forTilesIn(reach.x0, reach.y0, int64_t{reach.x1} - 1, int64_t{reach.y1} - 1, [&](Bin& bin) {
               bin.order.push(*arena_, Kind::Point);
               bin.points.push(*arena_, r);
               bin.varyings.append(*arena_, v.varyings, static_cast<size_t>(n));
               bytes_ += 1 + sizeof(PointRecord) + sizeof(float) * static_cast<size_t>(n);
             });
}

void TileScene::addClear(const ClearRequest& request) {
  if (!request.clearsSomething()) return;
  const PixelRect& rect = request.rect;
  forTilesIn(rect.x0, rect.y0, int64_t{rect.x1} - 1, int64_t{rect.y1} - 1, [&](Bin& bin) {
    bin.order.push(*arena_, Kind::Clear);
    bin.clears.push(*arena_, request);
    bytes_ += 1 + sizeof(ClearRequest);
  });
}

void TileScene::orderActiveTilesByPlace() { std::sort(activeTiles_.begin(), activeTiles_.end()); }

int TileScene::firstActiveTileFrom(int numerator, int denominator) const {
  const int64_t tileCount = int64_t{tilesX_} * tilesY_;
  const int first = static_cast<int>(tileCount * numerator / denominator);
  return static_cast<int>(std::lower_bound(activeTiles_.begin(), activeTiles_.end(), first) -
                          activeTiles_.begin());
}

void TileScene::runTile(int activeIndex) const { runBin(activeTiles_[static_cast<size_t>(activeIndex)]); }

void TileScene::runTileNow(int tile) {
  Bin& bin = bins_[static_cast<size_t>(tile)];
  if (bin.empty()) return;
  runBin(tile);
  bin.reset();
  activeTiles_.erase(std::find(activeTiles_.begin(), activeTiles_.end(), tile));
  // With no tile left, nothing is queued: the scene starts afresh, as after the last tile of a
  // launch (hasPrimitives() false again, so that a draw with other fragment settings may begin).
  if (activeTiles_.empty()) clear();
}

template <int kCorners>
void TileScene::runPolygon(const PolygonRecord<kCorners>& r, BinList<float>::Reader& varyingRuns, const PixelRect& rect,
                           const Bin& bin) const {
  TriangleSettings settings = *r.drawSettings;
  settings.depthBias = r.depthBias;
  settings.frontFacing = r.frontFacing;
  const int n = settings.varyingCount;
  const float* varyings =
      varyingRuns.take(kCorners * static_cast<size_t>(n) + static_cast<size_t>(settings.payloadCount));
  WindowVertex v[kCorners];
  for (int i = 0; i < kCorners; ++i) v[i] = rebuildVertex(r.position[i], varyings + i * n, n);
  settings.bounds = intersect(settings.bounds, rect);
  if (settings.payloadCount > 0) settings.payload = varyings + kCorners * n;
  // The same setup as the whole polygon's, its box cut to the tile (the edges and planes depend
  // on the vertices alone).
  TriangleSetup setup;
  if constexpr (kCorners == 3) {
    if (!setupTriangle(v[0], v[1], v[2], settings, setup)) return;
  } else {
    if (!setupQuad(v[0], v[1], v[2], v[3], settings, setup)) return;
  }
  setup.privateRect = rect;  // this thread owns the tile
  setup.hiddenBlockOdds = &bin.hiddenBlockOdds;
  rasterizeTriangle(setup, *r.sink);
}

void TileScene::runBin(int tile) const {
  const PixelRect rect = tileRect(tile);
  const Bin& bin = bins_[static_cast<size_t>(tile)];
  // Each list is read front to back; `order` says which list the next primitive comes from.
  BinList<Kind>::Reader order(bin.order);
  BinList<TriangleRecord>::Reader triangles(bin.triangles);
  BinList<QuadRecord>::Reader quads(bin.quads);
  BinList<LineRecord>::Reader lines(bin.lines);
  BinList<PointRecord>::Reader points(bin.points);
  BinList<ClearRequest>::Reader clears(bin.clears);
  BinList<float>::Reader varyingRuns(bin.varyings);
  for (size_t k = 0; k < bin.order.size(); ++k) {
    switch (*order.take(1)) {
      case Kind::Triangle:
        runPolygon(*triangles.take(1), varyingRuns, rect, bin);
        break;
      case Kind::Quad:
        runPolygon(*quads.take(1), varyingRuns, rect, bin);
        break;
      case Kind::Line: {
        const LineRecord& r = *lines.take(1);
        const int n = r.settings.varyingCount;
        const float* varyings = varyingRuns.take(2 * static_cast<size_t>(n));
        const WindowVertex a = rebuildVertex(r.a, varyings, n);
        const WindowVertex b = rebuildVertex(r.b, varyings + n, n);
        LineSettings settings = r.settings;
        settings.bounds = intersect(settings.bounds, rect);
        rasterizeLineSection(r.quad, a, b, settings, r.stippleStart, *r.sink);
        break;
      }
      case Kind::Point: {
        const PointRecord& r = *points.take(1);
        const int n = r.settings.varyingCount;
        const WindowVertex v = rebuildVertex(r.v, varyingRuns.take(static_cast<size_t>(n)), n);
        PointSettings settings = r.settings;
        settings.bounds = intersect(settings.bounds, rect);
        rasterizePoint(v, settings, *r.sink);
        break;
      }
      case Kind::Clear:
        clearFramebuffer(*clears.take(1), rect);
        break;
    }
  }
}

void TileScene::clear() {
  for (const int tile : activeTiles_) bins_[static_cast<size_t>(tile)].reset();
  arena_->reset();
  activeTiles_.clear();
  lastDrawSettings_ = nullptr;
  bytes_ = 0;
  hasPrimitives_ = false;
}

}  // namespace glass::raster
