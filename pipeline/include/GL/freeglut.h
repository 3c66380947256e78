/* glass: <GL/freeglut.h>, for programs written for freeglut. glass's <GL/glut.h> declares the
 * freeglut additions it has (the cylinder, rhombic dodecahedron, Sierpinski sponge, the font
 * extras such as glutBitmapString), so this header is that one. */
#ifndef GLASS_GL_FREEGLUT_H
#define GLASS_GL_FREEGLUT_H

#include <GL/glut.h>

#endif /* GLASS_GL_FREEGLUT_H */
