/* glass's headers against the system's (Mesa's <GL/gl.h>, <GL/glext.h> and <GL/glu.h>,
 * freeglut's <GL/freeglut.h>), compiled with -Werror by the test api_coverage.system_headers:
 *  - every GL_ and GLU_ name the system's gl.h and glu.h define is defined by glass's headers
 *    too (system_enum_names.h, written at configure time, has an #error for each missing one),
 *    but for the Mesa, ATI and OES extensions glass does not have;
 *  - then the system's headers are read after glass's: a function declared by both with another
 *    prototype is a conflicting declaration (an error), and a macro defined by both with other
 *    tokens is a redefinition (a warning, an error here). So every prototype and every enum value
 *    glass shares with the system headers is the same. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/freeglut.h>

#include "system_enum_names.h"

/* glass's guards keep the system headers out; lift them, and GLAPI, which Mesa's gl.h defines
 * its own way. */
#undef __gl_h_
#undef __GL_H__
#undef __glu_h__
#undef __GLU_H__
#undef GLAPI
#define GL_GLEXT_PROTOTYPES 1
#include GLASS_SYSTEM_GL_HEADER
#include GLASS_SYSTEM_GLU_HEADER
#include GLASS_SYSTEM_FREEGLUT_HEADER

int main(void) { return 0; }
