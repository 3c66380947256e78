#include "accum/accumulation.h"

#include <algorithm>
#include <cmath>
#include <new>

#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "core/state_value.h"

namespace glass::gl {

namespace {

// The 16-bit value of a float already scaled to the accumulation range: truncated towards zero
// (C's conversion, as in Mesa), saturated.
int16_t toAccumulation(float scaled) {
  const float t = std::trunc(scaled);
  if (!(t > -32768.0f)) return t != t ? 0 : -32768;  // also NaN
  if (t >= 32767.0f) return 32767;
  return static_cast<int16_t>(t);
}

int16_t saturatedSum(int a, int b) { return static_cast<int16_t>(std::clamp(a + b, -32768, 32767)); }

// Mesa's float-to-8-bit packing of colour buffer writes: clamp, then round x * 255 to the nearest
// integer, ties to even.
uint8_t packColorByte(float c) {
  if (!(c > 0.0f)) return 0;
  if (c > 1.0f) return 255;
  return static_cast<uint8_t>(std::nearbyint(c * 255.0f));
}

struct Region {
  int x0, y0, x1, y1;
};

// The scissor box (when enabled) within the window (spec 4.2.4 via 4.1.2; as Mesa bounds it).
Region accumulationRegion(const Context& ctx) {
  Region r{0, 0, ctx.framebuffer.width(), ctx.framebuffer.height()};
  const FragmentState& f = ctx.fragment;
  if (f.scissorTest) {
    r.x0 = std::max(r.x0, f.scissor.x);
    r.y0 = std::max(r.y0, f.scissor.y);
    r.x1 = static_cast<int>(std::min<long long>(r.x1, static_cast<long long>(f.scissor.x) + f.scissor.width));
    r.y1 = static_cast<int>(std::min<long long>(r.y1, static_cast<long long>(f.scissor.y) + f.scissor.height));
  }
  return r;
}

// The buffer, allocated (zeroed) on first use; null when memory runs out.
int16_t* accumulationBuffer(Context& ctx) {
  std::vector<int16_t>& buffer = ctx.accumulation.buffer;
  if (buffer.empty()) {
    try {
      buffer.assign(static_cast<size_t>(ctx.framebuffer.width()) *
                        static_cast<size_t>(ctx.framebuffer.height()) * 4,
                    0);
    } catch (const std::bad_alloc&) {
      return nullptr;
    }
  }
  return buffer.data();
}

}  // namespace

bool isAccumOperation(GLenum op) {
  return op == GL_ACCUM || op == GL_LOAD || op == GL_RETURN || op == GL_MULT || op == GL_ADD;
}

void accumulate(Context& ctx, GLenum op, float value) {
  if (ctx.renderMode.mode != GL_RENDER) return;
  if ((op == GL_ACCUM || op == GL_ADD) && value == 0.0f) return;
  if (op == GL_MULT && value == 1.0f) return;
  // GL_LOAD and GL_ACCUM read the read buffer and GL_RETURN writes the draw buffers (spec 4.2.4):
  // after glReadBuffer(GL_NONE) or glDrawBuffer(GL_NONE) there is none, and they do nothing, as
  // in Mesa.
  if ((op == GL_LOAD || op == GL_ACCUM) && !readsColor(ctx.pixelTransfer.readBuffer)) return;
  if (op == GL_RETURN && !drawsColor(ctx.fragment.drawBuffer)) return;
  int16_t* buffer = accumulationBuffer(ctx);
  if (!buffer) return recordError(ctx, GL_OUT_OF_MEMORY);

  const Region region = accumulationRegion(ctx);
  raster::Framebuffer& fb = ctx.framebuffer;
  const float loadScale = value * 32767.0f;
  const float returnScale = value / 32767.0f;
  const int16_t increment = toAccumulation(value * 32767.0f);
  const bool* mask = ctx.fragment.colorMask;
  // GL_RETURN into a colour buffer without alpha bitplanes keeps its alpha 255.
  const bool returnsAlpha = ctx.buffers.colorAlpha;

  const auto pass = [&] {
    for (int y = region.y0; y < region.y1; ++y) {
      for (int x = region.x0; x < region.x1; ++x) {
        int16_t* a = buffer + (static_cast<size_t>(y) * static_cast<size_t>(fb.width()) + static_cast<size_t>(x)) * 4;
        uint8_t* c = fb.colorAt(x, y);
        for (int k = 0; k < 4; ++k) {
          switch (op) {
            case GL_LOAD: a[k] = toAccumulation(static_cast<float>(c[k]) * (1.0f / 255.0f) * loadScale); break;
            case GL_ACCUM:
              a[k] = saturatedSum(a[k], toAccumulation(static_cast<float>(c[k]) * (1.0f / 255.0f) * loadScale));
              break;
            case GL_ADD: a[k] = saturatedSum(a[k], increment); break;
            case GL_MULT: a[k] = toAccumulation(static_cast<float>(a[k]) * value); break;
            case GL_RETURN:
              if (mask[k] && (k < 3 || returnsAlpha)) c[k] = packColorByte(static_cast<float>(a[k]) * returnScale);
              break;
            default: break;
          }
        }
      }
    }
  };
  if (op == GL_LOAD || op == GL_ACCUM) {
    const ReadBufferSelection read(ctx);  // the read buffer's pixels (a double buffer's front, say)
    pass();
  } else if (op == GL_RETURN) {
    forEachDrawnColorBuffer(ctx, pass);  // both buffers for GL_FRONT_AND_BACK
  } else {
    pass();
  }
}

void clearAccumulationBuffer(Context& ctx, int x0, int y0, int x1, int y1) {
  int16_t* buffer = accumulationBuffer(ctx);
  if (!buffer) return recordError(ctx, GL_OUT_OF_MEMORY);
  int16_t value[4];
  for (int k = 0; k < 4; ++k) {
    value[k] = toAccumulation((ctx.accumulation.clearValue[k] * 65535.0f - 1.0f) / 2.0f);
  }
  const size_t width = static_cast<size_t>(ctx.framebuffer.width());
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      std::copy(value, value + 4, buffer + (static_cast<size_t>(y) * width + static_cast<size_t>(x)) * 4);
    }
  }
}

bool queryAccumulationState(const Context& ctx, GLenum pname, StateValue& v) {
  switch (pname) {
    case GL_ACCUM_CLEAR_VALUE: v.setColors(ctx.accumulation.clearValue, 4); return true;
    case GL_ACCUM_RED_BITS:
    case GL_ACCUM_GREEN_BITS:
    case GL_ACCUM_BLUE_BITS:
    case GL_ACCUM_ALPHA_BITS:
      v.setIntegers({ctx.buffers.accumulation ? double(kAccumulationBits) : 0.0});
      return true;
    default: return false;
  }
}

}  // namespace glass::gl
