#include "glass/course/line_agreement.h"

#include <GL/gl.h>

#include <cstdio>

namespace glass::course {

using raster::GridPixel;

std::vector<AgreementResult> measureGlAgreement(std::size_t lines, int gridSize, std::uint64_t seed) {
  const std::vector<GridSegment> segments = randomSegments(lines, gridSize, seed);
  std::vector<AgreementResult> results;
  for (LineAlgorithm algorithm : kAllLineAlgorithms) results.push_back({algorithm, 0, lines, std::nullopt});

  glViewport(0, 0, gridSize, gridSize);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, gridSize, 0.0, gridSize, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LINE_SMOOTH);
  glLineWidth(1.0f);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);

  std::vector<unsigned char> pixels(static_cast<std::size_t>(gridSize) * gridSize * 4);
  for (const GridSegment& s : segments) {
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glVertex2f(static_cast<float>(s.x0) + 0.5f, static_cast<float>(s.y0) + 0.5f);
    glVertex2f(static_cast<float>(s.x1) + 0.5f, static_cast<float>(s.y1) + 0.5f);
    glEnd();
    glReadPixels(0, 0, gridSize, gridSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    std::vector<GridPixel> drawn;
    for (int y = 0; y < gridSize; ++y) {
      for (int x = 0; x < gridSize; ++x) {
        if (pixels[(static_cast<std::size_t>(y) * gridSize + x) * 4] > 127) drawn.push_back({x, y});
      }
    }
    drawn = sortedSquares(std::move(drawn));
    for (AgreementResult& result : results) {
      std::vector<GridPixel> chosen = lineSquares(result.algorithm, s);
      // GL leaves out the last square; so does lineDiamondExit. Leave it out of the others too.
      if (result.algorithm != LineAlgorithm::DiamondExit && !chosen.empty()) chosen.pop_back();
      if (sortedSquares(std::move(chosen)) == drawn) {
        ++result.equal;
      } else if (!result.firstDifference) {
        result.firstDifference = s;
      }
    }
  }
  return results;
}

std::string formatAgreement(const std::vector<AgreementResult>& results, const std::string& glName,
                            int gridSize) {
  std::string out;
  char line[256];
  for (const AgreementResult& r : results) {
    const double percent = r.lines == 0 ? 0.0 : 100.0 * static_cast<double>(r.equal) / static_cast<double>(r.lines);
    std::snprintf(line, sizeof line, "  %-9s %6.2f%% of %zu segments (%d x %d grid) draw the same squares as %s's GL_LINES",
                  std::string(lineAlgorithmName(r.algorithm)).c_str(), percent, r.lines, gridSize, gridSize,
                  glName.c_str());
    out += line;
    if (r.firstDifference) {
      std::snprintf(line, sizeof line, "; first difference (%d,%d)-(%d,%d)", r.firstDifference->x0,
                    r.firstDifference->y0, r.firstDifference->x1, r.firstDifference->y1);
      out += line;
    }
    out += "\n";
  }
  return out;
}

}  // namespace glass::course
