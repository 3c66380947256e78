#include "glut/glyph_bitmaps.h"

#include <algorithm>

#include "glut/font_glyphs.h"

namespace glass::gl::glut {

namespace {

// How a font draws the 5 x 9 grid: each grid row `rowScale` pixel rows tall, each grid column
// up to `columnScale` pixels wide. The small fonts draw the grid as it is: capitals 7 rows tall,
// about the capital height of 10- and 12-point Helvetica and Times at 75 dpi and of the fixed
// fonts. The 18- and 24-point fonts double the rows (capitals 14 rows, as Helvetica 18's 13 and
// Times 24's 16) and make a glyph as wide as its advance leaves room for (one pixel less), from
// one to three pixels a column: the narrow letters (i, r, t: 4 to 8 pixels in these fonts) keep
// thin stems rather than run into their neighbours, the wide ones (m, w: up to 23) spread.
struct BitmapStyle {
  int rowScale;
  int columnScale;
};

BitmapStyle styleOf(BitmapFont font) {
  switch (font) {
    case BitmapFont::TimesRoman24:
    case BitmapFont::Helvetica18:
      return {2, 3};
    default:
      return {1, 1};
  }
}

// Floor of a / 2 for any sign (C++ division truncates towards zero).
int halfFloor(int a) { return a >= 0 ? a / 2 : -((1 - a) / 2); }

}  // namespace

GlyphBitmap glyphBitmap(BitmapFont font, int character) {
  const BitmapFontMetrics& metrics = bitmapFontMetrics(font);
  const BitmapStyle style = styleOf(font);
  const int advance = bitmapAdvance(font, character);
  const std::uint8_t* rows = glyphRows(character);

  // The glyph's inked columns, first to last (bit 4 is column 0).
  std::uint8_t used = 0;
  for (int r = 0; r < kGlyphRows; ++r) used |= rows[r];
  int firstColumn = kGlyphColumns;
  int lastColumn = -1;
  for (int c = 0; c < kGlyphColumns; ++c) {
    if (used & (0x10 >> c)) {
      if (firstColumn == kGlyphColumns) firstColumn = c;
      lastColumn = c;
    }
  }
  const bool blank = lastColumn < 0;
  const int columns = blank ? 0 : lastColumn - firstColumn + 1;
  const int inkWidth = std::clamp(advance - 1, columns, columns * style.columnScale);
  // Grid column k of the ink covers pixels columnStart(k) to columnStart(k + 1) - 1: the ink
  // width shared out by nearest neighbour.
  auto columnStart = [&](int k) { return columns == 0 ? 0 : k * inkWidth / columns; };

  // The ink centred on the advance (its left column `inkLeft` pixels right of the raster
  // position), in a box from boxLeft to boxRight that holds both the advance and the ink.
  const int inkLeft = halfFloor(advance - inkWidth);
  const int boxLeft = blank ? 0 : std::min(0, inkLeft);
  const int boxRight = blank ? advance : std::max(advance, inkLeft + inkWidth);

  GlyphBitmap bitmap;
  bitmap.width = boxRight - boxLeft;
  bitmap.height = metrics.height;
  bitmap.xorig = static_cast<float>(-boxLeft);
  bitmap.yorig = static_cast<float>(metrics.descent);
  bitmap.xmove = static_cast<float>(advance);
  const int rowBytes = (bitmap.width + 7) / 8;
  bitmap.bits.assign(static_cast<std::size_t>(rowBytes * bitmap.height), 0);
  if (blank) return bitmap;

  auto set = [&](int x, int y) {
    if (x < 0 || x >= bitmap.width || y < 0 || y >= bitmap.height) return;
    bitmap.bits[static_cast<std::size_t>(y * rowBytes + x / 8)] |=
        static_cast<std::uint8_t>(0x80u >> (x % 8));
  };
  for (int r = 0; r < kGlyphRows; ++r) {
    // Grid row kGlyphBaselineRow sits on the baseline, which is row `descent` of the box.
    const int bottom = metrics.descent + (kGlyphBaselineRow - r) * style.rowScale;
    for (int c = firstColumn; c <= lastColumn; ++c) {
      if (!(rows[r] & (0x10 >> c))) continue;
      const int k = c - firstColumn;
      for (int x = columnStart(k); x < columnStart(k + 1); ++x)
        for (int dy = 0; dy < style.rowScale; ++dy) set(inkLeft - boxLeft + x, bottom + dy);
    }
  }
  return bitmap;
}

}  // namespace glass::gl::glut
