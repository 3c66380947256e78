/* glass: the OSMesa 11.2 off-screen interface, rendering into memory the caller owns.
 *
 * The names, prototypes and enum values are OSMesa's (Mesa's include/GL/osmesa.h, version 11.2),
 * so a program written for Mesa's libOSMesa compiles and links unchanged against glass
 * (pkg-config osmesa). docs/osmesa.md says what glass supports and where it differs from Mesa:
 * in short, every format below with GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_FLOAT (565 with
 * GL_UNSIGNED_SHORT_5_6_5); the caller's buffer holds the picture after glFlush, glFinish,
 * OSMesaGetColorBuffer and OSMesaMakeCurrent to another buffer; contexts on different threads
 * render at the same time; OSMesaPostprocess filters are not supported.
 *
 *   OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
 *   void *buffer = malloc(width * height * 4);
 *   OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, width, height);
 *   ... GL calls ...
 *   glFinish();            (buffer now holds the picture, bottom row first)
 *   OSMesaDestroyContext(ctx);
 */
#ifndef GLASS_GL_OSMESA_H
#define GLASS_GL_OSMESA_H

#ifndef OSMESA_H
#define OSMESA_H
#endif

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OSMESA_MAJOR_VERSION 11
#define OSMESA_MINOR_VERSION 2
#define OSMESA_PATCH_VERSION 0

/* Buffer formats: the format of OSMesaCreateContext and OSMESA_FORMAT. OSMESA_COLOR_INDEX is
 * named for source compatibility; glass, like Mesa since 7.x, refuses it. */
#define OSMESA_COLOR_INDEX GL_COLOR_INDEX
#define OSMESA_RGBA GL_RGBA
#define OSMESA_BGRA 0x1
#define OSMESA_ARGB 0x2
#define OSMESA_RGB GL_RGB
#define OSMESA_BGR 0x4
#define OSMESA_RGB_565 0x5

/* OSMesaPixelStore and OSMesaGetIntegerv. */
#define OSMESA_ROW_LENGTH 0x10
#define OSMESA_Y_UP 0x11

/* OSMesaGetIntegerv. */
#define OSMESA_WIDTH 0x20
#define OSMESA_HEIGHT 0x21
#define OSMESA_FORMAT 0x22
#define OSMESA_TYPE 0x23
#define OSMESA_MAX_WIDTH 0x24
#define OSMESA_MAX_HEIGHT 0x25

/* OSMesaCreateContextAttribs. */
#define OSMESA_DEPTH_BITS 0x30
#define OSMESA_STENCIL_BITS 0x31
#define OSMESA_ACCUM_BITS 0x32
#define OSMESA_PROFILE 0x33
#define OSMESA_CORE_PROFILE 0x34
#define OSMESA_COMPAT_PROFILE 0x35
#define OSMESA_CONTEXT_MAJOR_VERSION 0x36
#define OSMESA_CONTEXT_MINOR_VERSION 0x37

typedef struct osmesa_context *OSMesaContext;

/* A context whose buffer will have the given format (OSMESA_RGBA, _BGRA, _ARGB, _RGB, _BGR,
 * _RGB_565), sharing display lists with sharelist unless it is NULL; NULL for another format. */
GLAPI OSMesaContext GLAPIENTRY
OSMesaCreateContext( GLenum format, OSMesaContext sharelist );

/* The same, with the depth, stencil and accumulation bits asked for (each >= 0). glass always
 * gives 24 depth bits, 8 stencil bits and 16 accumulation bits per channel. */
GLAPI OSMesaContext GLAPIENTRY
OSMesaCreateContextExt( GLenum format, GLint depthBits, GLint stencilBits,
                        GLint accumBits, OSMesaContext sharelist);

/* The same from a list of (attribute, value) pairs ending with 0: OSMESA_FORMAT,
 * OSMESA_DEPTH_BITS, OSMESA_STENCIL_BITS, OSMESA_ACCUM_BITS, OSMESA_PROFILE (the compatibility
 * profile only) and OSMESA_CONTEXT_MAJOR/MINOR_VERSION (up to the version glGetString reports).
 * NULL, with the reason on stderr, for another attribute, a core profile or a newer version. */
GLAPI OSMesaContext GLAPIENTRY
OSMesaCreateContextAttribs( const int *attribList, OSMesaContext sharelist );

/* Frees the context; if it is current on the calling thread, no context is current after. The
 * caller's buffer is not written. */
GLAPI void GLAPIENTRY
OSMesaDestroyContext( OSMesaContext ctx );

/* Binds ctx to the caller's buffer of width x height pixels of the context's format with
 * components of the given type, and makes it current on the calling thread. The buffer holds
 * rows bottom first (OSMESA_Y_UP) of OSMESA_ROW_LENGTH pixels, and must stay valid while bound.
 * Its pixels become the colour buffer's. The first binding sets the viewport and scissor box to
 * the whole buffer. OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) releases the current context.
 * GL_FALSE, changing nothing, for a NULL context or buffer, a type the format does not take,
 * or a size below 1 or above OSMESA_MAX_WIDTH x OSMESA_MAX_HEIGHT. */
GLAPI GLboolean GLAPIENTRY
OSMesaMakeCurrent( OSMesaContext ctx, void *buffer, GLenum type,
                   GLsizei width, GLsizei height );

/* The context current on the calling thread, or NULL. */
GLAPI OSMesaContext GLAPIENTRY
OSMesaGetCurrentContext( void );

/* For the current context: OSMESA_ROW_LENGTH (pixels per row of the buffer; 0, the default,
 * means the width) or OSMESA_Y_UP (non-zero, the default: the first row is the bottom one). */
GLAPI void GLAPIENTRY
OSMesaPixelStore( GLint pname, GLint value );

/* OSMESA_WIDTH, _HEIGHT, _FORMAT, _TYPE, _ROW_LENGTH, _Y_UP, _MAX_WIDTH, _MAX_HEIGHT. */
GLAPI void GLAPIENTRY
OSMesaGetIntegerv( GLint pname, GLint *value );

/* A copy of the depth buffer taken now and refreshed at each glFlush and glFinish: width x
 * height values of 4 bytes, bottom row first, the depth in the low 24 bits and the stencil
 * value in the high 8. GL_FALSE when the context was never bound. */
GLAPI GLboolean GLAPIENTRY
OSMesaGetDepthBuffer( OSMesaContext c, GLint *width, GLint *height,
                      GLint *bytesPerValue, void **buffer );

/* The caller's buffer bound to c, its size and format, holding the picture drawn so far.
 * GL_FALSE when the context was never bound. */
GLAPI GLboolean GLAPIENTRY
OSMesaGetColorBuffer( OSMesaContext c, GLint *width, GLint *height,
                      GLint *format, void **buffer );

typedef void (*OSMESAproc)();

/* The address of a GL entry point glass implements or of an OSMesa function; NULL for any
 * other name. */
GLAPI OSMESAproc GLAPIENTRY
OSMesaGetProcAddress( const char *funcName );

/* Colour clamping for GL_FLOAT buffers. glass's colour buffer holds 8 bits per component in
 * [0, 1], so colours are always clamped; the call is accepted and changes nothing. */
GLAPI void GLAPIENTRY
OSMesaColorClamp(GLboolean enable);

/* Mesa's post-processing filters (anti-aliasing, colour effects) are not supported: the call
 * prints a message on stderr and changes nothing. */
GLAPI void GLAPIENTRY
OSMesaPostprocess(OSMesaContext osmesa, const char *filter,
                  unsigned enable_value);

#ifdef __cplusplus
}
#endif

#endif /* GLASS_GL_OSMESA_H */
