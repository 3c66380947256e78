/* Selection (GL 1.5 specification, section 5.2) as the Red Book's picksquare.c and pickdepth.c
 * use it, drawn so that the picture shows what the hit records said:
 *   left:  a 5 x 5 board of squares named by row and column (two names on the stack). Eight
 *          "clicks" are picked with gluPickMatrix through a 5-pixel region; every hit advances
 *          its square's colour, as in picksquare.c. A square clicked twice advances twice; a
 *          click on a corner between squares hits all four.
 *   right: three overlapping rectangles at different depths (pickdepth.c) and a line and a point
 *          named too; one pick through all of them, then one bar per hit record: its name picks
 *          the colour, its left and right ends are the record's minimum and maximum depth
 *          (divided by 2^32 - 1) across the panel.
 * A hit record count of -1 (overflow) or a GL error fails the program. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <stdio.h>
#include <stdlib.h>

#include "gl_program.h"

enum { SIZE = 250, BOARD = 5 };

static int board[BOARD][BOARD];

static void squares(GLenum mode)
{
  for (int i = 0; i < BOARD; ++i) {
    if (mode == GL_SELECT) glLoadName((GLuint)i);
    for (int j = 0; j < BOARD; ++j) {
      if (mode == GL_SELECT) glPushName((GLuint)j);
      const float shade = (float)board[i][j] / 3.0f;
      glColor3f(shade, 0.3f + 0.2f * (float)(i % 2), 1.0f - shade);
      glRecti(i, j, i + 1, j + 1);
      if (mode == GL_SELECT) glPopName();
    }
  }
}

static void boardProjection(void)
{
  gluOrtho2D(0.0, BOARD, 0.0, BOARD);
}

static void pickBoard(double x, double y)
{
  GLuint buffer[64];
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glSelectBuffer(64, buffer);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(0);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  gluPickMatrix(x, y, 5.0, 5.0, viewport);
  boardProjection();
  squares(GL_SELECT);
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  const GLint hits = glRenderMode(GL_RENDER);
  if (hits < 0) exit(1);
  GLuint *record = buffer;
  for (GLint h = 0; h < hits; ++h) {
    const GLuint names = record[0];
    if (names == 2) {
      const GLuint i = record[3], j = record[4];
      if (i < BOARD && j < BOARD) board[i][j] = (board[i][j] + 1) % 3;
    }
    record += 3 + names;
  }
}

static void depthScene(GLenum mode)
{
  static const float depths[3] = {-0.5f, 0.1f, 0.7f};
  static const float colors[3][3] = {{1.0f, 0.3f, 0.3f}, {0.3f, 1.0f, 0.3f}, {0.4f, 0.5f, 1.0f}};
  for (int k = 0; k < 3; ++k) {
    if (mode == GL_SELECT) glLoadName((GLuint)k);
    glColor3fv(colors[k]);
    glBegin(GL_QUADS);
    glVertex3f(0.15f + 0.2f * (float)k, 0.1f + 0.1f * (float)k, depths[k]);
    glVertex3f(0.55f + 0.2f * (float)k, 0.1f + 0.1f * (float)k, depths[k] - 0.2f);
    glVertex3f(0.55f + 0.2f * (float)k, 0.5f + 0.1f * (float)k, depths[k] - 0.2f);
    glVertex3f(0.15f + 0.2f * (float)k, 0.5f + 0.1f * (float)k, depths[k]);
    glEnd();
  }
  if (mode == GL_SELECT) glLoadName(3);
  glColor3f(1.0f, 1.0f, 0.3f);
  glBegin(GL_LINES);
  glVertex3f(0.2f, 0.35f, 0.9f);
  glVertex3f(0.9f, 0.4f, -0.9f);
  glEnd();
  if (mode == GL_SELECT) glLoadName(4);
  glPointSize(5.0f);
  glBegin(GL_POINTS);
  glVertex3f(0.52f, 0.38f, -0.3f);
  glEnd();
  glPointSize(1.0f);
}

static void depthPanel(void)
{
  static const float colors[5][3] = {{1.0f, 0.3f, 0.3f}, {0.3f, 1.0f, 0.3f}, {0.4f, 0.5f, 1.0f},
                                     {1.0f, 1.0f, 0.3f}, {1.0f, 1.0f, 1.0f}};
  GLuint buffer[64];
  GLint viewport[4];
  glViewport(SIZE, 0, SIZE, SIZE);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  depthScene(GL_RENDER);
  glDisable(GL_DEPTH_TEST);

  glSelectBuffer(64, buffer);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(99);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPickMatrix(SIZE + 0.52 * SIZE, 0.38 * SIZE, 8.0, 8.0, viewport);
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  depthScene(GL_SELECT);
  const GLint hits = glRenderMode(GL_RENDER);
  if (hits < 0) exit(1);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  GLuint *record = buffer;
  for (GLint h = 0; h < hits; ++h) {
    const GLuint names = record[0];
    const double zmin = record[1] / 4294967295.0, zmax = record[2] / 4294967295.0;
    const GLuint name = names > 0 ? record[3 + names - 1] : 4;
    glColor3fv(colors[name < 5 ? name : 4]);
    const float y = 0.94f - 0.06f * (float)h;
    glRectf((float)zmin, y, (float)zmax + 0.01f, y + 0.04f);
    record += 3 + names;
  }
}

static void draw(void)
{
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glViewport(0, 0, SIZE, SIZE);
  static const double clicks[8][2] = {{25, 25},  {75, 125},  {125, 125}, {125, 125},
                                      {175, 60}, {100, 200}, {230, 230}, {150, 100}};
  for (int c = 0; c < 8; ++c) pickBoard(clicks[c][0], clicks[c][1]);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  boardProjection();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  squares(GL_RENDER);

  depthPanel();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, 2 * SIZE, SIZE, draw);
}
