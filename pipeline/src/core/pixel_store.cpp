#include "core/pixel_store.h"

namespace glass::gl {

long long rowStrideBytes(const PixelPacking& packing, int width, int pixelBytes,
                         int componentBytes) {
  // Spec 3.6.1: k = a * ceil(n l s / a) when s < a, else n l s (s: component size, n: components
  // per pixel, l: row length, a: alignment). n * s is the pixel size.
  const long long length = packing.rowLength > 0 ? packing.rowLength : width;
  const long long bytes = length * pixelBytes;
  if (componentBytes >= packing.alignment) return bytes;
  const long long a = packing.alignment;
  return (bytes + a - 1) / a * a;
}

}  // namespace glass::gl
