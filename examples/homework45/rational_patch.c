#include "rational_patch.h"

#include <GL/glut.h>

#include "rounded_upright.h"

void control_point(float out[4], double x, double y, double z, double w)
{
  out[0] = (float)(x * w);
  out[1] = (float)(y * w);
  out[2] = (float)(z * w);
  out[3] = (float)w;
}

void draw_rational_patch(const float net[][3][4], const float tex[][3][2], const float normals[][3][3], int rows,
                         int v_steps)
{
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 3, 0, 1, 12, rows, &net[0][0][0]);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 3, 0, 1, 6, rows, &tex[0][0][0]);
  glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 3, 0, 1, 9, rows, &normals[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glEnable(GL_MAP2_NORMAL);
  glDisable(GL_AUTO_NORMAL);
  glMapGrid2f(ARC_STEPS, 0, 1, v_steps, 0, 1);
  glEvalMesh2(GL_FILL, 0, ARC_STEPS, 0, v_steps);
  glEnable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_NORMAL);
  glDisable(GL_MAP2_VERTEX_4);
  glDisable(GL_MAP2_TEXTURE_COORD_2);
}
