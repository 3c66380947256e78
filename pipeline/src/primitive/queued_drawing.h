// Draws are rasterized later, tile by tile, on several threads (primitive/draw_pipeline.h). Code
// that reads or writes the framebuffer other than through a draw (clearing, reading pixels,
// copying them to a texture, pixel rectangles, the accumulation buffer, writing a PNG) calls
// finishQueuedDrawing first, so that it sees, and comes after, every fragment drawn before it.
#pragma once

namespace glass::raster {
struct ClearRequest;
}

namespace glass::gl {

struct Context;

void finishQueuedDrawing(Context& ctx);

// glClear queues its clear with the draws (raster::TiledRasterizer::clear), so that the threads
// share it tile by tile. False when the context has no draw pipeline yet: the caller clears now.
bool queueClear(Context& ctx, const raster::ClearRequest& request);

// State that the fragments of a draw read by reference (texturing, fog, per-fragment lighting;
// see draw_pipeline.h) changes only between draws, except the material, which glMaterial may
// change between glBegin and glEnd: it calls this first, which finishes the fragments queued so
// far when the current draw reads such state.
void finishDrawReadingContext(Context& ctx);

// glColor with GL_COLOR_MATERIAL changes the material between glBegin and glEnd; it calls this
// first (DrawPipeline::beforeColorMaterialChange says why waiting for the threads is enough).
void beforeColorMaterialChange(Context& ctx);

}  // namespace glass::gl
