/* Frame times on heavy frames at 1920 x 1080, for glass (benchmark) and for Mesa
 * (benchmark_mesa, the same source). Not a test: the numbers depend on the machine.
 *
 * Frames, smooth colours, drawn from client vertex arrays with glDrawArrays unless named otherwise:
 *   small_triangles  250,000 triangles of about 18 pixels scattered with random depths, depth test
 *   large_triangles  64 triangles of about half the screen each, tilted in depth, depth test
 *   gouraud_quads    96 quads of a third to two thirds of the screen each way, tilted in depth,
 *                    depth test: about 25 fragments for every pixel (GL_QUADS)
 *   lines            200,000 width-1 lines up to 64 pixels long
 *   lines_immediate  the same lines through glBegin/glColor4ubv/glVertex3fv/glEnd
 *   smooth_lines     the same lines antialiased (GL_LINE_SMOOTH, GL_NICEST) and blended with
 *                    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA
 *   lit_spheres      48 spheres of 3,132 triangles (150,336 in all), smooth shaded and lit by a
 *                    directional and a positional light with a specular highlight, colour
 *                    material from a colour array, depth test
 *   lit_spheres_immediate  the same triangles through glBegin/glColor4ubv/glNormal3fv/glVertex3fv
 *   lit_spheres_indexed    the same spheres with shared vertices (1,711 each), by glDrawElements
 *   textured_scene   a floor with its 256 x 256 texture repeated 30 times each way and 24 textured
 *                    cubes, in perspective, lit by a directional light, GL_MODULATE, mipmapped
 *                    (GL_GENERATE_MIPMAP) and filtered trilinearly (GL_LINEAR_MIPMAP_LINEAR)
 *   small_triangles_immediate, gouraud_quads_immediate, textured_scene_immediate
 *                    those frames through glBegin/glColor4ubv/(glNormal3fv/glTexCoord2fv)/
 *                    glVertex3fv/glEnd, as programs written in immediate mode draw them
 * A frame is glClear, the draw and glFinish. Each frame is drawn once to warm up, then RUNS
 * times; the median time is reported, with the fastest and slowest. The last line gives the
 * process's peak memory (maximum resident set size).
 *
 * Usage: benchmark [--png DIR] [--runs N] [FRAME...]
 *   --png DIR  also writes each frame to DIR/<frame>.png, to look at
 *   --runs N   timed draws per frame (default 7)
 *   FRAME      draw only the frames named (default: all) */
#include <GL/gl.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <glass/context.h>

#include "lcg.h"

enum { WIDTH = 1920, HEIGHT = 1080, DEFAULT_RUNS = 7, MAX_RUNS = 101 };

/* How a frame sends its vertices. */
typedef enum { ARRAYS, IMMEDIATE, ELEMENTS } Submission;

typedef struct {
  const char *name;
  GLenum mode;
  int primitives;
  int verticesPerPrimitive;
  int depthTest;
  Submission submission;
  int vertexCount;    /* vertices in the arrays: primitives * verticesPerPrimitive, or fewer
                         when ELEMENTS shares them */
  GLuint *indices;    /* ELEMENTS: primitives * verticesPerPrimitive indices; NULL otherwise */
  GLfloat *positions; /* x, y, z per vertex */
  GLubyte *colors;    /* r, g, b, a per vertex */
  GLfloat *normals;   /* x, y, z per vertex, for lit frames; NULL otherwise */
  GLfloat *texCoords; /* s, t per vertex, for textured frames; NULL otherwise */
  int antialiased;    /* lines with GL_LINE_SMOOTH, blended by their coverage */
} Frame;

static void *allocateOrExit(size_t bytes)
{
  void *p = malloc(bytes);
  if (!p) {
    fprintf(stderr, "benchmark: out of memory\n");
    exit(1);
  }
  return p;
}

static void allocate(Frame *frame)
{
  const size_t vertices = (size_t)frame->primitives * (size_t)frame->verticesPerPrimitive;
  frame->vertexCount = (int)vertices;
  frame->positions = allocateOrExit(vertices * 3 * sizeof(GLfloat));
  frame->colors = allocateOrExit(vertices * 4);
}

static void setVertex(Frame *frame, size_t v, float x, float y, float z, Lcg *random)
{
  frame->positions[3 * v] = x;
  frame->positions[3 * v + 1] = y;
  frame->positions[3 * v + 2] = z;
  for (int c = 0; c < 3; ++c) frame->colors[4 * v + c] = (GLubyte)(40 + lcg_below(random, 216));
  frame->colors[4 * v + 3] = 255;
}

/* Triangles about 6 pixels across at random places and depths (z in [-1, 1], ortho). */
static Frame smallTriangles(void)
{
  Frame frame = {"small_triangles", GL_TRIANGLES, 250000, 3, 1, ARRAYS, 0, NULL, NULL, NULL, NULL, NULL, 0};
  Lcg random = {1u};
  allocate(&frame);
  for (int t = 0; t < frame.primitives; ++t) {
    const float x = lcg_range(&random, 0.0f, WIDTH), y = lcg_range(&random, 0.0f, HEIGHT);
    const float z = lcg_range(&random, -0.9f, 0.9f);
    for (int k = 0; k < 3; ++k)
      setVertex(&frame, 3 * (size_t)t + k, x + lcg_range(&random, -3.0f, 3.0f) * 2.0f,
                y + lcg_range(&random, -3.0f, 3.0f) * 2.0f, z, &random);
  }
  return frame;
}

/* Triangles with corners spread over and beyond the screen, each tilted in depth, so that they
 * cut through each other and the depth test decides most pixels many times over. */
static Frame largeTriangles(void)
{
  Frame frame = {"large_triangles", GL_TRIANGLES, 64, 3, 1, ARRAYS, 0, NULL, NULL, NULL, NULL, NULL, 0};
  Lcg random = {2u};
  allocate(&frame);
  for (int t = 0; t < frame.primitives; ++t)
    for (int k = 0; k < 3; ++k)
      setVertex(&frame, 3 * (size_t)t + k, lcg_range(&random, -0.3f * WIDTH, 1.3f * WIDTH),
                lcg_range(&random, -0.3f * HEIGHT, 1.3f * HEIGHT),
                lcg_range(&random, -0.95f, 0.95f), &random);
  return frame;
}

/* Quads a third to two thirds of the screen wide and high, each a plane tilted in depth, so that
 * they cut through each other: about 25 depth-tested fragments for every pixel of the screen. */
static Frame gouraudQuads(void)
{
  Frame frame = {"gouraud_quads", GL_QUADS, 96, 4, 1, ARRAYS, 0, NULL, NULL, NULL, NULL, NULL, 0};
  Lcg random = {5u};
  allocate(&frame);
  for (int q = 0; q < frame.primitives; ++q) {
    const float w = lcg_range(&random, WIDTH / 3.0f, 2.0f * WIDTH / 3.0f);
    const float h = lcg_range(&random, HEIGHT / 3.0f, 2.0f * HEIGHT / 3.0f);
    const float x = lcg_range(&random, 0.0f, WIDTH - w), y = lcg_range(&random, 0.0f, HEIGHT - h);
    /* z = z0 + dzdx * (corner x) + dzdy * (corner y), corners at 0 or 1 of the quad's size. */
    const float z0 = lcg_range(&random, -0.5f, 0.5f);
    const float dzdx = lcg_range(&random, -0.4f, 0.4f), dzdy = lcg_range(&random, -0.4f, 0.4f);
    static const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k)
      setVertex(&frame, 4 * (size_t)q + k, x + w * (float)corner[k][0], y + h * (float)corner[k][1],
                z0 + dzdx * (float)corner[k][0] + dzdy * (float)corner[k][1], &random);
  }
  return frame;
}

static Frame lines(void)
{
  Frame frame = {"lines", GL_LINES, 200000, 2, 0, ARRAYS, 0, NULL, NULL, NULL, NULL, NULL, 0};
  Lcg random = {3u};
  allocate(&frame);
  for (int l = 0; l < frame.primitives; ++l) {
    const float x = lcg_range(&random, 0.0f, WIDTH), y = lcg_range(&random, 0.0f, HEIGHT);
    setVertex(&frame, 2 * (size_t)l, x, y, 0.0f, &random);
    setVertex(&frame, 2 * (size_t)l + 1, x + lcg_range(&random, -45.0f, 45.0f),
              y + lcg_range(&random, -45.0f, 45.0f), 0.0f, &random);
  }
  return frame;
}

enum { SPHERE_COLUMNS = 8, SPHERE_ROWS = 6, SPHERE_SLICES = 58, SPHERE_STACKS = 28 };

/* One vertex of a sphere of radius r centred at (cx, cy): longitude i of SPHERE_SLICES, latitude j
 * of SPHERE_STACKS from the north pole; the normal is the unit direction from the centre. */
static void sphereVertex(Frame *frame, size_t v, float cx, float cy, float r, int i, int j,
                         const GLubyte color[3])
{
  const float theta = 2.0f * 3.14159265f * (float)i / SPHERE_SLICES;
  const float phi = 3.14159265f * (float)j / SPHERE_STACKS;
  const float nx = sinf(phi) * cosf(theta), ny = sinf(phi) * sinf(theta), nz = cosf(phi);
  frame->positions[3 * v] = cx + r * nx;
  frame->positions[3 * v + 1] = cy + r * ny;
  frame->positions[3 * v + 2] = r * nz;
  frame->normals[3 * v] = nx;
  frame->normals[3 * v + 1] = ny;
  frame->normals[3 * v + 2] = nz;
  for (int c = 0; c < 3; ++c) frame->colors[4 * v + c] = color[c];
  frame->colors[4 * v + 3] = 255;
}

/* 48 lit spheres on an 8 x 6 grid filling the screen, as separate triangles: two per quad of the
 * longitude-latitude grid, one at each pole. */
static Frame litSpheres(void)
{
  const int perSphere = 2 * SPHERE_SLICES * (SPHERE_STACKS - 1);
  Frame frame = {"lit_spheres", GL_TRIANGLES, SPHERE_COLUMNS * SPHERE_ROWS * perSphere, 3, 1, ARRAYS, 0,
                 NULL, NULL, NULL, NULL, NULL, 0};
  const float cellW = (float)WIDTH / SPHERE_COLUMNS, cellH = (float)HEIGHT / SPHERE_ROWS;
  const float r = 0.45f * (cellW < cellH ? cellW : cellH);
  Lcg random = {4u};
  size_t v = 0;
  allocate(&frame);
  frame.normals = allocateOrExit((size_t)frame.vertexCount * 3 * sizeof(GLfloat));
  for (int row = 0; row < SPHERE_ROWS; ++row)
    for (int column = 0; column < SPHERE_COLUMNS; ++column) {
      const float cx = cellW * ((float)column + 0.5f), cy = cellH * ((float)row + 0.5f);
      GLubyte color[3];
      for (int c = 0; c < 3; ++c) color[c] = (GLubyte)(60 + lcg_below(&random, 196));
      for (int j = 0; j < SPHERE_STACKS; ++j)
        for (int i = 0; i < SPHERE_SLICES; ++i) {
          /* The quad (i, j)-(i + 1, j + 1), counter-clockwise seen from outside. */
          if (j != 0) {
            sphereVertex(&frame, v++, cx, cy, r, i, j, color);
            sphereVertex(&frame, v++, cx, cy, r, i, j + 1, color);
            sphereVertex(&frame, v++, cx, cy, r, i + 1, j, color);
          }
          if (j != SPHERE_STACKS - 1) {
            sphereVertex(&frame, v++, cx, cy, r, i + 1, j, color);
            sphereVertex(&frame, v++, cx, cy, r, i, j + 1, color);
            sphereVertex(&frame, v++, cx, cy, r, i + 1, j + 1, color);
          }
        }
    }
  return frame;
}

/* The same 48 spheres with each grid vertex stored once, (SPHERE_SLICES + 1) x (SPHERE_STACKS + 1)
 * per sphere, and the triangles of litSpheres as indices into them, for glDrawElements. */
static Frame litSpheresIndexed(void)
{
  const int perSphere = 2 * SPHERE_SLICES * (SPHERE_STACKS - 1);
  const int gridVertices = (SPHERE_SLICES + 1) * (SPHERE_STACKS + 1);
  const int spheres = SPHERE_COLUMNS * SPHERE_ROWS;
  Frame frame = {"lit_spheres_indexed", GL_TRIANGLES, spheres * perSphere, 3, 1, ELEMENTS, 0,
                 NULL, NULL, NULL, NULL, NULL, 0};
  const float cellW = (float)WIDTH / SPHERE_COLUMNS, cellH = (float)HEIGHT / SPHERE_ROWS;
  const float r = 0.45f * (cellW < cellH ? cellW : cellH);
  Lcg random = {4u};
  size_t index = 0;
  frame.vertexCount = spheres * gridVertices;
  frame.positions = allocateOrExit((size_t)frame.vertexCount * 3 * sizeof(GLfloat));
  frame.colors = allocateOrExit((size_t)frame.vertexCount * 4);
  frame.normals = allocateOrExit((size_t)frame.vertexCount * 3 * sizeof(GLfloat));
  frame.indices = allocateOrExit((size_t)frame.primitives * 3 * sizeof(GLuint));
  for (int row = 0; row < SPHERE_ROWS; ++row)
    for (int column = 0; column < SPHERE_COLUMNS; ++column) {
      const float cx = cellW * ((float)column + 0.5f), cy = cellH * ((float)row + 0.5f);
      const GLuint base = (GLuint)((row * SPHERE_COLUMNS + column) * gridVertices);
      GLubyte color[3];
      for (int c = 0; c < 3; ++c) color[c] = (GLubyte)(60 + lcg_below(&random, 196));
      for (int j = 0; j <= SPHERE_STACKS; ++j)
        for (int i = 0; i <= SPHERE_SLICES; ++i)
          sphereVertex(&frame, base + (size_t)(j * (SPHERE_SLICES + 1) + i), cx, cy, r, i, j, color);
#define GRID(i, j) (base + (GLuint)((j) * (SPHERE_SLICES + 1) + (i)))
      for (int j = 0; j < SPHERE_STACKS; ++j)
        for (int i = 0; i < SPHERE_SLICES; ++i) {
          if (j != 0) {
            frame.indices[index++] = GRID(i, j);
            frame.indices[index++] = GRID(i, j + 1);
            frame.indices[index++] = GRID(i + 1, j);
          }
          if (j != SPHERE_STACKS - 1) {
            frame.indices[index++] = GRID(i + 1, j);
            frame.indices[index++] = GRID(i, j + 1);
            frame.indices[index++] = GRID(i + 1, j + 1);
          }
        }
#undef GRID
    }
  return frame;
}

/* The lines frame antialiased. */
static Frame smoothLines(void)
{
  Frame frame = lines();
  frame.name = "smooth_lines";
  frame.antialiased = 1;
  return frame;
}

/* A frame drawn through glBegin/glEnd instead of arrays, from the same data. */
static Frame immediately(Frame frame, const char *name)
{
  frame.name = name;
  frame.submission = IMMEDIATE;
  return frame;
}

enum { SCENE_CUBES_X = 6, SCENE_CUBES_Z = 4, SCENE_TEXTURE = 256 };

/* A textured quad: four corners counter-clockwise, one normal, texture coordinates s0..s1 along
 * the first edge and t0..t1 along the second. */
static void texturedQuad(Frame *frame, size_t v, const float corners[4][3], const float normal[3],
                         float sMax, float tMax)
{
  static const float st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k, ++v) {
    for (int c = 0; c < 3; ++c) {
      frame->positions[3 * v + c] = corners[k][c];
      frame->normals[3 * v + c] = normal[c];
    }
    for (int c = 0; c < 4; ++c) frame->colors[4 * v + c] = 255;
    frame->texCoords[2 * v] = st[k][0] * sMax;
    frame->texCoords[2 * v + 1] = st[k][1] * tMax;
  }
}

/* A floor 60 units square centred under the camera, its texture repeated 30 times each way, and
 * 6 x 4 cubes of side 2 standing on it, each face carrying the whole texture once. */
static Frame texturedScene(void)
{
  Frame frame = {"textured_scene", GL_QUADS, 1 + 6 * SCENE_CUBES_X * SCENE_CUBES_Z, 4, 1, ARRAYS, 0,
                 NULL, NULL, NULL, NULL, NULL, 0};
  allocate(&frame);
  frame.normals = allocateOrExit((size_t)frame.vertexCount * 3 * sizeof(GLfloat));
  frame.texCoords = allocateOrExit((size_t)frame.vertexCount * 2 * sizeof(GLfloat));
  static const float up[3] = {0, 1, 0};
  const float floorCorners[4][3] = {{-30, 0, 30}, {30, 0, 30}, {30, 0, -30}, {-30, 0, -30}};
  size_t v = 0;
  texturedQuad(&frame, v, floorCorners, up, 30.0f, 30.0f);
  v += 4;
  /* The six faces of a unit cube as corner indices (bit 0: x, bit 1: y, bit 2: z) with normals. */
  static const int faces[6][4] = {{4, 5, 7, 6}, {1, 0, 2, 3}, {5, 1, 3, 7},
                                  {0, 4, 6, 2}, {6, 7, 3, 2}, {0, 1, 5, 4}};
  static const float normals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0},
                                      {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  for (int i = 0; i < SCENE_CUBES_X; ++i)
    for (int j = 0; j < SCENE_CUBES_Z; ++j) {
      const float x0 = -11.0f + 4.0f * (float)i, z0 = -4.0f - 5.0f * (float)j;
      for (int f = 0; f < 6; ++f) {
        float corners[4][3];
        for (int k = 0; k < 4; ++k) {
          const int c = faces[f][k];
          corners[k][0] = x0 + 2.0f * (float)(c & 1);
          corners[k][1] = 2.0f * (float)((c >> 1) & 1);
          corners[k][2] = z0 + 2.0f * (float)((c >> 2) & 1);
        }
        texturedQuad(&frame, v, corners, normals[f], 1.0f, 1.0f);
        v += 4;
      }
    }
  return frame;
}

/* The textured scene's state: perspective from 3 units above the floor and 6 in front of the
 * first row of cubes, looking slightly down, a
 * directional light, and a mipmapped checkerboard texture modulated by the lit colour. */
static void prepareTexturedFrameState(void)
{
  static GLubyte texels[SCENE_TEXTURE][SCENE_TEXTURE][3];
  static const GLfloat direction[4] = {-0.3f, 0.8f, 0.5f, 0.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  for (int j = 0; j < SCENE_TEXTURE; ++j)
    for (int i = 0; i < SCENE_TEXTURE; ++i) {
      const int check = ((i / 32) + (j / 32)) % 2;
      texels[j][i][0] = (GLubyte)(check ? 230 : 60 + i / 4);
      texels[j][i][1] = (GLubyte)(check ? 210 : 70 + j / 4);
      texels[j][i][2] = (GLubyte)(check ? 170 : 140);
    }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.1 * WIDTH / HEIGHT, 0.1 * WIDTH / HEIGHT, -0.1, 0.1, 0.1, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(12.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, -3.0f, -6.0f);
  /* The light's direction is given in world space: the camera's matrix transforms it. */
  glLightfv(GL_LIGHT0, GL_POSITION, direction);
  static const GLfloat ambient[4] = {0.25f, 0.25f, 0.25f, 1.0f};
  static const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glDisable(GL_LIGHT1);
  /* The lit frame left colour material tracking; every material colour is set again here. */
  glDisable(GL_COLOR_MATERIAL);
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
  glMaterialfv(GL_FRONT, GL_SPECULAR, black);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glEnable(GL_CULL_FACE);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, SCENE_TEXTURE, SCENE_TEXTURE, 0, GL_RGB, GL_UNSIGNED_BYTE,
               texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
}

/* The state of a frame, set before it is timed. Lit frames: a depth range as deep as the screen
 * is wide (the spheres keep their shape in depth), a white directional light from the upper left
 * front, a warm positional light near the upper right corner, a white highlight, colour
 * material. The other frames: depth in [-1, 1], no lighting. */
static void prepareFrameState(int lit)
{
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, lit ? -WIDTH : -1.0, lit ? WIDTH : 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* What the textured frame may have left on, when frames are chosen in another order. */
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_CULL_FACE);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  static const GLfloat direction[4] = {-0.4f, 0.5f, 0.8f, 0.0f};
  static const GLfloat lamp[4] = {0.9f * WIDTH, 0.9f * HEIGHT, 600.0f, 1.0f};
  static const GLfloat warm[4] = {0.6f, 0.5f, 0.3f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  if (!lit) {
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    glDisableClientState(GL_NORMAL_ARRAY);
    return;
  }
  glLightfv(GL_LIGHT0, GL_POSITION, direction);
  glLightfv(GL_LIGHT1, GL_POSITION, lamp);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
  glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 32.0f);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);
  glEnableClientState(GL_NORMAL_ARRAY);
}

/* Antialiasing for the frames that want it: smooth lines blended by their coverage. */
static void prepareAntialiasing(int on)
{
  if (!on) {
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_BLEND);
    return;
  }
  glEnable(GL_LINE_SMOOTH);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}

static double now_ms(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* glBegin/glEnd with the attributes of every vertex as glColor4ubv, glNormal3fv, glTexCoord2fv
 * and glVertex3fv, in the order of the arrays. */
static void drawImmediately(const Frame *frame)
{
  const int count = frame->primitives * frame->verticesPerPrimitive;
  glBegin(frame->mode);
  for (int v = 0; v < count; ++v) {
    glColor4ubv(frame->colors + 4 * (size_t)v);
    if (frame->normals) glNormal3fv(frame->normals + 3 * (size_t)v);
    if (frame->texCoords) glTexCoord2fv(frame->texCoords + 2 * (size_t)v);
    glVertex3fv(frame->positions + 3 * (size_t)v);
  }
  glEnd();
}

static double drawFrame(const Frame *frame)
{
  const double start = now_ms();
  const int count = frame->primitives * frame->verticesPerPrimitive;
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (frame->depthTest)
    glEnable(GL_DEPTH_TEST);
  else
    glDisable(GL_DEPTH_TEST);
  if (frame->submission == IMMEDIATE) {
    drawImmediately(frame);
  } else {
    glVertexPointer(3, GL_FLOAT, 0, frame->positions);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, frame->colors);
    if (frame->normals) glNormalPointer(GL_FLOAT, 0, frame->normals);
    if (frame->texCoords) glTexCoordPointer(2, GL_FLOAT, 0, frame->texCoords);
    if (frame->submission == ELEMENTS)
      glDrawElements(frame->mode, count, GL_UNSIGNED_INT, frame->indices);
    else
      glDrawArrays(frame->mode, 0, count);
  }
  glFinish();
  return now_ms() - start;
}

static int byValue(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The "model name" line of /proc/cpuinfo, or "unknown CPU". */
static void cpuModel(char *model, size_t size)
{
  char line[512];
  FILE *cpuinfo = fopen("/proc/cpuinfo", "r");
  snprintf(model, size, "unknown CPU");
  if (!cpuinfo) return;
  while (fgets(line, sizeof line, cpuinfo)) {
    const char *colon = strchr(line, ':');
    if (strncmp(line, "model name", 10) == 0 && colon) {
      snprintf(model, size, "%s", colon + 2);
      model[strcspn(model, "\n")] = '\0';
      break;
    }
  }
  fclose(cpuinfo);
}

/* The process's peak resident memory in MiB (Linux reports ru_maxrss in KiB). */
static double peakMemoryMiB(void)
{
  struct rusage usage;
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return (double)usage.ru_maxrss / 1024.0;
}

enum { FRAME_COUNT = 13 };
static const char *const frameNames[FRAME_COUNT + 1] = {
    "small_triangles",       "large_triangles",     "gouraud_quads",  "lines",
    "lines_immediate",       "smooth_lines",        "lit_spheres",         "lit_spheres_immediate",
    "lit_spheres_indexed",   "textured_scene",      "small_triangles_immediate",
    "gouraud_quads_immediate", "textured_scene_immediate", NULL};

/* Builds frame `name`; returns 0 for a name no frame has. */
static int makeFrame(const char *name, Frame *frame)
{
  if (strcmp(name, "small_triangles") == 0) *frame = smallTriangles();
  else if (strcmp(name, "large_triangles") == 0) *frame = largeTriangles();
  else if (strcmp(name, "gouraud_quads") == 0) *frame = gouraudQuads();
  else if (strcmp(name, "lines") == 0) *frame = lines();
  else if (strcmp(name, "lines_immediate") == 0) *frame = immediately(lines(), "lines_immediate");
  else if (strcmp(name, "smooth_lines") == 0) *frame = smoothLines();
  else if (strcmp(name, "lit_spheres") == 0) *frame = litSpheres();
  else if (strcmp(name, "lit_spheres_immediate") == 0)
    *frame = immediately(litSpheres(), "lit_spheres_immediate");
  else if (strcmp(name, "lit_spheres_indexed") == 0) *frame = litSpheresIndexed();
  else if (strcmp(name, "textured_scene") == 0) *frame = texturedScene();
  else if (strcmp(name, "small_triangles_immediate") == 0)
    *frame = immediately(smallTriangles(), "small_triangles_immediate");
  else if (strcmp(name, "gouraud_quads_immediate") == 0)
    *frame = immediately(gouraudQuads(), "gouraud_quads_immediate");
  else if (strcmp(name, "textured_scene_immediate") == 0)
    *frame = immediately(texturedScene(), "textured_scene_immediate");
  else return 0;
  return 1;
}

static int usage(const char *program)
{
  fprintf(stderr, "usage: %s [--png DIR] [--runs N] [FRAME...]\nframes:", program);
  for (int f = 0; frameNames[f]; ++f) fprintf(stderr, " %s", frameNames[f]);
  fprintf(stderr, "\n");
  return 2;
}

int main(int argc, char **argv)
{
  const char *pngDir = NULL;
  const char *selected[FRAME_COUNT];
  int selectedCount = 0, runs = DEFAULT_RUNS;
  char model[256], path[1024];
  GlassContext *ctx;

  for (int a = 1; a < argc; ++a) {
    if (strcmp(argv[a], "--png") == 0 && a + 1 < argc) {
      pngDir = argv[++a];
    } else if (strcmp(argv[a], "--runs") == 0 && a + 1 < argc) {
      char *end = NULL;
      const long n = strtol(argv[++a], &end, 10);
      if (*end != '\0' || n < 1 || n > MAX_RUNS) return usage(argv[0]);
      runs = (int)n;
    } else {
      int known = 0;
      for (int f = 0; frameNames[f]; ++f) known |= strcmp(argv[a], frameNames[f]) == 0;
      if (!known || selectedCount == FRAME_COUNT) return usage(argv[0]);
      selected[selectedCount++] = argv[a];
    }
  }
  if (selectedCount == 0)
    for (int f = 0; frameNames[f]; ++f) selected[selectedCount++] = frameNames[f];

  ctx = glassCreateContext(WIDTH, HEIGHT);
  if (!ctx || !glassMakeCurrent(ctx)) {
    fprintf(stderr, "benchmark: cannot create a %d x %d context\n", WIDTH, HEIGHT);
    return 1;
  }
  glViewport(0, 0, WIDTH, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);

  cpuModel(model, sizeof model);
  printf("renderer:   %s, %s\n", (const char *)glGetString(GL_RENDERER),
         (const char *)glGetString(GL_VERSION));
  printf("machine:    %s, %ld hardware threads\n", model, sysconf(_SC_NPROCESSORS_ONLN));
  printf("resolution: %d x %d\n", WIDTH, HEIGHT);
  printf("threads:    LP_NUM_THREADS=%s GLASS_THREADS=%s\n",
         getenv("LP_NUM_THREADS") ? getenv("LP_NUM_THREADS") : "(unset)",
         getenv("GLASS_THREADS") ? getenv("GLASS_THREADS") : "(unset)");
  printf("timing:     median of %d frames after 1 warm-up frame, ms\n", runs);

  for (int f = 0; f < selectedCount; ++f) {
    double times[MAX_RUNS];
    Frame frame;
    makeFrame(selected[f], &frame);
    if (frame.texCoords)
      prepareTexturedFrameState();
    else
      prepareFrameState(frame.normals != NULL);
    prepareAntialiasing(frame.antialiased);
    drawFrame(&frame);
    for (int r = 0; r < runs; ++r) times[r] = drawFrame(&frame);
    qsort(times, (size_t)runs, sizeof times[0], byValue);
    printf("frame %-26s %8d primitives  median %9.2f ms  (min %.2f, max %.2f)\n", frame.name,
           frame.primitives, times[runs / 2], times[0], times[runs - 1]);
    fflush(stdout);
    if (pngDir) {
      snprintf(path, sizeof path, "%s/%s.png", pngDir, frame.name);
      if (!glassWritePNG(ctx, path)) fprintf(stderr, "benchmark: cannot write %s\n", path);
    }
    free(frame.positions);
    free(frame.colors);
    free(frame.normals);
    free(frame.texCoords);
    free(frame.indices);
  }
  printf("peak memory: %.1f MiB\n", peakMemoryMiB());

  glassDestroyContext(ctx);
  return 0;
}
