// The GL context: every piece of GL state, grouped by the stage that owns it. Each group lives in
// its own header, next to the code of that stage. GL entry points (pipeline/src/api/) find the
// current context with currentContext() and do nothing when there is none.
#pragma once

#include "glass/raster/framebuffer.h"

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
