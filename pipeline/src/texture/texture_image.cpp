#include "texture/texture_image.h"

#include <cmath>

namespace glass::gl {

bool baseFormatOfInternalFormat(GLint internalFormat, BaseFormat* base) {
  switch (internalFormat) {
    case GL_ALPHA:
    case GL_ALPHA4:
    case GL_ALPHA8:
    case GL_ALPHA12:
    case GL_ALPHA16:
    case GL_COMPRESSED_ALPHA:
      *base = BaseFormat::Alpha;
      return true;
    case 1:
    case GL_LUMINANCE:
    case GL_LUMINANCE4:
    case GL_LUMINANCE8:
    case GL_LUMINANCE12:
    case GL_LUMINANCE16:
    case GL_COMPRESSED_LUMINANCE:
      *base = BaseFormat::Luminance;
      return true;
    case 2:
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE4_ALPHA4:
    case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
    case GL_COMPRESSED_LUMINANCE_ALPHA:
      *base = BaseFormat::LuminanceAlpha;
      return true;
    case GL_INTENSITY:
    case GL_INTENSITY4:
    case GL_INTENSITY8:
    case GL_INTENSITY12:
    case GL_INTENSITY16:
    case GL_COMPRESSED_INTENSITY:
      *base = BaseFormat::Intensity;
      return true;
    case 3:
    case GL_RGB:
    case GL_R3_G3_B2:
    case GL_RGB4:
    case GL_RGB5:
    case GL_RGB8:
    case GL_RGB10:
    case GL_RGB12:
    case GL_RGB16:
    case GL_COMPRESSED_RGB:
      *base = BaseFormat::RGB;
      return true;
    case 4:
    case GL_RGBA:
    case GL_RGBA2:
    case GL_RGBA4:
    case GL_RGB5_A1:
    case GL_RGBA8:
    case GL_RGB10_A2:
    case GL_RGBA12:
    case GL_RGBA16:
    case GL_COMPRESSED_RGBA:
      *base = BaseFormat::RGBA;
      return true;
    // Depth textures (OpenGL 1.4; depth_texture.h): the base format is the luminance layout
    // their texels take by default; GL_DEPTH_TEXTURE_MODE decides what sampling sees.
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
      *base = BaseFormat::Luminance;
      return true;
    default:
      return false;
  }
}

GLenum baseFormatEnum(BaseFormat base) {
  switch (base) {
    case BaseFormat::Alpha: return GL_ALPHA;
    case BaseFormat::Luminance: return GL_LUMINANCE;
    case BaseFormat::LuminanceAlpha: return GL_LUMINANCE_ALPHA;
    case BaseFormat::Intensity: return GL_INTENSITY;
    case BaseFormat::RGB: return GL_RGB;
    case BaseFormat::RGBA: return GL_RGBA;
  }
  return GL_RGBA;
}

int componentBits(BaseFormat base, GLenum sizeQuery) {
  const bool hasRGB = base == BaseFormat::RGB || base == BaseFormat::RGBA;
  const bool hasAlpha = base == BaseFormat::Alpha || base == BaseFormat::LuminanceAlpha ||
                        base == BaseFormat::RGBA;
  const bool hasLuminance = base == BaseFormat::Luminance || base == BaseFormat::LuminanceAlpha;
  switch (sizeQuery) {
    case GL_TEXTURE_RED_SIZE:
    case GL_TEXTURE_GREEN_SIZE:
    case GL_TEXTURE_BLUE_SIZE: return hasRGB ? 8 : 0;
    case GL_TEXTURE_ALPHA_SIZE: return hasAlpha ? 8 : 0;
    case GL_TEXTURE_LUMINANCE_SIZE: return hasLuminance ? 8 : 0;
    case GL_TEXTURE_INTENSITY_SIZE: return base == BaseFormat::Intensity ? 8 : 0;
    default: return 0;
  }
}

uint8_t unitFloatToByte(float c) {
  // NaN compares false both ways and ends at 0. Ties round to even (the default rounding mode),
  // as Mesa's conversion to unsigned normalized values does.
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return 255;
  return static_cast<uint8_t>(std::nearbyint(c * 255.0f));
}

void storeTexel(BaseFormat base, const float rgba[4], uint8_t out[4]) {
  const uint8_t r = unitFloatToByte(rgba[0]);
  switch (base) {
    case BaseFormat::Alpha:
      out[0] = out[1] = out[2] = 0;
      out[3] = unitFloatToByte(rgba[3]);
      break;
    case BaseFormat::Luminance:
      out[0] = out[1] = out[2] = r;
      out[3] = 255;
      break;
    case BaseFormat::LuminanceAlpha:
      out[0] = out[1] = out[2] = r;
      out[3] = unitFloatToByte(rgba[3]);
      break;
    case BaseFormat::Intensity:
      out[0] = out[1] = out[2] = out[3] = r;
      break;
    case BaseFormat::RGB:
      out[0] = r;
      out[1] = unitFloatToByte(rgba[1]);
      out[2] = unitFloatToByte(rgba[2]);
      out[3] = 255;
      break;
    case BaseFormat::RGBA:
      out[0] = r;
      out[1] = unitFloatToByte(rgba[1]);
      out[2] = unitFloatToByte(rgba[2]);
      out[3] = unitFloatToByte(rgba[3]);
      break;
  }
}

}  // namespace glass::gl
