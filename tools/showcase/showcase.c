/* The showcase: one picture made only of the GL 1.x calls glass implements today.
 *
 *   - a sky gradient and stars (a smooth-shaded quad, points of two sizes);
 *   - a floor of lines in perspective, fading into the distance (gluPerspective, gluLookAt);
 *   - two interlocking tori, smooth shaded, that pass through each other (depth test); their
 *     shading is computed here per vertex, since GL lighting is not part of this picture;
 *   - on the left, the study guide's Sierpinski triangle (Listing 4's recursion with
 *     glPushMatrix / glScalef / glTranslatef), coloured by where each piece lands;
 *   - on the right, a cardioid drawn as string art: 120 lines, point k joined to point 2k.
 *
 * Usage: showcase OUTPUT.png */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"
#include "lcg.h"

enum { WIDTH = 960, HEIGHT = 540 };

static const float PI = 3.14159265358979f;

/* A saturated colour for a hue in [0, 1), scaled by brightness. */
static void hueColor(float hue, float brightness)
{
  const float r = 0.5f + 0.5f * cosf(2.0f * PI * hue);
  const float g = 0.5f + 0.5f * cosf(2.0f * PI * (hue - 1.0f / 3.0f));
  const float b = 0.5f + 0.5f * cosf(2.0f * PI * (hue + 1.0f / 3.0f));
  glColor3f(r * brightness, g * brightness, b * brightness);
}

static void sky(void)
{
  Lcg random = {7u};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glBegin(GL_QUADS);
  glColor3f(0.16f, 0.08f, 0.26f);
  glVertex2f(0.0f, 0.0f);
  glVertex2f((float)WIDTH, 0.0f);
  glColor3f(0.01f, 0.02f, 0.07f);
  glVertex2f((float)WIDTH, (float)HEIGHT);
  glVertex2f(0.0f, (float)HEIGHT);
  glEnd();

  for (int size = 1; size <= 2; ++size) {
    glPointSize((float)size);
    glBegin(GL_POINTS);
    for (int i = 0; i < (size == 1 ? 260 : 40); ++i) {
      const float x = lcg_range(&random, 0.0f, (float)WIDTH);
      const float y = lcg_range(&random, 0.45f * HEIGHT, (float)HEIGHT);
      const float brightness = lcg_range(&random, 0.35f, 1.0f);
      glColor3f(brightness, brightness, 0.9f * brightness + 0.1f);
      glVertex2f(x, y);
    }
    glEnd();
  }
  glPointSize(1.0f);
}

static void perspectiveCamera(void)
{
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 0.5, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 1.6, 7.0, 0.0, 0.6, 0.0, 0.0, 1.0, 0.0);
}

/* Grid lines on the plane y = -0.9; each vertex fades towards the sky colour with distance. */
static void floorGrid(void)
{
  glBegin(GL_LINES);
  for (int i = -30; i <= 30; ++i) {
    glColor3f(0.2f, 0.75f, 0.9f);
    glVertex3f((float)i, -0.9f, 6.0f);
    glColor3f(0.12f, 0.06f, 0.22f);
    glVertex3f((float)i, -0.9f, -40.0f);
  }
  for (int k = 0; k <= 46; ++k) {
    const float z = 6.0f - (float)k;
    const float fade = (float)k / 46.0f;
    glColor3f(0.2f + (0.12f - 0.2f) * fade, 0.75f + (0.06f - 0.75f) * fade,
              0.9f + (0.22f - 0.9f) * fade);
    glVertex3f(-30.0f, -0.9f, z);
    glVertex3f(30.0f, -0.9f, z);
  }
  glEnd();
}

/* A torus around the z axis of its frame, shaded per vertex like GL's lighting would: ambient,
 * diffuse and a Blinn-Phong highlight, for a light above and to the left of the eye. The
 * normals are taken to eye space with the modelview matrix, read back with glGetFloatv (it holds
 * only rotations and translations here, so its upper 3 x 3 part turns normals correctly). */
static void shadedTorus(float red, float green, float blue)
{
  const int rings = 64, sides = 28;
  const float major = 1.0f, minor = 0.32f;
  const float light[3] = {-0.4f, 0.6f, 0.69282f}; /* unit length, eye space */
  const float halfway[3] = {-0.21739f, 0.32609f, 0.92001f}; /* normalize(light + (0, 0, 1)) */
  float m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  for (int i = 0; i < rings; ++i) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= sides; ++j)
      for (int k = 1; k >= 0; --k) {
        const float u = 2.0f * PI * (float)(i + k) / (float)rings;
        const float v = 2.0f * PI * (float)j / (float)sides;
        const float n[3] = {cosf(v) * cosf(u), cosf(v) * sinf(u), sinf(v)};
        const float eyeNormal[3] = {m[0] * n[0] + m[4] * n[1] + m[8] * n[2],
                                    m[1] * n[0] + m[5] * n[1] + m[9] * n[2],
                                    m[2] * n[0] + m[6] * n[1] + m[10] * n[2]};
        const float r = major + minor * cosf(v);
        float diffuse = 0.0f, specular = 0.0f;
        for (int a = 0; a < 3; ++a) {
          diffuse += eyeNormal[a] * light[a];
          specular += eyeNormal[a] * halfway[a];
        }
        diffuse = diffuse > 0.0f ? diffuse : 0.0f;
        specular = specular > 0.0f ? powf(specular, 40.0f) : 0.0f;
        const float shade = 0.18f + 0.82f * diffuse;
        float c[3] = {red * shade + 0.8f * specular, green * shade + 0.8f * specular,
                      blue * shade + 0.8f * specular};
        for (int a = 0; a < 3; ++a) c[a] = c[a] > 1.0f ? 1.0f : c[a];
        glColor3fv(c);
        glVertex3f(r * cosf(u), r * sinf(u), minor * sinf(v));
      }
    glEnd();
  }
}

static void interlockingTori(void)
{
  glPushMatrix();
  glTranslatef(0.0f, 0.75f, 0.0f);
  glRotatef(-18.0f, 0.0f, 1.0f, 0.0f);
  glRotatef(12.0f, 1.0f, 0.0f, 0.0f);

  glPushMatrix();
  glTranslatef(-0.55f, 0.0f, 0.0f);
  shadedTorus(1.0f, 0.62f, 0.16f);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.55f, 0.0f, 0.0f);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  shadedTorus(0.15f, 0.8f, 0.75f);
  glPopMatrix();

  glPopMatrix();
}

/* Listing 4's recursion. Each smallest triangle is coloured by where the modelview matrix puts
 * it, read back with glGetFloatv, so the colours run across the whole figure. */
static void sierpinski(int step)
{
  if (step == 0) {
    float m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    const float x = m[12], y = m[13]; /* where the triangle's corner (0, 0) lands */
    glBegin(GL_TRIANGLES);
    const float hue = 0.1f + 0.45f * x + 0.7f * y;
    hueColor(hue, 1.0f);
    glVertex3f(1.0f, 0.0f, 0.0f);
    hueColor(hue + 0.05f, 1.0f);
    glVertex3f(0.0f, 1.0f, 0.0f);
    hueColor(hue + 0.025f, 0.8f);
    glVertex3f(0.0f, 0.0f, 0.0f);
    glEnd();
    return;
  }
  glPushMatrix();
  glPushMatrix();
  glScalef(0.5f, 0.5f, 1.0f);
  sierpinski(step - 1);
  glPopMatrix();
  glTranslatef(0.5f, 0.0f, 0.0f);
  glScalef(0.5f, 0.5f, 1.0f);
  sierpinski(step - 1);
  glPopMatrix();
  glTranslatef(0.0f, 0.5f, 0.0f);
  glScalef(0.5f, 0.5f, 1.0f);
  sierpinski(step - 1);
}

/* Sets a square viewport of the given size at (x, y) showing [-0.1, 1.1]^2, as the study guide's
 * resizeWindow does for a square window. */
static void squarePanel(int x, int y, int size)
{
  glViewport(x, y, size, size);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-0.1, 1.1, -0.1, 1.1, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void cardioid(void)
{
  const int points = 120;
  glBegin(GL_LINES);
  for (int k = 0; k < points; ++k) {
    const float a = 2.0f * PI * (float)k / (float)points;
    const float b = 2.0f * PI * (float)((2 * k) % points) / (float)points;
    hueColor((float)k / (float)points, 0.9f);
    glVertex2f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a));
    hueColor((float)k / (float)points + 0.25f, 0.8f);
    glVertex2f(0.5f + 0.5f * cosf(b), 0.5f + 0.5f * sinf(b));
  }
  glEnd();
}

static void draw(void)
{
  glViewport(0, 0, WIDTH, HEIGHT);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);

  sky(); /* behind everything: drawn without the depth test */

  glEnable(GL_DEPTH_TEST);
  perspectiveCamera();
  floorGrid();
  interlockingTori();

  /* The flat panels go over the scene, so their depth is cleared away first. */
  glClear(GL_DEPTH_BUFFER_BIT);
  squarePanel(20, 130, 300);
  sierpinski(6);

  squarePanel(WIDTH - 20 - 300, 130, 300);
  cardioid();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
