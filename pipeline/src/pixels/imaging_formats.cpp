#include "pixels/imaging_formats.h"

namespace glass::gl {

bool imagingBaseFormat(GLenum internalFormat, BaseFormat* base) {
  switch (internalFormat) {
    case GL_ALPHA: case GL_ALPHA4: case GL_ALPHA8: case GL_ALPHA12: case GL_ALPHA16:
      *base = BaseFormat::Alpha;
      return true;
    case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8: case GL_LUMINANCE12:
    case GL_LUMINANCE16:
      *base = BaseFormat::Luminance;
      return true;
    case GL_LUMINANCE_ALPHA: case GL_LUMINANCE4_ALPHA4: case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8: case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
      *base = BaseFormat::LuminanceAlpha;
      return true;
    case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_INTENSITY12:
    case GL_INTENSITY16:
      *base = BaseFormat::Intensity;
      return true;
    case GL_RGB: case GL_R3_G3_B2: case GL_RGB4: case GL_RGB5: case GL_RGB8: case GL_RGB10:
    case GL_RGB12: case GL_RGB16:
      *base = BaseFormat::RGB;
      return true;
    case GL_RGBA: case GL_RGBA2: case GL_RGBA4: case GL_RGB5_A1: case GL_RGBA8: case GL_RGB10_A2:
    case GL_RGBA12: case GL_RGBA16:
      *base = BaseFormat::RGBA;
      return true;
    default:
      return false;
  }
}

void keepBaseComponents(BaseFormat base, float* rgba) {
  switch (base) {
    case BaseFormat::Alpha: rgba[0] = rgba[1] = rgba[2] = 0.0f; break;
    case BaseFormat::Luminance:
    case BaseFormat::Intensity: rgba[1] = rgba[2] = 0.0f; rgba[3] = 1.0f; break;
    case BaseFormat::LuminanceAlpha: rgba[1] = rgba[2] = 0.0f; break;
    case BaseFormat::RGB: rgba[3] = 1.0f; break;
    case BaseFormat::RGBA: break;
  }
}

int imagingComponentBits(BaseFormat base, int index) {
  const bool rgb = base == BaseFormat::RGB || base == BaseFormat::RGBA;
  switch (index) {
    case 0: case 1: case 2: return rgb ? 8 : 0;
    case 3:
      return base == BaseFormat::Alpha || base == BaseFormat::LuminanceAlpha ||
                     base == BaseFormat::RGBA ? 8 : 0;
    case 4: return base == BaseFormat::Luminance || base == BaseFormat::LuminanceAlpha ? 8 : 0;
    case 5: return base == BaseFormat::Intensity ? 8 : 0;
    default: return 0;
  }
}

}  // namespace glass::gl
