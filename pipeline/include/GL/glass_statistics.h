/* glass: <GL/glass_statistics.h>, the GL_GLASS_pipeline_statistics extension (docs/teaching.md,
 * "Counting through a GL query").
 *
 * The counts GLASS_STATS prints per frame, for the commands a program chooses, through query
 * objects in the style of GL_ARB_occlusion_query (OpenGL 1.5, section 4.1.6) and
 * GL_ARB_pipeline_statistics_query, which glass, an OpenGL 1.4 implementation, does not have:
 *
 *   GLuint query;
 *   glGenQueriesGLASS(1, &query);
 *   glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, query);
 *   ... draw ...
 *   glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
 *   GLuint fragments, depthFailed;
 *   glGetQueryObjectuivGLASS(query, GL_FRAGMENTS_GENERATED_GLASS, &fragments);
 *   glGetQueryObjectuivGLASS(query, GL_FRAGMENTS_DEPTH_FAILED_GLASS, &depthFailed);
 *
 * One query object holds every count at once: each count is a pname of glGetQueryObject*GLASS,
 * where GL_ARB_pipeline_statistics_query has one target, and so one query, per count. Results
 * are available as soon as glEndQueryGLASS returns (GL_QUERY_RESULT_AVAILABLE_GLASS is always
 * GL_TRUE). glGetQueryObjectuivGLASS saturates a count above 2^32 - 1; the ui64v form does not.
 *
 * Errors, as GL 1.5 gives them for occlusion queries: GL_INVALID_ENUM for a target other than
 * GL_PIPELINE_STATISTICS_GLASS or an unknown pname; GL_INVALID_OPERATION for glBeginQueryGLASS
 * while a query is active or with the name 0, glEndQueryGLASS without an active query,
 * glGetQueryObject*GLASS of a name that is not a query object or of the active query, and for
 * every command between glBegin and glEnd; GL_INVALID_VALUE for a negative n. As in GL 1.5, any
 * unused name other than 0 may be given to glBeginQueryGLASS, which makes it a query object, and
 * glBeginQueryGLASS and glEndQueryGLASS are compiled into display lists; the other commands are
 * not. Query objects belong to their context (they are not shared).
 *
 * The enumerants 0x474C00xx ("GL" in ASCII) lie far above every range the OpenGL registry
 * assigns, as GL_GLASS_bump_map's in <GL/gl.h>. */
#ifndef GLASS_GL_GLASS_STATISTICS_H
#define GLASS_GL_GLASS_STATISTICS_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#ifndef GL_GLASS_pipeline_statistics
#define GL_GLASS_pipeline_statistics 1
typedef unsigned long long GLuint64GLASS;
/* The query target. */
#define GL_PIPELINE_STATISTICS_GLASS             0x474C0010
/* glGetQueryivGLASS pnames. */
#define GL_CURRENT_QUERY_GLASS                   0x474C0011
#define GL_QUERY_COUNTER_BITS_GLASS              0x474C0012
/* glGetQueryObject*GLASS pnames: the result is available, and each count, in the order of
 * GLASS_STATS's report (docs/teaching.md says what each counts). */
#define GL_QUERY_RESULT_AVAILABLE_GLASS          0x474C0013
#define GL_VERTICES_SUBMITTED_GLASS              0x474C0020
#define GL_PRIMITIVES_SUBMITTED_GLASS            0x474C0021
#define GL_POINTS_SUBMITTED_GLASS                0x474C0022
#define GL_LINES_SUBMITTED_GLASS                 0x474C0023
#define GL_TRIANGLES_SUBMITTED_GLASS             0x474C0024
#define GL_PRIMITIVES_CULLED_GLASS               0x474C0025
#define GL_PRIMITIVES_CLIPPED_AWAY_GLASS         0x474C0026
#define GL_PRIMITIVES_CLIPPED_GLASS              0x474C0027
#define GL_PRIMITIVES_MADE_BY_CLIPPING_GLASS     0x474C0028
#define GL_FRAGMENTS_GENERATED_GLASS             0x474C0029
#define GL_FRAGMENTS_SCISSOR_FAILED_GLASS        0x474C002A
#define GL_FRAGMENTS_ALPHA_FAILED_GLASS          0x474C002B
#define GL_FRAGMENTS_STENCIL_FAILED_GLASS        0x474C002C
#define GL_FRAGMENTS_DEPTH_FAILED_GLASS          0x474C002D
#define GL_FRAGMENTS_PASSED_GLASS                0x474C002E
#define GL_TEXEL_READS_GLASS                     0x474C002F

GLAPI void GLAPIENTRY glGenQueriesGLASS(GLsizei n, GLuint *ids);
GLAPI void GLAPIENTRY glDeleteQueriesGLASS(GLsizei n, const GLuint *ids);
GLAPI GLboolean GLAPIENTRY glIsQueryGLASS(GLuint id);
GLAPI void GLAPIENTRY glBeginQueryGLASS(GLenum target, GLuint id);
GLAPI void GLAPIENTRY glEndQueryGLASS(GLenum target);
GLAPI void GLAPIENTRY glGetQueryivGLASS(GLenum target, GLenum pname, GLint *params);
GLAPI void GLAPIENTRY glGetQueryObjectuivGLASS(GLuint id, GLenum pname, GLuint *params);
GLAPI void GLAPIENTRY glGetQueryObjectui64vGLASS(GLuint id, GLenum pname, GLuint64GLASS *params);

typedef void (GLAPIENTRYP PFNGLGENQUERIESGLASSPROC)(GLsizei n, GLuint *ids);
typedef void (GLAPIENTRYP PFNGLDELETEQUERIESGLASSPROC)(GLsizei n, const GLuint *ids);
typedef GLboolean (GLAPIENTRYP PFNGLISQUERYGLASSPROC)(GLuint id);
typedef void (GLAPIENTRYP PFNGLBEGINQUERYGLASSPROC)(GLenum target, GLuint id);
typedef void (GLAPIENTRYP PFNGLENDQUERYGLASSPROC)(GLenum target);
typedef void (GLAPIENTRYP PFNGLGETQUERYIVGLASSPROC)(GLenum target, GLenum pname, GLint *params);
typedef void (GLAPIENTRYP PFNGLGETQUERYOBJECTUIVGLASSPROC)(GLuint id, GLenum pname, GLuint *params);
typedef void (GLAPIENTRYP PFNGLGETQUERYOBJECTUI64VGLASSPROC)(GLuint id, GLenum pname, GLuint64GLASS *params);
#endif /* GL_GLASS_pipeline_statistics */

#ifdef __cplusplus
}
#endif

#endif /* GLASS_GL_GLASS_STATISTICS_H */
