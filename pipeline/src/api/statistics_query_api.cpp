// GL_GLASS_pipeline_statistics (<GL/glass_statistics.h>): query objects holding the counts of
// GLASS_STATS for the commands between glBeginQueryGLASS and glEndQueryGLASS. The rules are those
// of OpenGL 1.5's occlusion queries (section 4.1.6, 6.1.12): any unused name but 0 becomes a
// query object at glBeginQueryGLASS, one query is active at a time, a deleted active query counts
// on until glEndQueryGLASS, whose result then goes nowhere. glBeginQueryGLASS and glEndQueryGLASS
// are compiled into display lists, the other commands are not (spec 5.4).
#include <GL/gl.h>
#include <GL/glass_statistics.h>

#include <limits>

#include "core/context.h"
#include "lists/command_recording.h"
#include "primitive/queued_drawing.h"
#include "teaching/statistics_query.h"

using glass::gl::Context;
using glass::gl::PipelineCount;
using glass::gl::PipelineCounts;
using glass::gl::recordError;
using glass::gl::rejectInsideBeginEnd;
using glass::gl::StatisticsQueries;

namespace {

// The count a pname of glGetQueryObject*GLASS names; false for any other pname.
bool countNamed(GLenum pname, PipelineCount& count) {
  static_assert(GL_TEXEL_READS_GLASS - GL_VERTICES_SUBMITTED_GLASS + 1 ==
                glass::gl::kPipelineCountKinds + 1);  // the primitives' sum comes second
  switch (pname) {
    case GL_VERTICES_SUBMITTED_GLASS: count = PipelineCount::Vertices; return true;
    case GL_POINTS_SUBMITTED_GLASS: count = PipelineCount::Points; return true;
    case GL_LINES_SUBMITTED_GLASS: count = PipelineCount::Lines; return true;
    case GL_TRIANGLES_SUBMITTED_GLASS: count = PipelineCount::Triangles; return true;
    case GL_PRIMITIVES_CULLED_GLASS: count = PipelineCount::Culled; return true;
    case GL_PRIMITIVES_CLIPPED_AWAY_GLASS: count = PipelineCount::ClippedAway; return true;
    case GL_PRIMITIVES_CLIPPED_GLASS: count = PipelineCount::Clipped; return true;
    case GL_PRIMITIVES_MADE_BY_CLIPPING_GLASS: count = PipelineCount::ProducedByClipping; return true;
    case GL_FRAGMENTS_GENERATED_GLASS: count = PipelineCount::Fragments; return true;
    case GL_FRAGMENTS_SCISSOR_FAILED_GLASS: count = PipelineCount::ScissorRejected; return true;
    case GL_FRAGMENTS_ALPHA_FAILED_GLASS: count = PipelineCount::AlphaRejected; return true;
    case GL_FRAGMENTS_STENCIL_FAILED_GLASS: count = PipelineCount::StencilRejected; return true;
    case GL_FRAGMENTS_DEPTH_FAILED_GLASS: count = PipelineCount::DepthRejected; return true;
    case GL_FRAGMENTS_PASSED_GLASS: count = PipelineCount::Passed; return true;
    case GL_TEXEL_READS_GLASS: count = PipelineCount::TexelReads; return true;
    default: return false;
  }
}

// The value of pname for query object `id`, as glGetQueryObject*GLASS returns it; false (with
// the error recorded) when there is none.
bool queryObjectValue(Context& ctx, GLuint id, GLenum pname, unsigned long long& value) {
  if (rejectInsideBeginEnd(ctx)) return false;
  PipelineCount count{};
  const bool available = pname == GL_QUERY_RESULT_AVAILABLE_GLASS;
  const bool primitives = pname == GL_PRIMITIVES_SUBMITTED_GLASS;
  if (!available && !primitives && !countNamed(pname, count)) {
    recordError(ctx, GL_INVALID_ENUM);
    return false;
  }
  // The active query has no result yet, and names never begun or deleted are no query objects.
  const StatisticsQueries* queries = glass::gl::findStatisticsQueries(ctx);
  const bool hasResult = queries && id != queries->active && queries->results.count(id) != 0;
  if (!hasResult) {
    recordError(ctx, GL_INVALID_OPERATION);
    return false;
  }
  const PipelineCounts& counts = queries->results.at(id);
  if (available) {
    value = GL_TRUE;  // glEndQueryGLASS finished the drawing it counted
  } else if (primitives) {
    value = counts[PipelineCount::Points] + counts[PipelineCount::Lines] + counts[PipelineCount::Triangles];
  } else {
    value = counts[count];
  }
  return true;
}

}  // namespace

extern "C" {

void glGenQueriesGLASS(GLsizei n, GLuint* ids) {
  glass::gl::executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (n < 0) return recordError(ctx, GL_INVALID_VALUE);
    if (n == 0 || !ids) return;
    StatisticsQueries& queries = glass::gl::statisticsQueriesOf(ctx);
    // Names not in use; they become query objects at glBeginQueryGLASS, as in GL 1.5.
    GLuint candidate = queries.lastGenerated;
    for (GLsizei i = 0; i < n; ++i) {
      do {
        ++candidate;
      } while (candidate == 0 || queries.results.count(candidate) != 0 || candidate == queries.active);
      ids[i] = candidate;
    }
    queries.lastGenerated = candidate;
  });
}

void glDeleteQueriesGLASS(GLsizei n, const GLuint* ids) {
  glass::gl::executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (n < 0) return recordError(ctx, GL_INVALID_VALUE);
    StatisticsQueries* queries = glass::gl::findStatisticsQueries(ctx);
    if (!queries || !ids) return;
    for (GLsizei i = 0; i < n; ++i) {
      if (ids[i] != 0 && ids[i] == queries->active) queries->activeDeleted = true;
      queries->results.erase(ids[i]);  // unused names and 0 are silently ignored
    }
  });
}

GLboolean glIsQueryGLASS(GLuint id) {
  return glass::gl::queryNow(GLboolean(GL_FALSE), [=](Context& ctx) -> GLboolean {
    if (rejectInsideBeginEnd(ctx)) return GL_FALSE;
    const StatisticsQueries* queries = glass::gl::findStatisticsQueries(ctx);
    if (!queries || id == 0) return GL_FALSE;
    const bool counting = id == queries->active && !queries->activeDeleted;
    return counting || queries->results.count(id) != 0 ? GL_TRUE : GL_FALSE;
  });
}

void glBeginQueryGLASS(GLenum target, GLuint id) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (target != GL_PIPELINE_STATISTICS_GLASS) return recordError(ctx, GL_INVALID_ENUM);
    StatisticsQueries& queries = glass::gl::statisticsQueriesOf(ctx);
    if (id == 0 || queries.active != 0) return recordError(ctx, GL_INVALID_OPERATION);
    // Fragments of earlier draws still queued belong to no query.
    glass::gl::finishQueuedDrawing(ctx);
    queries.results.erase(id);  // counted anew: no result until glEndQueryGLASS
    queries.active = id;
    queries.activeDeleted = false;
    glass::gl::beginQueryCounting(ctx);
  });
}

void glEndQueryGLASS(GLenum target) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (target != GL_PIPELINE_STATISTICS_GLASS) return recordError(ctx, GL_INVALID_ENUM);
    StatisticsQueries* queries = glass::gl::findStatisticsQueries(ctx);
    if (!queries || queries->active == 0) return recordError(ctx, GL_INVALID_OPERATION);
    // The counts are complete once every fragment drawn before is.
    glass::gl::finishQueuedDrawing(ctx);
    const PipelineCounts counts = glass::gl::endQueryCounting(ctx);
    if (!queries->activeDeleted) queries->results[queries->active] = counts;
    queries->active = 0;
    queries->activeDeleted = false;
  });
}

void glGetQueryivGLASS(GLenum target, GLenum pname, GLint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (target != GL_PIPELINE_STATISTICS_GLASS) return recordError(ctx, GL_INVALID_ENUM);
    const StatisticsQueries* queries = glass::gl::findStatisticsQueries(ctx);
    GLint value = 0;
    switch (pname) {
      case GL_CURRENT_QUERY_GLASS:
        value = queries && !queries->activeDeleted ? static_cast<GLint>(queries->active) : 0;
        break;
      case GL_QUERY_COUNTER_BITS_GLASS: value = 64; break;
      default: return recordError(ctx, GL_INVALID_ENUM);
    }
    if (params) *params = value;
  });
}

void glGetQueryObjectuivGLASS(GLuint id, GLenum pname, GLuint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    unsigned long long value = 0;
    if (!queryObjectValue(ctx, id, pname, value) || !params) return;
    // Saturated: the 64-bit form gives the whole count (<GL/glass_statistics.h>).
    constexpr unsigned long long largest = std::numeric_limits<GLuint>::max();
    *params = static_cast<GLuint>(value < largest ? value : largest);
  });
}

void glGetQueryObjectui64vGLASS(GLuint id, GLenum pname, GLuint64GLASS* params) {
  glass::gl::executeNow([=](Context& ctx) {
    unsigned long long value = 0;
    if (queryObjectValue(ctx, id, pname, value) && params) *params = value;
  });
}

}  // extern "C"
