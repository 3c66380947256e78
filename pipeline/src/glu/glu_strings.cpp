// gluErrorString, gluGetString and gluCheckExtension (GLU 1.3 specification, sections 2.1-2.3),
// with the strings of SGI's reference GLU.
#include <GL/glu.h>

#include <cstring>

namespace {

// The 37 NURBS errors (GLU_NURBS_ERROR1 .. GLU_NURBS_ERROR37), in GLU's order.
const char* nurbsErrorString(GLenum error) {
  static const char* const kNurbsErrors[] = {
      "spline order un-supported",
      "too few knots",
      "valid knot range is empty",
      "decreasing knot sequence knot",
      "knot multiplicity greater than order of spline",
      "gluEndCurve() must follow gluBeginCurve()",
      "gluBeginCurve() must precede gluEndCurve()",
      "missing or extra geometric data",
      "can't draw piecewise linear trimming curves",
      "missing or extra domain data",
      "missing or extra domain data",
      "gluEndTrim() must precede gluEndSurface()",
      "gluBeginSurface() must precede gluEndSurface()",
      "curve of improper type passed as trim curve",
      "gluBeginSurface() must precede gluBeginTrim()",
      "gluEndTrim() must follow gluBeginTrim()",
      "gluBeginTrim() must precede gluEndTrim()",
      "invalid or missing trim curve",
      "gluBeginTrim() must precede gluPwlCurve()",
      "piecewise linear trimming curve referenced twice",
      "piecewise linear trimming curve and nurbs curve mixed",
      "improper usage of trim data type",
      "nurbs curve referenced twice",
      "nurbs curve and piecewise linear trimming curve mixed",
      "nurbs surface referenced twice",
      "invalid property",
      "gluEndSurface() must follow gluBeginSurface()",
      "intersecting or misoriented trim curves",
      "intersecting trim curves",
      "UNUSED",
      "unconnected trim curves",
      "unknown knot error",
      "negative vertex count encountered",
      "negative byte-stride encounteed",
      "unknown type descriptor",
      "null control point reference",
      "duplicate point on piecewise linear trimming curve",
  };
  if (error < GLU_NURBS_ERROR1 || error > GLU_NURBS_ERROR37) return nullptr;
  return kNurbsErrors[error - GLU_NURBS_ERROR1];
}

}  // namespace

extern "C" {

const GLubyte* gluErrorString(GLenum error) {
  const char* text = nullptr;
  switch (error) {
    case GL_NO_ERROR: text = "no error"; break;
    case GL_INVALID_ENUM: case GLU_INVALID_ENUM: text = "invalid enumerant"; break;
    case GL_INVALID_VALUE: case GLU_INVALID_VALUE: text = "invalid value"; break;
    case GL_INVALID_OPERATION: case GLU_INVALID_OPERATION: text = "invalid operation"; break;
    case GL_STACK_OVERFLOW: text = "stack overflow"; break;
    case GL_STACK_UNDERFLOW: text = "stack underflow"; break;
    case GL_OUT_OF_MEMORY: case GLU_OUT_OF_MEMORY: text = "out of memory"; break;
    case GL_TABLE_TOO_LARGE: text = "table too large"; break;
    case GLU_INCOMPATIBLE_GL_VERSION: text = "incompatible gl version"; break;
    case GLU_TESS_MISSING_BEGIN_POLYGON: text = "gluTessBeginPolygon() must precede a gluTessEndPolygon()"; break;
    case GLU_TESS_MISSING_BEGIN_CONTOUR: text = "gluTessBeginContour() must precede a gluTessEndContour()"; break;
    case GLU_TESS_MISSING_END_POLYGON: text = "gluTessEndPolygon() must follow a gluTessBeginPolygon()"; break;
    case GLU_TESS_MISSING_END_CONTOUR: text = "gluTessEndContour() must follow a gluTessBeginContour()"; break;
    case GLU_TESS_COORD_TOO_LARGE: text = "a coordinate is too large"; break;
    case GLU_TESS_NEED_COMBINE_CALLBACK: text = "need combine callback"; break;
    default: text = nurbsErrorString(error); break;
  }
  return reinterpret_cast<const GLubyte*>(text);
}

// GLU 1.3: whether extName is one of the space-separated names in extString (whole names only).
GLboolean gluCheckExtension(const GLubyte* extName, const GLubyte* extString) {
  if (!extName || !extString) return GL_FALSE;
  const char* name = reinterpret_cast<const char*>(extName);
  const size_t length = std::strlen(name);
  if (length == 0 || std::strchr(name, ' ')) return GL_FALSE;
  const char* p = reinterpret_cast<const char*>(extString);
  while (*p) {
    const size_t word = std::strcspn(p, " ");
    if (word == length && std::strncmp(p, name, length) == 0) return GL_TRUE;
    p += word;
    while (*p == ' ') ++p;
  }
  return GL_FALSE;
}

const GLubyte* gluGetString(GLenum name) {
  switch (name) {
    case GLU_VERSION: return reinterpret_cast<const GLubyte*>("1.3");
    case GLU_EXTENSIONS: return reinterpret_cast<const GLubyte*>("");
    default: return nullptr;
  }
}

}  // extern "C"
