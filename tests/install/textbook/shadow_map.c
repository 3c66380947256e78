/* A textbook-style shadow map, written with the GL_ARB_depth_texture and GL_ARB_shadow names:
 * the depth buffer seen from a light above a floor and a raised square is copied into a
 * GL_DEPTH_COMPONENT24_ARB texture; the floor is then drawn from the eye with eye-linear texture
 * coordinates in the light's clip space and GL_COMPARE_R_TO_TEXTURE_ARB, so that it is white where
 * the light sees it and black in the square's shadow. Built unchanged against an installed glass
 * by the install test, which checks the pixels it prints. */
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <glass/context.h>

#include <stdio.h>

enum { SIZE = 64 };

static void floor_and_square(int with_square)
{
  glBegin(GL_QUADS);
  glVertex3f(-2, 0, 2);
  glVertex3f(2, 0, 2);
  glVertex3f(2, 0, -2);
  glVertex3f(-2, 0, -2);
  if (with_square) {
    glVertex3f(-0.5f, 1, 0.5f);
    glVertex3f(0.5f, 1, 0.5f);
    glVertex3f(0.5f, 1, -0.5f);
    glVertex3f(-0.5f, 1, -0.5f);
  }
  glEnd();
}

static void light_transform(void)
{
  glOrtho(-2.5, 2.5, -2.5, 2.5, 1.0, 6.0);
  gluLookAt(0, 4, 0, 0, 0, 0, 0, 0, -1);
}

static int brightness(int x, int y)
{
  GLubyte p[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return p[0];
}

int main(void)
{
  GlassContext *ctx = glassCreateContext(SIZE, SIZE);
  GLfloat m[16], plane[4];
  GLuint map;
  GLint bits = 0;
  int i, lit, shadowed, ok;
  if (!ctx || !glassMakeCurrent(ctx)) return 1;
  if (!gluCheckExtension((const GLubyte *)"GL_ARB_depth_texture", glGetString(GL_EXTENSIONS)) ||
      !gluCheckExtension((const GLubyte *)"GL_ARB_shadow", glGetString(GL_EXTENSIONS))) {
    fprintf(stderr, "no GL_ARB_depth_texture or GL_ARB_shadow\n");
    return 1;
  }
  glEnable(GL_DEPTH_TEST);

  /* The light's view into the depth buffer, then into the texture. */
  glClear(GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  light_transform();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 4.0f);
  floor_and_square(1);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glGenTextures(1, &map);
  glBindTexture(GL_TEXTURE_2D, map);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24_ARB, 0, 0, SIZE, SIZE, 0);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE_ARB, &bits);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_COMPARE_R_TO_TEXTURE_ARB);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC_ARB, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE_ARB, GL_LUMINANCE);

  /* The light's matrix: bias * light projection * light view. */
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.5f);
  glScalef(0.5f, 0.5f, 0.5f);
  light_transform();
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  /* The floor alone, from straight above, white where lit. */
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2, 2, -2, 2, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(90, 1, 0, 0);
  /* Eye-linear planes: the rows of the light's matrix, given under the camera's view, so that
   * the GL's inverse of it makes them act on the floor's object coordinates. */
  for (i = 0; i < 4; ++i) {
    plane[0] = m[i];
    plane[1] = m[4 + i];
    plane[2] = m[8 + i];
    plane[3] = m[12 + i];
    glTexGeni(GL_S + i, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S + i, GL_EYE_PLANE, plane);
    glEnable(GL_TEXTURE_GEN_S + i);
  }
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1, 1, 1);
  floor_and_square(0);

  lit = brightness(4, 4);
  shadowed = brightness(SIZE / 2, SIZE / 2);
  ok = bits == 24 && lit == 255 && shadowed == 0 && glGetError() == GL_NO_ERROR;
  printf("shadow map: depth bits %d, lit floor %d, shadowed floor %d: %s\n", bits, lit, shadowed,
         ok ? "ok" : "FAILED");
  glassDestroyContext(ctx);
  return ok ? 0 : 1;
}
