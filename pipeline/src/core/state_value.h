// A piece of GL state as glGet returns it, before conversion to the type the caller asked for
// (spec 6.1.2). Each stage answers glGet for its own state by filling a StateValue; glGetBooleanv,
// glGetIntegerv, glGetFloatv and glGetDoublev then convert it:
//   Boolean  -> integer 0/1, float 0.0/1.0
//   Integer  -> boolean (non-zero is TRUE), float
//   Float    -> boolean (non-zero), integer rounded to the nearest
//   Color    -> like Float, except that integer queries map [-1, 1] linearly onto the whole
//               integer range (colours, normals, depth range and the depth clear value, 6.1.2)
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <initializer_list>

namespace glass::gl {

struct StateValue {
  enum class Kind { Boolean, Integer, Float, Color };
  Kind kind = Kind::Integer;
  int count = 0;
  double values[16] = {};

  void setBooleans(std::initializer_list<bool> v) { set(Kind::Boolean, v.begin(), v.size()); }
  void setIntegers(std::initializer_list<double> v) { set(Kind::Integer, v.begin(), v.size()); }
  void setFloats(std::initializer_list<double> v) { set(Kind::Float, v.begin(), v.size()); }
  void setColors(std::initializer_list<double> v) { set(Kind::Color, v.begin(), v.size()); }
  void setFloats(const float* v, int n) { set(Kind::Float, v, static_cast<size_t>(n)); }
  void setColors(const float* v, int n) { set(Kind::Color, v, static_cast<size_t>(n)); }

 private:
  template <class T>
  void set(Kind k, const T* v, size_t n) {
    kind = k;
    count = static_cast<int>(n);
    for (size_t i = 0; i < n && i < 16; ++i) values[i] = static_cast<double>(v[i]);
  }
};

}  // namespace glass::gl
