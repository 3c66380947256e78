// GLU quadrics (GLU 1.3 specification, chapter 6) as streams of immediate-mode calls.
//
// The shapes are generated into a PrimitiveEmitter rather than straight into glBegin/glVertex, so
// the same code feeds the GL (quadrics.cpp) and the unit test that compares the stream, call by
// call and bit by bit, with the stream of the SGI GLU that Mesa ships.
#pragma once

#include <GL/gl.h>

namespace glass::gl::glu {

class PrimitiveEmitter {
 public:
  virtual ~PrimitiveEmitter() = default;
  virtual void begin(GLenum mode) = 0;
  virtual void normal(float x, float y, float z) = 0;
  virtual void texCoord(float s, float t) = 0;
  virtual void vertex(float x, float y, float z) = 0;
  virtual void end() = 0;
};

// GLU's enum values for quadrics (the same as GL/glu.h's GLU_SMOOTH, ...).
inline constexpr GLenum kSmooth = 100000, kFlat = 100001, kNoNormals = 100002;
inline constexpr GLenum kPoint = 100010, kLine = 100011, kFill = 100012, kSilhouette = 100013;
inline constexpr GLenum kOutside = 100020, kInside = 100021;

// The settings of a GLUquadric object (gluQuadricNormals, ...Texture, ...Orientation,
// ...DrawStyle).
struct QuadricStyle {
  GLenum normals = kSmooth;
  bool textureCoords = false;
  GLenum orientation = kOutside;
  GLenum drawStyle = kFill;
};

// Each returns false, emitting nothing, for arguments GLU rejects with GLU_INVALID_VALUE.
bool emitCylinder(const QuadricStyle& style, double baseRadius, double topRadius, double height,
                  int slices, int stacks, PrimitiveEmitter& out);
bool emitPartialDisk(const QuadricStyle& style, double innerRadius, double outerRadius,
                     int slices, int loops, double startAngle, double sweepAngle,
                     PrimitiveEmitter& out);
bool emitSphere(const QuadricStyle& style, double radius, int slices, int stacks,
                PrimitiveEmitter& out);

// GLU keeps at most this many slices (and sphere stacks): larger counts are reduced to it.
inline constexpr int kMaxQuadricDivisions = 239;

}  // namespace glass::gl::glu
