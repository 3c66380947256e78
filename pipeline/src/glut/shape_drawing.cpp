// Sends a GLUT shape to the GL in immediate mode. freeglut draws the same vertices through
// vertex arrays (glDrawElements); immediate mode gives the same primitives without touching the
// program's client array state, and records into display lists like any other drawing.
#include <GL/gl.h>

#include <cstddef>

#include "glut/shape_mesh.h"

namespace glass::gl::glut {

void drawShapeMesh(const ShapeMesh& mesh) {
  for (const ShapeMesh::Draw& d : mesh.draws) {
    glBegin(d.mode);
    for (int k : d.indices) {
      glNormal3fv(&mesh.normals[3 * static_cast<std::size_t>(k)]);
      if (!mesh.texCoords.empty()) glTexCoord2fv(&mesh.texCoords[2 * static_cast<std::size_t>(k)]);
      glVertex3fv(&mesh.positions[3 * static_cast<std::size_t>(k)]);
    }
    glEnd();
  }
}

}  // namespace glass::gl::glut
