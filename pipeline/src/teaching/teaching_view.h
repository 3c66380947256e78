// Teaching views (GLASS_VIEW): what a program's frames show instead of their colours, for any
// program linked against glass, without a line of it changed (docs/teaching.md).
//
//   depth      the depth buffer as grey: the nearest depth drawn black, the farthest white
//   overdraw   the fragments rasterized on each pixel since the last glClear of the colour
//              buffer, as the heat map of glass/geometry/teaching_scales.h
//   wireframe  the edges of every triangle rasterized, those clipping produced included
//   normals    the eye-space normal of the last fragment written on each pixel, as a colour
//   mipmap     the mipmap level the last fragment written on each pixel sampled, a colour a level
//
// The variable is read once, when a context is created. The picture is made at presentation
// (glassWritePNG, glassGetColorBuffer and so the GLUT window); the program's own colour buffer
// is drawn as always, so glReadPixels still reads the program's colours. With no view, the
// pipeline's hooks cost one test of a pointer per draw (teachingCanvasFor).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace glass::gl {

struct Context;

enum class TeachingView { Depth, Overdraw, Wireframe, Normals, Mipmap };

// The view a GLASS_VIEW value names; nullopt for an unknown name.
std::optional<TeachingView> parseTeachingView(std::string_view name);
const char* teachingViewName(TeachingView view);

// What a view gathers while a frame is drawn, for one context.
struct TeachingCanvas {
  TeachingView view = TeachingView::Depth;
  int width = 0, height = 0;
  // Overdraw: fragments per pixel, bottom row first, saturating. Written by the rasterizer's
  // threads, each on the pixels of its own tiles only.
  std::vector<std::uint16_t> fragmentCounts;
  // Wireframe: 1 where a triangle's edge passes, bottom row first. Written on the drawing thread.
  std::vector<std::uint8_t> edges;
  // Normals and mipmap: the view's colour of the last fragment written on each pixel since the
  // colour buffer was last cleared (RGBA, bottom row first; black where none was). Written by the
  // rasterizer's threads, each on the pixels of its own tiles only.
  std::vector<std::uint8_t> fragmentColors;
  // The picture presented instead of the colour buffer (RGBA, bottom row first).
  std::vector<std::uint8_t> shown;
};

// Reads GLASS_VIEW and gives ctx its view; an unknown name is reported on stderr and ignored.
void attachTeachingViewFromEnvironment(Context& ctx);
// Gives ctx a view (the GLUT menu switches views), or none; the frame's counts start again.
void setTeachingView(Context& ctx, std::optional<TeachingView> view);
std::optional<TeachingView> teachingViewOf(const Context& ctx);
void detachTeachingView(const Context& ctx);
// The vertex stage passes the eye-space normal to the fragments (the normals view).
bool teachingViewNeedsEyeNormals(const Context& ctx);

// The canvas of ctx's view, sized to its framebuffer, or nullptr when it has none: called once
// per draw, on the drawing thread, with nothing of an older size queued.
TeachingCanvas* teachingCanvasFor(Context& ctx);

// glClear of the colour buffer starts a frame: counts and edges start again.
void restartTeachingFrame(Context& ctx);

// The picture of ctx's view, width * height RGBA bottom row first, or nullptr when it has none.
// The queued drawing must be finished. Presenting ends a frame: GLASS_STATS prints its counts.
const std::uint8_t* presentTeachingView(Context& ctx);

}  // namespace glass::gl
