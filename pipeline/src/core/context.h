// The GL context: every piece of GL state, grouped by the stage that owns it. Each group lives in
// its own header, next to the code of that stage. GL entry points (pipeline/src/api/) find the
// current context with currentContext() and do nothing when there is none.
#pragma once

#include <functional>
#include <memory>

#include "accum/accumulation_state.h"
#include "core/ancillary_buffers.h"
#include "core/attrib_stack.h"
#include "core/errors.h"
#include "core/hint_state.h"
#include "core/pixel_store.h"
#include "core/transform_state.h"
#include "evaluators/evaluator_state.h"
#include "fragment/fog_state.h"
#include "fragment/fragment_state.h"
#include "glass/raster/framebuffer.h"
#include "lighting/lighting_state.h"
#include "lists/display_lists.h"
#include "pixels/imaging_state.h"
#include "pixels/pixel_transfer_state.h"
#include "pixels/raster_position.h"
#include "primitive/raster_state.h"
#include "select/render_mode_state.h"
#include "texture/texture_state.h"
#include "vertex/current_state.h"
#include "vertex/primitive_assembly.h"
#include "vertex/vertex_arrays.h"

// Stage state. Each header defines one struct with its GL defaults as member initialisers.
//   core/errors.h               ErrorState        the sticky GL error flag
//   core/transform_state.h      TransformState    matrix stacks, viewport, depth range, clip planes,
//                                                 GL_NORMALIZE, GL_RESCALE_NORMAL
//   vertex/current_state.h      CurrentState      current colour, normal, texture coordinates, edge flag
//   vertex/vertex_arrays.h      ArrayState        client arrays and their enables
//   vertex/primitive_assembly.h PrimitiveAssembly glBegin/glEnd bookkeeping for the ten primitive types
//   primitive/raster_state.h    RasterState       point size, line width, shade model, polygon mode,
//                                                 culling, front face, polygon offset
//   fragment/fragment_state.h   FragmentState     scissor, alpha, stencil, depth, blend, logic op,
//                                                 write masks, clear values
//   fragment/fog_state.h        FogState          glFog
//   lighting/lighting_state.h   LightingState     lights, materials, light model, colour material
//   texture/texture_state.h     TextureState      texture objects, binding, environment, texgen
//   lists/display_lists.h       DisplayListState  display lists and the list being compiled
//   core/pixel_store.h          PixelStoreState   glPixelStore pack and unpack parameters
//   evaluators/evaluator_state.h EvaluatorState   glMap1/glMap2 and the grid
//   core/hint_state.h           HintState         glHint
//   pixels/raster_position.h    RasterPositionState the current raster position (glRasterPos)
//   pixels/pixel_transfer_state.h PixelTransferState glPixelTransfer, glPixelMap, glPixelZoom
//   pixels/imaging_state.h      ImagingState      colour tables, convolution, colour matrix,
//                                                 histogram and minmax (GL_ARB_imaging)
//   accum/accumulation_state.h  AccumulationState glClearAccum and the accumulation buffer
//   select/render_mode_state.h  RenderModeState   glRenderMode, selection and feedback
//
// Besides GL state, a context holds its framebuffer and the per-draw setup derived from the
// state at glBegin (primitive/draw_pipeline.h), which is working storage, not GL state.

namespace glass::gl {

class DrawPipeline;

struct Context {
  Context(int width, int height);  // throws std::bad_alloc when memory runs out
  // A context in the initial state drawing into `framebuffer`, which it takes; if the
  // constructor throws (std::bad_alloc), `framebuffer` is left as it was.
  explicit Context(raster::Framebuffer& framebuffer);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  ErrorState errors;
  TransformState transform;
  CurrentState current;
  ArrayState arrays;
  PrimitiveAssembly assembly;
  RasterState raster;
  FragmentState fragment;
  FogState fog;
  LightingState lighting;
  TextureState texture;
  DisplayListState lists;
  PixelStoreState pixelStore;
  EvaluatorState evaluators;
  HintState hints;
  AttribStackState attribStack;  // glPushAttrib / glPushClientAttrib (core/attrib_stack.h)
  RasterPositionState rasterPosition;
  PixelTransferState pixelTransfer;
  ImagingState imaging;
  AccumulationState accumulation;
  RenderModeState renderMode;

  raster::Framebuffer framebuffer;
  AncillaryBuffers buffers;  // which of depth, stencil, accumulation and alpha it has (all by default)
  std::unique_ptr<DrawPipeline> draw;

  // Set by an embedding that shows the framebuffer elsewhere (an OSMesa context copies it into
  // the caller's buffer, pipeline/src/osmesa/; a single-buffered GLUT window shows it, through
  // glassSetFlushCallback): called by glFlush and glFinish once the queued drawing is in the
  // framebuffer, with the context current.
  std::function<void(Context&)> afterFlush;

 private:
  // The viewport and scissor box over the framebuffer, and what the environment attaches.
  void startInInitialState();
};

// Gives the context a framebuffer of another size (OSMesaMakeCurrent to a buffer of another
// size), after finishing the queued drawing. The new colour, depth and stencil buffers hold
// zeros (alpha 255 in a colour buffer without alpha bitplanes) and the accumulation buffer is allocated again when next used; GL state, the viewport
// included, is unchanged. Throws (std::bad_alloc, std::system_error for the threads), leaving the context as it was.
void resizeFramebuffer(Context& ctx, int width, int height);

// A context in GL's initial state, as a new context of previous's size is, that takes over what
// outlives a frame: previous's framebuffer and accumulation buffer (their contents kept), its
// display lists and texture objects (as a context sharing them would), which ancillary buffers
// and alpha bitplanes it has, its flush callback and its teaching view. The queued drawing of previous is finished
// first; previous is left with a 1 x 1 framebuffer, to be destroyed. Throws (std::bad_alloc,
// std::system_error for the threads), leaving previous as it was.
std::unique_ptr<Context> contextInInitialState(Context& previous);

// The context current on the calling thread (glassMakeCurrent), or nullptr.
Context* currentContext();
void setCurrentContext(Context* ctx);

}  // namespace glass::gl
