// GLUT's shapes as meshes: one position and one normal per vertex, and the draw calls that use
// them (a primitive mode and a list of vertex indices each). The mesh builders reproduce the
// vertices, normals, vertex order and draw calls of freeglut 3, so a program draws the same
// picture with glass as with freeglut; shape_drawing.cpp sends a mesh to the GL.
#pragma once

#include <GL/gl.h>

#include <vector>

namespace glass::gl::glut {

struct ShapeMesh {
  struct Draw {
    GLenum mode;
    std::vector<int> indices;  // into positions/normals (vertex k at [3k, 3k + 3))
  };
  std::vector<float> positions;
  std::vector<float> normals;
  std::vector<float> texCoords;  // s, t per vertex, or empty (only the solid teaset has them)
  std::vector<Draw> draws;

  int vertexCount() const { return static_cast<int>(positions.size() / 3); }
  void addVertex(float x, float y, float z, float nx, float ny, float nz) {
    positions.insert(positions.end(), {x, y, z});
    normals.insert(normals.end(), {nx, ny, nz});
  }
};

// The Platonic solids. Each face has its own vertices (a vertex carries the face's normal).
// Wireframes draw one GL_LINE_LOOP per face; solids draw triangles (squares and pentagons split
// into triangles around their first vertex as freeglut splits them).
ShapeMesh cubeMesh(float size, bool wire);          // edge `size`, centred at the origin
ShapeMesh tetrahedronMesh(bool wire);               // circumradius 1
ShapeMesh octahedronMesh(bool wire);                // circumradius 1
ShapeMesh dodecahedronMesh(bool wire);              // circumradius sqrt(3)
ShapeMesh icosahedronMesh(bool wire);               // circumradius 1
// freeglut's additions: the rhombic dodecahedron (corners at distance 1 on the axes) and the
// Sierpinski sponge (`levels` times four half-size tetrahedra at the corners of the last).
ShapeMesh rhombicDodecahedronMesh(bool wire);
ShapeMesh sierpinskiSpongeMesh(int levels, const double offset[3], float scale, bool wire);

// The round shapes, built from sine/cosine tables of float angles as freeglut builds them. The
// solids are triangle strips; the wireframes line strips or loops along both directions.
// Counts freeglut cannot build (too few slices, stacks, sides or rings) give an empty mesh.
ShapeMesh sphereMesh(float radius, int slices, int stacks, bool wire);
ShapeMesh coneMesh(float base, float height, int slices, int stacks, bool wire);
ShapeMesh cylinderMesh(float radius, float height, int slices, int stacks, bool wire);
ShapeMesh torusMesh(float innerRadius, float outerRadius, int sides, int rings, bool wire);

// The Utah teaset exactly as freeglut 3 tessellates it (teaset_mesh.cpp): 8 x 8 points per patch
// as triangles with texture coordinates (solid), 10 x 10 as line strips (wire).
ShapeMesh teapotMesh(float size, bool wire);
ShapeMesh teacupMesh(float size, bool wire);
ShapeMesh teaspoonMesh(float size, bool wire);

// Sends the mesh to the current GL context as glBegin/glNormal3fv/glVertex3fv/glEnd.
void drawShapeMesh(const ShapeMesh& mesh);

}  // namespace glass::gl::glut
