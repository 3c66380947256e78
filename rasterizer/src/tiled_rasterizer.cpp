// The scheduling of tiled_rasterizer.h: two scenes, one being filled by the submitting thread and
// one being rasterized, and a pool of workers that take the tiles of the scene in flight one at a
// time.
//
// A scene in flight is shared by the threads by place: the window's tiles, row by row, are cut into
// one run per thread (the thread that submits is thread 0), each run with an atomic counter of its
// next unclaimed tile. A thread takes the tiles of its own run with fetch_add, then helps with the
// others' runs the same way; a tile is claimed once, so it is never run by two threads, and its
// primitives run in bin order. Running its own run first, a thread draws the same part of the
// window frame after frame, and finds its tiles' pixels still in its own caches: when every tile
// went to whichever thread was free, the pixels moved between the cores' caches every frame, and
// two threads needed 1.4 times the processor time of one for the same large triangles (21 ms a
// frame against 24 ms on one thread; 14 ms by place). The mutex and condition variables only hand
// scenes over and wait for them: a worker registers as a user of the scene under the mutex and
// deregisters under it when no tile is left, so when the submitting thread sees, under the mutex,
// every tile claimed and no user left, every tile has finished, and everything the workers wrote
// (the framebuffer) happens-before what the submitting thread does next.
#include "glass/raster/tiled_rasterizer.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "line_section.h"
#include "tile_scene.h"

namespace glass::raster {
namespace {

// A scene is handed to the threads when its primitives take this much memory. Smaller scenes let
// the workers start sooner (they rasterize one scene while the next is binned) and stay in the
// cache; larger ones visit every tile of the framebuffer fewer times.
constexpr size_t kSceneBudgetBytes = size_t{32} << 20;

// With workers, a scene is handed over sooner, once it holds this much, whenever the workers have
// nothing left to do: when binning is the slower half (many small lit triangles), the workers
// then rasterize while the submitting thread goes on binning instead of waiting for the whole
// budget (often the whole frame) to fill. When rasterizing is the slower half, the workers are
// never idle and the scenes grow to the budget as before.
constexpr size_t kIdleLaunchBytes = size_t{1} << 20;

// A scene of at most this many active tiles and bytes is rasterized by the submitting thread
// itself, as with one thread: handing it to the workers (a lock, a wake-up, a wait) costs more
// than its tiles take. Drawing that is finished after every glEnd (a textured draw is finished
// there, docs/pipeline.md) hands over a scene of a tile or two per draw: 2,000 small textured
// quads, each in its own glBegin/glEnd, took about 45 ms a frame on 2 threads against 28 on one.
// (The bytes keep a scene of many primitives in a few tiles, which the workers can rasterize
// while the submitting thread goes on binning, with the workers.)
constexpr int kSubmitterTiles = 4;
constexpr size_t kSubmitterBytes = size_t{64} << 10;

// With one thread, a primitive whose pixels lie within this many each way is drawn when it is
// submitted rather than binned (Impl::drawsAtOnce).
constexpr int kAtOnceSize = kTileSize;

// Before a tile's bin runs, asks the memory system for the tile's depth and colour rows all at
// once. Otherwise the first fragments to reach each cache line of the tile wait for it one line
// at a time, which for scattered small primitives costs more than shading them. (A hint only:
// it changes no value.)
void prefetchTile(const Framebuffer& fb, const PixelRect& tile) {
  constexpr int kLineBytes = 64;
  const int rowBytes = (tile.x1 - tile.x0) * 4;  // 4 bytes per pixel in both buffers
  for (int y = tile.y0; y < tile.y1; ++y) {
    const char* depth = reinterpret_cast<const char*>(fb.depthAt(tile.x0, y));
    const char* color = reinterpret_cast<const char*>(fb.colorAt(tile.x0, y));
    for (int offset = 0; offset < rowBytes; offset += kLineBytes) {
      __builtin_prefetch(depth + offset, 1);
      __builtin_prefetch(color + offset, 1);
    }
  }
}

// A sink for the stipple counter's dry run: the line is walked for its counter only.
class DiscardingSink final : public FragmentSink {
 public:
  void processFragments(const FragmentBatch&) override {}
};

}  // namespace

struct TiledRasterizer::Impl {
  // One thread's share of the scene in flight: active tiles [next, end), next claimed with
  // fetch_add. On a cache line of its own, since other threads claim from it too.
  struct alignas(64) Run {
    std::atomic<int> next{0};
    int end = 0;
  };
  struct Flight {
    TileScene* scene = nullptr;
    std::vector<Run> runs;  // one per thread, set under the mutex when the scene is handed over
    int users = 0;  // workers currently taking tiles from it (guarded by mutex)
    // Set when the last worker leaves it with every tile claimed: a hint for afterSubmit, read
    // without the mutex (land() still waits under it).
    std::atomic<bool> finished{false};
  };

  Impl(const Framebuffer& fb, int threads)
      : framebuffer(fb),
        scenes{TileScene(fb.width(), fb.height()), TileScene(fb.width(), fb.height())},
        threadCount(threads) {
    flight.runs = std::vector<Run>(static_cast<size_t>(threadCount));
    for (int i = 1; i < threadCount; ++i) workers.emplace_back([this, i] { workerLoop(i); });
  }

  ~Impl() {
    finish();
    {
      std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
    }
    wake.notify_all();
    for (std::thread& t : workers) t.join();
  }

  TileScene& filling() { return scenes[fillingIndex]; }

  void runTile(const TileScene& scene, int i) const {
    prefetchTile(framebuffer, scene.activeTileRect(i));
    scene.runTile(i);
  }

  // Rasterizes tiles of the scene in flight until none is left unclaimed: thread `self`'s own run
  // first, then the others' in turn.
  void takeTiles(TileScene& scene, int self) {
    for (int k = 0; k < threadCount; ++k) {
      Run& run = flight.runs[static_cast<size_t>((self + k) % threadCount)];
      for (int i = run.next.fetch_add(1, std::memory_order_relaxed); i < run.end;
           i = run.next.fetch_add(1, std::memory_order_relaxed)) {
        runTile(scene, i);
      }
    }
  }

  // Cuts the scene's active tiles into the threads' runs by place (see the top of this file).
  void shareOut(TileScene& scene) {
    scene.orderActiveTilesByPlace();
    int start = 0;  // each run ends where the next one starts
    for (int r = 0; r < threadCount; ++r) {
      Run& run = flight.runs[static_cast<size_t>(r)];
      run.next.store(start, std::memory_order_relaxed);
      run.end = start = scene.firstActiveTileFrom(r + 1, threadCount);
    }
  }

  void workerLoop(int self) {
    uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      wake.wait(lock, [&] { return stopping || (flight.scene != nullptr && flightNumber != seen); });
      if (stopping) return;
      seen = flightNumber;
      TileScene& scene = *flight.scene;
      ++flight.users;
      lock.unlock();
      takeTiles(scene, self);
      lock.lock();
      if (--flight.users == 0) {
        flight.finished.store(true, std::memory_order_relaxed);
        done.notify_all();
      }
    }
  }

  // Waits for the scene in flight to finish, rasterizing tiles of it meanwhile, then empties it.
  void land() {
    if (flight.scene == nullptr) return;
    takeTiles(*flight.scene, 0);
    std::unique_lock<std::mutex> lock(mutex);
    done.wait(lock, [&] { return flight.users == 0; });
    // Every tile is claimed (takeTiles returned) and no worker is still running one.
    flight.scene->clear();
    flight.scene = nullptr;
  }

  // Hands the filled scene to the workers and starts filling the other one. The previous scene
  // must have landed first: a tile's bins of two scenes must not run at the same time.
  void launch() {
    land();
    TileScene& scene = filling();
    if (scene.empty()) return;
    const bool small = scene.activeTileCount() <= kSubmitterTiles && scene.bytes() <= kSubmitterBytes;
    if (workers.empty() || small) {  // rasterize it right here
      for (int i = 0; i < scene.activeTileCount(); ++i) runTile(scene, i);
      scene.clear();
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      flight.scene = &scene;
      shareOut(scene);
      flight.finished.store(false, std::memory_order_relaxed);
      ++flightNumber;
    }
    wake.notify_all();
    fillingIndex = 1 - fillingIndex;
  }

  bool workersIdle() const {
    return !workers.empty() &&
           (flight.scene == nullptr || flight.finished.load(std::memory_order_relaxed));
  }

  void afterSubmit() {
    const size_t bytes = filling().bytes();
    if (bytes >= kSceneBudgetBytes || (bytes >= kIdleLaunchBytes && workersIdle())) launch();
  }

  void finish() {
    launch();
    land();
  }

  // With one thread, deferring a small primitive gains nothing: the tiles keep a large
  // primitive's pixels in the cache while the primitives after it are drawn, but a small one's
  // pixels stay there anyway, and binning it (its record stored and read back, a triangle's edges
  // set up twice and its whole setup again in each tile it crosses) costs more than drawing it.
  // So a primitive whose pixels lie within kAtOnceSize each way is drawn at once, after the bins of
  // the tiles it overlaps (runTilesUnder). Its fragments are those the tiles would give (neither
  // coverage nor attributes depend on the tiles, see tiled_rasterizer.h).
  bool drawsAtOnce(const PixelRect& pixels) const {
    return workers.empty() && pixels.x1 - pixels.x0 <= kAtOnceSize && pixels.y1 - pixels.y0 <= kAtOnceSize;
  }

  // Runs now the bins of the tiles that `pixels` overlaps, so that what is drawn there next comes
  // after everything queued there, every pixel getting its fragments in submission order. Only
  // those: a clear of the window queued at the start of a frame is still done a tile at a time,
  // just before the tile's first primitive, while the tile is in the cache. One thread only.
  void runTilesUnder(const PixelRect& pixels) {
    TileScene& scene = filling();  // with no workers, the only scene
    for (int y = pixels.y0 - pixels.y0 % kTileSize; y < pixels.y1; y += kTileSize)
      for (int x = pixels.x0 - pixels.x0 % kTileSize; x < pixels.x1; x += kTileSize) {
        const int tile = scene.tileAt(x, y);
        if (!scene.queuedIn(tile)) continue;
        prefetchTile(framebuffer, scene.tileRect(tile));
        scene.runTileNow(tile);
      }
  }

  // A line or point drawn at once (by `draw`) when drawsAtOnce says so of the pixels it can reach
  // (`reach`, the rectangle its bins would use); false when it is to be binned.
  template <typename Draw>
  bool drawnAtOnce(const PixelRect& reach, Draw draw) {
    if (!drawsAtOnce(reach)) return false;
    runTilesUnder(reach);
    draw();
    return true;
  }

  // A triangle set up (with the bounds of the whole window) and drawn at once, when drawsAtOnce
  // says so; false when it is to be binned.
  bool triangleAtOnce(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                      const TriangleSettings& settings, FragmentSink& sink) {
    if (!workers.empty()) return false;  // spares the threads' path the corners' spread
    // A triangle whose corners lie further apart than kAtOnceSize (and a pixel) is binned without
    // being set up here (its plane fits would be wasted: each tile sets it up again). Its box
    // could still be small, cut by the bounds, but drawing it binned is as right.
    const auto spread = [](float p, float q, float r) { return std::max({p, q, r}) - std::min({p, q, r}); };
    if (spread(a.x, b.x, c.x) > kAtOnceSize + 1 || spread(a.y, b.y, c.y) > kAtOnceSize + 1) return false;
    // The quads of antialiased lines and points (a triangle with a coverage payload) stay binned:
    // they are thin and blended, each reading and writing pixels the tile keeps in the cache for
    // the next; drawn at once, the smooth_lines frame took 4% longer (smooth_stage.cpp).
    if (settings.payload != nullptr) return false;
    if (scatteredWith(a)) return false;
    TriangleSetup setup;
    if (!setupTriangle(a, b, c, settings, setup)) return true;  // nothing to draw, binned or not
    if (!drawsAtOnce(setup.box)) return false;
    runTilesUnder(setup.box);
    setup.privateRect = PixelRect{0, 0, framebuffer.width(), framebuffer.height()};  // no other thread
    const TileScene& scene = filling();
    setup.hiddenBlockOdds = &scene.hiddenBlockOdds(scene.tileAt(setup.box.x0, setup.box.y0));
    rasterizeTriangle(setup, sink);
    return true;
  }

  // Whether the small triangles lately submitted, `a` the corner of the latest, are scattered: most
  // of the last 64 lie in another tile than the one before them. Then they are binned after all:
  // drawn at once, each would fetch its rows of both buffers from memory (and wait for them:
  // prefetching them a few triangles ahead did not help), while a tile's bin runs with the
  // tile's rows in the cache. 250,000 triangles scattered over 1920 x 1080 took 116 ms a frame
  // binned against 132 at once; the triangles of a mesh, each next to the one before, are
  // faster at once (lit spheres 46 ms against 54 binned).
  bool scatteredWith(const WindowVertex& a) {
    const float right = static_cast<float>(framebuffer.width() - 1), top = static_cast<float>(framebuffer.height() - 1);
    // NaN and negative coordinates count as 0.
    const int x = static_cast<int>(a.x > 0.0f ? std::min(a.x, right) : 0.0f);
    const int y = static_cast<int>(a.y > 0.0f ? std::min(a.y, top) : 0.0f);
    const int tile = filling().tileAt(x, y);
    const uint64_t changed = tile != lastSmallTriangleTile ? 1u : 0u;
    // The count follows the history as it shifts (std::popcount is a library call on the
    // baseline x86-64 target, which has no POPCNT instruction).
    recentTileChanges += static_cast<int>(changed) - static_cast<int>(tileChanges >> 63);
    tileChanges = tileChanges << 1 | changed;
    lastSmallTriangleTile = tile;
    return recentTileChanges > 32;
  }

  const Framebuffer& framebuffer;
  // The tile of the last small triangle's first corner, and bit i: whether the small triangle i
  // submissions ago lay in another tile than the one before it (scatteredWith), and how many of
  // the 64 bits are set.
  int lastSmallTriangleTile = -1;
  uint64_t tileChanges = 0;
  int recentTileChanges = 0;
  TileScene scenes[2];
  int fillingIndex = 0;
  Flight flight;
  uint64_t flightNumber = 0;
  bool stopping = false;
  int threadCount;
  std::mutex mutex;
  std::condition_variable wake, done;
  std::vector<std::thread> workers;
};

TiledRasterizer::TiledRasterizer(const Framebuffer& framebuffer, int threadCount)
    : impl_(std::make_unique<Impl>(framebuffer, std::max(1, threadCount))) {}

TiledRasterizer::~TiledRasterizer() = default;

int TiledRasterizer::threadCount() const { return impl_->threadCount; }

void TiledRasterizer::triangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                               const TriangleSettings& settings, FragmentSink& sink) {
  if (impl_->triangleAtOnce(a, b, c, settings, sink)) return;
  impl_->filling().addTriangle(a, b, c, settings, sink);
  impl_->afterSubmit();
}

void TiledRasterizer::quad(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                           const WindowVertex& v3, const TriangleSettings& settings, FragmentSink& sink) {
  TriangleSetup edges;  // the edge functions and the box alone, as for binning a triangle
  if (setupQuadEdges(v0, v1, v2, v3, settings.bounds, edges)) {
    impl_->filling().addQuad(v0, v1, v2, v3, edges, settings, sink);
    impl_->afterSubmit();
    return;
  }
  // Refused: corners that snap to no strictly convex quadrilateral are drawn as the two
  // triangles; a quadrilateral outside the bounds draws nothing, and its triangles neither.
  if (!quadIsConvex(v0, v1, v2, v3)) {
    triangle(v0, v1, v2, settings, sink);
    triangle(v2, v3, v0, settings, sink);
  }
}

void TiledRasterizer::line(const WindowVertex& a, const WindowVertex& b,
                           const LineSettings& settings, FragmentSink& sink) {
  LineQuad quad;
  if (!lineQuadOf(a, b, settings, quad)) return;
  const PixelRect pixels = lineQuadPixels(quad, settings.bounds);
  // Drawn at once, the line advances the stipple counter as the walk below does.
  if (impl_->drawnAtOnce(pixels, [&] { rasterizeLine(quad, a, b, settings, sink); })) return;
  int stippleStart = 0;
  if (settings.stippleFactor > 0 && settings.stippleCounter != nullptr) {
    // The next segment of a strip continues this one's counter, so find where it ends now: walk
    // the line with nothing inside the bounds (the counter runs outside the bounds too).
    stippleStart = *settings.stippleCounter;
    LineSettings walk = settings;
    walk.bounds = PixelRect{};
    DiscardingSink discard;
    rasterizeLine(quad, a, b, walk, discard);
  }
  // Outside the bounds the counter was all there was to do.
  if (pixels.empty()) return;
  impl_->filling().addLine(quad, pixels, a, b, settings, stippleStart, sink);
  impl_->afterSubmit();
}

void TiledRasterizer::point(const WindowVertex& v, const PointSettings& settings,
                            FragmentSink& sink) {
  if (impl_->drawnAtOnce(TileScene::pointReach(v, settings), [&] { rasterizePoint(v, settings, sink); })) return;
  impl_->filling().addPoint(v, settings, sink);
  impl_->afterSubmit();
}

void TiledRasterizer::clear(const ClearRequest& request) {
  impl_->filling().addClear(request);
  impl_->afterSubmit();
}

bool TiledRasterizer::primitivesQueued() const {
  const TileScene* flying = impl_->flight.scene;
  return (flying != nullptr && flying->hasPrimitives()) || impl_->filling().hasPrimitives();
}

bool TiledRasterizer::idle() const {
  return impl_->flight.scene == nullptr && impl_->scenes[impl_->fillingIndex].empty();
}

void TiledRasterizer::finish() { impl_->finish(); }

void TiledRasterizer::waitForThreads() { impl_->land(); }

}  // namespace glass::raster
