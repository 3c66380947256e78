// GLASS_TRACE_VERTEX=N or N@FRAME: vertex N (counting from 0) of frame FRAME (counting from 0,
// default 0) of any program, printed to stderr through every stage of the vertex pipeline, with
// the values the pipeline itself computed: object, eye, clip, normalized device and window
// coordinates, which clip planes it lies outside, the eye-space normal, the lighting equation
// term by term for each light, the colours, and the texture coordinates before and after texgen
// and the texture matrix (docs/teaching.md, "Tracing a vertex"). A frame ends when it is
// presented (glassWritePNG, glassGetColorBuffer and so a GLUT swap, an OSMesa glFlush/glFinish).
//
// The vertices counted are those the vertex stage processes, in order: glVertex, array elements,
// evaluator points, glRect corners. While tracing, glDrawArrays and glDrawElements take the
// reference path (vertex_batch.h), which computes the same values one vertex at a time.
#pragma once

#include <string>

#include "vertex/pipeline_vertex.h"

namespace glass::gl {

struct Context;
struct VertexStageSetup;

struct VertexTrace {
  long vertex = 0;          // the vertex to trace, in its frame
  long frame = 0;           // the frame to trace it in
  long framesEnded = 0;     // frames presented so far
  long verticesSeen = 0;    // vertices processed in this frame
  bool done = false;        // traced, or its frame ended without it
  std::string report;       // what was printed
};

// Reads GLASS_TRACE_VERTEX for a new context; a malformed value is reported on stderr and ignored.
void attachVertexTraceFromEnvironment(Context& ctx);
void detachVertexTrace(const Context& ctx);
// ctx's trace while it still waits for its vertex, else nullptr: called once per glBegin.
VertexTrace* vertexTraceFor(const Context& ctx);

// The vertex stage, after processing a vertex: traces it when it is the one asked for.
// object as given; eye = MODELVIEW object; normal the eye-space normal as lighting uses it.
void traceVertex(const Context& ctx, const VertexStageSetup& setup, VertexTrace& trace,
                 const float object[4], const float eye[4], const float normal[3],
                 const PipelineVertex& out);

// What the trace printed so far (empty before its vertex or the end of its frame).
std::string vertexTraceReport(const Context& ctx);

// Presentation ends a frame: reports a traced frame that never reached the vertex.
void endTracedFrame(Context& ctx);

}  // namespace glass::gl
