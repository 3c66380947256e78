// GL_GLASS_pipeline_statistics (<GL/glass_statistics.h>, docs/teaching.md): the query objects of
// a context, which hold the counts frame_statistics.h gathers between glBeginQueryGLASS and
// glEndQueryGLASS. They live beside the context (per_context_table.h): a context whose program
// never used a query carries nothing.
#pragma once

#include <GL/gl.h>

#include <map>

#include "teaching/frame_statistics.h"

namespace glass::gl {

struct Context;

struct StatisticsQueries {
  std::map<GLuint, PipelineCounts> results;  // every query object by name, with its last result
  GLuint active = 0;                         // the query counting now, 0 for none
  bool activeDeleted = false;                // glDeleteQueriesGLASS freed its name while it counted
  GLuint lastGenerated = 0;                  // glGenQueriesGLASS looks for free names above it
};

// The context's query objects, made on first use.
StatisticsQueries& statisticsQueriesOf(const Context& ctx);
// nullptr when the context never used a query.
StatisticsQueries* findStatisticsQueries(const Context& ctx);
void detachStatisticsQueries(const Context& ctx);

}  // namespace glass::gl
