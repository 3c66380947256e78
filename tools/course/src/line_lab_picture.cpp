#include "glass/course/line_lab_picture.h"

#include <GL/gl.h>

#include <algorithm>

namespace glass::course {

namespace {

constexpr int kPanelGap = 16;  // pixels of background between panels

int panelPixels(const LineLabPicture& picture) { return picture.gridSize * picture.cellPixels + 1; }

// The square (x, y) of a panel covers pixels [left + x c + 1, left + (x + 1) c) and the same in y:
// the pixel columns x c are left for the grid lines. Corners on pixel edges, so that the fill rule
// covers exactly those pixels.
void fillSquare(int left, int cell, int x, int y) {
  const float x0 = static_cast<float>(left + x * cell + 1), x1 = static_cast<float>(left + (x + 1) * cell);
  const float y0 = static_cast<float>(y * cell + 1), y1 = static_cast<float>((y + 1) * cell);
  glVertex2f(x0, y0);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glVertex2f(x0, y1);
}

// The centre of square (x, y) in pixel coordinates.
float centre(int origin, int cell, int i) { return static_cast<float>(origin + i * cell) + (cell + 1) / 2.0f; }

}  // namespace

PictureSize lineLabPictureSize(const LineLabPicture& picture) {
  const int panels = std::max<int>(1, static_cast<int>(picture.algorithms.size()));
  const int panel = panelPixels(picture);
  return {panels * panel + (panels - 1) * kPanelGap, panel};
}

void drawLineLabPicture(const LineLabPicture& picture) {
  const PictureSize size = lineLabPictureSize(picture);
  const int cell = picture.cellPixels;
  const int panel = panelPixels(picture);

  // Pixel coordinates: one unit per pixel, origin at the bottom left.
  glViewport(0, 0, size.width, size.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, size.width, 0.0, size.height, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glShadeModel(GL_FLAT);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  const GridSegment& s = picture.segment;
  for (std::size_t p = 0; p < picture.algorithms.size(); ++p) {
    const int left = static_cast<int>(p) * (panel + kPanelGap);
    // The grid lines: the panel in grey, the squares drawn over it leave one-pixel lines.
    glColor3f(0.72f, 0.72f, 0.74f);
    glBegin(GL_QUADS);
    glVertex2f(static_cast<float>(left), 0.0f);
    glVertex2f(static_cast<float>(left + panel), 0.0f);
    glVertex2f(static_cast<float>(left + panel), static_cast<float>(panel));
    glVertex2f(static_cast<float>(left), static_cast<float>(panel));
    glEnd();

    std::vector<char> chosen(static_cast<std::size_t>(picture.gridSize) * picture.gridSize, 0);
    for (const raster::GridPixel& q : lineSquares(picture.algorithms[p], s)) {
      if (q.x >= 0 && q.y >= 0 && q.x < picture.gridSize && q.y < picture.gridSize) {
        chosen[static_cast<std::size_t>(q.y) * picture.gridSize + q.x] = 1;
      }
    }
    glBegin(GL_QUADS);
    for (int y = 0; y < picture.gridSize; ++y) {
      for (int x = 0; x < picture.gridSize; ++x) {
        if (chosen[static_cast<std::size_t>(y) * picture.gridSize + x]) {
          glColor3f(0.36f, 0.56f, 0.86f);
        } else {
          glColor3f(1.0f, 1.0f, 1.0f);
        }
        fillSquare(left, cell, x, y);
      }
    }
    glEnd();

    // The true segment between the centres of the end squares, and the two end points.
    glColor3f(0.86f, 0.08f, 0.08f);
    glLineWidth(std::max(1.0f, cell / 6.0f));
    glBegin(GL_LINES);
    glVertex2f(centre(left, cell, s.x0), centre(0, cell, s.y0));
    glVertex2f(centre(left, cell, s.x1), centre(0, cell, s.y1));
    glEnd();
    glPointSize(std::max(3.0f, cell / 3.0f));
    glBegin(GL_POINTS);
    glVertex2f(centre(left, cell, s.x0), centre(0, cell, s.y0));
    glVertex2f(centre(left, cell, s.x1), centre(0, cell, s.y1));
    glEnd();
  }
  glLineWidth(1.0f);
  glPointSize(1.0f);
}

}  // namespace glass::course
