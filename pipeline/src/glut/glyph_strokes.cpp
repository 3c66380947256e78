#include "glut/glyph_strokes.h"

#include <algorithm>

#include "glut/font_glyphs.h"

namespace glass::gl::glut {

namespace {

// One grid row: the capitals' 7 rows (0 to 6) span 6 steps from the baseline to y = 100.
constexpr float kRowStep = 100.0f / 6.0f;
// Space kept free on each side of a glyph within its advance (2 units of the Hershey grid the
// Roman fonts are drawn on, scaled by 100/21 as they are).
constexpr float kSideBearing = 2.0f * 100.0f / 21.0f;
constexpr float kMaxColumnStep = 1.5f * kRowStep;

struct Grid {
  const std::uint8_t* rows;
  bool at(int r, int c) const {
    return r >= 0 && r < kGlyphRows && c >= 0 && c < kGlyphColumns && (rows[r] & (0x10 >> c));
  }
};

// Whether the cells (r, c) and (r + dr, c + dc) are joined. Orthogonal neighbours always are;
// diagonal ones only where no cell beside both already joins them, so that a corner is one bend
// and not a triangle.
bool joined(const Grid& g, int r, int c, int dr, int dc) {
  if (!g.at(r, c) || !g.at(r + dr, c + dc)) return false;
  if (dr != 0 && dc != 0) return !g.at(r, c + dc) && !g.at(r + dr, c);
  return true;
}

bool hasAnyNeighbour(const Grid& g, int r, int c) {
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      if ((dr != 0 || dc != 0) && g.at(r + dr, c + dc)) return true;
  return false;
}

}  // namespace

std::vector<StrokeStrip> glyphStrokes(StrokeFont font, int character) {
  std::vector<StrokeStrip> strips;
  if (!hasStrokeCharacter(font, character)) return strips;
  const Grid g{glyphRows(character)};

  int firstColumn = kGlyphColumns;
  int lastColumn = -1;
  for (int r = 0; r < kGlyphRows; ++r)
    for (int c = 0; c < kGlyphColumns; ++c)
      if (g.at(r, c)) {
        firstColumn = std::min(firstColumn, c);
        lastColumn = std::max(lastColumn, c);
      }
  if (lastColumn < 0) return strips;

  // The glyph fills its advance but for the side bearings: columns narrower than the rows for
  // the narrow characters of GLUT_STROKE_ROMAN (i, l, the punctuation), wider for the wide ones
  // (m, w), up to half as wide again as a row is tall. Centred.
  const float advance = strokeAdvance(font, character);
  const int span = lastColumn - firstColumn;
  float columnStep = kRowStep;
  if (span > 0) {
    columnStep = std::min(kMaxColumnStep, std::max(0.0f, advance - 2.0f * kSideBearing) / span);
  }
  const float centreColumn = 0.5f * static_cast<float>(firstColumn + lastColumn);
  auto point = [&](int r, int c) {
    return StrokePoint{0.5f * advance + (static_cast<float>(c) - centreColumn) * columnStep,
                       static_cast<float>(kGlyphBaselineRow - r) * kRowStep};
  };

  // Maximal straight runs of joined cells, in each of the four directions.
  constexpr int kDirections[4][2] = {{0, 1}, {1, 0}, {1, 1}, {1, -1}};
  for (const auto& d : kDirections) {
    for (int r = 0; r < kGlyphRows; ++r) {
      for (int c = 0; c < kGlyphColumns; ++c) {
        if (!joined(g, r, c, d[0], d[1]) || joined(g, r - d[0], c - d[1], d[0], d[1])) continue;
        StrokeStrip strip{point(r, c)};
        int rr = r;
        int cc = c;
        while (joined(g, rr, cc, d[0], d[1])) {
          rr += d[0];
          cc += d[1];
        }
        strip.push_back(point(rr, cc));
        strips.push_back(std::move(strip));
      }
    }
  }
  // A cell with no neighbour (the dot of i and j) is a short upright tick, half a row tall,
  // hanging from the cell's centre so that it stays below the capitals' height.
  for (int r = 0; r < kGlyphRows; ++r) {
    for (int c = 0; c < kGlyphColumns; ++c) {
      if (!g.at(r, c) || hasAnyNeighbour(g, r, c)) continue;
      const StrokePoint centre = point(r, c);
      strips.push_back({centre, {centre.x, centre.y - 0.5f * kRowStep}});
    }
  }
  return strips;
}

}  // namespace glass::gl::glut
