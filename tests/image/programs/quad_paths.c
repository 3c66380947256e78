/* The same GL_QUADS drawn through the four paths a program can take: glBegin/glEnd,
 * glDrawArrays, glDrawElements and a display list (top left, top right, bottom left, bottom
 * right). Each quad's corner colours are not planar (one corner differs from the mean of the
 * other three), so the diagonal a quad is split along shows: the specification leaves the split
 * to the implementation (section 2.6.1: a quadrilateral is drawn as two triangles, whose choice
 * is not specified), and Mesa splits along v0-v2 in the first two paths and along v1-v3 in the
 * other two (docs/pipeline.md gives the numbers). A fourth row in each panel is partly outside
 * the view, so that it is clipped. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 320, QUADS = 12 };

static GLfloat positions[QUADS * 4][2];
static GLfloat colors[QUADS * 4][3];
static GLuint indices[QUADS * 4];

static void build(void)
{
  int q, k;
  for (q = 0; q < QUADS; ++q) {
    const float x = -0.95f + 0.62f * (float)(q % 3), y = -0.95f + 0.5f * (float)(q / 3);
    const float corners[4][2] = {{x, y}, {x + 0.55f, y}, {x + 0.55f, y + 0.42f}, {x, y + 0.42f}};
    for (k = 0; k < 4; ++k) {
      const int v = q * 4 + k;
      positions[v][0] = corners[k][0] + (q / 3 == 3 ? 0.3f : 0.0f);
      positions[v][1] = corners[k][1];
      colors[v][0] = k == (q % 4) ? 1.0f : 0.1f;
      colors[v][1] = k == ((q + 1) % 4) ? 0.9f : 0.2f;
      colors[v][2] = k == ((q + 2) % 4) ? 0.8f : 0.3f * (float)(q % 2);
      indices[v] = (GLuint)v;
    }
  }
}

static void immediate(void)
{
  int v;
  glBegin(GL_QUADS);
  for (v = 0; v < QUADS * 4; ++v) {
    glColor3fv(colors[v]);
    glVertex2fv(positions[v]);
  }
  glEnd();
}

static void panel(int x, int y)
{
  glViewport(x, y, WIDTH / 2, HEIGHT / 2);
}

static void draw(void)
{
  GLuint list;
  build();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glColorPointer(3, GL_FLOAT, 0, colors);

  panel(0, HEIGHT / 2);
  immediate();

  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  panel(WIDTH / 2, HEIGHT / 2);
  glDrawArrays(GL_QUADS, 0, QUADS * 4);
  panel(0, 0);
  glDrawElements(GL_QUADS, QUADS * 4, GL_UNSIGNED_INT, indices);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);

  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  immediate();
  glEndList();
  panel(WIDTH / 2, 0);
  glCallList(list);
  glDeleteLists(list, 1);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
