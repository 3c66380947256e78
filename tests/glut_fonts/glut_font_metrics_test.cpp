// glass's GLUT font metrics (pipeline/src/glut/font_metrics.cpp) against the installed
// freeglut's: every character's advance and every font's line height, which decide where GLUT
// text and the layout a program computes around it land.
#include <GL/freeglut.h>
#include <doctest/doctest.h>

#include <cstdarg>

#include "glut/font_metrics.h"

namespace fonts = glass::gl::glut;

namespace {

// freeglut's font queries check that glutInit ran, and glutInit needs an X display. With an
// error handler installed the check reports and returns instead of exiting, and the query
// (which touches no window) answers.
void ignore(const char*, va_list) {}

struct QuietFreeglut {
  QuietFreeglut() {
    glutInitErrorFunc(ignore);
    glutInitWarningFunc(ignore);
  }
};

}  // namespace

TEST_CASE("glut font metrics: bitmap advances and heights are freeglut's") {
  QuietFreeglut quiet;
  const struct {
    void* handle;
    fonts::BitmapFont font;
  } bitmapFonts[] = {
      {GLUT_BITMAP_9_BY_15, fonts::BitmapFont::Fixed9By15},
      {GLUT_BITMAP_8_BY_13, fonts::BitmapFont::Fixed8By13},
      {GLUT_BITMAP_TIMES_ROMAN_10, fonts::BitmapFont::TimesRoman10},
      {GLUT_BITMAP_TIMES_ROMAN_24, fonts::BitmapFont::TimesRoman24},
      {GLUT_BITMAP_HELVETICA_10, fonts::BitmapFont::Helvetica10},
      {GLUT_BITMAP_HELVETICA_12, fonts::BitmapFont::Helvetica12},
      {GLUT_BITMAP_HELVETICA_18, fonts::BitmapFont::Helvetica18},
  };
  int compared = 0;
  for (const auto& f : bitmapFonts) {
    CAPTURE(static_cast<int>(f.font));
    CHECK(fonts::bitmapFontMetrics(f.font).height == glutBitmapHeight(f.handle));
    for (int c = -1; c <= 256; ++c) {
      CAPTURE(c);
      CHECK(fonts::bitmapAdvance(f.font, c) == glutBitmapWidth(f.handle, c));
      ++compared;
    }
  }
  CHECK(compared == 7 * 258);
}

TEST_CASE("glut font metrics: stroke advances and heights are freeglut's, to the bit") {
  QuietFreeglut quiet;
  const struct {
    void* handle;
    fonts::StrokeFont font;
  } strokeFonts[] = {
      {GLUT_STROKE_ROMAN, fonts::StrokeFont::Roman},
      {GLUT_STROKE_MONO_ROMAN, fonts::StrokeFont::MonoRoman},
  };
  for (const auto& f : strokeFonts) {
    CAPTURE(static_cast<int>(f.font));
    CHECK(fonts::strokeFontHeight(f.font) == glutStrokeHeight(f.handle));
    for (int c = -1; c <= 256; ++c) {
      CAPTURE(c);
      CHECK(fonts::strokeAdvance(f.font, c) == glutStrokeWidthf(f.handle, c));
      // A character freeglut draws nothing for and does not move after is one glass lacks too.
      if (c >= 0 && c < 256 && glutStrokeWidthf(f.handle, c) == 0.0f) {
        CHECK_FALSE(fonts::hasStrokeCharacter(f.font, c));
      }
    }
  }
}
