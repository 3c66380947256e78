// GLUT's text (GLUT 3.7 specification, sections 13.1 and 13.2, and freeglut's additions):
// glutBitmapCharacter/String/Width/Length/Height and glutStrokeCharacter/String/Width/Length/
// Height, with freeglut's float variants, for the nine fonts GLUT names.
//
// The effects on GL state are freeglut 3's, call for call, so that text lands where it does with
// freeglut and records, selects and feeds back as it does:
//  - a bitmap character is one glBitmap, moving the raster position by the character's advance
//    (and only if the raster position is valid, as glBitmap does), drawn in the current raster
//    colour, compiled into a display list being made (GL 1.5 section 5.4: glBitmap is);
//  - the unpack state is pushed with glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT), set to
//    glass's bitmap layout (no swap, MSB first, no row length or skips, alignment 1) and popped;
//  - glutBitmapString's newline is a glBitmap of nothing that moves back to where the line
//    started and down one line height;
//  - a stroke character is GL_LINE_STRIPs in model units, then glTranslatef(advance, 0, 0);
//    glutStrokeString's newline is glTranslatef(-line length, -line height, 0).
// Bad fonts and characters are ignored as freeglut ignores them (nothing drawn, 0 returned);
// GLUT functions set no GL error. The glyphs are glass's own (glut/glyph_bitmaps.h,
// glut/glyph_strokes.h); the advances and heights are freeglut's (glut/font_metrics.h).
#include <GL/glut.h>

#include <algorithm>
#include <optional>

#include "glut/font_metrics.h"
#include "glut/glyph_bitmaps.h"
#include "glut/glyph_strokes.h"

using glass::gl::glut::BitmapFont;
using glass::gl::glut::StrokeFont;
namespace fonts = glass::gl::glut;

extern "C" {
// The font handles: GLUT_BITMAP_9_BY_15 and the others are these variables' addresses, as in
// freeglut on Unix (freeglut_std.h), so programs built against either header agree. Their values
// are never read.
void* glutStrokeRoman = nullptr;
void* glutStrokeMonoRoman = nullptr;
void* glutBitmap9By15 = nullptr;
void* glutBitmap8By13 = nullptr;
void* glutBitmapTimesRoman10 = nullptr;
void* glutBitmapTimesRoman24 = nullptr;
void* glutBitmapHelvetica10 = nullptr;
void* glutBitmapHelvetica12 = nullptr;
void* glutBitmapHelvetica18 = nullptr;
}  // extern "C"

namespace {

std::optional<BitmapFont> bitmapFontOf(const void* handle) {
  if (handle == GLUT_BITMAP_9_BY_15) return BitmapFont::Fixed9By15;
  if (handle == GLUT_BITMAP_8_BY_13) return BitmapFont::Fixed8By13;
  if (handle == GLUT_BITMAP_TIMES_ROMAN_10) return BitmapFont::TimesRoman10;
  if (handle == GLUT_BITMAP_TIMES_ROMAN_24) return BitmapFont::TimesRoman24;
  if (handle == GLUT_BITMAP_HELVETICA_10) return BitmapFont::Helvetica10;
  if (handle == GLUT_BITMAP_HELVETICA_12) return BitmapFont::Helvetica12;
  if (handle == GLUT_BITMAP_HELVETICA_18) return BitmapFont::Helvetica18;
  return std::nullopt;
}

std::optional<StrokeFont> strokeFontOf(const void* handle) {
  if (handle == GLUT_STROKE_ROMAN) return StrokeFont::Roman;
  if (handle == GLUT_STROKE_MONO_ROMAN) return StrokeFont::MonoRoman;
  return std::nullopt;
}

// glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT) and the unpack state glyph bitmaps are laid out
// for, for the lifetime of the object; glPopClientAttrib after.
class BitmapUnpackState {
 public:
  BitmapUnpackState() {
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  ~BitmapUnpackState() { glPopClientAttrib(); }
  BitmapUnpackState(const BitmapUnpackState&) = delete;
  BitmapUnpackState& operator=(const BitmapUnpackState&) = delete;
};

void drawBitmapGlyph(BitmapFont font, int character) {
  const fonts::GlyphBitmap g = fonts::glyphBitmap(font, character);
  glBitmap(g.width, g.height, g.xorig, g.yorig, g.xmove, 0.0f, g.bits.data());
}

void drawStrokeGlyph(StrokeFont font, int character) {
  for (const fonts::StrokeStrip& strip : fonts::glyphStrokes(font, character)) {
    glBegin(GL_LINE_STRIP);
    for (const fonts::StrokePoint& p : strip) glVertex2f(p.x, p.y);
    glEnd();
  }
  glTranslatef(fonts::strokeAdvance(font, character), 0.0f, 0.0f);
}

}  // namespace

extern "C" {

void glutBitmapCharacter(void* font, int character) {
  const std::optional<BitmapFont> f = bitmapFontOf(font);
  if (!f || character < 1 || character > 255) return;
  BitmapUnpackState unpack;
  drawBitmapGlyph(*f, character);
}

void glutBitmapString(void* font, const unsigned char* string) {
  const std::optional<BitmapFont> f = bitmapFontOf(font);
  if (!f || !string || !*string) return;
  BitmapUnpackState unpack;
  float lineLength = 0.0f;
  for (; *string; ++string) {
    if (*string == '\n') {
      glBitmap(0, 0, 0.0f, 0.0f, -lineLength,
               -static_cast<float>(fonts::bitmapFontMetrics(*f).height), nullptr);
      lineLength = 0.0f;
    } else {
      drawBitmapGlyph(*f, *string);
      lineLength += static_cast<float>(fonts::bitmapAdvance(*f, *string));
    }
  }
}

int glutBitmapWidth(void* font, int character) {
  const std::optional<BitmapFont> f = bitmapFontOf(font);
  return f ? fonts::bitmapAdvance(*f, character) : 0;
}

// The widest line of the string, in pixels (lines end at '\n').
int glutBitmapLength(void* font, const unsigned char* string) {
  const std::optional<BitmapFont> f = bitmapFontOf(font);
  if (!f || !string) return 0;
  int widest = 0;
  int line = 0;
  for (; *string; ++string) {
    if (*string == '\n') {
      widest = std::max(widest, line);
      line = 0;
    } else {
      line += fonts::bitmapAdvance(*f, *string);
    }
  }
  return std::max(widest, line);
}

int glutBitmapHeight(void* font) {
  const std::optional<BitmapFont> f = bitmapFontOf(font);
  return f ? fonts::bitmapFontMetrics(*f).height : 0;
}

void glutStrokeCharacter(void* font, int character) {
  const std::optional<StrokeFont> f = strokeFontOf(font);
  if (!f || !fonts::hasStrokeCharacter(*f, character)) return;
  drawStrokeGlyph(*f, character);
}

void glutStrokeString(void* font, const unsigned char* string) {
  const std::optional<StrokeFont> f = strokeFontOf(font);
  if (!f || !string) return;
  float lineLength = 0.0f;
  for (; *string; ++string) {
    if (*string == '\n') {
      glTranslatef(-lineLength, -fonts::strokeFontHeight(*f), 0.0f);
      lineLength = 0.0f;
    } else if (fonts::hasStrokeCharacter(*f, *string)) {
      drawStrokeGlyph(*f, *string);
      lineLength += fonts::strokeAdvance(*f, *string);
    }
  }
}

GLfloat glutStrokeWidthf(void* font, int character) {
  const std::optional<StrokeFont> f = strokeFontOf(font);
  return f ? fonts::strokeAdvance(*f, character) : 0.0f;
}

// freeglut rounds the float advance to the nearest integer (adding 0.5 and truncating).
int glutStrokeWidth(void* font, int character) {
  return static_cast<int>(glutStrokeWidthf(font, character) + 0.5f);
}

// The widest line of the string, in model units (lines end at '\n').
GLfloat glutStrokeLengthf(void* font, const unsigned char* string) {
  const std::optional<StrokeFont> f = strokeFontOf(font);
  if (!f || !string) return 0.0f;
  float widest = 0.0f;
  float line = 0.0f;
  for (; *string; ++string) {
    if (*string == '\n') {
      widest = std::max(widest, line);
      line = 0.0f;
    } else {
      line += fonts::strokeAdvance(*f, *string);
    }
  }
  return std::max(widest, line);
}

int glutStrokeLength(void* font, const unsigned char* string) {
  return static_cast<int>(glutStrokeLengthf(font, string) + 0.5f);
}

GLfloat glutStrokeHeight(void* font) {
  const std::optional<StrokeFont> f = strokeFontOf(font);
  return f ? fonts::strokeFontHeight(*f) : 0.0f;
}

}  // extern "C"
