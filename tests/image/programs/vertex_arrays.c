/* Vertex arrays as programs use them: an array of structs (position, normal, colour interleaved
 * by hand, with a stride), pointers set with glVertexPointer/glNormalPointer/glColorPointer and
 * drawn with glDrawElements through GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_UNSIGNED_INT
 * indices; a lit cube from shared corners (8 vertices, 36 indices, smooth normals at the corners);
 * a grid mesh of GL_TRIANGLE_STRIPs, one glDrawElements per row; glDrawArrays with a first index
 * other than 0 on GL_LINE_STRIP and GL_POINTS; glArrayElement between glBegin and glEnd; and
 * tightly packed double and short arrays with colours as unsigned bytes. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300, GRID = 12 };

struct Vertex {
  GLfloat position[3];
  GLfloat normal[3];
  GLubyte colour[4];
};

static struct Vertex cube[8];
static const GLubyte cubeIndices[36] = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 4, 5, 0, 5, 1,
                                        1, 5, 6, 1, 6, 2, 2, 6, 7, 2, 7, 3, 3, 7, 4, 3, 4, 0};

static GLdouble gridPositions[GRID + 1][GRID + 1][3];
static GLubyte gridColours[GRID + 1][GRID + 1][3];
static GLushort gridRow[2 * (GRID + 1)];
static GLshort wave[40][2];
static GLuint pointIndices[20];

static void makeData(void)
{
  int i, j;
  for (i = 0; i < 8; ++i) {
    const float x = (i == 1 || i == 2 || i == 5 || i == 6) ? 1.0f : -1.0f;
    const float y = (i == 2 || i == 3 || i == 6 || i == 7) ? 1.0f : -1.0f;
    const float z = i < 4 ? 1.0f : -1.0f;
    const float n = 1.0f / sqrtf(3.0f);
    cube[i].position[0] = x;
    cube[i].position[1] = y;
    cube[i].position[2] = z;
    cube[i].normal[0] = x * n;
    cube[i].normal[1] = y * n;
    cube[i].normal[2] = z * n;
    cube[i].colour[0] = (GLubyte)(x > 0 ? 230 : 40);
    cube[i].colour[1] = (GLubyte)(y > 0 ? 230 : 40);
    cube[i].colour[2] = (GLubyte)(z > 0 ? 230 : 40);
    cube[i].colour[3] = 255;
  }
  for (i = 0; i <= GRID; ++i) {
    for (j = 0; j <= GRID; ++j) {
      const double x = -1.0 + 2.0 * j / GRID, z = -1.0 + 2.0 * i / GRID;
      gridPositions[i][j][0] = x;
      gridPositions[i][j][1] = 0.25 * sin(3.0 * x) * cos(2.0 * z);
      gridPositions[i][j][2] = z;
      gridColours[i][j][0] = (GLubyte)(20 * i);
      gridColours[i][j][1] = (GLubyte)(128 + 60 * gridPositions[i][j][1] * 4.0);
      gridColours[i][j][2] = (GLubyte)(20 * j);
    }
  }
  for (i = 0; i < 40; ++i) {
    wave[i][0] = (GLshort)(10 + 9 * i);
    wave[i][1] = (GLshort)(40 + 25.0 * sin(i * 0.4));
  }
  for (i = 0; i < 20; ++i) pointIndices[i] = (GLuint)(39 - 2 * i);
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {-1.0f, 2.0f, 3.0f, 0.0f};
  int i;
  makeData();

  glClearColor(0.15f, 0.15f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  gluLookAt(0.0, 3.0, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  /* The lit cube, colour material from the colour array. */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(struct Vertex), cube[0].position);
  glNormalPointer(GL_FLOAT, sizeof(struct Vertex), cube[0].normal);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct Vertex), cube[0].colour);
  glPushMatrix();
  glTranslatef(-1.8f, 0.5f, 0.0f);
  glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
  glScalef(0.7f, 0.7f, 0.7f);
  glEnable(GL_RESCALE_NORMAL);
  glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_BYTE, cubeIndices);
  glPopMatrix();
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);

  /* The wavy grid: one strip per row from short indices. */
  glVertexPointer(3, GL_DOUBLE, 0, gridPositions);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, gridColours);
  glPushMatrix();
  glTranslatef(1.4f, 0.0f, 0.0f);
  glScalef(1.3f, 1.3f, 1.3f);
  for (i = 0; i < GRID; ++i) {
    int j;
    for (j = 0; j <= GRID; ++j) {
      gridRow[2 * j] = (GLushort)((i + 1) * (GRID + 1) + j);
      gridRow[2 * j + 1] = (GLushort)(i * (GRID + 1) + j);
    }
    glDrawElements(GL_TRIANGLE_STRIP, 2 * (GRID + 1), GL_UNSIGNED_SHORT, gridRow);
  }
  glPopMatrix();
  glDisableClientState(GL_COLOR_ARRAY);

  /* 2D overlay in window coordinates: a line strip from a short array starting at index 5, and
   * points through unsigned int indices, then glArrayElement inside glBegin. */
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  gluOrtho2D(0.0, WIDTH, 0.0, HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glVertexPointer(2, GL_SHORT, 0, wave);
  glColor3f(1.0f, 1.0f, 0.0f);
  glDrawArrays(GL_LINE_STRIP, 5, 30);
  glPointSize(4.0f);
  glColor3f(1.0f, 0.3f, 0.3f);
  glDrawElements(GL_POINTS, 20, GL_UNSIGNED_INT, pointIndices);
  glPointSize(1.0f);
  glTranslatef(0.0f, 220.0f, 0.0f);
  glColor3f(0.4f, 0.8f, 1.0f);
  glBegin(GL_TRIANGLE_STRIP);
  for (i = 0; i < 12; ++i) glArrayElement(i * 3);
  glEnd();
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glDisableClientState(GL_VERTEX_ARRAY);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
