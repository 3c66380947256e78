/* GL errors and state queries, call by call: a long script of GL 1.x calls a program could make,
 * many of them wrong, each followed by one line with the call and the error glGetError returns,
 * and, after calls that set state, the values glGet* then returns. Built against glass and
 * against Mesa (OSMesa); tests/gl_errors/reference.txt is Mesa's output, written by
 * tools/make-gl-errors-reference.sh, and the gl_errors test compares glass's output with it line
 * by line (tests/gl_errors/exceptions.txt lists where Mesa departs from the specification).
 *
 * Implementation-dependent values (GL_MAX_* limits, stack depths at their limits, bit counts,
 * strings, texture residency, the first texture unit or clip plane past the limits) are not
 * printed: where a limit matters (stack overflows), the script reads it and prints only whether
 * the result matches it. Nor are results the specification leaves undefined or to the
 * implementation (noted where they would be).
 *
 * Printed values: integers as they are, floats rounded to 6 significant digits, booleans as
 * GL_TRUE/GL_FALSE. No line holds ';', '[' or ']', so that the comparison can read lines as
 * CMake list elements. */
#define GL_GLEXT_PROTOTYPES
#include <glass/context.h>

#include <GL/gl.h>

#include <stdio.h>
#include <string.h>

/* ---- printing -------------------------------------------------------------------------- */

static const char *error_name(GLenum e) {
  switch (e) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown error";
  }
}

/* Writes text with the characters a CMake list would split or group on replaced. */
static void put_text(const char *text) {
  for (const char *c = text; *c; ++c) {
    char ch = *c;
    if (ch == ';') ch = ',';
    if (ch == '[') ch = '(';
    if (ch == ']') ch = ')';
    if (ch == '\n' || ch == '\t') ch = ' ';
    putchar(ch);
  }
}

static int checked_lines = 0;

/* One checked line: the text, then every error glGetError returns (one, in practice; the rest
 * would show an implementation that keeps several flags). */
static void report(const char *text) {
  GLenum e = glGetError();
  put_text(text);
  printf(" -> %s", error_name(e));
  for (int i = 0; i < 4 && e != GL_NO_ERROR; ++i) {
    e = glGetError();
    if (e != GL_NO_ERROR) printf(" then %s", error_name(e));
  }
  putchar('\n');
  ++checked_lines;
}

/* Runs a call and reports it. */
#define E(...)             \
  do {                     \
    __VA_ARGS__;           \
    report(#__VA_ARGS__);  \
  } while (0)

static void section(const char *name) { printf("== %s\n", name); }

static void print_float(double v) {
  char text[32];
  if (v == 0.0) v = 0.0; /* no "-0" */
  snprintf(text, sizeof text, "%.6g", v);
  if (strcmp(text, "-0") == 0) strcpy(text, "0");
  printf(" %s", text);
}

/* A query's own error, if it made one, follows its values. */
static void end_query(void) {
  GLenum e = glGetError();
  if (e != GL_NO_ERROR) printf(" (query error %s)", error_name(e));
  putchar('\n');
  ++checked_lines;
}

static void query_i(const char *name, GLenum pname, int n) {
  GLint v[16];
  for (int i = 0; i < 16; ++i) v[i] = -12345;
  glGetIntegerv(pname, v);
  printf("  %s =", name);
  for (int i = 0; i < n; ++i) printf(" %d", v[i]);
  end_query();
}

static void query_f(const char *name, GLenum pname, int n) {
  GLfloat v[16];
  for (int i = 0; i < 16; ++i) v[i] = -12345.0f;
  glGetFloatv(pname, v);
  printf("  %s =", name);
  for (int i = 0; i < n; ++i) print_float(v[i]);
  end_query();
}

static void query_d(const char *name, GLenum pname, int n) {
  GLdouble v[16];
  for (int i = 0; i < 16; ++i) v[i] = -12345.0;
  glGetDoublev(pname, v);
  printf("  %s (double) =", name);
  for (int i = 0; i < n; ++i) print_float(v[i]);
  end_query();
}

static void query_b(const char *name, GLenum pname, int n) {
  GLboolean v[16];
  memset(v, 7, sizeof v);
  glGetBooleanv(pname, v);
  printf("  %s =", name);
  for (int i = 0; i < n; ++i) printf(" %s", v[i] == GL_TRUE ? "GL_TRUE" : v[i] == GL_FALSE ? "GL_FALSE" : "other");
  end_query();
}

static void query_enabled(const char *name, GLenum cap) {
  GLboolean v = glIsEnabled(cap);
  printf("  glIsEnabled(%s) = %s", name, v == GL_TRUE ? "GL_TRUE" : v == GL_FALSE ? "GL_FALSE" : "other");
  end_query();
}

/* A value the script computed (a return value, a comparison with a limit). */
static void value_i(const char *name, long v) {
  printf("  %s = %ld", name, v);
  end_query();
}

static void values_f(const char *name, const GLfloat *v, int n) {
  printf("  %s =", name);
  for (int i = 0; i < n; ++i) print_float(v[i]);
  end_query();
}

#define QI(pname, n) query_i(#pname, pname, n)
#define QF(pname, n) query_f(#pname, pname, n)
#define QD(pname, n) query_d(#pname, pname, n)
#define QB(pname, n) query_b(#pname, pname, n)
#define QE(cap) query_enabled(#cap, cap)

static GLint limit(GLenum pname) {
  GLint v = 0;
  glGetIntegerv(pname, &v);
  return v;
}

/* ---- the script ------------------------------------------------------------------------ */

static GLubyte image[64 * 64 * 4];
static GLfloat points[4096];

static void state_and_enables(void) {
  section("errors and enables (2.5, 2.11, 6.1)");
  E(glGetError());
  E(glEnable(0x1234));
  E(glDisable(GL_TRIANGLES));
  E(glEnable(GL_VERTEX_ARRAY));
  E(glIsEnabled(0x1234));
  E(glEnable(GL_LIGHTING));
  QE(GL_LIGHTING);
  QB(GL_LIGHTING, 1);
  E(glDisable(GL_LIGHTING));
  QE(GL_LIGHTING);
  QE(GL_DITHER);
  QE(GL_MULTISAMPLE);
  QE(GL_NORMALIZE);
  QE(GL_RESCALE_NORMAL);
  QE(GL_COLOR_SUM);
  QE(GL_TEXTURE_GEN_S);
  QE(GL_CLIP_PLANE5);
  E(glEnable(GL_CLIP_PLANE5));
  QE(GL_CLIP_PLANE5);
  E(glDisable(GL_CLIP_PLANE5));
  E(glEnable(GL_LIGHT7));
  QE(GL_LIGHT7);
  E(glDisable(GL_LIGHT7));
  E(glGetIntegerv(0x1234, (GLint *)image));
  E(glGetFloatv(0x1235, (GLfloat *)image));
  E(glGetString(0x1234));
  E(glHint(0x1234, GL_NICEST));
  E(glHint(GL_FOG_HINT, GL_LINE));
  E(glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST));
  QI(GL_PERSPECTIVE_CORRECTION_HINT, 1);
  E(glHint(GL_GENERATE_MIPMAP_HINT, GL_FASTEST));
  QI(GL_GENERATE_MIPMAP_HINT, 1);
  QI(GL_FOG_HINT, 1);
}

static void matrices(void) {
  section("matrices (2.10.2)");
  E(glMatrixMode(GL_DEPTH));
  E(glMatrixMode(GL_TEXTURE));
  QI(GL_MATRIX_MODE, 1);
  E(glMatrixMode(GL_MODELVIEW));
  E(glOrtho(1, 1, 0, 1, 0, 1));
  E(glOrtho(0, 1, 2, 2, 0, 1));
  E(glOrtho(0, 1, 0, 1, 3, 3));
  E(glFrustum(-1, 1, -1, 1, 0, 10));
  E(glFrustum(-1, 1, -1, 1, 1, -10));
  E(glFrustum(1, 1, -1, 1, 1, 10));
  E(glFrustum(-1, 1, -1, 1, 2, 2));
  E(glLoadIdentity());
  E(glTranslatef(1, 2, 3));
  E(glRotatef(90, 0, 0, 1));
  E(glScalef(2, 2, 2));
  QF(GL_MODELVIEW_MATRIX, 16);
  E(glRotatef(45, 0, 0, 0));
  QF(GL_MODELVIEW_MATRIX, 16);
  E(glLoadIdentity());
  QI(GL_MODELVIEW_STACK_DEPTH, 1);
  E(glPopMatrix());
  QI(GL_MODELVIEW_STACK_DEPTH, 1);

  /* Every stack to its (implementation-dependent) limit, one more push, then back and one pop
   * too many; only whether the depth reached the limit is printed. */
  static const struct {
    GLenum mode, depth, max;
    const char *name;
  } stacks[] = {
      {GL_MODELVIEW, GL_MODELVIEW_STACK_DEPTH, GL_MAX_MODELVIEW_STACK_DEPTH, "GL_MODELVIEW"},
      {GL_PROJECTION, GL_PROJECTION_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH, "GL_PROJECTION"},
      {GL_TEXTURE, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH, "GL_TEXTURE"},
  };
  for (int s = 0; s < 3; ++s) {
    char text[160];
    GLint max = limit(stacks[s].max);
    glMatrixMode(stacks[s].mode);
    glLoadIdentity();
    glTranslatef(5, 0, 0);
    for (int i = 1; i < max; ++i) glPushMatrix();
    snprintf(text, sizeof text, "glMatrixMode(%s), glPushMatrix() until the stack is full", stacks[s].name);
    report(text);
    value_i("depth == GL_MAX_*_STACK_DEPTH", limit(stacks[s].depth) == max);
    glScalef(3, 3, 3);
    snprintf(text, sizeof text, "glPushMatrix() on a full %s stack", stacks[s].name);
    glPushMatrix();
    report(text);
    value_i("depth == GL_MAX_*_STACK_DEPTH", limit(stacks[s].depth) == max);
    QF(stacks[s].mode == GL_MODELVIEW    ? GL_MODELVIEW_MATRIX
       : stacks[s].mode == GL_PROJECTION ? GL_PROJECTION_MATRIX
                                         : GL_TEXTURE_MATRIX,
       16);
    for (int i = 1; i < max; ++i) glPopMatrix();
    snprintf(text, sizeof text, "glPopMatrix() down to one %s matrix", stacks[s].name);
    report(text);
    query_i("stack depth", stacks[s].depth, 1);
    glPopMatrix();
    snprintf(text, sizeof text, "glPopMatrix() on a %s stack of one", stacks[s].name);
    report(text);
    query_i("stack depth", stacks[s].depth, 1);
    glLoadIdentity();
  }
  glMatrixMode(GL_MODELVIEW);

  E(glMatrixMode(GL_PROJECTION));
  E(glLoadIdentity());
  E(glFrustum(-1, 1, -1, 1, 1, 3));
  QF(GL_PROJECTION_MATRIX, 16);
  E(glLoadIdentity());
  E(glMatrixMode(GL_MODELVIEW));
}

static void viewport_depth_range(void) {
  section("viewport and depth range (2.10.1)");
  E(glViewport(0, 0, -1, 10));
  E(glViewport(0, 0, 10, -1));
  E(glViewport(-5, 3, 40, 30));
  QI(GL_VIEWPORT, 4);
  E(glDepthRange(-1, 2));
  QF(GL_DEPTH_RANGE, 2);
  QD(GL_DEPTH_RANGE, 2);
  E(glDepthRange(0.75, 0.25));
  QF(GL_DEPTH_RANGE, 2);
  QB(GL_DEPTH_RANGE, 2);
  E(glDepthRange(0, 0));
  QB(GL_DEPTH_RANGE, 2);
  E(glDepthRange(0, 1));
  QI(GL_DEPTH_RANGE, 2);
  E(glViewport(0, 0, 64, 64));
  {
    /* The first plane past the implementation's GL_MAX_CLIP_PLANES. */
    const GLenum past_last_plane = GL_CLIP_PLANE0 + (GLenum)limit(GL_MAX_CLIP_PLANES);
    E(glClipPlane(past_last_plane, (const GLdouble *)points));
    E(glEnable(past_last_plane));
  }
  E(glGetClipPlane(GL_LIGHT0, (GLdouble *)image));
  {
    const GLdouble plane[4] = {1, 2, 3, 4};
    GLdouble got[4] = {0, 0, 0, 0};
    GLfloat shown[4];
    E(glTranslatef(0, 0, 1));
    E(glClipPlane(GL_CLIP_PLANE1, plane));
    E(glGetClipPlane(GL_CLIP_PLANE1, got));
    for (int i = 0; i < 4; ++i) shown[i] = (GLfloat)got[i];
    values_f("GL_CLIP_PLANE1 in eye coordinates", shown, 4);
    E(glLoadIdentity());
  }
}

static void begin_end(void) {
  section("glBegin and glEnd (2.6.3)");
  E(glBegin(0x1234));
  E(glBegin(GL_POLYGON + 1));
  E(glEnd());
  E(glBegin(GL_TRIANGLES); glBegin(GL_POINTS); glEnd());
  E(glBegin(GL_TRIANGLES); glColor3f(1, 0, 0); glNormal3f(0, 0, 1); glTexCoord2f(0, 0);
    glMaterialf(GL_FRONT, GL_SHININESS, 5); glEdgeFlag(GL_FALSE); glEvalCoord1f(0.5f);
    glSecondaryColor3f(0, 1, 0); glFogCoordf(1); glMultiTexCoord2f(GL_TEXTURE0, 0, 1);
    glIndexi(3); glCallList(999); glVertex2f(0, 0); glEnd());
  E(glBegin(GL_POINTS); glEnable(GL_LIGHTING); glEnd());
  QE(GL_LIGHTING);
  E(glBegin(GL_POINTS); glMatrixMode(GL_PROJECTION); glEnd());
  QI(GL_MATRIX_MODE, 1);
  E(glBegin(GL_POINTS); glPushMatrix(); glEnd());
  QI(GL_MODELVIEW_STACK_DEPTH, 1);
  E(glBegin(GL_POINTS); glLineWidth(4); glEnd());
  QF(GL_LINE_WIDTH, 1);
  E(glBegin(GL_POINTS); glNewList(5, GL_COMPILE); glEnd());
  E(glBegin(GL_POINTS); glEndList(); glEnd());
  E(glBegin(GL_POINTS); glGenLists(1); glEnd());
  E(glBegin(GL_POINTS); glIsList(1); glEnd());
  E(glBegin(GL_POINTS); glIsTexture(1); glEnd());
  E(glBegin(GL_POINTS); glFlush(); glEnd());
  E(glBegin(GL_POINTS); glFinish(); glEnd());
  E(glBegin(GL_POINTS); glPixelStorei(GL_UNPACK_ALIGNMENT, 1); glEnd());
  QI(GL_UNPACK_ALIGNMENT, 1);
  E(glBegin(GL_POINTS); glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image); glEnd());
  E(glBegin(GL_POINTS); glRectf(0, 0, 1, 1); glEnd());
  E(glBegin(GL_POINTS); glRenderMode(GL_SELECT); glEnd());
  QI(GL_RENDER_MODE, 1);
  E(glBegin(GL_POINTS); glBindTexture(GL_TEXTURE_2D, 3); glEnd());
  E(glBegin(GL_POINTS); glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, image); glEnd());
  E(glBegin(GL_POINTS); glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2); glEnd());
  E(glBegin(GL_POINTS); glPushAttrib(GL_ALL_ATTRIB_BITS); glEnd());
  QI(GL_ATTRIB_STACK_DEPTH, 1);
  E(glBegin(GL_POINTS); glGetIntegerv(GL_MATRIX_MODE, (GLint *)image); glEnd());
  E(glBegin(GL_POINTS); glViewport(0, 0, 1, 1); glEnd());
  QI(GL_VIEWPORT, 4);
  E(glBegin(GL_POINTS); glClear(GL_COLOR_BUFFER_BIT); glEnd());
  E(glBegin(GL_POINTS); glMapGrid1f(4, 0, 1); glEnd());
  {
    GLenum inside = 77;
    E(glBegin(GL_POINTS); inside = glGetError(); glEnd());
    value_i("glGetError() between glBegin and glEnd returned", (long)inside);
  }
  E(glBegin(GL_LINES); glVertex2f(0, 0); glEnd());
  E(glBegin(GL_QUADS); glVertex2f(0, 0); glVertex2f(1, 0); glVertex2f(1, 1); glEnd());
}

static void current_values(void) {
  section("current values (2.7)");
  E(glColor4ub(255, 128, 0, 64));
  QF(GL_CURRENT_COLOR, 4);
  QI(GL_CURRENT_COLOR, 4);
  E(glColor4f(2, -1, 0.5f, 3));
  QF(GL_CURRENT_COLOR, 4);
  E(glColor3b(-128, 127, 0));
  QF(GL_CURRENT_COLOR, 4);
  E(glColor4us(65535, 32768, 0, 65535));
  QF(GL_CURRENT_COLOR, 4);
  E(glColor3i(2147483647, 0, -2147483647 - 1));
  QF(GL_CURRENT_COLOR, 4);
  E(glColor4d(0.25, 0.5, 0.75, 1.0));
  QF(GL_CURRENT_COLOR, 4);
  E(glNormal3b(127, -128, 0));
  QF(GL_CURRENT_NORMAL, 3);
  E(glNormal3f(0, 0, 5));
  QF(GL_CURRENT_NORMAL, 3);
  E(glTexCoord1f(0.5f));
  QF(GL_CURRENT_TEXTURE_COORDS, 4);
  E(glTexCoord3s(1, 2, 3));
  QF(GL_CURRENT_TEXTURE_COORDS, 4);
  E(glMultiTexCoord4f(GL_TEXTURE0, 1, 2, 3, 4));
  QF(GL_CURRENT_TEXTURE_COORDS, 4);
  {
    /* The first unit past the implementation's GL_MAX_TEXTURE_UNITS. */
    const GLenum past_last_unit = GL_TEXTURE0 + (GLenum)limit(GL_MAX_TEXTURE_UNITS);
    E(glMultiTexCoord2f(past_last_unit, 1, 2));
  }
  E(glIndexf(7.5f));
  QF(GL_CURRENT_INDEX, 1);
  E(glSecondaryColor3ub(255, 0, 51));
  QF(GL_CURRENT_SECONDARY_COLOR, 4);
  E(glFogCoordf(2.5f));
  QF(GL_CURRENT_FOG_COORDINATE, 1);
  E(glEdgeFlag(GL_FALSE));
  QB(GL_EDGE_FLAG, 1);
  E(glEdgeFlag(GL_TRUE));
  E(glColor4f(1, 1, 1, 1));
  E(glNormal3f(0, 0, 1));
  E(glTexCoord4f(0, 0, 0, 1));
}

static void raster_position(void) {
  section("raster position (2.13)");
  E(glRasterPos2f(0, 0));
  QF(GL_CURRENT_RASTER_POSITION, 4);
  QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
  QF(GL_CURRENT_RASTER_DISTANCE, 1);
  E(glColor3f(1, 0.5f, 0.25f); glRasterPos3f(0.5f, -0.5f, 0.5f));
  QF(GL_CURRENT_RASTER_POSITION, 4);
  QF(GL_CURRENT_RASTER_COLOR, 4);
  E(glRasterPos3f(0, 0, 2));
  QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
  E(glRasterPos2f(3, 0));
  QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
  E(glBitmap(0, 0, 0, 0, 5, 5, NULL));
  E(glBitmap(-1, 1, 0, 0, 0, 0, image));
  E(glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glWindowPos2i(10, 20));
  QF(GL_CURRENT_RASTER_POSITION, 4);
  QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
  E(glWindowPos3f(-3, 70, 2));
  QF(GL_CURRENT_RASTER_POSITION, 4);
  QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
  E(glBitmap(0, 0, 0, 0, 5, -2, NULL));
  QF(GL_CURRENT_RASTER_POSITION, 4);
  E(glColor4f(1, 1, 1, 1));
  /* glRasterPos4f(0, 0, 0, 0) is not compared: the point satisfies the clip volume's
   * inequalities (spec 2.12) but has no window position (division by w = 0); glass makes the
   * raster position invalid, as it discards such a point, and Mesa keeps it valid. */
  E(glRasterPos2f(0, 0));
}

static void lists(void) {
  section("display lists (5.4)");
  E(glEndList());
  E(glNewList(0, GL_COMPILE));
  E(glNewList(1, 0x1234));
  E(glNewList(1, GL_COMPILE); glNewList(2, GL_COMPILE));
  QI(GL_LIST_INDEX, 1);
  QI(GL_LIST_MODE, 1);
  E(glEnable(0x1234));
  E(glBegin(GL_POINTS); glVertex2f(0, 0); glEnd(); glEndList());
  QI(GL_LIST_INDEX, 1);
  E(glCallList(1));
  E(glIsList(1));
  value_i("glIsList(1)", glIsList(1));
  value_i("glIsList(2)", glIsList(2));
  value_i("glIsList(0)", glIsList(0));
  E(glGenLists(-1));
  value_i("glGenLists(0)", (long)glGenLists(0));
  report("glGenLists(0)");
  {
    GLuint base = glGenLists(3);
    report("glGenLists(3)");
    value_i("glIsList on a name glGenLists returned", glIsList(base + 1));
    E(glDeleteLists(base, -1));
    E(glDeleteLists(base, 0));
    E(glDeleteLists(base, 3));
    value_i("glIsList after glDeleteLists", glIsList(base + 1));
  }
  E(glNewList(3, GL_COMPILE_AND_EXECUTE); glEnable(0x1234); glEndList());
  E(glNewList(3, GL_COMPILE); glLineWidth(-1); glEndList());
  E(glCallList(3));
  E(glNewList(4, GL_COMPILE); glMatrixMode(GL_PROJECTION); glEndList());
  QI(GL_MATRIX_MODE, 1);
  E(glCallList(4));
  QI(GL_MATRIX_MODE, 1);
  E(glMatrixMode(GL_MODELVIEW));
  E(glNewList(6, GL_COMPILE); glPixelStorei(GL_UNPACK_ALIGNMENT, 2); glEndList());
  QI(GL_UNPACK_ALIGNMENT, 1);
  E(glCallList(6));
  E(glPixelStorei(GL_UNPACK_ALIGNMENT, 4));
  E(glNewList(7, GL_COMPILE); glPushMatrix(); glPopMatrix(); glPopMatrix(); glEndList());
  E(glCallList(7));
  {
    static const GLubyte names[3] = {1, 3, 4};
    E(glCallLists(3, 0x1234, names));
    E(glCallLists(-1, GL_UNSIGNED_BYTE, names));
    E(glListBase(2));
    QI(GL_LIST_BASE, 1);
    E(glCallLists(2, GL_UNSIGNED_BYTE, names));
    QI(GL_MATRIX_MODE, 1);
    E(glMatrixMode(GL_MODELVIEW));
    E(glListBase(0));
    E(glCallLists(1, GL_2_BYTES, names));
    E(glCallLists(0, GL_UNSIGNED_BYTE, names));
  }
  E(glCallList(12345));
  E(glDeleteLists(1, 10));
}

static void lighting(void) {
  section("lighting (2.13)");
  GLfloat v[4] = {0, 0, 0, 0};
  E(glLightf(0x1234, GL_SPOT_EXPONENT, 1));
  E(glLightf(GL_LIGHT0, 0x1234, 1));
  E(glLightf(GL_LIGHT0, GL_POSITION, 1));
  E(glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129));
  E(glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, -1));
  E(glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128));
  E(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 91));
  E(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, -1));
  E(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180));
  E(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90));
  E(glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, -1));
  E(glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -0.5f));
  E(glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 2));
  E(glGetLightfv(GL_LIGHT0, GL_SPOT_EXPONENT, v));
  values_f("GL_SPOT_EXPONENT", v, 1);
  E(glGetLightfv(GL_LIGHT0, GL_SPOT_CUTOFF, v));
  values_f("GL_SPOT_CUTOFF", v, 1);
  E(glGetLightfv(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, v));
  values_f("GL_QUADRATIC_ATTENUATION", v, 1);
  E(glGetLightfv(GL_LIGHT1, GL_DIFFUSE, v));
  values_f("GL_LIGHT1 GL_DIFFUSE", v, 4);
  E(glGetLightfv(GL_LIGHT0, GL_SPECULAR, v));
  values_f("GL_LIGHT0 GL_SPECULAR", v, 4);
  E(glGetLightfv(GL_LIGHT0, 0x1234, v));
  E(glGetLightfv(0x1234, GL_AMBIENT, v));
  {
    const GLfloat position[4] = {1, 2, 3, 0};
    const GLfloat direction[3] = {0, 0, 1};
    const GLfloat colour[4] = {2, -1, 0.5f, 1};
    E(glTranslatef(10, 0, 0); glRotatef(90, 0, 1, 0));
    E(glLightfv(GL_LIGHT2, GL_POSITION, position));
    E(glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, direction));
    E(glLoadIdentity());
    E(glGetLightfv(GL_LIGHT2, GL_POSITION, v));
    values_f("GL_LIGHT2 GL_POSITION", v, 4);
    E(glGetLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, v));
    values_f("GL_LIGHT2 GL_SPOT_DIRECTION", v, 3);
    E(glLightfv(GL_LIGHT2, GL_DIFFUSE, colour));
    E(glGetLightfv(GL_LIGHT2, GL_DIFFUSE, v));
    values_f("GL_LIGHT2 GL_DIFFUSE (not clamped)", v, 4);
  }
  E(glLightModelf(0x1234, 1));
  E(glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_LINE));
  E(glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR));
  QI(GL_LIGHT_MODEL_COLOR_CONTROL, 1);
  E(glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 5));
  QB(GL_LIGHT_MODEL_TWO_SIDE, 1);
  E(glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 0.5f));
  QB(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  QF(GL_LIGHT_MODEL_AMBIENT, 4);
  E(glLightModeli(GL_LIGHT_MODEL_AMBIENT, 1));
  E(glMaterialf(GL_FRONT, GL_SHININESS, 129));
  E(glMaterialf(GL_FRONT, GL_SHININESS, -0.5f));
  E(glMaterialf(GL_FRONT, GL_SHININESS, 64));
  E(glMaterialf(GL_FRONT, GL_SPOT_EXPONENT, 4));
  E(glMaterialf(0x1234, GL_SHININESS, 4));
  E(glMaterialf(GL_FRONT, GL_AMBIENT, 4));
  E(glMateriali(GL_BACK, GL_SHININESS, 3));
  E(glGetMaterialfv(GL_FRONT, GL_SHININESS, v));
  values_f("GL_FRONT GL_SHININESS", v, 1);
  E(glGetMaterialfv(GL_BACK, GL_SHININESS, v));
  values_f("GL_BACK GL_SHININESS", v, 1);
  E(glGetMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, v));
  E(glGetMaterialfv(GL_FRONT, GL_POSITION, v));
  {
    const GLfloat colour[4] = {1.5f, -0.5f, 0.25f, 2};
    E(glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colour));
    E(glGetMaterialfv(GL_BACK, GL_DIFFUSE, v));
    values_f("GL_BACK GL_DIFFUSE (not clamped)", v, 4);
    E(glGetMaterialfv(GL_FRONT, GL_AMBIENT, v));
    values_f("GL_FRONT GL_AMBIENT", v, 4);
    E(glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, colour));
    E(glGetMaterialfv(GL_FRONT, GL_EMISSION, v));
    values_f("GL_FRONT GL_EMISSION", v, 4);
  }
  E(glColorMaterial(GL_FRONT, GL_SHININESS));
  E(glColorMaterial(0x1234, GL_DIFFUSE));
  E(glColorMaterial(GL_BACK, GL_SPECULAR));
  QI(GL_COLOR_MATERIAL_FACE, 1);
  QI(GL_COLOR_MATERIAL_PARAMETER, 1);
  E(glShadeModel(GL_LINE));
  E(glShadeModel(GL_FLAT));
  QI(GL_SHADE_MODEL, 1);
  E(glShadeModel(GL_SMOOTH));
}

static void clipping_and_rasterization(void) {
  section("points, lines, polygons (3.3-3.5)");
  E(glPointSize(-1));
  E(glPointSize(0));
  E(glPointSize(2.5f));
  QF(GL_POINT_SIZE, 1);
  E(glPointParameterf(GL_POINT_SIZE_MIN, -1));
  E(glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -1));
  E(glPointParameterf(0x1234, 1));
  E(glPointParameterf(GL_POINT_SIZE_MAX, 10));
  QF(GL_POINT_SIZE_MAX, 1);
  {
    const GLfloat attenuation[3] = {1, 0.5f, 0.25f};
    E(glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation));
    QF(GL_POINT_DISTANCE_ATTENUATION, 3);
  }
  E(glLineWidth(0));
  E(glLineWidth(-2));
  E(glLineWidth(3));
  QF(GL_LINE_WIDTH, 1);
  E(glLineWidth(1));
  E(glLineStipple(0, 0xf0f0));
  QI(GL_LINE_STIPPLE_REPEAT, 1);
  QI(GL_LINE_STIPPLE_PATTERN, 1);
  E(glLineStipple(300, 0xa5a5));
  QI(GL_LINE_STIPPLE_REPEAT, 1);
  QI(GL_LINE_STIPPLE_PATTERN, 1);
  E(glLineStipple(-5, 0xffff));
  QI(GL_LINE_STIPPLE_REPEAT, 1);
  E(glCullFace(GL_LINE));
  E(glCullFace(GL_FRONT_AND_BACK));
  QI(GL_CULL_FACE_MODE, 1);
  E(glCullFace(GL_BACK));
  E(glFrontFace(GL_FRONT));
  E(glFrontFace(GL_CW));
  QI(GL_FRONT_FACE, 1);
  E(glFrontFace(GL_CCW));
  E(glPolygonMode(GL_FRONT, GL_POINTS));
  E(glPolygonMode(GL_LEFT, GL_LINE));
  E(glPolygonMode(GL_BACK, GL_LINE));
  QI(GL_POLYGON_MODE, 2);
  E(glPolygonMode(GL_FRONT, GL_POINT));
  QI(GL_POLYGON_MODE, 2);
  E(glPolygonMode(GL_FRONT_AND_BACK, GL_FILL));
  E(glPolygonOffset(-1, 2));
  QF(GL_POLYGON_OFFSET_FACTOR, 1);
  QF(GL_POLYGON_OFFSET_UNITS, 1);
  E(glPolygonStipple(NULL));
  E(glGetPolygonStipple(NULL));
  {
    GLubyte stipple[128];
    GLubyte got[128];
    for (int i = 0; i < 128; ++i) stipple[i] = (GLubyte)(i * 37);
    E(glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE));
    E(glPolygonStipple(stipple));
    E(glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE));
    E(glGetPolygonStipple(got));
    value_i("stipple byte 1 (LSB first in, MSB first out)", got[1]);
    value_i("stipple byte 5", got[5]);
  }
  E(glSampleCoverage(2, GL_TRUE));
  QF(GL_SAMPLE_COVERAGE_VALUE, 1);
  QB(GL_SAMPLE_COVERAGE_INVERT, 1);
  E(glSampleCoverage(-1, GL_FALSE));
  QF(GL_SAMPLE_COVERAGE_VALUE, 1);
  E(glSampleCoverage(1, GL_FALSE));
}

static void fog(void) {
  section("fog (3.10)");
  E(glFogi(GL_FOG_MODE, GL_LINE));
  E(glFogi(GL_FOG_MODE, GL_EXP2));
  QI(GL_FOG_MODE, 1);
  E(glFogf(GL_FOG_DENSITY, -1));
  E(glFogf(GL_FOG_DENSITY, 0.5f));
  QF(GL_FOG_DENSITY, 1);
  E(glFogf(0x1234, 1));
  E(glFogf(GL_FOG_START, -10));
  E(glFogf(GL_FOG_END, -20));
  QF(GL_FOG_START, 1);
  QF(GL_FOG_END, 1);
  E(glFogi(GL_FOG_COORDINATE_SOURCE, GL_LINE));
  E(glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE));
  QI(GL_FOG_COORDINATE_SOURCE, 1);
  E(glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH));
  {
    const GLfloat colour[4] = {2, -1, 0.5f, 1};
    E(glFogfv(GL_FOG_COLOR, colour));
    QF(GL_FOG_COLOR, 4);
  }
  E(glFogf(GL_FOG_INDEX, 3.5f));
  QF(GL_FOG_INDEX, 1);
  E(glFogi(GL_FOG_MODE, GL_EXP));
}

static void textures(void) {
  section("texture images (3.8.1-3.8.3)");
  E(glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 40, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, -1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, 0, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, 5, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, 0x1234, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_BITMAP, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_BITMAP, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, image));
  E(glTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  {
    GLint v = -1;
    E(glGetTexLevelParameteriv(GL_TEXTURE_1D, 0, GL_TEXTURE_WIDTH, &v));
    value_i("1D level 0 GL_TEXTURE_WIDTH", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_1D, 0, GL_TEXTURE_BORDER, &v));
    value_i("1D level 0 GL_TEXTURE_BORDER", v);
  }
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5_A1, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 0, 0, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5_A1, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  {
    GLint v = -1;
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v));
    value_i("level 0 GL_TEXTURE_WIDTH", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v));
    value_i("level 0 GL_TEXTURE_INTERNAL_FORMAT", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPONENTS, &v));
    value_i("level 0 GL_TEXTURE_COMPONENTS", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &v));
    value_i("missing level 1 GL_TEXTURE_WIDTH", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_BORDER, &v));
    value_i("missing level 1 GL_TEXTURE_BORDER", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_INTERNAL_FORMAT, &v));
    value_i("missing level 1 GL_TEXTURE_INTERNAL_FORMAT", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_HEIGHT, &v));
    value_i("level 2 GL_TEXTURE_HEIGHT", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v));
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 40, GL_TEXTURE_WIDTH, &v));
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, 0x1234, &v));
    E(glGetTexLevelParameteriv(0x1234, 0, GL_TEXTURE_WIDTH, &v));
    E(glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, image));
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, 0x1234, image));
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, image));
    E(glGetTexImage(GL_TEXTURE_2D, 5, GL_RGBA, GL_UNSIGNED_BYTE, image));
  }
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, 5, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage1D(GL_TEXTURE_1D, 0, -1, 4, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glTexSubImage1D(GL_TEXTURE_1D, 0, -2, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));

  section("copying textures from the framebuffer (3.8.2)");
  E(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -20, -20, 16, 16, 0));
  E(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 100, 100, 16, 16, 0));
  E(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 16, 16, 2));
  E(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 15, 16, 0));
  E(glCopyTexImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 16, 16, 0));
  E(glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 0, 0, 16, 16, 0));
  E(glCopyTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 0, 0, 16, 16, 0));
  E(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 16, 16, 0));
  {
    GLint v = -1;
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v));
    value_i("level 0 GL_TEXTURE_WIDTH", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v));
    value_i("level 0 GL_TEXTURE_INTERNAL_FORMAT", v);
  }
  E(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, -30, -30, 8, 8));
  E(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 9, 8, 0, 0, 8, 8));
  E(glCopyTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 0, 0, 1, 1));
  E(glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 0, 0, 2));
  E(glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 6, 0));
  E(glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, 0, 0, 8, 0));

  section("proxy textures (3.8.1)");
  {
    GLint v = -1;
    E(glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 65536, 65536, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    E(glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v));
    value_i("proxy too large: GL_TEXTURE_WIDTH", v);
    E(glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    E(glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &v));
    value_i("proxy 64x32: GL_TEXTURE_HEIGHT", v);
    E(glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 64, 32, 3, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    E(glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 64, 32, 0, 0x1234, GL_UNSIGNED_BYTE, NULL));
    E(glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
    E(glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
    E(glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  }

  section("texture parameters (3.8.4)");
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST_MIPMAP_NEAREST));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT));
  E(glTexParameteri(GL_TEXTURE_2D, 0x1234, GL_NEAREST));
  E(glTexParameteri(0x1234, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
  E(glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 2));
  E(glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -5));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -1));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2));
  E(glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE));
  E(glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGBA));
  E(glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_NEVER));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL));
  {
    const GLfloat border[4] = {2, -1, 0.5f, 1};
    GLfloat v[4] = {0, 0, 0, 0};
    GLint iv[4] = {0, 0, 0, 0};
    E(glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border));
    E(glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, v));
    values_f("GL_TEXTURE_BORDER_COLOR", v, 4);
    E(glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, v));
    values_f("GL_TEXTURE_PRIORITY", v, 1);
    E(glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, v));
    values_f("GL_TEXTURE_MIN_LOD", v, 1);
    E(glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, v));
    values_f("GL_TEXTURE_MAX_LOD", v, 1);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, iv));
    value_i("GL_TEXTURE_MIN_FILTER", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, iv));
    value_i("GL_TEXTURE_WRAP_S", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, iv));
    value_i("GL_TEXTURE_WRAP_R", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, iv));
    value_i("GL_TEXTURE_BASE_LEVEL", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, iv));
    value_i("GL_TEXTURE_MAX_LEVEL", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, iv));
    value_i("GL_GENERATE_MIPMAP", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, iv));
    value_i("GL_DEPTH_TEXTURE_MODE", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, iv));
    value_i("GL_TEXTURE_COMPARE_FUNC", iv[0]);
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iv));
    value_i("GL_TEXTURE_BORDER_COLOR as integer, red == largest", iv[0] == 2147483647);
    E(glGetTexParameteriv(GL_TEXTURE_2D, 0x1234, iv));
    E(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, iv));
    E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0));
    E(glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE));
  }

  section("texture objects (3.8.12)");
  {
    GLuint names[3] = {0, 0, 0};
    GLuint zero = 0;
    E(glGenTextures(-1, names));
    E(glGenTextures(3, names));
    value_i("glIsTexture(0)", glIsTexture(0));
    value_i("glIsTexture of a generated, unbound name", glIsTexture(names[0]));
    E(glBindTexture(GL_TEXTURE_2D, names[0]));
    value_i("glIsTexture after glBindTexture", glIsTexture(names[0]));
    QI(GL_TEXTURE_BINDING_2D, 1);
    E(glBindTexture(GL_TEXTURE_1D, names[0]));
    E(glBindTexture(0x1234, names[1]));
    E(glBindTexture(GL_TEXTURE_3D, names[1]));
    QI(GL_TEXTURE_BINDING_3D, 1);
    E(glBindTexture(GL_TEXTURE_2D, names[1]));
    E(glBindTexture(GL_TEXTURE_CUBE_MAP, 999));
    E(glBindTexture(GL_TEXTURE_2D, 999));
    value_i("glIsTexture(999) bound as a cube map", glIsTexture(999));
    E(glDeleteTextures(1, &zero));
    E(glDeleteTextures(-1, names));
    E(glDeleteTextures(3, names));
    QI(GL_TEXTURE_BINDING_2D, 1);
    value_i("glIsTexture after glDeleteTextures", glIsTexture(names[0]));
    {
      const GLclampf priorities[2] = {0.5f, 2};
      GLuint bad[2] = {0, 999};
      GLboolean resident[2] = {GL_FALSE, GL_FALSE};
      E(glPrioritizeTextures(-1, names, priorities));
      E(glPrioritizeTextures(2, bad, priorities));
      E(glAreTexturesResident(-1, bad, resident));
      E(glAreTexturesResident(2, bad, resident));
      E(glAreTexturesResident(1, bad + 1, resident));
    }
    E(glBindTexture(GL_TEXTURE_CUBE_MAP, 0));
    E(glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
    E(glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
    E(glBindTexture(GL_TEXTURE_2D, 0));
    E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
  }

  section("texture environment and coordinate generation (3.8.13, 2.10.4)");
  E(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINE));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE));
  E(glTexEnvi(0x1234, GL_TEXTURE_ENV_MODE, GL_MODULATE));
  E(glTexEnvi(GL_TEXTURE_ENV, 0x1234, GL_MODULATE));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGBA));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_SUBTRACT));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE3));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_LINE));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_ONE_MINUS_SRC_ALPHA));
  E(glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3));
  E(glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4));
  E(glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f));
  E(glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, GL_MODULATE));
  {
    const GLfloat colour[4] = {2, -1, 0.5f, 1};
    GLfloat v[4] = {0, 0, 0, 0};
    GLint iv[4] = {0, 0, 0, 0};
    E(glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, colour));
    E(glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v));
    values_f("GL_TEXTURE_ENV_COLOR", v, 4);
    E(glGetTexEnvfv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, v));
    values_f("GL_ALPHA_SCALE", v, 1);
    E(glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, v));
    values_f("GL_TEXTURE_LOD_BIAS", v, 1);
    E(glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv));
    value_i("GL_TEXTURE_ENV_MODE", iv[0]);
    E(glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, iv));
    value_i("GL_COMBINE_ALPHA", iv[0]);
    E(glGetTexEnviv(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, iv));
    value_i("GL_SOURCE2_ALPHA", iv[0]);
    E(glGetTexEnviv(GL_TEXTURE_ENV, GL_OPERAND2_RGB, iv));
    value_i("GL_OPERAND2_RGB", iv[0]);
    E(glGetTexEnviv(GL_TEXTURE_ENV, 0x1234, iv));
    E(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE));
  }
  E(glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP));
  E(glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP));
  E(glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP));
  E(glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP));
  E(glTexGeni(0x1234, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR));
  E(glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_LINE));
  E(glTexGeni(GL_S, GL_OBJECT_PLANE, 1));
  {
    const GLfloat plane[4] = {1, 2, 3, 4};
    GLfloat v[4] = {0, 0, 0, 0};
    GLint iv[1] = {0};
    E(glTranslatef(0, 0, 2));
    E(glTexGenfv(GL_T, GL_EYE_PLANE, plane));
    E(glLoadIdentity());
    E(glGetTexGenfv(GL_T, GL_EYE_PLANE, v));
    values_f("GL_T GL_EYE_PLANE", v, 4);
    E(glGetTexGenfv(GL_R, GL_OBJECT_PLANE, v));
    values_f("GL_R GL_OBJECT_PLANE", v, 4);
    E(glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, iv));
    value_i("GL_S GL_TEXTURE_GEN_MODE", iv[0]);
    E(glGetTexGeniv(GL_Q, GL_TEXTURE_GEN_MODE, iv));
    value_i("GL_Q GL_TEXTURE_GEN_MODE", iv[0]);
  }
  {
    const GLenum past_last_unit = GL_TEXTURE0 + (GLenum)limit(GL_MAX_TEXTURE_UNITS);
    E(glActiveTexture(past_last_unit));
    E(glActiveTexture(GL_TEXTURE0 - 1));
    E(glClientActiveTexture(past_last_unit));
    E(glActiveTexture(GL_TEXTURE0));
  }
  E(glActiveTexture(GL_TEXTURE1));
  QI(GL_ACTIVE_TEXTURE, 1);
  E(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD));
  E(glActiveTexture(GL_TEXTURE0));
  {
    GLint iv[1] = {0};
    E(glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv));
    value_i("unit 0 GL_TEXTURE_ENV_MODE", iv[0]);
  }
  E(glClientActiveTexture(GL_TEXTURE1));
  QI(GL_CLIENT_ACTIVE_TEXTURE, 1);
  E(glClientActiveTexture(GL_TEXTURE0));

  section("compressed textures (3.8.3)");
  E(glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 16, image));
  E(glCompressedTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 4, 4, 0, 16, image));
  E(glGetCompressedTexImage(GL_TEXTURE_2D, 0, image));
}

static void pixels(void) {
  section("pixel storage and transfer (3.6)");
  E(glPixelStorei(GL_UNPACK_ALIGNMENT, 3));
  E(glPixelStorei(GL_UNPACK_ALIGNMENT, 0));
  E(glPixelStorei(GL_PACK_ALIGNMENT, 8));
  QI(GL_PACK_ALIGNMENT, 1);
  E(glPixelStorei(GL_PACK_ROW_LENGTH, -1));
  E(glPixelStorei(GL_UNPACK_SKIP_ROWS, -1));
  E(glPixelStorei(GL_UNPACK_SKIP_PIXELS, -1));
  E(glPixelStorei(GL_PACK_SKIP_IMAGES, -1));
  E(glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, -1));
  E(glPixelStorei(0x1234, 1));
  E(glPixelStorei(GL_UNPACK_SWAP_BYTES, 2));
  QB(GL_UNPACK_SWAP_BYTES, 1);
  E(glPixelStoref(GL_UNPACK_ROW_LENGTH, 2.6f));
  QI(GL_UNPACK_ROW_LENGTH, 1);
  E(glPixelStoref(GL_UNPACK_ROW_LENGTH, 0));
  E(glPixelStoref(GL_PACK_LSB_FIRST, 0.25f));
  QB(GL_PACK_LSB_FIRST, 1);
  E(glPixelStorei(GL_UNPACK_SWAP_BYTES, 0));
  E(glPixelStorei(GL_PACK_LSB_FIRST, 0));
  E(glPixelStorei(GL_PACK_ALIGNMENT, 4));

  E(glPixelTransferf(0x1234, 1));
  E(glPixelTransferf(GL_RED_SCALE, 2));
  QF(GL_RED_SCALE, 1);
  E(glPixelTransferf(GL_INDEX_SHIFT, 2.7f));
  QI(GL_INDEX_SHIFT, 1);
  E(glPixelTransferi(GL_MAP_COLOR, 7));
  QB(GL_MAP_COLOR, 1);
  E(glPixelTransferf(GL_RED_SCALE, 1));
  E(glPixelTransferi(GL_INDEX_SHIFT, 0));
  E(glPixelTransferi(GL_MAP_COLOR, 0));
  E(glPixelZoom(-2, 0.5f));
  QF(GL_ZOOM_X, 1);
  QF(GL_ZOOM_Y, 1);
  E(glPixelZoom(1, 1));
  {
    const GLfloat map[4] = {0, 0.5f, 2, -1};
    GLfloat got[4] = {9, 9, 9, 9};
    GLuint big_map_size = (GLuint)limit(GL_MAX_PIXEL_MAP_TABLE) + 1;
    E(glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 3, map));
    E(glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 0, map));
    E(glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, map));
    E(glPixelMapfv(0x1234, 1, map));
    E(glPixelMapfv(GL_PIXEL_MAP_I_TO_R, -4, map));
    E(glPixelMapfv(GL_PIXEL_MAP_I_TO_I, big_map_size, points));
    E(glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, map));
    QI(GL_PIXEL_MAP_I_TO_R_SIZE, 1);
    E(glGetPixelMapfv(GL_PIXEL_MAP_I_TO_R, got));
    values_f("GL_PIXEL_MAP_I_TO_R (clamped)", got, 4);
    E(glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 4, map));
    E(glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, got));
    values_f("GL_PIXEL_MAP_I_TO_I", got, 4);
    E(glGetPixelMapfv(0x1234, got));
    QI(GL_PIXEL_MAP_R_TO_R_SIZE, 1);
    E(glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, got));
    values_f("GL_PIXEL_MAP_R_TO_R (initial)", got, 1);
  }

  section("reading, drawing and copying pixels (4.3, 3.6.4)");
  E(glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, image));
  E(glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, image));
  E(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, image));
  E(glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, image));
  E(glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, image));
  E(glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, image));
  E(glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, image));
  E(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, image));
  E(glReadPixels(0, 0, 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, image));
  E(glReadPixels(-10, -10, 20, 20, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
  E(glDrawPixels(1, 1, 0x1234, GL_UNSIGNED_BYTE, image));
  E(glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, image));
  E(glDrawPixels(1, 1, GL_COLOR_INDEX, GL_BITMAP, image));
  E(glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, image));
  E(glDrawPixels(1, 1, GL_LUMINANCE_ALPHA, GL_FLOAT, points));
  E(glCopyPixels(0, 0, 1, 1, 0x1234));
  E(glCopyPixels(0, 0, -1, 1, GL_COLOR));
  E(glCopyPixels(0, 0, 1, 1, GL_STENCIL));
  E(glCopyPixels(-5, -5, 100, 100, GL_DEPTH));
  E(glReadBuffer(0x1234));
  E(glReadBuffer(GL_AUX0));
  E(glReadBuffer(GL_FRONT));
  QI(GL_READ_BUFFER, 1);
  E(glDrawBuffer(0x1234));
  E(glDrawBuffer(GL_AUX3));
  E(glDrawBuffer(GL_FRONT_LEFT));
  QI(GL_DRAW_BUFFER, 1);
  E(glDrawBuffer(GL_RIGHT));
  E(glDrawBuffer(GL_NONE));
  QI(GL_DRAW_BUFFER, 1);
  E(glDrawBuffer(GL_FRONT));

  /* The imaging subset (colour tables, convolution, the colour matrix) is optional in OpenGL
   * 1.4 and not checked; glBlendEquation and glBlendColor are core. */
  section("blend equation and colour (4.1.7)");
  E(glBlendEquation(0x1234));
  E(glBlendEquation(GL_FUNC_SUBTRACT));
  QI(GL_BLEND_EQUATION, 1);
  E(glBlendEquation(GL_FUNC_ADD));
  E(glBlendColor(2, -1, 0.5f, 1));
  QF(GL_BLEND_COLOR, 4);
}

static void fragments(void) {
  section("per-fragment operations and clears (4.1, 4.2)");
  E(glScissor(0, 0, -1, 5));
  E(glScissor(-3, 2, 10, 20));
  QI(GL_SCISSOR_BOX, 4);
  E(glAlphaFunc(0x1234, 0.5f));
  E(glAlphaFunc(GL_GREATER, 2));
  QF(GL_ALPHA_TEST_REF, 1);
  E(glAlphaFunc(GL_LESS, -1));
  QF(GL_ALPHA_TEST_REF, 1);
  QI(GL_ALPHA_TEST_FUNC, 1);
  E(glAlphaFunc(GL_ALWAYS, 0));
  E(glStencilFunc(GL_INCR, 0, 0));
  /* Mask bits beyond the stencil buffer's are kept or dropped as the implementation likes, so
   * the masks set here fit in 8 bits. */
  E(glStencilFunc(GL_EQUAL, 300, 0x3c));
  QI(GL_STENCIL_REF, 1);
  QI(GL_STENCIL_VALUE_MASK, 1);
  E(glStencilFunc(GL_EQUAL, -4, 0x0f));
  QI(GL_STENCIL_REF, 1);
  E(glStencilOp(GL_KEEP, GL_NEVER, GL_KEEP));
  E(glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT));
  QI(GL_STENCIL_FAIL, 1);
  QI(GL_STENCIL_PASS_DEPTH_FAIL, 1);
  QI(GL_STENCIL_PASS_DEPTH_PASS, 1);
  E(glStencilMask(0x5a));
  QI(GL_STENCIL_WRITEMASK, 1);
  E(glStencilMask(0xffffffff));
  E(glDepthFunc(GL_KEEP));
  E(glDepthFunc(GL_GEQUAL));
  QI(GL_DEPTH_FUNC, 1);
  E(glDepthFunc(GL_LESS));
  E(glDepthMask(5));
  query_b("GL_DEPTH_WRITEMASK after glDepthMask(5)", GL_DEPTH_WRITEMASK, 1);
  E(glDepthMask(GL_TRUE));
  E(glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE));
  E(glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE));
  E(glBlendFunc(0x1234, GL_ONE));
  E(glBlendFunc(GL_SRC_COLOR, GL_DST_COLOR));
  QI(GL_BLEND_SRC, 1);
  QI(GL_BLEND_DST, 1);
  E(glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_COLOR));
  E(glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_SRC_ALPHA, 0x1234));
  E(glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_SRC_ALPHA, GL_DST_ALPHA));
  QI(GL_BLEND_SRC_RGB, 1);
  QI(GL_BLEND_DST_ALPHA, 1);
  E(glBlendFunc(GL_ONE, GL_ZERO));
  E(glLogicOp(GL_COPY + 0x20));
  E(glLogicOp(GL_XOR));
  QI(GL_LOGIC_OP_MODE, 1);
  E(glLogicOp(GL_COPY));
  E(glColorMask(GL_TRUE, GL_FALSE, 3, GL_FALSE));
  QB(GL_COLOR_WRITEMASK, 4);
  QI(GL_COLOR_WRITEMASK, 4);
  E(glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE));
  E(glIndexMask(0x0f));
  QI(GL_INDEX_WRITEMASK, 1);
  E(glClear(0x8));
  E(glClear(GL_COLOR_BUFFER_BIT | 0x100000));
  E(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT));
  E(glClearColor(2, -1, 0.5f, 3));
  QF(GL_COLOR_CLEAR_VALUE, 4);
  E(glClearDepth(2));
  QF(GL_DEPTH_CLEAR_VALUE, 1);
  E(glClearDepth(-0.5));
  QF(GL_DEPTH_CLEAR_VALUE, 1);
  E(glClearAccum(-2, 2, 0.25f, 0.5f));
  QF(GL_ACCUM_CLEAR_VALUE, 4);
  E(glClearStencil(0x1ff));
  QI(GL_STENCIL_CLEAR_VALUE, 1);
  /* A clear index is kept in fixed point of unspecified precision: only whole values are compared. */
  E(glClearIndex(3));
  QF(GL_INDEX_CLEAR_VALUE, 1);
  E(glClearColor(0, 0, 0, 0));
  E(glClearDepth(1));
  E(glClearStencil(0));
  E(glAccum(0x1234, 1));
  E(glAccum(GL_LOAD, 1));
  E(glAccum(GL_RETURN, 1));
  E(glAccum(GL_MULT, -2));
  E(glFlush());
  E(glFinish());
}

static void vertex_arrays(void) {
  section("vertex arrays (2.8)");
  static const GLushort indices[4] = {0, 1, 2, 3};
  E(glVertexPointer(1, GL_FLOAT, 0, points));
  E(glVertexPointer(5, GL_FLOAT, 0, points));
  E(glVertexPointer(3, GL_UNSIGNED_BYTE, 0, points));
  E(glVertexPointer(3, GL_FLOAT, -4, points));
  E(glVertexPointer(3, GL_SHORT, 16, points));
  QI(GL_VERTEX_ARRAY_SIZE, 1);
  QI(GL_VERTEX_ARRAY_TYPE, 1);
  QI(GL_VERTEX_ARRAY_STRIDE, 1);
  E(glColorPointer(2, GL_FLOAT, 0, points));
  E(glColorPointer(3, GL_DOUBLE, 0, points));
  E(glColorPointer(4, 0x1234, 0, points));
  E(glNormalPointer(GL_UNSIGNED_BYTE, 0, points));
  E(glNormalPointer(GL_BYTE, -1, points));
  E(glTexCoordPointer(5, GL_FLOAT, 0, points));
  E(glTexCoordPointer(1, GL_INT, 0, points));
  E(glTexCoordPointer(2, GL_BYTE, 0, points));
  E(glIndexPointer(GL_BYTE, 0, points));
  E(glIndexPointer(GL_UNSIGNED_BYTE, 0, points));
  E(glEdgeFlagPointer(-1, points));
  E(glFogCoordPointer(GL_INT, 0, points));
  E(glFogCoordPointer(GL_DOUBLE, 8, points));
  E(glSecondaryColorPointer(4, GL_FLOAT, 0, points));
  E(glSecondaryColorPointer(3, GL_UNSIGNED_INT, 0, points));
  QI(GL_SECONDARY_COLOR_ARRAY_SIZE, 1);
  E(glEnableClientState(0x1234));
  E(glEnableClientState(GL_LIGHTING));
  E(glDisableClientState(GL_TEXTURE_2D));
  E(glEnableClientState(GL_VERTEX_ARRAY));
  QE(GL_VERTEX_ARRAY);
  {
    GLvoid *pointer = NULL;
    E(glVertexPointer(2, GL_FLOAT, 0, points + 8));
    E(glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer));
    value_i("GL_VERTEX_ARRAY_POINTER is the pointer given", pointer == (GLvoid *)(points + 8));
    E(glGetPointerv(0x1234, &pointer));
    E(glGetPointerv(GL_VERTEX_ARRAY_SIZE, &pointer));
    pointer = (GLvoid *)image;
    E(glGetPointerv(GL_COLOR_ARRAY_POINTER, &pointer));
    value_i("GL_COLOR_ARRAY_POINTER is the pointer given", pointer == (GLvoid *)points);
    pointer = (GLvoid *)image;
    E(glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &pointer));
    value_i("GL_FEEDBACK_BUFFER_POINTER is NULL", pointer == NULL);
  }
  E(glDrawArrays(0x1234, 0, 3));
  E(glDrawArrays(GL_TRIANGLES, 0, -1));
  E(glDrawArrays(GL_TRIANGLES, 0, 0));
  E(glDrawArrays(GL_POINTS, 0, 4));
  E(glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, indices));
  E(glDrawElements(GL_TRIANGLES, 3, GL_SHORT, indices));
  E(glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_SHORT, indices));
  E(glDrawElements(0x1234, 3, GL_UNSIGNED_SHORT, indices));
  E(glDrawElements(GL_LINES, 4, GL_UNSIGNED_SHORT, indices));
  E(glDrawRangeElements(GL_TRIANGLES, 3, 0, 3, GL_UNSIGNED_SHORT, indices));
  E(glDrawRangeElements(GL_TRIANGLES, 0, 3, -1, GL_UNSIGNED_SHORT, indices));
  E(glDrawRangeElements(GL_TRIANGLES, 0, 3, 3, GL_UNSIGNED_SHORT, indices));
  {
    const GLint firsts[2] = {0, 1};
    const GLsizei counts[2] = {3, -1};
    const GLvoid *lists[2] = {indices, indices};
    E(glMultiDrawArrays(GL_TRIANGLES, firsts, counts, -1));
    E(glMultiDrawArrays(GL_TRIANGLES, firsts, counts, 1));
    E(glMultiDrawArrays(GL_TRIANGLES, firsts, counts, 2));
    E(glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_SHORT, lists, 1));
    E(glMultiDrawElements(GL_TRIANGLES, counts, GL_DOUBLE, lists, 1));
  }
  E(glBegin(GL_POINTS); glArrayElement(1); glEnd());
  E(glArrayElement(-1));
  E(glInterleavedArrays(0x1234, 0, points));
  E(glInterleavedArrays(GL_T2F_C4F_N3F_V3F, -1, points));
  E(glInterleavedArrays(GL_T2F_C4F_N3F_V3F, 0, points));
  QI(GL_VERTEX_ARRAY_STRIDE, 1);
  QI(GL_COLOR_ARRAY_SIZE, 1);
  QI(GL_TEXTURE_COORD_ARRAY_STRIDE, 1);
  QE(GL_NORMAL_ARRAY);
  QE(GL_INDEX_ARRAY);
  E(glInterleavedArrays(GL_C4UB_V3F, 0, points));
  QI(GL_COLOR_ARRAY_TYPE, 1);
  QI(GL_VERTEX_ARRAY_STRIDE, 1);
  QE(GL_TEXTURE_COORD_ARRAY);
  E(glInterleavedArrays(GL_V2F, 20, points));
  QI(GL_VERTEX_ARRAY_STRIDE, 1);
  QE(GL_COLOR_ARRAY);
  E(glDisableClientState(GL_VERTEX_ARRAY));
  E(glDrawArrays(GL_TRIANGLES, 0, 3));
}

static void attribute_stacks(void) {
  section("attribute stacks (6.1.14)");
  GLint max = limit(GL_MAX_ATTRIB_STACK_DEPTH);
  E(glPopAttrib());
  E(glPushAttrib(GL_ENABLE_BIT); glEnable(GL_LIGHTING); glEnable(GL_TEXTURE_2D); glPopAttrib());
  QE(GL_LIGHTING);
  QE(GL_TEXTURE_2D);
  E(glPushAttrib(GL_CURRENT_BIT); glColor3f(0, 1, 0); glPopAttrib());
  QF(GL_CURRENT_COLOR, 4);
  E(glPushAttrib(GL_LIGHTING_BIT); glEnable(GL_LIGHT3); glShadeModel(GL_FLAT); glPopAttrib());
  QE(GL_LIGHT3);
  QI(GL_SHADE_MODEL, 1);
  E(glPushAttrib(GL_TRANSFORM_BIT); glMatrixMode(GL_TEXTURE); glEnable(GL_NORMALIZE); glPopAttrib());
  QI(GL_MATRIX_MODE, 1);
  QE(GL_NORMALIZE);
  E(glPushAttrib(GL_VIEWPORT_BIT); glViewport(1, 2, 3, 4); glDepthRange(0.5, 0.5); glPopAttrib());
  QI(GL_VIEWPORT, 4);
  QF(GL_DEPTH_RANGE, 2);
  E(glPushAttrib(GL_COLOR_BUFFER_BIT); glClearColor(1, 1, 1, 1); glDrawBuffer(GL_NONE); glPopAttrib());
  QF(GL_COLOR_CLEAR_VALUE, 4);
  QI(GL_DRAW_BUFFER, 1);
  E(glPushAttrib(GL_TEXTURE_BIT); glBindTexture(GL_TEXTURE_2D, 77); glPopAttrib());
  QI(GL_TEXTURE_BINDING_2D, 1);
  E(glPushAttrib(GL_PIXEL_MODE_BIT); glPixelZoom(3, 3); glReadBuffer(GL_BACK); glPopAttrib());
  QF(GL_ZOOM_X, 1);
  E(glPushAttrib(GL_LIST_BIT); glListBase(7); glPopAttrib());
  QI(GL_LIST_BASE, 1);
  E(glPushAttrib(0); glPopAttrib());
  E(glPushAttrib(0xffffffff); glPopAttrib());
  for (int i = 0; i < max; ++i) glPushAttrib(GL_CURRENT_BIT);
  report("glPushAttrib(GL_CURRENT_BIT) until the stack is full");
  value_i("GL_ATTRIB_STACK_DEPTH == GL_MAX_ATTRIB_STACK_DEPTH", limit(GL_ATTRIB_STACK_DEPTH) == max);
  E(glPushAttrib(GL_CURRENT_BIT));
  value_i("GL_ATTRIB_STACK_DEPTH == GL_MAX_ATTRIB_STACK_DEPTH", limit(GL_ATTRIB_STACK_DEPTH) == max);
  for (int i = 0; i < max; ++i) glPopAttrib();
  report("glPopAttrib() until the stack is empty");
  QI(GL_ATTRIB_STACK_DEPTH, 1);
  E(glPopAttrib());

  max = limit(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH);
  E(glPopClientAttrib());
  E(glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT); glPixelStorei(GL_UNPACK_ALIGNMENT, 1); glPopClientAttrib());
  QI(GL_UNPACK_ALIGNMENT, 1);
  E(glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT); glEnableClientState(GL_NORMAL_ARRAY);
    glClientActiveTexture(GL_TEXTURE1); glPopClientAttrib());
  QE(GL_NORMAL_ARRAY);
  QI(GL_CLIENT_ACTIVE_TEXTURE, 1);
  E(glClientActiveTexture(GL_TEXTURE0));
  E(glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS); glPopClientAttrib());
  for (int i = 0; i < max; ++i) glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  report("glPushClientAttrib until the stack is full");
  value_i("GL_CLIENT_ATTRIB_STACK_DEPTH == GL_MAX_CLIENT_ATTRIB_STACK_DEPTH",
          limit(GL_CLIENT_ATTRIB_STACK_DEPTH) == max);
  E(glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT));
  for (int i = 0; i < max; ++i) glPopClientAttrib();
  report("glPopClientAttrib until the stack is empty");
  QI(GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
  E(glPopClientAttrib());
}

static void selection_and_feedback(void) {
  section("selection (5.2)");
  static GLuint select_buffer[64];
  GLint max = limit(GL_MAX_NAME_STACK_DEPTH);
  E(glInitNames());
  E(glPushName(1));
  E(glPopName());
  E(glLoadName(1));
  QI(GL_NAME_STACK_DEPTH, 1);
  E(glRenderMode(GL_SELECT));
  value_i("GL_RENDER_MODE after glRenderMode(GL_SELECT) without a select buffer", limit(GL_RENDER_MODE));
  E(glRenderMode(GL_RENDER));
  E(glSelectBuffer(-1, select_buffer));
  E(glRenderMode(0x1234));
  E(glSelectBuffer(4, select_buffer));
  QI(GL_SELECTION_BUFFER_SIZE, 1);
  value_i("glRenderMode(GL_SELECT) returned", glRenderMode(GL_SELECT));
  report("glRenderMode(GL_SELECT)");
  QI(GL_RENDER_MODE, 1);
  E(glSelectBuffer(64, select_buffer));
  E(glFeedbackBuffer(64, GL_3D, (GLfloat *)select_buffer));
  E(glLoadName(5));
  E(glPopName());
  E(glPushName(7));
  E(glLoadName(8));
  E(glBegin(GL_TRIANGLES); glVertex2f(0, 0); glVertex2f(0.5f, 0); glVertex2f(0, 0.5f); glEnd());
  E(glPushName(9); glRectf(-0.1f, -0.1f, 0.1f, 0.1f));
  E(glPushName(10); glPopName(); glBegin(GL_POINTS); glVertex3f(0, 0, 0.5f); glEnd());
  E(glPushName(11); glBegin(GL_POINTS); glVertex3f(5, 0, 0); glEnd());
  value_i("hits", glRenderMode(GL_RENDER));
  report("glRenderMode(GL_RENDER)");
  for (int i = 0; i < 14; ++i) {
    char name[32];
    snprintf(name, sizeof name, "select buffer %d", i);
    value_i(name, (long)select_buffer[i]);
  }
  E(glSelectBuffer(64, select_buffer));
  value_i("glRenderMode(GL_SELECT) returned", glRenderMode(GL_SELECT));
  report("glRenderMode(GL_SELECT)");
  QI(GL_NAME_STACK_DEPTH, 1);
  E(glPopName());
  E(glLoadName(3));
  for (int i = 0; i < max; ++i) glPushName((GLuint)i);
  report("glPushName until the name stack is full");
  E(glPushName(99));
  value_i("GL_NAME_STACK_DEPTH == GL_MAX_NAME_STACK_DEPTH", limit(GL_NAME_STACK_DEPTH) == max);
  E(glInitNames());
  QI(GL_NAME_STACK_DEPTH, 1);
  {
    static GLuint small[6];
    value_i("glRenderMode(GL_RENDER) returned", glRenderMode(GL_RENDER));
    E(glSelectBuffer(6, small));
    E(glRenderMode(GL_SELECT));
    E(glPushName(1); glRectf(-0.5f, -0.5f, 0.5f, 0.5f); glPushName(2); glRectf(-0.5f, -0.5f, 0.5f, 0.5f));
    E(glLoadName(3); glRectf(-0.5f, -0.5f, 0.5f, 0.5f));
    value_i("overflowed glRenderMode(GL_RENDER) returned", glRenderMode(GL_RENDER));
    report("glRenderMode(GL_RENDER)");
  }

  section("feedback (5.3)");
  {
    static GLfloat feedback[64];
    E(glFeedbackBuffer(-1, GL_2D, feedback));
    E(glFeedbackBuffer(64, 0x1234, feedback));
    E(glRenderMode(GL_FEEDBACK));
    E(glFeedbackBuffer(64, GL_3D_COLOR, feedback));
    QI(GL_FEEDBACK_BUFFER_SIZE, 1);
    QI(GL_FEEDBACK_BUFFER_TYPE, 1);
    value_i("glRenderMode(GL_FEEDBACK) returned", glRenderMode(GL_FEEDBACK));
    E(glFeedbackBuffer(64, GL_2D, feedback));
    E(glPassThrough(42));
    E(glColor4f(1, 0.5f, 0.25f, 1); glBegin(GL_POINTS); glVertex3f(0.5f, 0.5f, 0.5f); glEnd());
    E(glBegin(GL_LINES); glVertex2f(0, 0); glVertex2f(0.5f, 0); glEnd());
    E(glBegin(GL_POINTS); glVertex3f(0, 0, 5); glEnd());
    E(glRasterPos2f(0, 0); glBitmap(0, 0, 0, 0, 1, 1, NULL));
    E(glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image));
    E(glCopyPixels(0, 0, 1, 1, GL_COLOR));
    {
      GLint count = glRenderMode(GL_RENDER);
      report("glRenderMode(GL_RENDER)");
      value_i("feedback values", count);
      if (count > 64) count = 64;
      if (count > 0) values_f("feedback", feedback, count);
    }
    E(glFeedbackBuffer(5, GL_3D, feedback));
    E(glRenderMode(GL_FEEDBACK));
    E(glBegin(GL_POINTS); glVertex2f(0, 0); glVertex2f(0.1f, 0); glEnd());
    value_i("overflowed glRenderMode(GL_RENDER) returned", glRenderMode(GL_RENDER));
    E(glColor4f(1, 1, 1, 1));
  }
}

static void evaluators(void) {
  section("evaluators (5.1)");
  GLint iv[2] = {0, 0};
  GLfloat v[64] = {0};  /* GL_COEFF returns order x components values */
  for (int i = 0; i < 4096; ++i) points[i] = (GLfloat)(i % 7) * 0.25f;
  E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, points));
  E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 1000, points));
  E(glMap1f(GL_MAP1_VERTEX_3, 1, 1, 3, 2, points));
  E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 2, points));
  E(glMap1f(0x1234, 0, 1, 3, 2, points));
  E(glMap1f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, points));
  E(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 0, points));
  E(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 2, 2, points));
  E(glMap2f(GL_MAP2_VERTEX_3, 0, 0, 3, 2, 0, 1, 6, 2, points));
  E(glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, iv));
  value_i("GL_MAP1_VERTEX_3 GL_ORDER (initial)", iv[0]);
  E(glGetMapfv(GL_MAP1_VERTEX_3, GL_DOMAIN, v));
  values_f("GL_MAP1_VERTEX_3 GL_DOMAIN (initial)", v, 2);
  E(glGetMapfv(GL_MAP1_COLOR_4, GL_COEFF, v));
  values_f("GL_MAP1_COLOR_4 GL_COEFF (initial)", v, 4);
  E(glGetMapfv(GL_MAP1_VERTEX_3, 0x1234, v));
  E(glGetMapfv(0x1234, GL_ORDER, v));
  E(glEnable(GL_MAP1_VERTEX_3));
  E(glEvalMesh1(GL_LINE, 0, 4));
  E(glEvalMesh1(GL_FILL, 0, 4));
  E(glEvalMesh2(GL_POINTS, 0, 1, 0, 1));
  E(glEvalPoint1(2));
  QI(GL_MAP1_GRID_SEGMENTS, 1);
  QF(GL_MAP1_GRID_DOMAIN, 2);
  QI(GL_MAP2_GRID_SEGMENTS, 2);
  E(glMapGrid1f(0, 0, 1));
  E(glMapGrid1f(-1, 0, 1));
  E(glMapGrid2f(4, 0, 1, 0, 0, 1));
  E(glMapGrid1f(8, 1, 0));
  QF(GL_MAP1_GRID_DOMAIN, 2);
  E(glMapGrid2d(2, 0, 1, 3, 0.5, 1));
  QI(GL_MAP2_GRID_SEGMENTS, 2);
  QF(GL_MAP2_GRID_DOMAIN, 4);
  E(glMap1f(GL_MAP1_VERTEX_3, 2, 4, 3, 4, points));
  E(glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, iv));
  value_i("GL_MAP1_VERTEX_3 GL_ORDER", iv[0]);
  E(glGetMapfv(GL_MAP1_VERTEX_3, GL_DOMAIN, v));
  values_f("GL_MAP1_VERTEX_3 GL_DOMAIN", v, 2);
  E(glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, v));
  values_f("GL_MAP1_VERTEX_3 GL_COEFF", v, 4);
  E(glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 3, 0, 1, 6, 2, points));
  E(glGetMapiv(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, iv));
  value_i("GL_MAP2_TEXTURE_COORD_2 GL_ORDER u", iv[0]);
  value_i("GL_MAP2_TEXTURE_COORD_2 GL_ORDER v", iv[1]);
  E(glEvalMesh1(GL_POINT, 0, 8));
  E(glEvalMesh1(GL_LINE, 8, 0));
  E(glBegin(GL_POINTS); glEvalMesh1(GL_POINT, 0, 1); glEnd());
  E(glDisable(GL_MAP1_VERTEX_3));
  E(glEnable(GL_AUTO_NORMAL));
  QE(GL_AUTO_NORMAL);
  E(glDisable(GL_AUTO_NORMAL));
  E(glEnable(GL_MAP2_VERTEX_4));
  QE(GL_MAP2_VERTEX_4);
  E(glDisable(GL_MAP2_VERTEX_4));
}

static void queries_and_strings(void) {
  section("other queries (6.1)");
  QB(GL_RGBA_MODE, 1);
  QB(GL_INDEX_MODE, 1);
  QB(GL_DOUBLEBUFFER, 1);
  QB(GL_STEREO, 1);
  QI(GL_LINE_STIPPLE_REPEAT, 1);
  QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
  QF(GL_TEXTURE_MATRIX, 16);
  QI(GL_PACK_ROW_LENGTH, 1);
  QI(GL_UNPACK_SKIP_IMAGES, 1);
  QI(GL_TEXTURE_BINDING_1D, 1);
  QI(GL_TEXTURE_BINDING_CUBE_MAP, 1);
  QF(GL_FOG_COLOR, 4);
  QI(GL_STENCIL_FUNC, 1);
  QF(GL_POINT_SIZE_MIN, 1);
  QF(GL_POINT_FADE_THRESHOLD_SIZE, 1);
  QB(GL_SAMPLE_COVERAGE_INVERT, 1);
  QI(GL_BLEND_DST_RGB, 1);
  QI(GL_BLEND_SRC_ALPHA, 1);
  QI(GL_EDGE_FLAG, 1);
  QB(GL_CURRENT_INDEX, 1);
  QI(GL_CURRENT_INDEX, 1);
  QI(GL_SELECTION_BUFFER_SIZE, 1);
  QI(GL_FEEDBACK_BUFFER_SIZE, 1);
  QI(GL_POLYGON_OFFSET_FACTOR, 1);
  QF(GL_INDEX_OFFSET, 1);
  QF(GL_DEPTH_BIAS, 1);
  QI(GL_TRANSPOSE_MODELVIEW_MATRIX, 16);
  E(glMatrixMode(GL_MODELVIEW); glTranslatef(1, 2, 3));
  QF(GL_TRANSPOSE_MODELVIEW_MATRIX, 16);
  QI(GL_MODELVIEW_MATRIX, 16);
  E(glLoadIdentity());
  E((void)glGetString(GL_VERSION));
  E((void)glGetString(GL_EXTENSIONS));
  E(glIsEnabled(GL_COLOR_ARRAY));
  E(glIsEnabled(GL_FOG_COORDINATE_ARRAY));
}

static void refused_calls_change_nothing(void) {
  section("a refused call changes no state (2.5)");
  E(glLineWidth(2.5f); glLineWidth(0));
  QF(GL_LINE_WIDTH, 1);
  E(glViewport(1, 2, 30, 40); glViewport(0, 0, -1, -1));
  QI(GL_VIEWPORT, 4);
  E(glBlendFunc(GL_SRC_ALPHA, GL_ONE); glBlendFunc(GL_SRC_ALPHA, 0x1234));
  QI(GL_BLEND_SRC, 1);
  QI(GL_BLEND_DST, 1);
  E(glStencilOp(GL_REPLACE, GL_KEEP, GL_INCR); glStencilOp(GL_REPLACE, GL_KEEP, 0x1234));
  QI(GL_STENCIL_FAIL, 1);
  QI(GL_STENCIL_PASS_DEPTH_PASS, 1);
  E(glFogi(GL_FOG_MODE, GL_LINEAR); glFogi(GL_FOG_MODE, GL_LINE));
  QI(GL_FOG_MODE, 1);
  E(glPointSize(3); glPointSize(-3));
  QF(GL_POINT_SIZE, 1);
  E(glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 30); glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 100));
  {
    GLfloat v[1] = {0};
    glGetLightfv(GL_LIGHT1, GL_SPOT_CUTOFF, v);
    values_f("GL_LIGHT1 GL_SPOT_CUTOFF", v, 1);
  }
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR));
  {
    GLint v[1] = {0};
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, v);
    value_i("GL_TEXTURE_MAG_FILTER", v[0]);
  }
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR));
  E(glMatrixMode(GL_PROJECTION); glMatrixMode(0x1234));
  QI(GL_MATRIX_MODE, 1);
  E(glMatrixMode(GL_MODELVIEW));
  E(glSelectBuffer(8, NULL); glSelectBuffer(-2, NULL));
  QI(GL_SELECTION_BUFFER_SIZE, 1);
  E(glDepthFunc(GL_ALWAYS); glDepthFunc(GL_ALWAYS + 1));
  QI(GL_DEPTH_FUNC, 1);
  E(glDepthFunc(GL_LESS));
  E(glLineWidth(1); glPointSize(1); glBlendFunc(GL_ONE, GL_ZERO); glFogi(GL_FOG_MODE, GL_EXP));
  E(glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP));
}

static void derived_state(void) {
  section("state derived from other state (2.7, 2.13, 2.10.4)");
  {
    const GLfloat ambient[4] = {0.2f, 0.4f, 0.6f, 1};
    GLfloat v[4] = {0, 0, 0, 0};
    E(glColorMaterial(GL_FRONT, GL_AMBIENT); glEnable(GL_COLOR_MATERIAL));
    E(glColor4f(0.5f, 0.25f, 0.125f, 0.75f));
    E(glGetMaterialfv(GL_FRONT, GL_AMBIENT, v));
    values_f("GL_FRONT GL_AMBIENT follows the colour", v, 4);
    E(glGetMaterialfv(GL_BACK, GL_AMBIENT, v));
    values_f("GL_BACK GL_AMBIENT does not", v, 4);
    E(glMaterialfv(GL_FRONT, GL_AMBIENT, ambient));
    E(glDisable(GL_COLOR_MATERIAL); glColor4f(1, 1, 1, 1));
    E(glGetMaterialfv(GL_FRONT, GL_AMBIENT, v));
    values_f("GL_FRONT GL_AMBIENT after glDisable(GL_COLOR_MATERIAL)", v, 4);
    E(glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE));
  }
  E(glEnable(GL_NORMALIZE); glNormal3f(0, 3, 4));
  QF(GL_CURRENT_NORMAL, 3);
  E(glDisable(GL_NORMALIZE); glNormal3f(0, 0, 1));
  E(glMatrixMode(GL_TEXTURE); glTranslatef(0.5f, 0, 0); glMatrixMode(GL_MODELVIEW));
  E(glTexCoord2f(0.25f, 0.5f));
  QF(GL_CURRENT_TEXTURE_COORDS, 4);
  E(glRasterPos2f(0, 0));
  QF(GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
  E(glMatrixMode(GL_TEXTURE); glLoadIdentity(); glMatrixMode(GL_MODELVIEW));
  {
    const GLfloat plane[4] = {0, 0, 0, 0.75f};
    E(glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR); glTexGenfv(GL_T, GL_OBJECT_PLANE, plane);
      glEnable(GL_TEXTURE_GEN_T));
    E(glRasterPos2f(0.5f, 0.5f));
    QF(GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    E(glDisable(GL_TEXTURE_GEN_T));
  }
  {
    const GLfloat white[4] = {1, 1, 1, 1};
    const GLfloat half[4] = {0.5f, 0.5f, 0.5f, 1};
    const GLfloat black[4] = {0, 0, 0, 1};
    const GLfloat model_ambient[4] = {0.2f, 0.2f, 0.2f, 1};
    const GLfloat from_z[4] = {0, 0, 1, 0};
    E(glLightfv(GL_LIGHT0, GL_DIFFUSE, white); glLightfv(GL_LIGHT0, GL_POSITION, from_z);
      glLightfv(GL_LIGHT0, GL_SPECULAR, black); glLightfv(GL_LIGHT0, GL_AMBIENT, black));
    E(glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient));
    E(glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, half); glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, half);
      glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black); glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black));
    E(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180); glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
      glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1); glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0));
    E(glEnable(GL_LIGHTING); glEnable(GL_LIGHT0));
    E(glNormal3f(0, 0, 1); glRasterPos3f(0, 0, 0));
    QF(GL_CURRENT_RASTER_COLOR, 4);
    E(glNormal3f(0, 0, -1); glRasterPos3f(0, 0, 0));
    QF(GL_CURRENT_RASTER_COLOR, 4);
    E(glDisable(GL_LIGHTING); glDisable(GL_LIGHT0); glNormal3f(0, 0, 1));
  }
  E(glTranslatef(0, 0, -0.5f); glRasterPos3f(0.3f, 0.4f, 0));
  QF(GL_CURRENT_RASTER_DISTANCE, 1);
  QF(GL_CURRENT_RASTER_POSITION, 4);
  E(glLoadIdentity());
  E(glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE); glFogCoordf(7); glRasterPos2f(0, 0));
  QF(GL_CURRENT_RASTER_DISTANCE, 1);
  E(glWindowPos2f(3, 4));
  QF(GL_CURRENT_RASTER_DISTANCE, 1);
  E(glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH); glWindowPos2f(3, 4));
  QF(GL_CURRENT_RASTER_DISTANCE, 1);
  E(glColor4f(0.25f, 0.5f, 0.75f, 1); glWindowPos3f(1.5f, 2.5f, 0.25f));
  QF(GL_CURRENT_RASTER_COLOR, 4);
  QF(GL_CURRENT_RASTER_POSITION, 4);
  E(glColor4f(1, 1, 1, 1));
  {
    const GLdouble plane[4] = {-1, 0, 0, 0};
    E(glClipPlane(GL_CLIP_PLANE2, plane); glEnable(GL_CLIP_PLANE2); glRasterPos2f(0.5f, 0));
    QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
    E(glRasterPos2f(-0.5f, 0));
    QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
    E(glDisable(GL_CLIP_PLANE2));
  }
  E(glRasterPos2f(5, 5); glBitmap(0, 0, 0, 0, 10, 10, NULL));
  QF(GL_CURRENT_RASTER_POSITION, 4);
  QB(GL_CURRENT_RASTER_POSITION_VALID, 1);
  E(glRasterPos2f(0, 0));
}

static void conversions(void) {
  section("query conversions (6.1.2)");
  E(glColor4f(0.5f, -0.5f, 1, 0));
  QI(GL_CURRENT_COLOR, 4);
  QB(GL_CURRENT_COLOR, 4);
  QD(GL_CURRENT_COLOR, 4);
  E(glNormal3f(0.5f, -1, 0));
  QI(GL_CURRENT_NORMAL, 3);
  E(glNormal3f(0, 0, 1); glColor4f(1, 1, 1, 1));
  E(glClearColor(0.25f, 0.5f, 0.75f, 1));
  QI(GL_COLOR_CLEAR_VALUE, 4);
  E(glClearDepth(0.5));
  QI(GL_DEPTH_CLEAR_VALUE, 1);
  QB(GL_DEPTH_CLEAR_VALUE, 1);
  E(glClearColor(0, 0, 0, 0); glClearDepth(1));
  E(glLineWidth(2.5f));
  QI(GL_LINE_WIDTH, 1);
  E(glLineWidth(3.5f));
  QI(GL_LINE_WIDTH, 1);
  E(glLineWidth(1));
  E(glPolygonOffset(-1.5f, 0.5f));
  QI(GL_POLYGON_OFFSET_FACTOR, 1);
  QB(GL_POLYGON_OFFSET_UNITS, 1);
  E(glPolygonOffset(0, 0));
  E(glViewport(2, 4, 30, 40));
  QF(GL_VIEWPORT, 4);
  QB(GL_VIEWPORT, 4);
  E(glViewport(0, 0, 64, 64));
  QD(GL_MATRIX_MODE, 1);
  QB(GL_MATRIX_MODE, 1);
  QF(GL_LIGHT_MODEL_AMBIENT, 4);
  QI(GL_LIGHT_MODEL_AMBIENT, 4);
  E(glFogf(GL_FOG_START, 2.5f));
  QI(GL_FOG_START, 1);
  E(glFogf(GL_FOG_START, 0));
  E(glPixelZoom(2.5f, -1.5f));
  QI(GL_ZOOM_X, 1);
  QI(GL_ZOOM_Y, 1);
  E(glPixelZoom(1, 1));
  QI(GL_FOG_COLOR, 4);
  QB(GL_FOG_COLOR, 4);
  QB(GL_TEXTURE_MATRIX, 16);
  QD(GL_PROJECTION_MATRIX, 16);
  {
    const GLfloat m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    E(glLoadTransposeMatrixf(m));
    QF(GL_MODELVIEW_MATRIX, 16);
    QF(GL_TRANSPOSE_MODELVIEW_MATRIX, 16);
    E(glMultTransposeMatrixf(m));
    QF(GL_MODELVIEW_MATRIX, 16);
    E(glLoadIdentity());
  }
}

static void more_stacks_and_units(void) {
  section("texture units and their stacks (2.10.2, 3.8.12)");
  E(glActiveTexture(GL_TEXTURE1); glMatrixMode(GL_TEXTURE); glPushMatrix(); glTranslatef(1, 0, 0));
  QI(GL_TEXTURE_STACK_DEPTH, 1);
  QF(GL_TEXTURE_MATRIX, 16);
  E(glActiveTexture(GL_TEXTURE0));
  QI(GL_TEXTURE_STACK_DEPTH, 1);
  QF(GL_TEXTURE_MATRIX, 16);
  E(glActiveTexture(GL_TEXTURE1); glPopMatrix(); glActiveTexture(GL_TEXTURE0); glMatrixMode(GL_MODELVIEW));
  E(glActiveTexture(GL_TEXTURE1); glEnable(GL_TEXTURE_2D); glBindTexture(GL_TEXTURE_2D, 5));
  E(glPushAttrib(GL_TEXTURE_BIT | GL_ENABLE_BIT); glDisable(GL_TEXTURE_2D); glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0); glPopAttrib());
  QI(GL_ACTIVE_TEXTURE, 1);
  E(glActiveTexture(GL_TEXTURE1));
  QE(GL_TEXTURE_2D);
  QI(GL_TEXTURE_BINDING_2D, 1);
  E(glDisable(GL_TEXTURE_2D); glBindTexture(GL_TEXTURE_2D, 0); glActiveTexture(GL_TEXTURE0));
  QE(GL_TEXTURE_2D);
  E(glMultiTexCoord3f(GL_TEXTURE1, 1, 2, 3); glActiveTexture(GL_TEXTURE1));
  QF(GL_CURRENT_TEXTURE_COORDS, 4);
  E(glActiveTexture(GL_TEXTURE0));
  QF(GL_CURRENT_TEXTURE_COORDS, 4);

  section("more attribute groups (6.1.14)");
  E(glPushAttrib(GL_FOG_BIT | GL_HINT_BIT); glFogf(GL_FOG_DENSITY, 3); glHint(GL_FOG_HINT, GL_NICEST); glPopAttrib());
  QF(GL_FOG_DENSITY, 1);
  QI(GL_FOG_HINT, 1);
  E(glPushAttrib(GL_POINT_BIT | GL_LINE_BIT); glPointSize(4); glLineStipple(3, 0xff00); glEnable(GL_LINE_STIPPLE);
    glPopAttrib());
  QF(GL_POINT_SIZE, 1);
  QI(GL_LINE_STIPPLE_REPEAT, 1);
  QE(GL_LINE_STIPPLE);
  E(glPushAttrib(GL_POLYGON_BIT); glCullFace(GL_FRONT); glPolygonMode(GL_BACK, GL_POINT); glEnable(GL_CULL_FACE);
    glPopAttrib());
  QI(GL_CULL_FACE_MODE, 1);
  QI(GL_POLYGON_MODE, 2);
  QE(GL_CULL_FACE);
  E(glPushAttrib(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); glStencilFunc(GL_NEVER, 1, 1); glDepthMask(GL_FALSE);
    glClearDepth(0.25); glPopAttrib());
  QI(GL_STENCIL_FUNC, 1);
  QB(GL_DEPTH_WRITEMASK, 1);
  QF(GL_DEPTH_CLEAR_VALUE, 1);
  E(glPushAttrib(GL_SCISSOR_BIT); glScissor(1, 1, 2, 2); glEnable(GL_SCISSOR_TEST); glPopAttrib());
  QI(GL_SCISSOR_BOX, 4);
  QE(GL_SCISSOR_TEST);
  E(glPushAttrib(GL_EVAL_BIT); glEnable(GL_MAP1_COLOR_4); glMapGrid1f(9, 0, 1); glPopAttrib());
  QE(GL_MAP1_COLOR_4);
  QI(GL_MAP1_GRID_SEGMENTS, 1);
  E(glPushAttrib(GL_ACCUM_BUFFER_BIT); glClearAccum(0.5f, 0.5f, 0.5f, 0.5f); glPopAttrib());
  QF(GL_ACCUM_CLEAR_VALUE, 4);
  E(glPushAttrib(GL_MULTISAMPLE_BIT); glDisable(GL_MULTISAMPLE); glSampleCoverage(0.5f, GL_TRUE); glPopAttrib());
  QE(GL_MULTISAMPLE);
  QF(GL_SAMPLE_COVERAGE_VALUE, 1);
  E(glPushAttrib(GL_POLYGON_STIPPLE_BIT); glPolygonStipple(image); glPopAttrib());
  {
    GLubyte got[128];
    glGetPolygonStipple(got);
    value_i("polygon stipple byte 1 after glPopAttrib", got[1]);
  }
  E(glPushAttrib(GL_PIXEL_MODE_BIT); glPixelTransferf(GL_RED_BIAS, 0.5f); glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, points);
    glPopAttrib());
  QF(GL_RED_BIAS, 1);
  QI(GL_PIXEL_MAP_R_TO_R_SIZE, 1);
  E(glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT); glVertexPointer(4, GL_INT, 32, points); glPopClientAttrib());
  QI(GL_VERTEX_ARRAY_SIZE, 1);
  QI(GL_VERTEX_ARRAY_TYPE, 1);
}

static void nesting_and_names(void) {
  section("lists that call themselves, names, buffers (5.4, 4.2.1)");
  E(glNewList(20, GL_COMPILE); glTranslatef(1, 0, 0); glCallList(20); glEndList());
  E(glCallList(20));
  {
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    value_i("modelview x translation == GL_MAX_LIST_NESTING", (long)m[12] == limit(GL_MAX_LIST_NESTING));
  }
  E(glLoadIdentity());
  E(glNewList(21, GL_COMPILE); glDeleteLists(21, 1); glEndList());
  value_i("glIsList(21)", glIsList(21));
  E(glNewList(22, GL_COMPILE); glGenLists(2); glEndList());
  E(glDeleteLists(20, 4));
  QI(GL_LIST_MODE, 1);
  QI(GL_LIST_INDEX, 1);
  E(glReadBuffer(GL_BACK));
  E(glDrawBuffer(GL_BACK_LEFT));
  E(glDrawBuffer(GL_FRONT_AND_BACK));
  QI(GL_DRAW_BUFFER, 1);
  E(glDrawBuffer(GL_FRONT));
  QI(GL_READ_BUFFER, 1);
  E(glGetString(GL_VENDOR); glBegin(GL_POINTS); glGetString(GL_VENDOR); glEnd());
  E(glBegin(GL_POINTS); glIsEnabled(GL_LIGHTING); glEnd());
  E(glBegin(GL_POINTS); glGetError(); glEnd());
  E(glRectf(1, 1, 0, 0); glRecti(0, 0, 0, 0));
  E(glBegin(GL_POLYGON); glVertex2f(0, 0); glVertex2f(1, 0); glEnd());
  E(glBegin(GL_TRIANGLES); glEnd());
  E(glEdgeFlagPointer(4, points); glEnableClientState(GL_EDGE_FLAG_ARRAY));
  QI(GL_EDGE_FLAG_ARRAY_STRIDE, 1);
  E(glDisableClientState(GL_EDGE_FLAG_ARRAY));
  E(glAccum(GL_ADD, 0.5f); glAccum(GL_ACCUM, 2));
  E(glDrawBuffer(GL_NONE); glAccum(GL_RETURN, 1); glDrawBuffer(GL_FRONT));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL));
  E(glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT24, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 8, 1, 0, GL_COLOR_INDEX, GL_BITMAP, image));
  {
    GLint v = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
    value_i("GL_TEXTURE_WIDTH of the bitmap texture", v);
  }
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 1, GL_COLOR_INDEX, GL_BITMAP, image));
  E(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 1, GL_RGB, GL_BITMAP, image));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image));
}

/* Byte offset of an array pointer from the start of `points`, or -1 for another pointer. */
static long offset_in_points(GLenum pname) {
  GLvoid *pointer = NULL;
  glGetPointerv(pname, &pointer);
  if (pointer == NULL) return -1;
  const char *base = (const char *)points;
  const char *p = (const char *)pointer;
  return p >= base && p < base + sizeof points ? (long)(p - base) : -1;
}

static void interleaved_formats(void) {
  section("interleaved array formats (2.8, table 2.5)");
  static const struct {
    GLenum format;
    const char *name;
  } formats[] = {
      {GL_V2F, "GL_V2F"}, {GL_V3F, "GL_V3F"}, {GL_C4UB_V2F, "GL_C4UB_V2F"},
      {GL_C4UB_V3F, "GL_C4UB_V3F"}, {GL_C3F_V3F, "GL_C3F_V3F"}, {GL_N3F_V3F, "GL_N3F_V3F"},
      {GL_C4F_N3F_V3F, "GL_C4F_N3F_V3F"}, {GL_T2F_V3F, "GL_T2F_V3F"}, {GL_T4F_V4F, "GL_T4F_V4F"},
      {GL_T2F_C4UB_V3F, "GL_T2F_C4UB_V3F"}, {GL_T2F_C3F_V3F, "GL_T2F_C3F_V3F"},
      {GL_T2F_N3F_V3F, "GL_T2F_N3F_V3F"}, {GL_T2F_C4F_N3F_V3F, "GL_T2F_C4F_N3F_V3F"},
      {GL_T4F_C4F_N3F_V4F, "GL_T4F_C4F_N3F_V4F"},
  };
  for (int f = 0; f < 14; ++f) {
    char text[120];
    glEnableClientState(GL_INDEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glInterleavedArrays(formats[f].format, 0, points);
    snprintf(text, sizeof text, "glInterleavedArrays(%s, 0, points)", formats[f].name);
    report(text);
    printf("  enabled: vertex %d colour %d normal %d texture %d index %d edge %d", glIsEnabled(GL_VERTEX_ARRAY),
           glIsEnabled(GL_COLOR_ARRAY), glIsEnabled(GL_NORMAL_ARRAY), glIsEnabled(GL_TEXTURE_COORD_ARRAY),
           glIsEnabled(GL_INDEX_ARRAY), glIsEnabled(GL_EDGE_FLAG_ARRAY));
    end_query();
    printf("  vertex size %d type %d stride %d offset %ld", limit(GL_VERTEX_ARRAY_SIZE), limit(GL_VERTEX_ARRAY_TYPE),
           limit(GL_VERTEX_ARRAY_STRIDE), offset_in_points(GL_VERTEX_ARRAY_POINTER));
    end_query();
    if (glIsEnabled(GL_COLOR_ARRAY)) {
      printf("  colour size %d type %d stride %d offset %ld", limit(GL_COLOR_ARRAY_SIZE), limit(GL_COLOR_ARRAY_TYPE),
             limit(GL_COLOR_ARRAY_STRIDE), offset_in_points(GL_COLOR_ARRAY_POINTER));
      end_query();
    }
    if (glIsEnabled(GL_NORMAL_ARRAY)) {
      printf("  normal type %d stride %d offset %ld", limit(GL_NORMAL_ARRAY_TYPE), limit(GL_NORMAL_ARRAY_STRIDE),
             offset_in_points(GL_NORMAL_ARRAY_POINTER));
      end_query();
    }
    if (glIsEnabled(GL_TEXTURE_COORD_ARRAY)) {
      printf("  texture size %d type %d stride %d offset %ld", limit(GL_TEXTURE_COORD_ARRAY_SIZE),
             limit(GL_TEXTURE_COORD_ARRAY_TYPE), limit(GL_TEXTURE_COORD_ARRAY_STRIDE),
             offset_in_points(GL_TEXTURE_COORD_ARRAY_POINTER));
      end_query();
    }
  }
  E(glInterleavedArrays(GL_T2F_C4UB_V3F, 40, points));
  QI(GL_VERTEX_ARRAY_STRIDE, 1);
  QI(GL_COLOR_ARRAY_STRIDE, 1);
  E(glClientActiveTexture(GL_TEXTURE1); glInterleavedArrays(GL_T2F_V3F, 0, points));
  QE(GL_TEXTURE_COORD_ARRAY);
  E(glClientActiveTexture(GL_TEXTURE0));
  QE(GL_TEXTURE_COORD_ARRAY);
  E(glDisableClientState(GL_VERTEX_ARRAY); glDisableClientState(GL_COLOR_ARRAY); glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY));
  E(glClientActiveTexture(GL_TEXTURE1); glDisableClientState(GL_TEXTURE_COORD_ARRAY); glClientActiveTexture(GL_TEXTURE0));
}

static void feedback_formats(void) {
  section("feedback types and tokens (5.3)");
  static GLfloat feedback[256];
  static const struct {
    GLenum type;
    const char *name;
  } types[] = {{GL_2D, "GL_2D"}, {GL_3D, "GL_3D"}, {GL_3D_COLOR, "GL_3D_COLOR"},
               {GL_3D_COLOR_TEXTURE, "GL_3D_COLOR_TEXTURE"}, {GL_4D_COLOR_TEXTURE, "GL_4D_COLOR_TEXTURE"}};
  E(glColor4f(0.25f, 0.5f, 0.75f, 1); glTexCoord4f(0.5f, 0.25f, 0, 1));
  for (int t = 0; t < 5; ++t) {
    char text[120];
    GLint count;
    glFeedbackBuffer(256, types[t].type, feedback);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex3f(0.5f, -0.5f, 0.25f);
    glEnd();
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0, 0.5f);
    glEnd();
    count = glRenderMode(GL_RENDER);
    snprintf(text, sizeof text, "feedback of a point and a triangle as %s", types[t].name);
    report(text);
    value_i("values", count);
    if (count > 0) values_f("feedback", feedback, count > 64 ? 64 : count);
  }
  /* Not compared: which line segments carry GL_LINE_RESET_TOKEN rather than GL_LINE_TOKEN
   * (glass marks each segment that starts a stipple pattern, GL_LINES segments and polygon edges
   * included; Mesa's feedback marks almost none), where the edges of a GL_LINE polygon start, and
   * how a clipped polygon is split into feedback polygons. Compared: the points of a GL_POINT
   * polygon and a culled polygon (nothing). */
  {
    GLint count;
    glFeedbackBuffer(256, GL_2D, feedback);
    glRenderMode(GL_FEEDBACK);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0, 0.5f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0, 0.5f);
    glVertex2f(0.5f, -0.5f);
    glEnd();
    glDisable(GL_CULL_FACE);
    count = glRenderMode(GL_RENDER);
    report("feedback of a GL_POINT polygon and a culled polygon as GL_2D");
    value_i("values", count);
    if (count > 0) values_f("feedback", feedback, count > 80 ? 80 : count);
  }
  E(glColor4f(1, 1, 1, 1); glTexCoord4f(0, 0, 0, 1));
}

static void more_texture_and_raster_state(void) {
  section("more texture, evaluator and raster state (3.8, 5.1, 2.13)");
  {
    GLuint name = 0;
    GLfloat v[4] = {0, 0, 0, 0};
    const GLclampf priority = 2;
    glGenTextures(1, &name);
    E(glBindTexture(GL_TEXTURE_2D, name); glPrioritizeTextures(1, &name, &priority));
    E(glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, v));
    values_f("GL_TEXTURE_PRIORITY after glPrioritizeTextures(2)", v, 1);
    E(glBindTexture(GL_TEXTURE_2D, 0); glDeleteTextures(1, &name));
  }
  E(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, -2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  {
    GLint v = -1;
    E(glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v));
    value_i("3D level 0 GL_TEXTURE_DEPTH", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v));
    E(glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_TEXTURE_WIDTH, &v));
    value_i("cube map -Z level 0 GL_TEXTURE_WIDTH", v);
    E(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &v));
    value_i("GL_TEXTURE_COMPRESSED", v);
    E(glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, &v));
    value_i("cube map GL_TEXTURE_WRAP_R", v);
    E(glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE));
    E(glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, &v));
    value_i("cube map GL_TEXTURE_WRAP_R", v);
    E(glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_REPEAT));
  }
  E(glHint(GL_TEXTURE_COMPRESSION_HINT, GL_NICEST));
  QI(GL_TEXTURE_COMPRESSION_HINT, 1);
  E(glHint(GL_TEXTURE_COMPRESSION_HINT, GL_DONT_CARE));
  {
    GLint iv[4] = {0, 0, 0, 0};
    GLfloat v[64] = {0};
    GLdouble dv[4] = {0, 0, 0, 0};
    E(glMap2f(GL_MAP2_VERTEX_3, 0.5f, 1.5f, 3, 2, -1, 1, 6, 3, points));
    E(glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, iv));
    value_i("GL_MAP2_VERTEX_3 GL_ORDER u", iv[0]);
    value_i("GL_MAP2_VERTEX_3 GL_ORDER v", iv[1]);
    E(glGetMapfv(GL_MAP2_VERTEX_3, GL_DOMAIN, v));
    values_f("GL_MAP2_VERTEX_3 GL_DOMAIN", v, 4);
    E(glGetMapdv(GL_MAP2_VERTEX_3, GL_DOMAIN, dv));
    for (int i = 0; i < 4; ++i) v[i] = (GLfloat)dv[i];
    values_f("GL_MAP2_VERTEX_3 GL_DOMAIN (double)", v, 4);
    E(glGetMapiv(GL_MAP2_VERTEX_3, GL_DOMAIN, iv));
    value_i("GL_MAP2_VERTEX_3 GL_DOMAIN as integers, u1", iv[0]);
    E(glGetMapfv(GL_MAP2_VERTEX_3, GL_COEFF, v));
    values_f("GL_MAP2_VERTEX_3 GL_COEFF", v, 18);
    E(glMap1d(GL_MAP1_TEXTURE_COORD_1, 0, 1, 1, 3, (const GLdouble *)image));
    E(glMap2d(GL_MAP2_NORMAL, 0, 1, 2, 2, 0, 1, 3, 2, (const GLdouble *)image));
  }
  E(glColor4f(2, -1, 0.5f, 1); glRasterPos2f(0, 0));
  QF(GL_CURRENT_RASTER_COLOR, 4);
  QF(GL_CURRENT_RASTER_INDEX, 1);
  E(glColor4f(1, 1, 1, 1));
  E(glActiveTexture(GL_TEXTURE1); glMultiTexCoord2f(GL_TEXTURE1, 0.25f, 0.75f); glRasterPos2f(0, 0));
  QF(GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
  E(glActiveTexture(GL_TEXTURE0));
  QF(GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
  {
    GLfloat rgba[4] = {0, 0, 0, 0};
    GLfloat depth = -1;
    GLubyte stencil = 0;
    E(glClearColor(0.2f, 0.4f, 0.6f, 0.8f); glClearDepth(0.5); glClearStencil(0x35);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT));
    E(glReadPixels(3, 3, 1, 1, GL_RGBA, GL_FLOAT, rgba));
    values_f("cleared colour", rgba, 4);
    E(glReadPixels(3, 3, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth));
    values_f("cleared depth", &depth, 1);
    E(glReadPixels(3, 3, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil));
    value_i("cleared stencil", stencil);
    E(glPixelTransferi(GL_INDEX_OFFSET, 2); glReadPixels(3, 3, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil));
    value_i("stencil read with GL_INDEX_OFFSET 2", stencil);
    E(glPixelTransferi(GL_INDEX_OFFSET, 0); glPixelTransferf(GL_RED_SCALE, 2); glPixelTransferf(GL_ALPHA_BIAS, -0.5f);
      glReadPixels(3, 3, 1, 1, GL_RGBA, GL_FLOAT, rgba));
    values_f("colour read with GL_RED_SCALE 2, GL_ALPHA_BIAS -0.5", rgba, 4);
    E(glPixelTransferf(GL_RED_SCALE, 1); glPixelTransferf(GL_ALPHA_BIAS, 0));
    E(glClearColor(0, 0, 0, 0); glClearDepth(1); glClearStencil(0));
  }
}

static void restored_and_evaluated_state(void) {
  section("state restored by glPopAttrib, current values and evaluation (6.1.14, 5.1)");
  {
    const GLfloat position[4] = {1, 2, 3, 1};
    const GLfloat other[4] = {0, 0, 1, 0};
    const GLfloat emission[4] = {0.5f, 0.25f, 0, 1};
    GLfloat v[4] = {0, 0, 0, 0};
    E(glTranslatef(1, 0, 0); glLightfv(GL_LIGHT3, GL_POSITION, position); glLoadIdentity());
    E(glGetLightfv(GL_LIGHT3, GL_POSITION, v));
    values_f("GL_LIGHT3 GL_POSITION", v, 4);
    E(glPushAttrib(GL_LIGHTING_BIT); glLightfv(GL_LIGHT3, GL_POSITION, other);
      glMaterialfv(GL_FRONT, GL_EMISSION, emission); glPopAttrib());
    E(glGetLightfv(GL_LIGHT3, GL_POSITION, v));
    values_f("GL_LIGHT3 GL_POSITION after glPopAttrib", v, 4);
    E(glGetMaterialfv(GL_FRONT, GL_EMISSION, v));
    values_f("GL_FRONT GL_EMISSION after glPopAttrib", v, 4);
  }
  E(glWindowPos2i(7, 9); glPushAttrib(GL_CURRENT_BIT); glWindowPos2i(20, 30); glEdgeFlag(GL_FALSE); glPopAttrib());
  QF(GL_CURRENT_RASTER_POSITION, 4);
  QB(GL_EDGE_FLAG, 1);
  {
    const GLdouble plane[4] = {0, 1, 0, 0};
    GLdouble got[4] = {0, 0, 0, 0};
    GLfloat shown[4];
    E(glPushAttrib(GL_TRANSFORM_BIT); glClipPlane(GL_CLIP_PLANE4, plane); glEnable(GL_CLIP_PLANE4);
      glEnable(GL_RESCALE_NORMAL); glPopAttrib());
    QE(GL_CLIP_PLANE4);
    QE(GL_RESCALE_NORMAL);
    E(glGetClipPlane(GL_CLIP_PLANE4, got));
    for (int i = 0; i < 4; ++i) shown[i] = (GLfloat)got[i];
    values_f("GL_CLIP_PLANE4 after glPopAttrib", shown, 4);
  }
  {
    const GLfloat plane[4] = {1, 1, 0, 0};
    GLfloat v[4] = {0, 0, 0, 0};
    GLint mode = 0;
    E(glPushAttrib(GL_TEXTURE_BIT); glTexGenfv(GL_S, GL_OBJECT_PLANE, plane); glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
      glEnable(GL_TEXTURE_GEN_S); glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL); glPopAttrib());
    E(glGetTexGenfv(GL_S, GL_OBJECT_PLANE, v));
    values_f("GL_S GL_OBJECT_PLANE after glPopAttrib", v, 4);
    QE(GL_TEXTURE_GEN_S);
    E(glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &mode));
    value_i("GL_TEXTURE_ENV_MODE after glPopAttrib", mode);
  }
  E(glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT); glPixelStorei(GL_PACK_ALIGNMENT, 1); glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
    glPopClientAttrib());
  QI(GL_PACK_ALIGNMENT, 1);
  QI(GL_UNPACK_SKIP_ROWS, 1);
  {
    static const GLfloat colours[8] = {1, 0, 0, 1, 0, 0, 1, 1};
    static const GLfloat vertices[2] = {0.25f, 0.75f};
    E(glColor4f(0.5f, 0.5f, 0.5f, 0.5f); glMap1f(GL_MAP1_COLOR_4, 0, 1, 4, 2, colours); glEnable(GL_MAP1_COLOR_4));
    E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 1, vertices));
    E(glBegin(GL_POINTS); glEvalCoord1f(0.25f); glEnd());
    QF(GL_CURRENT_COLOR, 4);
    E(glDisable(GL_MAP1_COLOR_4); glColor4f(1, 1, 1, 1));
  }
  {
    GLfloat v[4] = {0, 0, 0, 0};
    E(glColorMaterial(GL_FRONT, GL_SPECULAR); glEnable(GL_COLOR_MATERIAL); glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
      glDisable(GL_COLOR_MATERIAL));
    E(glGetMaterialfv(GL_FRONT, GL_SPECULAR, v));
    values_f("GL_FRONT GL_SPECULAR from glColor", v, 4);
    E(glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE); glColor4f(1, 1, 1, 1));
  }
  {
    static GLuint hits[16];
    E(glSelectBuffer(16, hits); glRenderMode(GL_SELECT); glInitNames(); glPushName(4); glRasterPos2f(0, 0);
      glLoadName(5); glRasterPos2f(3, 0); glLoadName(6); glWindowPos2i(1, 1); glLoadName(7);
      glBitmap(0, 0, 0, 0, 1, 1, NULL));
    value_i("hits from raster positions", glRenderMode(GL_RENDER));
    for (int i = 0; i < 8; ++i) {
      char name[32];
      snprintf(name, sizeof name, "hit word %d", i);
      value_i(name, (long)hits[i]);
    }
  }
}

static void script(void) {
  state_and_enables();
  matrices();
  viewport_depth_range();
  begin_end();
  current_values();
  raster_position();
  lists();
  lighting();
  clipping_and_rasterization();
  fog();
  textures();
  pixels();
  fragments();
  vertex_arrays();
  attribute_stacks();
  selection_and_feedback();
  evaluators();
  queries_and_strings();
  refused_calls_change_nothing();
  derived_state();
  conversions();
  more_stacks_and_units();
  nesting_and_names();
  interleaved_formats();
  feedback_formats();
  more_texture_and_raster_state();
  restored_and_evaluated_state();
}

int main(void) {
  GlassContext *ctx = glassCreateContext(64, 64);
  if (!ctx || !glassMakeCurrent(ctx)) {
    fprintf(stderr, "gl_errors: cannot create a 64 x 64 GL context\n");
    glassDestroyContext(ctx);
    return 1;
  }
  script();
  printf("== %d checked lines\n", checked_lines);
  glassDestroyContext(ctx);
  return 0;
}
