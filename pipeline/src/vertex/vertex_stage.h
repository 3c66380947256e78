// The vertex stage (spec 2.10-2.14): from a glVertex in object coordinates and the current
// attributes to a vertex in clip coordinates with its varyings (lit colours, texture coordinates,
// fog coordinate, eye position and normal), its user clip distances and its edge flag.
//
// What a vertex needs depends only on state that cannot change between glBegin and glEnd, so
// prepareVertexStage derives it once per glBegin and processVertex reads that setup.
#pragma once

#include "core/matrix.h"
#include "glass/raster/vertex.h"
#include "vertex/pipeline_vertex.h"

namespace glass::gl {

struct Context;
struct VertexTrace;

struct VertexStageSetup {
  Matrix4 modelview;
  Matrix4 modelviewProjection;   // projection * modelview: clip = MVP * object (as Mesa)
  Matrix4 modelviewInverse;      // normals: n_e = n_o^T * modelview^-1 (spec 2.11.3)
  float rescaleFactor = 1.0f;    // GL_RESCALE_NORMAL's f, from the inverse's third row

  bool needEyePosition = false;  // lighting, Phong, fog, texturing or user clip planes
  bool needEyeNormal = false;    // lighting, Phong or texturing
  bool lightPerVertex = false;   // GL_LIGHTING with a shade model other than GL_PHONG_WIN
  bool phong = false;            // GL_LIGHTING with GL_PHONG_WIN
  bool eyeNormalVarying = false; // the eye position and normal go to the fragments: Phong, or
                                 // GLASS_VIEW=normals (teaching/teaching_view.h)
  bool twoSided = false;         // back colours are computed
  bool texturing = false;
  int textureUnits = 0;          // texture coordinates are computed for units 0 .. textureUnits - 1
  bool fog = false;
  bool secondaryColor = false;  // unlit with GL_COLOR_SUM: glSecondaryColor goes to the varyings
  bool normalize = false;
  bool rescaleNormal = false;

  unsigned clipPlaneMask = 0;    // enabled user clip planes
  float clipPlanes[raster::kMaxUserClipPlanes][4] = {};  // eye space

  int varyingCount = 4;          // the prefix of varying slots the rest of the pipeline uses

  VertexTrace* trace = nullptr;  // GLASS_TRACE_VERTEX waits for a vertex (teaching/vertex_trace.h)
};

void prepareVertexStage(const Context& ctx, VertexStageSetup& setup);

// Processes one vertex whose object coordinates are (x, y, z, w), with the current attributes of
// ctx.current.
void processVertex(const Context& ctx, const VertexStageSetup& setup, const float object[4],
                   PipelineVertex& out);

}  // namespace glass::gl
