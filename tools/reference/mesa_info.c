/* Prints the GL version and renderer of the Mesa build that makes the reference images, for
 * reference_images/README.md. */
#include <glass/context.h>

#include <GL/gl.h>

#include <stdio.h>

int main(void) {
  GlassContext *ctx = glassCreateContext(16, 16);
  if (!ctx || !glassMakeCurrent(ctx)) {
    fprintf(stderr, "mesa_info: cannot create an OSMesa context\n");
    return 1;
  }
  printf("GL_VERSION: %s\nGL_RENDERER: %s\n", (const char *)glGetString(GL_VERSION),
         (const char *)glGetString(GL_RENDERER));
  glassDestroyContext(ctx);
  return 0;
}
