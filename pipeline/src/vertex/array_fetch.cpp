#include "vertex/array_fetch.h"

#include <algorithm>

#include "vertex/attribute_conversion.h"

namespace glass::gl {
namespace {

// Elements with `Present` components of type T in the array: the loop over components has a
// fixed length, so the compiler unrolls it.
template <typename T, int Present>
void fetchElements(const ClientArray& a, bool normalized, const int* indices, int first, int count,
                   float* const* rows) {
  const auto* base = static_cast<const unsigned char*>(a.pointer);
  const long long stride = arrayElementStride(a);
  for (int i = 0; i < count; ++i) {
    const long long index = indices != nullptr ? indices[i] : static_cast<long long>(first) + i;
    const unsigned char* element = base + index * stride;
    for (int c = 0; c < Present; ++c) {
      rows[c][i] = arrayComponentToFloat(loadUnaligned<T>(element + c * sizeof(T)), normalized);
    }
  }
}

template <typename T>
void fetchTyped(const ClientArray& a, bool normalized, const float* defaults, int components,
                const int* indices, int first, int count, float* const* rows) {
  const int present = std::min(a.size, components);
  switch (present) {
    case 1: fetchElements<T, 1>(a, normalized, indices, first, count, rows); break;
    case 2: fetchElements<T, 2>(a, normalized, indices, first, count, rows); break;
    case 3: fetchElements<T, 3>(a, normalized, indices, first, count, rows); break;
    case 4: fetchElements<T, 4>(a, normalized, indices, first, count, rows); break;
    default: break;
  }
  for (int c = std::max(present, 0); c < components; ++c) {
    std::fill(rows[c], rows[c] + count, defaults[c]);
  }
}

}  // namespace

void fetchArrayRows(const ClientArray& a, bool normalized, const float* defaults, int components,
                    const int* indices, int first, int count, float* const* rows) {
  switch (a.type) {
    case GL_BYTE: return fetchTyped<GLbyte>(a, normalized, defaults, components, indices, first, count, rows);
    case GL_UNSIGNED_BYTE:
      return fetchTyped<GLubyte>(a, normalized, defaults, components, indices, first, count, rows);
    case GL_SHORT: return fetchTyped<GLshort>(a, normalized, defaults, components, indices, first, count, rows);
    case GL_UNSIGNED_SHORT:
      return fetchTyped<GLushort>(a, normalized, defaults, components, indices, first, count, rows);
    case GL_INT: return fetchTyped<GLint>(a, normalized, defaults, components, indices, first, count, rows);
    case GL_UNSIGNED_INT:
      return fetchTyped<GLuint>(a, normalized, defaults, components, indices, first, count, rows);
    case GL_FLOAT: return fetchTyped<GLfloat>(a, normalized, defaults, components, indices, first, count, rows);
    case GL_DOUBLE: return fetchTyped<GLdouble>(a, normalized, defaults, components, indices, first, count, rows);
    default:
      // A type glass never accepts in an array pointer; as readElement, it reads as zeros.
      for (int c = 0; c < components; ++c)
        std::fill(rows[c], rows[c] + count, c < a.size ? 0.0f : defaults[c]);
      return;
  }
}

}  // namespace glass::gl
