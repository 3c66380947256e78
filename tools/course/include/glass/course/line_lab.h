// Homework 1 of the study guide (section 2.1), the line lab: the squares each line algorithm
// chooses, the symmetry check the guide asks for ("switching endpoints of the segment should
// produce the same result"), and the speed comparison of the float, integer and Bresenham
// versions. The algorithms themselves are the rasterizer's teaching functions
// (glass/raster/teaching_lines.h); this file only runs and measures them. No GL here: the picture
// and the comparison with GL_LINES are in line_lab_picture.h and line_agreement.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glass/raster/teaching_lines.h"

namespace glass::course {

enum class LineAlgorithm {
  Float,        // Listing 1
  Integer,      // Listing 2
  Bresenham,    // Listing 3
  DiamondExit,  // GL's rule for GL_LINES (specification section 3.4.1)
};

inline constexpr LineAlgorithm kAllLineAlgorithms[] = {LineAlgorithm::Float, LineAlgorithm::Integer,
                                                        LineAlgorithm::Bresenham, LineAlgorithm::DiamondExit};

// "float", "integer", "bresenham", "gl".
std::string_view lineAlgorithmName(LineAlgorithm algorithm);
std::optional<LineAlgorithm> parseLineAlgorithm(std::string_view name);

struct GridSegment {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// The squares the algorithm fills for the segment between the centres of two grid squares.
std::vector<raster::GridPixel> lineSquares(LineAlgorithm algorithm, const GridSegment& segment);

// The squares as a sorted set, to compare drawings regardless of the order of travel.
std::vector<raster::GridPixel> sortedSquares(std::vector<raster::GridPixel> squares);

struct SymmetryFailure {
  GridSegment segment;
  std::vector<raster::GridPixel> forward;   // sorted squares from (x0, y0) to (x1, y1)
  std::vector<raster::GridPixel> backward;  // sorted squares from (x1, y1) to (x0, y0)
};

struct SymmetryReport {
  LineAlgorithm algorithm = LineAlgorithm::Bresenham;
  int gridSize = 0;
  std::uint64_t segmentsChecked = 0;  // ordered pairs of distinct squares, each unordered pair once
  std::uint64_t failureCount = 0;
  std::vector<SymmetryFailure> firstFailures;  // up to the requested number
};

// Every segment between two distinct squares of a gridSize x gridSize grid, drawn both ways.
// GL's rule leaves out the last square by design (so that line strips do not draw shared
// vertices twice); for it, the two drawings are compared with both endpoints added.
SymmetryReport checkSymmetry(LineAlgorithm algorithm, int gridSize, std::size_t keepFailures = 10);

// Random segments with distinct endpoints, uniform in a gridSize x gridSize grid, from a seed:
// the same segments on every machine (glass::geometry::SplitMix64).
std::vector<GridSegment> randomSegments(std::size_t count, int gridSize, std::uint64_t seed);

struct SpeedResult {
  LineAlgorithm algorithm = LineAlgorithm::Float;
  double bestSeconds = 0.0;  // of the repetitions
  double nsPerLine = 0.0;
  double nsPerSquare = 0.0;
  std::uint64_t squares = 0;   // per repetition
  std::uint64_t checksum = 0;  // folded from every square, printed so the work cannot be dropped
};

struct SpeedReport {
  std::size_t lines = 0;
  int gridSize = 0;
  std::uint64_t seed = 0;
  int repetitions = 0;
  std::vector<SpeedResult> results;  // float, integer, Bresenham
};

// Times the allocation-free *Into variants of Listings 1-3 on the same random segments, without
// drawing: each algorithm writes its squares into a buffer that is never drawn, every square is
// folded into a checksum (so the compiler cannot remove the work), the segments are generated
// before the clock starts, and each algorithm's time is the best of `repetitions` runs with the
// algorithms interleaved (so that a slow moment of the machine does not favour one of them).
SpeedReport measureLineSpeed(std::size_t lines, int gridSize, std::uint64_t seed, int repetitions);

// The report as the tool prints it, saying how it was measured.
std::string formatSpeedReport(const SpeedReport& report);
std::string formatSymmetryReport(const SymmetryReport& report);

}  // namespace glass::course
