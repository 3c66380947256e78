#include "teaching/teaching_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "core/context.h"
#include "glass/geometry/teaching_scales.h"
#include "glass/raster/fragment.h"
#include "teaching/frame_statistics.h"
#include "teaching/per_context_table.h"
#include "teaching/vertex_trace.h"

namespace glass::gl {
namespace {

PerContextTable<TeachingCanvas>& canvases() {
  static PerContextTable<TeachingCanvas> table;
  return table;
}

TeachingCanvas* findCanvas(const Context& ctx) { return canvases().find(ctx); }

bool paintsFragments(TeachingView view) {
  return view == TeachingView::Normals || view == TeachingView::Mipmap;
}

void sizeCanvas(TeachingCanvas& canvas, int width, int height) {
  if (canvas.width == width && canvas.height == height) return;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  canvas.width = width;
  canvas.height = height;
  canvas.fragmentCounts.assign(canvas.view == TeachingView::Overdraw ? pixels : 0, 0);
  canvas.edges.assign(canvas.view == TeachingView::Wireframe ? pixels : 0, 0);
  canvas.fragmentColors.assign(paintsFragments(canvas.view) ? pixels * 4 : 0, 0);
  canvas.shown.assign(pixels * 4, 0);
}

void putPixel(std::uint8_t* p, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
}

// Depth as grey over the range of depths drawn, as `glass render --view depth` shows it; the
// range is the picture's legend, printed when it changes.
void showDepth(const raster::Framebuffer& fb, TeachingCanvas& canvas) {
  std::uint32_t nearest = raster::kDepthMax, farthest = 0;
  const std::size_t pixels = canvas.shown.size() / 4;
  const std::uint32_t* depth = fb.depthAt(0, 0);
  for (std::size_t i = 0; i < pixels; ++i) {
    if (depth[i] < raster::kDepthMax) {
      nearest = std::min(nearest, depth[i]);
      farthest = std::max(farthest, depth[i]);
    }
  }
  const bool any = nearest <= farthest;
  const double span = any && farthest > nearest ? static_cast<double>(farthest - nearest) : 1.0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const double grey = depth[i] >= raster::kDepthMax ? 1.0 : (depth[i] - static_cast<double>(nearest)) / span;
    const auto level = static_cast<std::uint8_t>(std::lround(std::clamp(grey, 0.0, 1.0) * 255.0));
    putPixel(&canvas.shown[i * 4], level, level, level);
  }
  static thread_local std::uint64_t lastLegend = ~std::uint64_t{0};
  const std::uint64_t legend = any ? (std::uint64_t{nearest} << 32 | farthest) : 0;
  if (legend != lastLegend) {
    lastLegend = legend;
    if (any) {
      std::fprintf(stderr, "glass view depth: near %.6f (black) to far %.6f (white); nothing drawn: white\n",
                   nearest / static_cast<double>(raster::kDepthMax),
                   farthest / static_cast<double>(raster::kDepthMax));
    } else {
      std::fprintf(stderr, "glass view depth: nothing drawn with a depth below 1\n");
    }
  }
}

void showOverdraw(TeachingCanvas& canvas) {
  int largest = 0;
  for (std::size_t i = 0; i < canvas.fragmentCounts.size(); ++i) {
    const int count = canvas.fragmentCounts[i];
    largest = std::max(largest, count);
    const auto c = geometry::overdrawScaleColor(count);
    putPixel(&canvas.shown[i * 4], c[0], c[1], c[2]);
  }
  static thread_local int lastLargest = -1;
  if (largest != lastLargest) {
    lastLargest = largest;
    std::fprintf(stderr, "glass view overdraw: up to %d fragments on a pixel; scale 0 black, 1 dark blue, "
                 "2 blue, 3 green, 4 yellow-green, 5 yellow, 6 orange, 7 red, 8 or more white\n", largest);
  }
}

void showWireframe(TeachingCanvas& canvas) {
  for (std::size_t i = 0; i < canvas.edges.size(); ++i) {
    const std::uint8_t level = canvas.edges[i] ? 255 : 0;
    putPixel(&canvas.shown[i * 4], level, level, level);
  }
}

// Normals and mipmap: the fragments painted the picture; what none painted is black.
void showFragmentColors(TeachingCanvas& canvas) {
  for (std::size_t i = 0; i < canvas.fragmentColors.size(); i += 4) {
    const std::uint8_t* c = &canvas.fragmentColors[i];
    putPixel(&canvas.shown[i], c[0], c[1], c[2]);
  }
}

void printNormalsLegend() {
  static thread_local bool printed = false;
  if (printed) return;
  printed = true;
  std::fprintf(stderr, "glass view normals: the eye-space normal n, normalized, as the colour 255 (n + 1) / 2: "
               "+x red, +y green, +z (towards the eye) blue, so a face turned to the eye is (128, 128, 255); "
               "nothing drawn black\n");
}

void printMipmapLegend() {
  static thread_local bool printed = false;
  if (printed) return;
  printed = true;
  std::fprintf(stderr, "glass view mipmap: level");
  for (int level = 0; level + 1 < geometry::kMipmapScaleSteps; ++level) {
    std::fprintf(stderr, " %d %s,", level, geometry::mipmapScaleName(level));
  }
  std::fprintf(stderr, " %d or more %s;", geometry::kMipmapScaleSteps - 1,
               geometry::mipmapScaleName(geometry::kMipmapScaleSteps - 1));
  std::fprintf(stderr, " untextured grey, nothing drawn black\n");
}

}  // namespace

std::optional<TeachingView> parseTeachingView(std::string_view name) {
  if (name == "depth") return TeachingView::Depth;
  if (name == "overdraw") return TeachingView::Overdraw;
  if (name == "wireframe") return TeachingView::Wireframe;
  if (name == "normals") return TeachingView::Normals;
  if (name == "mipmap") return TeachingView::Mipmap;
  return std::nullopt;
}

const char* teachingViewName(TeachingView view) {
  switch (view) {
    case TeachingView::Depth: return "depth";
    case TeachingView::Overdraw: return "overdraw";
    case TeachingView::Wireframe: return "wireframe";
    case TeachingView::Normals: return "normals";
    case TeachingView::Mipmap: return "mipmap";
  }
  return "";
}

void attachTeachingViewFromEnvironment(Context& ctx) {
  const char* name = std::getenv("GLASS_VIEW");
  if (!name || !*name) return;
  const std::optional<TeachingView> view = parseTeachingView(name);
  if (!view) {
    std::fprintf(stderr, "glass: GLASS_VIEW=%s is not a view (depth, overdraw, wireframe, normals, mipmap); "
                 "showing the program's colours\n", name);
    return;
  }
  setTeachingView(ctx, view);
}

void setTeachingView(Context& ctx, std::optional<TeachingView> view) {
  if (!view) return detachTeachingView(ctx);
  auto canvas = std::make_unique<TeachingCanvas>();
  canvas->view = *view;
  canvases().attach(ctx, std::move(canvas));
}

std::optional<TeachingView> teachingViewOf(const Context& ctx) {
  const TeachingCanvas* canvas = findCanvas(ctx);
  return canvas ? std::optional<TeachingView>(canvas->view) : std::nullopt;
}

void detachTeachingView(const Context& ctx) { canvases().detach(ctx); }

bool teachingViewNeedsEyeNormals(const Context& ctx) {
  return teachingViewOf(ctx) == TeachingView::Normals;
}

TeachingCanvas* teachingCanvasFor(Context& ctx) {
  TeachingCanvas* canvas = findCanvas(ctx);
  if (canvas) sizeCanvas(*canvas, ctx.framebuffer.width(), ctx.framebuffer.height());
  return canvas;
}

void restartTeachingFrame(Context& ctx) {
  TeachingCanvas* canvas = teachingCanvasFor(ctx);
  if (!canvas) return;
  std::fill(canvas->fragmentCounts.begin(), canvas->fragmentCounts.end(), 0);
  std::fill(canvas->edges.begin(), canvas->edges.end(), 0);
  std::fill(canvas->fragmentColors.begin(), canvas->fragmentColors.end(), 0);
}

const std::uint8_t* presentTeachingView(Context& ctx) {
  // Presentation ends a frame (teaching/frame_statistics.h, vertex_trace.h).
  reportFrameStatistics(ctx);
  endTracedFrame(ctx);
  TeachingCanvas* canvas = teachingCanvasFor(ctx);
  if (!canvas) return nullptr;
  switch (canvas->view) {
    case TeachingView::Depth: showDepth(ctx.framebuffer, *canvas); break;
    case TeachingView::Overdraw: showOverdraw(*canvas); break;
    case TeachingView::Wireframe: showWireframe(*canvas); break;
    case TeachingView::Normals:
      showFragmentColors(*canvas);
      printNormalsLegend();
      break;
    case TeachingView::Mipmap:
      showFragmentColors(*canvas);
      printMipmapLegend();
      break;
  }
  return canvas->shown.data();
}

}  // namespace glass::gl
