/* An off-screen rendering program as programs written for Mesa's OSMesa are (in the style of
 * Mesa's demo osdemo.c): create a context, make it current into a malloc'd buffer, draw lit
 * solids, and write the buffer, here as a binary PPM. It includes only <GL/osmesa.h> and
 * <GL/glu.h>, and the test osmesa.osdemo builds it unchanged against glass's osmesa.pc and
 * against Mesa's (Debian's libosmesa6-dev).
 *
 *   osdemo OUTPUT.ppm */
#include <GL/osmesa.h>
#include <GL/glu.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define WIDTH 400
#define HEIGHT 300

static void torus(float r, float R, int nsides, int rings)
{
  const float pi = 3.14159265358979f;
  for (int i = 0; i < rings; i++) {
    float theta = (float)i * 2.0f * pi / rings;
    float theta1 = (float)(i + 1) * 2.0f * pi / rings;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= nsides; j++) {
      float phi = (float)j * 2.0f * pi / nsides;
      for (int k = 1; k >= 0; k--) {
        float t = k ? theta1 : theta;
        glNormal3f(cosf(t) * cosf(phi), -sinf(t) * cosf(phi), sinf(phi));
        glVertex3f(cosf(t) * (R + r * cosf(phi)), -sinf(t) * (R + r * cosf(phi)), r * sinf(phi));
      }
    }
    glEnd();
  }
}

static void material(float r, float g, float b)
{
  const GLfloat colour[4] = {r, g, b, 1.0f};
  const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colour);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
}

static void render_image(void)
{
  const GLfloat light_ambient[] = {0.0f, 0.0f, 0.0f, 1.0f};
  const GLfloat light_diffuse[] = {1.0f, 1.0f, 1.0f, 1.0f};
  const GLfloat light_specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
  const GLfloat light_position[] = {1.0f, 1.0f, 1.0f, 0.0f};
  GLUquadricObj *q = gluNewQuadric();

  glLightfv(GL_LIGHT0, GL_AMBIENT, light_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, light_specular);
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.5, 2.5, -1.875, 1.875, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glPushMatrix();
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);

  glPushMatrix();
  glTranslatef(-0.75f, 0.5f, 0.0f);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  material(0.9f, 0.2f, 0.2f);
  torus(0.275f, 0.85f, 20, 40);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-0.75f, -0.5f, 0.0f);
  glRotatef(270.0f, 1.0f, 0.0f, 0.0f);
  material(0.2f, 0.9f, 0.2f);
  gluCylinder(q, 1.0, 0.0, 2.0, 32, 8);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.75f, 0.0f, -1.0f);
  material(0.3f, 0.3f, 1.0f);
  gluSphere(q, 1.0, 40, 20);
  glPopMatrix();

  glPopMatrix();

  /* OSMesa promises the buffer's contents after glFinish. */
  glFinish();
  gluDeleteQuadric(q);
}

/* The buffer holds RGBA rows bottom first (OSMESA_Y_UP); a PPM starts with the top row. */
static int write_ppm(const char *path, const GLubyte *buffer, int width, int height)
{
  FILE *f = fopen(path, "wb");
  if (!f) return 0;
  fprintf(f, "P6\n%d %d\n255\n", width, height);
  for (int y = height - 1; y >= 0; y--) {
    for (int x = 0; x < width; x++) {
      const GLubyte *p = buffer + ((size_t)y * width + x) * 4;
      fputc(p[0], f);
      fputc(p[1], f);
      fputc(p[2], f);
    }
  }
  return fclose(f) == 0;
}

int main(int argc, char *argv[])
{
  OSMesaContext ctx;
  void *buffer;
  int ok;

  if (argc != 2) {
    fprintf(stderr, "usage: %s OUTPUT.ppm\n", argv[0]);
    return 2;
  }
#if OSMESA_MAJOR_VERSION * 100 + OSMESA_MINOR_VERSION >= 305
  ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
#else
  ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
#endif
  if (!ctx) {
    fprintf(stderr, "OSMesaCreateContext failed\n");
    return 1;
  }
  buffer = malloc(WIDTH * HEIGHT * 4 * sizeof(GLubyte));
  if (!buffer) {
    fprintf(stderr, "cannot allocate the image buffer\n");
    return 1;
  }
  if (!OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
    fprintf(stderr, "OSMesaMakeCurrent failed\n");
    return 1;
  }
  {
    GLint z, s, a;
    glGetIntegerv(GL_DEPTH_BITS, &z);
    glGetIntegerv(GL_STENCIL_BITS, &s);
    glGetIntegerv(GL_ACCUM_RED_BITS, &a);
    printf("%s: depth %d, stencil %d, accum %d bits\n", (const char *)glGetString(GL_RENDERER), z,
           s, a);
  }

  render_image();
  ok = write_ppm(argv[1], buffer, WIDTH, HEIGHT);

  free(buffer);
  OSMesaDestroyContext(ctx);
  if (!ok) {
    fprintf(stderr, "cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
