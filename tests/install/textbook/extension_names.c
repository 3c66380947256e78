/* A textbook-style program of the GL 1.3/1.4 era, which names everything by its extension: it
 * asks for the extensions with gluCheckExtension, then draws with GL_ARB_multitexture and
 * GL_ARB_texture_env_combine (glActiveTextureARB, GL_COMBINE_ARB), GL_EXT_fog_coord
 * (glFogCoordfEXT), GL_EXT_secondary_color, GL_EXT_multi_draw_arrays and
 * GL_ARB_texture_cube_map's names, and checks a few pixels. Built unchanged against an installed
 * glass by the install test. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <glass/context.h>

#include <stdio.h>

static const char *needed[] = {"GL_ARB_multitexture", "GL_ARB_texture_env_combine",
                               "GL_EXT_fog_coord", "GL_EXT_secondary_color",
                               "GL_EXT_multi_draw_arrays", "GL_ARB_texture_cube_map",
                               "GL_EXT_texture_object", "GL_SGIS_texture_edge_clamp"};

static int pixel_near(int x, int y, int r, int g, int b)
{
  GLubyte p[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  if (p[0] - r > 2 || r - p[0] > 2 || p[1] - g > 2 || g - p[1] > 2 || p[2] - b > 2 || b - p[2] > 2) {
    fprintf(stderr, "pixel (%d, %d) is %d %d %d, expected %d %d %d\n", x, y, p[0], p[1], p[2], r, g, b);
    return 0;
  }
  return 1;
}

int main(void)
{
  GlassContext *ctx = glassCreateContext(64, 64);
  const GLubyte *extensions;
  GLubyte texels[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
  GLint first[2] = {0, 4};
  GLsizei count[2] = {4, 4};
  GLfloat quads[8][2] = {{0, 0}, {32, 0}, {32, 32}, {0, 32}, {32, 32}, {64, 32}, {64, 64}, {32, 64}};
  GLuint texture;
  GLint units = 0;
  unsigned i;
  int ok = 1;
  if (!ctx || !glassMakeCurrent(ctx)) return 1;

  extensions = glGetString(GL_EXTENSIONS);
  for (i = 0; i < sizeof needed / sizeof needed[0]; ++i) {
    if (!gluCheckExtension((const GLubyte *)needed[i], extensions)) {
      fprintf(stderr, "%s is missing\n", needed[i]);
      return 1;
    }
  }
  glGetIntegerv(GL_MAX_TEXTURE_UNITS_ARB, &units);
  if (units < 2) return 1;

  glMatrixMode(GL_PROJECTION);
  gluOrtho2D(0, 64, 0, 64);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  /* A 2 x 2 texture on unit 1, combined as texture - primary colour with GL_SUBTRACT_ARB. */
  glActiveTextureARB(GL_TEXTURE1_ARB);
  glGenTexturesEXT(1, &texture);
  glBindTextureEXT(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE_SGIS);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE_SGIS);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE_ARB);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB_ARB, GL_SUBTRACT_ARB);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB_ARB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB_ARB, GL_PRIMARY_COLOR_ARB);
  glEnable(GL_TEXTURE_2D);
  glColor3ub(0, 0, 64);
  glBegin(GL_QUADS);
  glMultiTexCoord2fARB(GL_TEXTURE1_ARB, 0, 0);
  glVertex2f(0, 0);
  glMultiTexCoord2fARB(GL_TEXTURE1_ARB, 1, 0);
  glVertex2f(64, 0);
  glMultiTexCoord2fARB(GL_TEXTURE1_ARB, 1, 1);
  glVertex2f(64, 64);
  glMultiTexCoord2fARB(GL_TEXTURE1_ARB, 0, 1);
  glVertex2f(0, 64);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glActiveTextureARB(GL_TEXTURE0_ARB);
  ok = ok && pixel_near(8, 8, 255, 0, 0) && pixel_near(56, 8, 0, 255, 0) &&
       pixel_near(8, 56, 0, 0, 191) && pixel_near(56, 56, 255, 255, 191);

  /* Two quads in one call of glMultiDrawArraysEXT, fogged by their fog coordinates to grey and
   * with a secondary colour added. */
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 1.0f);
  glFogi(GL_FOG_COORDINATE_SOURCE_EXT, GL_FOG_COORDINATE_EXT);
  glFogCoordfEXT(0.5f);
  glEnable(GL_COLOR_SUM_EXT);
  glSecondaryColor3fEXT(0.0f, 0.5f, 0.0f);
  glColor3f(0.5f, 0.0f, 0.0f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, quads);
  glMultiDrawArraysEXT(GL_QUADS, first, count, 2);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_FOG);
  glDisable(GL_COLOR_SUM_EXT);
  /* Fog factor (1 - 0.5) / 1 = 0.5 mixes (0.5, 0.5, 0) with the fog colour black. */
  ok = ok && pixel_near(16, 16, 64, 64, 0) && pixel_near(48, 48, 64, 64, 0) &&
       pixel_near(48, 16, 0, 0, 0);

  ok = ok && glGetError() == GL_NO_ERROR;
  glassDestroyContext(ctx);
  printf("extension names: %s\n", ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
