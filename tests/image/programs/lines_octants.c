/* GL_LINES in every octant, width 1: the picture must match Mesa pixel for pixel, since the
 * diamond-exit rule of the GL specification (section 3.4.1) decides every fragment.
 *
 * Window coordinates equal object coordinates (glOrtho over the 256 x 256 viewport, all exact in
 * float). Every octant gets lines whose endpoints lie on pixel centres (n + 1/2), on pixel corners
 * (whole numbers, where the rule's tie-breaking matters) and at sixteenths of a pixel. The
 * eight axis and diagonal directions between octants are drawn in both orders along the bottom.
 * All lines stay inside the window, so no clipping is involved. */
#include <GL/gl.h>

#include "gl_program.h"
#include "lcg.h"

enum { SIZE = 256, LINES_PER_OCTANT_AND_KIND = 6 };

static void randomColor(Lcg *random)
{
  glColor3ub((GLubyte)(64 + lcg_below(random, 192)), (GLubyte)(64 + lcg_below(random, 192)),
             (GLubyte)(64 + lcg_below(random, 192)));
}

/* Snaps a coordinate to the grid of one kind: 0 pixel centres, 1 pixel corners, 2 sixteenths. */
static float snap(float value, int kind)
{
  switch (kind) {
  case 0: return (float)(int)value + 0.5f;
  case 1: return (float)(int)value;
  default: return (float)(int)(value * 16.0f) / 16.0f;
  }
}

/* A line of length 4..100 in the given octant (octant k holds the directions from 45k to
 * 45(k+1) degrees, anticlockwise from +x), inside [8, 248] x [72, 248]. */
static void lineInOctant(Lcg *random, int octant, int kind)
{
  float major = lcg_range(random, 4.0f, 100.0f);
  float minor = major * lcg_unit(random); /* 0 <= minor < major: strictly inside the octant */
  float dx, dy;
  /* Octants 0, 3, 4, 7 are x-major; the sign of dx and dy follows the quadrant. */
  int xMajor = octant == 0 || octant == 3 || octant == 4 || octant == 7;
  dx = xMajor ? major : minor;
  dy = xMajor ? minor : major;
  if (octant >= 2 && octant <= 5) dx = -dx;
  if (octant >= 4) dy = -dy;

  float x0 = lcg_range(random, 8.0f, 248.0f), y0 = lcg_range(random, 72.0f, 248.0f);
  if (x0 + dx < 8.0f || x0 + dx > 248.0f) x0 = 128.0f - dx / 2.0f;
  if (y0 + dy < 72.0f || y0 + dy > 248.0f) y0 = 160.0f - dy / 2.0f;

  randomColor(random);
  glVertex2f(snap(x0, kind), snap(y0, kind));
  glVertex2f(snap(x0 + dx, kind), snap(y0 + dy, kind));
}

static void draw(void)
{
  Lcg random = {20240601u};
  glViewport(0, 0, SIZE, SIZE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, SIZE, 0.0, SIZE, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  glBegin(GL_LINES);
  for (int octant = 0; octant < 8; ++octant)
    for (int kind = 0; kind < 3; ++kind)
      for (int i = 0; i < LINES_PER_OCTANT_AND_KIND; ++i) lineInOctant(&random, octant, kind);

  /* The eight directions between octants (axes and diagonals) as rays of six stars along the
   * bottom, one star per endpoint kind, rays drawn outwards in the first three, inwards in the
   * last three. */
  for (int star = 0; star < 6; ++star) {
    const int kind = star % 3, inwards = star >= 3;
    const float cx = 20.5f + 43.0f * (float)star, cy = 36.5f;
    for (int ray = 0; ray < 8; ++ray) {
      static const float dx[8] = {1, 1, 0, -1, -1, -1, 0, 1}, dy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
      const float inner[2] = {snap(cx + 3.0f * dx[ray], kind), snap(cy + 3.0f * dy[ray], kind)};
      const float outer[2] = {snap(cx + 18.0f * dx[ray], kind), snap(cy + 18.0f * dy[ray], kind)};
      randomColor(&random);
      glVertex2fv(inwards ? outer : inner);
      glVertex2fv(inwards ? inner : outer);
    }
  }
  glEnd();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, SIZE, SIZE, draw); }
