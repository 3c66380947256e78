#include "glass/course/line_lab.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "glass/geometry/deterministic_random.h"

namespace glass::course {

using raster::GridPixel;

std::string_view lineAlgorithmName(LineAlgorithm algorithm) {
  switch (algorithm) {
    case LineAlgorithm::Float: return "float";
    case LineAlgorithm::Integer: return "integer";
    case LineAlgorithm::Bresenham: return "bresenham";
    case LineAlgorithm::DiamondExit: return "gl";
  }
  return "?";
}

std::optional<LineAlgorithm> parseLineAlgorithm(std::string_view name) {
  for (LineAlgorithm algorithm : kAllLineAlgorithms) {
    if (lineAlgorithmName(algorithm) == name) return algorithm;
  }
  return std::nullopt;
}

std::vector<GridPixel> lineSquares(LineAlgorithm algorithm, const GridSegment& s) {
  switch (algorithm) {
    case LineAlgorithm::Float: return raster::lineFloat(s.x0, s.y0, s.x1, s.y1);
    case LineAlgorithm::Integer: return raster::lineInteger(s.x0, s.y0, s.x1, s.y1);
    case LineAlgorithm::Bresenham: return raster::lineBresenham(s.x0, s.y0, s.x1, s.y1);
    case LineAlgorithm::DiamondExit: return raster::lineDiamondExit(s.x0, s.y0, s.x1, s.y1);
  }
  return {};
}

std::vector<GridPixel> sortedSquares(std::vector<GridPixel> squares) {
  std::sort(squares.begin(), squares.end(),
            [](const GridPixel& a, const GridPixel& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  squares.erase(std::unique(squares.begin(), squares.end()), squares.end());
  return squares;
}

SymmetryReport checkSymmetry(LineAlgorithm algorithm, int gridSize, std::size_t keepFailures) {
  SymmetryReport report;
  report.algorithm = algorithm;
  report.gridSize = gridSize;
  const bool addEndpoints = algorithm == LineAlgorithm::DiamondExit;
  const int cells = gridSize * gridSize;
  for (int a = 0; a < cells; ++a) {
    for (int b = a + 1; b < cells; ++b) {
      const GridSegment s{a % gridSize, a / gridSize, b % gridSize, b / gridSize};
      std::vector<GridPixel> forward = lineSquares(algorithm, s);
      std::vector<GridPixel> backward = lineSquares(algorithm, {s.x1, s.y1, s.x0, s.y0});
      if (addEndpoints) {
        for (auto* squares : {&forward, &backward}) {
          squares->push_back({s.x0, s.y0});
          squares->push_back({s.x1, s.y1});
        }
      }
      forward = sortedSquares(std::move(forward));
      backward = sortedSquares(std::move(backward));
      ++report.segmentsChecked;
      if (forward != backward) {
        ++report.failureCount;
        if (report.firstFailures.size() < keepFailures) {
          report.firstFailures.push_back({s, std::move(forward), std::move(backward)});
        }
      }
    }
  }
  return report;
}

std::vector<GridSegment> randomSegments(std::size_t count, int gridSize, std::uint64_t seed) {
  geometry::SplitMix64 random(seed);
  std::vector<GridSegment> segments;
  segments.reserve(count);
  const auto n = static_cast<std::uint64_t>(gridSize);
  while (segments.size() < count) {
    GridSegment s;
    s.x0 = static_cast<int>(random.below(n));
    s.y0 = static_cast<int>(random.below(n));
    s.x1 = static_cast<int>(random.below(n));
    s.y1 = static_cast<int>(random.below(n));
    if (s.x0 != s.x1 || s.y0 != s.y1) segments.push_back(s);
  }
  return segments;
}

namespace {

using IntoFunction = int (*)(int, int, int, int, GridPixel*);

// One timed pass over all segments. The function is called through a pointer, the same way for
// every algorithm, and every square it writes is folded into the checksum.
double timePass(IntoFunction draw, const std::vector<GridSegment>& segments, GridPixel* buffer,
                std::uint64_t& squares, std::uint64_t& checksum) {
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t count = 0, fold = 0;
  for (const GridSegment& s : segments) {
    const int n = draw(s.x0, s.y0, s.x1, s.y1, buffer);
    // A plain sum: one add per square, with no chain of multiplies that would cost more than
    // the algorithms themselves.
    for (int i = 0; i < n; ++i) {
      fold += (static_cast<std::uint64_t>(buffer[i].x) << 20) + static_cast<std::uint64_t>(buffer[i].y);
    }
    count += static_cast<std::uint64_t>(n);
  }
  const auto stop = std::chrono::steady_clock::now();
  squares = count;
  checksum = fold;
  return std::chrono::duration<double>(stop - start).count();
}

}  // namespace

SpeedReport measureLineSpeed(std::size_t lines, int gridSize, std::uint64_t seed, int repetitions) {
  SpeedReport report;
  report.lines = lines;
  report.gridSize = gridSize;
  report.seed = seed;
  report.repetitions = repetitions;
  const std::vector<GridSegment> segments = randomSegments(lines, gridSize, seed);
  std::vector<GridPixel> buffer(static_cast<std::size_t>(gridSize) + 1);
  const struct {
    LineAlgorithm algorithm;
    IntoFunction draw;
  } algorithms[] = {{LineAlgorithm::Float, raster::lineFloatInto},
                    {LineAlgorithm::Integer, raster::lineIntegerInto},
                    {LineAlgorithm::Bresenham, raster::lineBresenhamInto}};
  for (const auto& a : algorithms) report.results.push_back({a.algorithm, 1e300, 0, 0, 0, 0});
  for (int rep = 0; rep < std::max(1, repetitions); ++rep) {
    for (std::size_t i = 0; i < std::size(algorithms); ++i) {
      std::uint64_t squares = 0, checksum = 0;
      const double seconds = timePass(algorithms[i].draw, segments, buffer.data(), squares, checksum);
      SpeedResult& r = report.results[i];
      r.bestSeconds = std::min(r.bestSeconds, seconds);
      r.squares = squares;
      r.checksum = checksum;
    }
  }
  for (SpeedResult& r : report.results) {
    r.nsPerLine = r.bestSeconds * 1e9 / static_cast<double>(std::max<std::size_t>(lines, 1));
    r.nsPerSquare = r.bestSeconds * 1e9 / static_cast<double>(std::max<std::uint64_t>(r.squares, 1));
  }
  return report;
}

std::string formatSpeedReport(const SpeedReport& report) {
  std::string out;
  char line[256];
  const double squaresPerLine =
      report.results.empty() ? 0.0 : static_cast<double>(report.results[0].squares) / static_cast<double>(report.lines);
  std::snprintf(line, sizeof line,
                "Speed of the line algorithms: %zu random segments in a %d x %d grid (seed %llu), "
                "%.1f squares per segment on average.\n",
                report.lines, report.gridSize, report.gridSize, static_cast<unsigned long long>(report.seed),
                squaresPerLine);
  out += line;
  out +=
      "How: pure computation, no drawing. Each algorithm (the allocation-free variants of Listings 1-3)\n"
      "writes its squares into a buffer that is never drawn; every square is folded into a checksum,\n"
      "printed below, so the compiler cannot remove the work (equal checksums also show the algorithms\n"
      "chose the same squares). The segments are made before the clock starts. Time: steady_clock around\n";
  std::snprintf(line, sizeof line,
                "the whole batch, the best of %d runs, the algorithms taking turns.\n\n", report.repetitions);
  out += line;
  out += "  algorithm   ns/line  ns/square   checksum\n";
  for (const SpeedResult& r : report.results) {
    std::snprintf(line, sizeof line, "  %-9s  %8.2f  %9.3f   %016llx\n", std::string(lineAlgorithmName(r.algorithm)).c_str(),
                  r.nsPerLine, r.nsPerSquare, static_cast<unsigned long long>(r.checksum));
    out += line;
  }
  return out;
}

std::string formatSymmetryReport(const SymmetryReport& report) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-9s: %llu segments of a %d x %d grid drawn both ways, %llu differ%s\n",
                std::string(lineAlgorithmName(report.algorithm)).c_str(),
                static_cast<unsigned long long>(report.segmentsChecked), report.gridSize, report.gridSize,
                static_cast<unsigned long long>(report.failureCount),
                report.algorithm == LineAlgorithm::DiamondExit ? " (with the endpoint GL leaves out added to both)" : "");
  out += line;
  for (const SymmetryFailure& f : report.firstFailures) {
    std::snprintf(line, sizeof line, "  (%d,%d)-(%d,%d):", f.segment.x0, f.segment.y0, f.segment.x1, f.segment.y1);
    out += line;
    // The squares only one of the two drawings has.
    for (const GridPixel& p : f.forward) {
      if (!std::binary_search(f.backward.begin(), f.backward.end(), p,
                              [](const GridPixel& a, const GridPixel& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; })) {
        std::snprintf(line, sizeof line, " forward only (%d,%d)", p.x, p.y);
        out += line;
      }
    }
    for (const GridPixel& p : f.backward) {
      if (!std::binary_search(f.forward.begin(), f.forward.end(), p,
                              [](const GridPixel& a, const GridPixel& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; })) {
        std::snprintf(line, sizeof line, " backward only (%d,%d)", p.x, p.y);
        out += line;
      }
    }
    out += "\n";
  }
  return out;
}

}  // namespace glass::course
