// The GL the scene library speaks: GL/gl.h, GL/glu.h and GL/freeglut.h (GLUT with freeglut's
// shapes) of whichever implementation the library is built against (glass's own headers, or the
// system's Mesa and freeglut headers for the reference renderer). Nothing else of the
// implementation is used.
#pragma once

#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/freeglut.h>

// glass extension GL_WIN_phong_shading (docs/scene-format.md, `shade_model phong`). Mesa's
// headers lack the name; Mesa rejects the value and the interpreter falls back to smooth shading.
#ifndef GL_PHONG_WIN
#define GL_PHONG_WIN 0x80EA
#endif

// OpenGL 1.2-1.4 names that older headers may lack.
#ifndef GL_RESCALE_NORMAL
#define GL_RESCALE_NORMAL 0x803A
#endif
#ifndef GL_CLAMP_TO_EDGE
#define GL_CLAMP_TO_EDGE 0x812F
#endif
#ifndef GL_CLAMP_TO_BORDER
#define GL_CLAMP_TO_BORDER 0x812D
#endif
#ifndef GL_MIRRORED_REPEAT
#define GL_MIRRORED_REPEAT 0x8370
#endif
#ifndef GL_DEPTH_TEXTURE_MODE
#define GL_DEPTH_COMPONENT24 0x81A6
#define GL_DEPTH_TEXTURE_MODE 0x884B
#define GL_TEXTURE_COMPARE_MODE 0x884C
#define GL_TEXTURE_COMPARE_FUNC 0x884D
#define GL_COMPARE_R_TO_TEXTURE 0x884E
#endif
#ifndef GL_LIGHT_MODEL_COLOR_CONTROL
#define GL_LIGHT_MODEL_COLOR_CONTROL 0x81F8
#define GL_SINGLE_COLOR 0x81F9
#define GL_SEPARATE_SPECULAR_COLOR 0x81FA
#endif
