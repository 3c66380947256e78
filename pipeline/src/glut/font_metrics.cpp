// freeglut 3's font metrics (glut/font_metrics.h): the numbers glutBitmapWidth, glutBitmapHeight,
// glutStrokeWidthf and glutStrokeHeight return, character by character. They are what
// text layout depends on (where each character starts, where the next line goes), so they are
// freeglut's exactly; tests/glut_fonts checks every one against the installed freeglut.
#include "glut/font_metrics.h"

namespace glass::gl::glut {

namespace {

// Advances of characters 32 to 255 of the proportional bitmap fonts (X11's Adobe Times and
// Helvetica at 75 dpi, ISO 8859-1, as freeglut carries them). Characters 1 to 31, which these
// fonts lack, advance as 127 to 160 do, which they lack too.
constexpr std::uint8_t kTimesRoman10[224] = {
     2,  3,  4,  5,  5,  8,  8,  3,  4,  4,  5,  6,  3,  7,  3,  3,  // 32-47
     5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  3,  3,  5,  6,  5,  4,  // 48-63
     9,  8,  6,  7,  7,  6,  6,  7,  8,  4,  4,  7,  6, 10,  8,  7,  // 64-79
     6,  7,  7,  5,  6,  8,  8, 10,  8,  8,  6,  3,  3,  3,  5,  5,  // 80-95
     3,  4,  5,  4,  5,  4,  4,  5,  5,  3,  3,  5,  4,  8,  5,  5,  // 96-111
     5,  5,  4,  4,  4,  5,  5,  8,  6,  5,  5,  4,  2,  4,  7,  2,  // 112-127
     2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  // 128-143
     2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  2,  // 144-159
     2,  3,  5,  5,  5,  5,  2,  5,  5,  9,  4,  5,  7,  4,  9,  4,  // 160-175
     4,  6,  3,  3,  3,  5,  6,  2,  4,  3,  4,  5,  8,  8,  8,  4,  // 176-191
     8,  8,  8,  8,  8,  8,  9,  7,  6,  6,  6,  6,  4,  4,  4,  4,  // 192-207
     7,  8,  7,  7,  7,  7,  7,  6,  8,  8,  8,  8,  8,  8,  6,  5,  // 208-223
     4,  4,  4,  4,  4,  4,  6,  4,  4,  4,  4,  4,  4,  4,  4,  4,  // 224-239
     5,  5,  5,  5,  5,  5,  5,  6,  5,  5,  5,  5,  5,  5,  5,  5,  // 240-255
};

constexpr std::uint8_t kTimesRoman24[224] = {
     6,  8, 10, 13, 12, 19, 18,  8,  8,  8, 12, 14,  7, 14,  6,  7,  // 32-47
    12, 12, 12, 12, 12, 12, 12, 12, 12, 12,  6,  7, 13, 14, 13, 11,  // 48-63
    22, 17, 16, 16, 17, 15, 14, 18, 19,  8, 11, 17, 14, 22, 18, 18,  // 64-79
    15, 18, 16, 13, 16, 18, 17, 23, 18, 16, 15,  8,  7,  8, 11, 13,  // 80-95
     7, 11, 12, 11, 12, 11,  7, 12, 13,  6,  6, 12,  6, 20, 13, 12,  // 96-111
    12, 12,  8, 10,  7, 13, 11, 17, 13, 11, 10, 10,  6, 10, 13,  6,  // 112-127
     6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  // 128-143
     6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  // 144-159
     6,  8, 12, 12, 13, 14,  6, 12,  8, 19,  8, 13, 14,  9, 19,  8,  // 160-175
     9, 14,  7,  7,  8, 13, 11,  6,  8,  7,  8, 12, 18, 18, 18, 11,  // 176-191
    17, 17, 17, 17, 17, 17, 21, 16, 15, 15, 15, 15,  8,  8,  8,  8,  // 192-207
    17, 18, 18, 18, 18, 18, 18, 14, 18, 18, 18, 18, 18, 16, 15, 12,  // 208-223
    11, 11, 11, 11, 11, 11, 16, 11, 11, 11, 11, 11,  6,  6,  6,  6,  // 224-239
    12, 13, 12, 12, 12, 12, 12, 14, 12, 13, 13, 13, 13, 11, 12, 11,  // 240-255
};

constexpr std::uint8_t kHelvetica10[224] = {
     3,  3,  4,  6,  6,  9,  8,  3,  4,  4,  4,  6,  3,  7,  3,  3,  // 32-47
     6,  6,  6,  6,  6,  6,  6,  6,  6,  6,  3,  3,  6,  5,  6,  6,  // 48-63
    11,  7,  7,  8,  8,  7,  6,  8,  8,  3,  5,  7,  6,  9,  8,  8,  // 64-79
     7,  8,  7,  7,  5,  8,  7,  9,  7,  7,  7,  3,  3,  3,  6,  6,  // 80-95
     3,  5,  6,  5,  6,  5,  4,  6,  6,  2,  2,  5,  2,  8,  6,  6,  // 96-111
     6,  6,  4,  5,  4,  5,  6,  8,  6,  5,  5,  3,  3,  3,  7,  3,  // 112-127
     3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  // 128-143
     3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  3,  // 144-159
     3,  3,  6,  6,  5,  6,  3,  6,  3,  9,  4,  6,  7,  4,  9,  3,  // 160-175
     4,  6,  3,  3,  3,  5,  6,  3,  3,  3,  4,  6,  9,  9,  9,  6,  // 176-191
     7,  7,  7,  7,  7,  7, 10,  8,  7,  7,  7,  7,  3,  3,  3,  3,  // 192-207
     8,  8,  8,  8,  8,  8,  8,  6,  8,  8,  8,  8,  8,  7,  7,  5,  // 208-223
     5,  5,  5,  5,  5,  5,  8,  5,  5,  5,  5,  5,  2,  2,  2,  2,  // 224-239
     6,  5,  6,  6,  6,  6,  6,  6,  6,  5,  5,  5,  5,  5,  6,  5,  // 240-255
};

constexpr std::uint8_t kHelvetica12[224] = {
     4,  3,  5,  7,  7, 11,  9,  3,  4,  4,  5,  7,  4,  8,  3,  4,  // 32-47
     7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  3,  3,  7,  7,  7,  7,  // 48-63
    12,  9,  8,  9,  9,  8,  8,  9,  9,  3,  7,  8,  7, 11,  9, 10,  // 64-79
     8, 10,  8,  8,  7,  8,  9, 11,  9,  9,  9,  3,  4,  3,  6,  7,  // 80-95
     3,  7,  7,  7,  7,  7,  3,  7,  7,  3,  3,  6,  3,  9,  7,  7,  // 96-111
     7,  7,  4,  6,  3,  7,  7,  9,  6,  7,  6,  4,  3,  4,  7,  4,  // 112-127
     4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  // 128-143
     4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  4,  // 144-159
     4,  3,  7,  7,  7,  7,  3,  6,  3, 11,  5,  7,  8,  5, 11,  4,  // 160-175
     5,  7,  4,  4,  2,  7,  7,  3,  3,  4,  5,  7, 10, 10, 10,  7,  // 176-191
     9,  9,  9,  9,  9,  9, 11,  9,  8,  8,  8,  8,  3,  3,  3,  3,  // 192-207
     9,  9, 10, 10, 10, 10, 10,  7, 10,  8,  8,  8,  8,  9,  8,  7,  // 208-223
     7,  7,  7,  7,  7,  7, 11,  7,  7,  7,  7,  7,  3,  3,  3,  3,  // 224-239
     7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  7,  // 240-255
};

constexpr std::uint8_t kHelvetica18[224] = {
     5,  6,  5, 10, 10, 16, 13,  4,  6,  6,  7, 10,  5, 11,  5,  5,  // 32-47
    10, 10, 10, 10, 10, 10, 10, 10, 10, 10,  5,  5, 10, 11, 10, 10,  // 48-63
    18, 12, 13, 14, 13, 11, 11, 14, 13,  6, 10, 13, 10, 16, 13, 15,  // 64-79
    12, 15, 12, 13, 12, 13, 14, 18, 13, 14, 12,  5,  5,  5,  9, 10,  // 80-95
     4,  9, 11, 10, 11, 10,  6, 11, 10,  4,  4,  9,  4, 14, 10, 11,  // 96-111
    11, 11,  6,  9,  6, 10, 10, 14, 10, 10,  9,  6,  4,  6, 10,  5,  // 112-127
     5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  // 128-143
     5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  5,  // 144-159
     5,  6, 10, 10, 10, 10,  4, 10,  6, 15,  7,  9, 11,  7, 14,  5,  // 160-175
     7, 10,  6,  6,  4, 10, 10,  4,  5,  6,  7,  9, 15, 15, 15, 10,  // 176-191
    12, 12, 12, 12, 12, 12, 18, 14, 11, 11, 11, 11,  6,  6,  6,  6,  // 192-207
    13, 13, 15, 15, 15, 15, 15, 10, 15, 13, 13, 13, 13, 14, 12,  9,  // 208-223
     9,  9,  9,  9,  9,  9, 15, 10, 10, 10, 10, 10,  4,  4,  4,  4,  // 224-239
    11, 10, 11, 11, 11, 11, 11, 10, 11, 10, 10, 10, 10, 10, 11, 10,  // 240-255
};

// Advances of characters 32 to 127 of the proportional stroke font, GLUT_STROKE_ROMAN (the
// Hershey simplex Roman scaled to capitals 100 units tall). GLUT_STROKE_MONO_ROMAN advances
// every character by the same 104.762.
constexpr float kRoman[96] = {
    104.762f, 26.6238f, 51.4352f, 79.4886f, 76.2067f, 96.5743f, 101.758f, 13.62f,  // 32-39
    47.1733f, 47.5333f, 59.439f, 97.2543f, 26.0638f, 100.754f, 26.4838f, 82.1067f,  // 40-47
    77.0667f, 66.5295f, 77.6467f, 77.0467f, 80.1686f, 77.6867f, 73.8048f, 77.2267f,  // 48-55
    77.6667f, 74.0648f, 26.2238f, 26.3038f, 81.6105f, 97.2543f, 81.6105f, 73.9029f,  // 56-63
    74.3648f, 80.4905f, 83.6267f, 84.4886f, 85.2867f, 78.1848f, 78.7448f, 89.7686f,  // 64-71
    89.0867f, 21.3f, 59.999f, 79.3267f, 71.3229f, 97.2105f, 88.8067f, 88.8305f,  // 72-79
    85.6667f, 88.0905f, 82.3667f, 80.8267f, 71.9467f, 89.4867f, 81.6105f, 100.518f,  // 80-87
    72.3667f, 79.6505f, 73.7467f, 46.1133f, 78.2067f, 46.3933f, 90.2305f, 104.062f,  // 88-95
    83.5714f, 66.6029f, 70.4629f, 68.9229f, 70.2629f, 68.5229f, 38.6552f, 70.9829f,  // 96-103
    71.021f, 28.8638f, 36.2314f, 62.521f, 19.34f, 123.962f, 70.881f, 71.7448f,  // 104-111
    70.8029f, 70.7429f, 49.4952f, 62.321f, 39.3152f, 71.161f, 60.6029f, 80.4905f,  // 112-119
    56.401f, 66.0648f, 61.821f, 41.6295f, 23.78f, 41.4695f, 91.2743f, 66.6667f,  // 120-127
};

constexpr float kMonoRomanAdvance = 104.762f;
// Both stroke fonts: 152.381 units from one line to the next.
constexpr float kStrokeLineHeight = 152.381f;
constexpr int kFirstStrokeCharacter = 32;
constexpr int kStrokeCharacterEnd = 128;

struct BitmapFontTable {
  BitmapFontMetrics metrics;
  int fixedAdvance;                   // the monospaced fonts: every character's advance
  const std::uint8_t* advances;       // the proportional fonts: characters 32 to 255
};

// In the order of BitmapFont. freeglut's line heights for the fixed fonts are 16 and 14, one row
// more than their names say.
constexpr BitmapFontTable kBitmapFonts[kBitmapFontCount] = {
    {{16, 4}, 9, nullptr},               // 9 by 15
    {{14, 3}, 8, nullptr},               // 8 by 13
    {{14, 4}, 0, kTimesRoman10},         // Times Roman 10
    {{29, 7}, 0, kTimesRoman24},         // Times Roman 24
    {{14, 3}, 0, kHelvetica10},          // Helvetica 10
    {{16, 4}, 0, kHelvetica12},          // Helvetica 12
    {{23, 5}, 0, kHelvetica18},          // Helvetica 18
};

}  // namespace

const BitmapFontMetrics& bitmapFontMetrics(BitmapFont font) {
  return kBitmapFonts[static_cast<int>(font)].metrics;
}

int bitmapAdvance(BitmapFont font, int character) {
  if (character < 1 || character > 255) return 0;
  const BitmapFontTable& table = kBitmapFonts[static_cast<int>(font)];
  if (!table.advances) return table.fixedAdvance;
  if (character < 32) character = 127;
  return table.advances[character - 32];
}

float strokeFontHeight(StrokeFont) { return kStrokeLineHeight; }

bool hasStrokeCharacter(StrokeFont, int character) {
  return character >= kFirstStrokeCharacter && character < kStrokeCharacterEnd;
}

float strokeAdvance(StrokeFont font, int character) {
  if (!hasStrokeCharacter(font, character)) return 0.0f;
  if (font == StrokeFont::MonoRoman) return kMonoRomanAdvance;
  return kRoman[character - kFirstStrokeCharacter];
}

}  // namespace glass::gl::glut
