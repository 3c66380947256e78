/* All ten primitive types, smooth shaded, with the depth test on, and shapes that pass through
 * each other in depth.
 *
 * A 4 x 3 grid of 120-pixel cells under one orthographic projection; each cell is placed with
 * glTranslatef and holds one primitive type, except the last two: three triangles that overlap
 * cyclically (each is in front of the next somewhere, which no drawing order can resolve without
 * a depth buffer) and a rotated cube. Under glOrtho(..., -1, 1), larger z is nearer.
 *
 * The spec leaves open how quadrilaterals and polygons are split into triangles, and a colour
 * interpolated over a split depends on the split unless the colour is an affine function of
 * position across the face. So every quad and polygon here has affine colours (and is planar),
 * and any split gives the same picture. */
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { CELL = 120, COLUMNS = 4, ROWS = 3 };

static const float PI = 3.14159265358979f;

/* A colour that is an affine function of (x, y) in a cell's unit square. */
static void affineColor(float x, float y) { glColor3f(x, y, 1.0f - 0.5f * (x + y)); }

static void points(void)
{
  /* Sizes 1 to 5, one row each, smooth colours per point. */
  for (int size = 1; size <= 5; ++size) {
    glPointSize((float)size);
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; ++i) {
      const float x = 0.12f + 0.15f * (float)i, y = 0.1f + 0.18f * (float)(size - 1);
      affineColor(x, y);
      glVertex3f(x, y, 0.0f);
    }
    glEnd();
  }
  glPointSize(1.0f);
}

static void lines(void)
{
  /* Lines crossing each other at different depths: the depth test decides who is on top. */
  glBegin(GL_LINES);
  for (int i = 0; i < 6; ++i) {
    const float t = 0.1f + 0.16f * (float)i;
    glColor3f(1.0f, 0.2f, 0.2f);
    glVertex3f(0.05f, t, -0.5f);
    glColor3f(1.0f, 1.0f, 0.2f);
    glVertex3f(0.95f, t, 0.5f);
    glColor3f(0.2f, 0.4f, 1.0f);
    glVertex3f(t, 0.05f, 0.5f);
    glColor3f(0.2f, 1.0f, 1.0f);
    glVertex3f(t, 0.95f, -0.5f);
  }
  glEnd();
}

static void lineStrip(void)
{
  /* A spiral, nearer towards the middle. */
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 60; ++i) {
    const float t = (float)i / 60.0f, angle = 4.0f * PI * t, radius = 0.45f * (1.0f - 0.8f * t);
    glColor3f(1.0f - t, 0.3f + 0.7f * t, 0.5f);
    glVertex3f(0.5f + radius * cosf(angle), 0.5f + radius * sinf(angle), t - 0.5f);
  }
  glEnd();
}

static void lineLoop(void)
{
  /* A five-pointed star drawn as one loop: vertex k joins vertex k + 2 of a pentagon. */
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 5; ++i) {
    const float angle = PI / 2.0f + 4.0f * PI * (float)i / 5.0f;
    glColor3f(0.5f + 0.5f * cosf(angle), 0.5f + 0.5f * sinf(angle), 1.0f - 0.2f * (float)i);
    glVertex3f(0.5f + 0.42f * cosf(angle), 0.5f + 0.42f * sinf(angle), 0.0f);
  }
  glEnd();
}

static void triangles(void)
{
  /* Two triangles that cut through each other: red rises in z to the right, blue falls. */
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.1f, 0.1f);
  glVertex3f(0.05f, 0.15f, -0.6f);
  glColor3f(1.0f, 0.7f, 0.1f);
  glVertex3f(0.95f, 0.3f, 0.6f);
  glColor3f(0.8f, 0.1f, 0.4f);
  glVertex3f(0.4f, 0.95f, 0.0f);
  glColor3f(0.1f, 0.3f, 1.0f);
  glVertex3f(0.05f, 0.6f, 0.6f);
  glColor3f(0.1f, 0.9f, 1.0f);
  glVertex3f(0.95f, 0.85f, -0.6f);
  glColor3f(0.3f, 0.1f, 0.9f);
  glVertex3f(0.6f, 0.05f, 0.0f);
  glEnd();
}

static void triangleStrip(void)
{
  /* A wavy ribbon through a flat green bar at z = 0. */
  glBegin(GL_TRIANGLES);
  glColor3f(0.1f, 0.8f, 0.2f);
  glVertex3f(0.05f, 0.4f, 0.0f);
  glVertex3f(0.95f, 0.4f, 0.0f);
  glVertex3f(0.5f, 0.62f, 0.0f);
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 12; ++i) {
    const float t = (float)i / 12.0f, x = 0.05f + 0.9f * t, z = 0.5f * sinf(2.0f * PI * t);
    glColor3f(1.0f, 0.4f + 0.6f * t, 0.2f);
    glVertex3f(x, 0.25f, z);
    glColor3f(0.6f, 0.2f, 1.0f - t);
    glVertex3f(x, 0.75f, z);
  }
  glEnd();
}

static void triangleFan(void)
{
  /* A disc: white centre, colour wheel rim. */
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex3f(0.5f, 0.5f, 0.0f);
  for (int i = 0; i <= 12; ++i) {
    const float angle = 2.0f * PI * (float)i / 12.0f;
    glColor3f(0.5f + 0.5f * cosf(angle), 0.5f + 0.5f * cosf(angle - 2.0944f),
              0.5f + 0.5f * cosf(angle + 2.0944f));
    glVertex3f(0.5f + 0.45f * cosf(angle), 0.5f + 0.45f * sinf(angle), 0.0f);
  }
  glEnd();
}

static void quads(void)
{
  /* Two planar quads crossing in depth: one tilted about the x axis, one about the y axis. */
  glBegin(GL_QUADS);
  affineColor(0.1f, 0.2f);
  glVertex3f(0.1f, 0.2f, -0.6f);
  affineColor(0.9f, 0.2f);
  glVertex3f(0.9f, 0.2f, -0.6f);
  affineColor(0.9f, 0.8f);
  glVertex3f(0.9f, 0.8f, 0.6f);
  affineColor(0.1f, 0.8f);
  glVertex3f(0.1f, 0.8f, 0.6f);

  glColor3f(0.9f, 0.9f, 0.9f);
  glVertex3f(0.3f, 0.05f, 0.6f);
  glColor3f(0.2f, 0.2f, 0.2f);
  glVertex3f(0.7f, 0.05f, -0.6f);
  glVertex3f(0.7f, 0.95f, -0.6f);
  glColor3f(0.9f, 0.9f, 0.9f);
  glVertex3f(0.3f, 0.95f, 0.6f);
  glEnd();
}

static void quadStrip(void)
{
  /* A ring. Colour and depth depend only on the radius, which is affine across each segment
   * (inner and outer edge are parallel chords), so the split of a quad does not matter. */
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 16; ++i) {
    const float angle = 2.0f * PI * (float)i / 16.0f, c = cosf(angle), s = sinf(angle);
    glColor3f(1.0f, 0.85f, 0.2f);
    glVertex3f(0.5f + 0.22f * c, 0.5f + 0.22f * s, 0.3f);
    glColor3f(0.7f, 0.1f, 0.5f);
    glVertex3f(0.5f + 0.45f * c, 0.5f + 0.45f * s, -0.3f);
  }
  glEnd();
}

static void polygon(void)
{
  /* A convex octagon with affine colours. */
  glBegin(GL_POLYGON);
  for (int i = 0; i < 8; ++i) {
    const float angle = PI / 8.0f + 2.0f * PI * (float)i / 8.0f;
    const float x = 0.5f + 0.45f * cosf(angle), y = 0.5f + 0.45f * sinf(angle);
    affineColor(x, y);
    glVertex3f(x, y, 0.0f);
  }
  glEnd();
}

static void cyclicTriangles(void)
{
  /* Three long triangles, each passing over the next and under the one before. */
  static const float colors[3][3] = {{1.0f, 0.3f, 0.3f}, {0.3f, 1.0f, 0.3f}, {0.3f, 0.5f, 1.0f}};
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; ++i) {
    const float angle = 2.0f * PI * (float)i / 3.0f, c = cosf(angle), s = sinf(angle);
    /* Tip far from the centre and low, base across the centre and high. */
    glColor3f(colors[i][0] * 0.4f, colors[i][1] * 0.4f, colors[i][2] * 0.4f);
    glVertex3f(0.5f + 0.47f * c, 0.5f + 0.47f * s, -0.8f);
    glColor3fv(colors[i]);
    glVertex3f(0.5f - 0.3f * c - 0.12f * s, 0.5f - 0.3f * s + 0.12f * c, 0.8f);
    glVertex3f(0.5f - 0.3f * c + 0.12f * s, 0.5f - 0.3f * s - 0.12f * c, 0.8f);
  }
  glEnd();
}

static void cube(void)
{
  /* A unit cube coloured by position (an RGB cube), turned to show three faces. */
  static const float corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  glPushMatrix();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-40.0f, 0.0f, 1.0f, 0.0f);
  glScalef(0.45f, 0.45f, 0.45f);
  glTranslatef(-0.5f, -0.5f, -0.5f);
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) {
      const float *p = corners[faces[f][k]];
      glColor3fv(p);
      glVertex3fv(p);
    }
  glEnd();
  glPopMatrix();
}

static void draw(void)
{
  static void (*const cells[COLUMNS * ROWS])(void) = {
      points,        lines,       lineStrip, lineLoop,        triangles, triangleStrip,
      triangleFan,   quads,       quadStrip, polygon,         cyclicTriangles, cube};

  glViewport(0, 0, COLUMNS * CELL, ROWS * CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS, 0.0, ROWS, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_SMOOTH);
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* Row by row from the top left, as the list above reads. */
  for (int i = 0; i < COLUMNS * ROWS; ++i) {
    glPushMatrix();
    glTranslatef((float)(i % COLUMNS), (float)(ROWS - 1 - i / COLUMNS), 0.0f);
    cells[i]();
    glPopMatrix();
  }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
