// glass lines: homework 1 of the study guide as a command.
#include <glass/context.h>

#include <GL/gl.h>

#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

#include "command_arguments.h"
#include "glass/course/commands.h"
#include "glass/course/line_agreement.h"
#include "glass/course/line_lab.h"
#include "glass/course/line_lab_picture.h"

namespace glass::course {

std::string linesHelp() {
  return R"(usage: glass lines X0 Y0 X1 Y1 [-a ALGORITHMS] [--grid N] [--cell PX] [-o OUT.png]
       glass lines --symmetry [-a ALGORITHMS] [--grid N]
       glass lines --speed [--lines N] [--grid N] [--repeat R] [--seed S]
       glass lines --agreement [--lines N] [--grid N] [--seed S]

The study guide's homework 1 (section 2.1): a segment between the centres of two squares of a
grid of big pixels, and the squares each line algorithm fills.

Algorithms (-a, a comma-separated list, or all; default all):
  float       Listing 1, the floating-point error
  integer     Listing 2, the error scaled by 2 dx
  bresenham   Listing 3, Bresenham's algorithm
  gl          GL's diamond-exit rule for GL_LINES (it leaves out the last square)

Modes:
  X0 Y0 X1 Y1    print the squares each algorithm chooses and the ties (Figure 2.2: two squares
                 equally near the line); with -o, also draw the grid, the filled squares and the
                 true segment in red, one panel per algorithm, through glass's GL
  --symmetry     draw every segment of the grid both ways and report any whose squares change
                 when the endpoints are swapped (the guide's "switching endpoints ... should
                 produce the same result")
  --speed        time float, integer and Bresenham on random segments, without drawing
                 (default 200000 segments in a 1024 x 1024 grid, best of 5)
  --agreement    the share of random segments (default 10000) whose squares equal those glass's
                 GL_LINES draws, and Mesa's when lines_agreement_mesa was built

Options:
  --grid N       squares per side (default 32; 1024 for --speed)
  --cell PX      pixels per square in the picture (default: about 512 pixels per panel)
  --seed S       seed of the random segments (default 1)

Examples:
  glass lines 31 23 21 11 -o lines.png
  glass lines 0 0 31 12 -a bresenham,gl --cell 24 -o two.png
  glass lines --symmetry
  glass lines --speed
  glass lines --agreement
)";
}

namespace {

std::vector<LineAlgorithm> parseAlgorithms(const std::string& list) {
  if (list == "all") return {std::begin(kAllLineAlgorithms), std::end(kAllLineAlgorithms)};
  std::vector<LineAlgorithm> algorithms;
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t comma = list.find(',', start);
    if (comma == std::string::npos) comma = list.size();
    const std::string name = list.substr(start, comma - start);
    const auto algorithm = parseLineAlgorithm(name);
    if (!algorithm) {
      throw UsageError(std::string("unknown algorithm '") + name + "' (float, integer, bresenham, gl or all)");
    }
    algorithms.push_back(*algorithm);
    start = comma + 1;
  }
  return algorithms;
}

// Where the true line passes exactly halfway between two squares (Figure 2.2), as text.
std::string describeTies(const GridSegment& s) {
  const int dx = s.x1 - s.x0, dy = s.y1 - s.y0;
  const bool xMajor = std::abs(dx) >= std::abs(dy);
  const int major = xMajor ? dx : dy, minor = xMajor ? dy : dx;
  std::string ties;
  for (int step = 1; step < std::abs(major); ++step) {
    // The minor coordinate at this step is minor * step / |major|; a tie when its fraction is 1/2.
    const long long twice = 2LL * minor * step;
    const long long denominator = std::abs(major);
    if (std::llabs(twice) % (2 * denominator) != denominator) continue;
    const int along = (xMajor ? s.x0 : s.y0) + (major > 0 ? step : -step);
    // twice = (2j + 1) |major| (or its negative): the two squares are floor and floor + 1 of
    // (twice / 2|major|), and (twice - |major|) / (2 |major|) is that floor exactly.
    const int lower = (xMajor ? s.y0 : s.x0) + static_cast<int>((twice - denominator) / (2 * denominator));
    char text[96];
    if (xMajor) {
      std::snprintf(text, sizeof text, " (%d,%d)|(%d,%d)", along, lower, along, lower + 1);
    } else {
      std::snprintf(text, sizeof text, " (%d,%d)|(%d,%d)", lower, along, lower + 1, along);
    }
    ties += text;
  }
  return ties;
}

int drawPicture(const LineLabPicture& picture, const std::string& path, std::ostream& err) {
  const PictureSize size = lineLabPictureSize(picture);
  GlassContext* previous = glassGetCurrentContext();
  GlassContext* context = glassCreateContext(size.width, size.height);
  if (context == nullptr || !glassMakeCurrent(context)) {
    err << "glass lines: cannot create a " << size.width << " x " << size.height << " GL context\n";
    glassDestroyContext(context);
    return 1;
  }
  drawLineLabPicture(picture);
  const bool written = glassWritePNG(context, path.c_str()) != 0;
  glassDestroyContext(context);
  glassMakeCurrent(previous);
  if (!written) {
    err << "glass lines: cannot write " << path << "\n";
    return 1;
  }
  return 0;
}

// lines_agreement_mesa, built next to this library's programs when the reference tool is on.
std::optional<std::filesystem::path> findMesaAgreementProgram() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  const std::filesystem::path dir = self.parent_path();
  for (const std::filesystem::path& candidate :
       {dir / "lines_agreement_mesa", dir / ".." / "course" / "lines_agreement_mesa"}) {
    if (std::filesystem::is_regular_file(candidate, error) && ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return std::nullopt;
}

int runAgreement(std::size_t lines, int grid, std::uint64_t seed, std::ostream& out, std::ostream& err) {
  GlassContext* previous = glassGetCurrentContext();
  GlassContext* context = glassCreateContext(grid, grid);
  if (context == nullptr || !glassMakeCurrent(context)) {
    err << "glass lines: cannot create a GL context\n";
    glassDestroyContext(context);
    return 1;
  }
  const auto results = measureGlAgreement(lines, grid, seed);
  glassDestroyContext(context);
  glassMakeCurrent(previous);
  out << "Agreement with GL_LINES: the same random segments drawn by each algorithm and by GL (one pixel\n"
         "per square, from centre to centre; GL leaves out the last square, so the algorithms' last square\n"
         "is left out of the comparison).\n";
  out << formatAgreement(results, "glass", grid);
  if (const auto mesa = findMesaAgreementProgram()) {
    const std::string command = std::string("'") + mesa->string() + "' " + std::to_string(lines) + " " + std::to_string(grid) +
                                " " + std::to_string(seed);
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (pipe) {
      std::array<char, 512> buffer;
      while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe.get()) != nullptr) out << buffer.data();
    }
  } else {
    out << "  (Mesa: lines_agreement_mesa was not built; it needs the reference tool's OSMesa, see "
           "tools/reference)\n";
  }
  return 0;
}

}  // namespace

int runLinesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentList list(args);
    std::vector<double> endpoints;
    std::vector<LineAlgorithm> algorithms(std::begin(kAllLineAlgorithms), std::end(kAllLineAlgorithms));
    std::optional<int> grid, cell;
    std::optional<std::size_t> lines;
    std::string output;
    bool symmetry = false, speed = false, agreement = false;
    int repeat = 5;
    std::uint64_t seed = 1;
    while (!list.empty()) {
      const std::string arg = list.take();
      if (arg == "-h" || arg == "--help") {
        out << linesHelp();
        return 0;
      } else if (arg == "-a" || arg == "--algorithm") {
        algorithms = parseAlgorithms(list.value(arg));
      } else if (arg == "--grid") {
        grid = static_cast<int>(parseInteger(list.value(arg), arg, 2, 4096));
      } else if (arg == "--cell") {
        cell = static_cast<int>(parseInteger(list.value(arg), arg, 2, 256));
      } else if (arg == "-o" || arg == "--output") {
        output = list.value(arg);
      } else if (arg == "--symmetry") {
        symmetry = true;
      } else if (arg == "--speed") {
        speed = true;
      } else if (arg == "--agreement") {
        agreement = true;
      } else if (arg == "--lines") {
        lines = static_cast<std::size_t>(parseInteger(list.value(arg), arg, 1, 100'000'000));
      } else if (arg == "--repeat") {
        repeat = static_cast<int>(parseInteger(list.value(arg), arg, 1, 100));
      } else if (arg == "--seed") {
        seed = static_cast<std::uint64_t>(parseInteger(list.value(arg), arg, 0, 1LL << 62));
      } else if (looksLikeNumber(arg) && endpoints.size() < 4) {
        endpoints.push_back(parseInteger(arg, "an endpoint coordinate", -1000000, 1000000));
      } else {
        throw UsageError(std::string("unexpected argument '") + arg + "' (see glass lines --help)");
      }
    }
    const int modes = (endpoints.empty() ? 0 : 1) + symmetry + speed + agreement;
    if (modes != 1) {
      throw UsageError(modes == 0 ? "give the endpoints X0 Y0 X1 Y1, or --symmetry, --speed or --agreement"
                                  : "give one of: endpoints, --symmetry, --speed, --agreement");
    }

    if (speed) {
      const SpeedReport report = measureLineSpeed(lines.value_or(200'000), grid.value_or(1024), seed, repeat);
      out << formatSpeedReport(report);
      return 0;
    }
    if (agreement) return runAgreement(lines.value_or(10'000), grid.value_or(32), seed, out, err);
    if (symmetry) {
      const int n = grid.value_or(32);
      if (n > 128) throw UsageError("--symmetry checks every segment: use --grid 128 or less");
      std::uint64_t failures = 0;
      for (LineAlgorithm algorithm : algorithms) {
        const SymmetryReport report = checkSymmetry(algorithm, n);
        out << formatSymmetryReport(report);
        failures += report.failureCount;
      }
      out << (failures == 0 ? "Swapping the endpoints never changes the squares.\n"
                            : "Some segments change when their endpoints are swapped.\n");
      return failures == 0 ? 0 : 1;
    }

    if (endpoints.size() != 4) throw UsageError("the segment needs four numbers: X0 Y0 X1 Y1");
    LineLabPicture picture;
    picture.gridSize = grid.value_or(32);
    if (picture.gridSize > 512) throw UsageError("--grid must be 512 or less for a picture");
    picture.cellPixels = cell.value_or(std::max(3, 512 / picture.gridSize));
    picture.segment = {static_cast<int>(endpoints[0]), static_cast<int>(endpoints[1]), static_cast<int>(endpoints[2]),
                       static_cast<int>(endpoints[3])};
    picture.algorithms = algorithms;
    const GridSegment& s = picture.segment;
    for (int v : {s.x0, s.y0, s.x1, s.y1}) {
      if (v < 0 || v >= picture.gridSize) {
        throw UsageError(std::string("the endpoints must lie in the grid, 0..") + std::to_string(picture.gridSize - 1));
      }
    }
    if (s.x0 == s.x1 && s.y0 == s.y1) throw UsageError("the two endpoints are the same square");

    out << "Segment (" << s.x0 << "," << s.y0 << ") - (" << s.x1 << "," << s.y1 << ") on a " << picture.gridSize
        << " x " << picture.gridSize << " grid\n";
    for (LineAlgorithm algorithm : algorithms) {
      const auto squares = lineSquares(algorithm, s);
      out << "  " << lineAlgorithmName(algorithm) << std::string(11 - lineAlgorithmName(algorithm).size(), ' ')
          << squares.size() << " squares:";
      for (const auto& q : squares) out << " (" << q.x << "," << q.y << ")";
      if (algorithm == LineAlgorithm::DiamondExit) out << "  (the last square is left out by GL's rule)";
      out << "\n";
    }
    const std::string ties = describeTies(s);
    out << (ties.empty() ? "  No ties: at every step one square is nearest the line.\n"
                         : std::string("  Ties, where the line passes halfway between two squares (Figure 2.2):") + ties + "\n");
    if (!output.empty()) {
      const int status = drawPicture(picture, output, err);
      if (status != 0) return status;
      const PictureSize size = lineLabPictureSize(picture);
      out << "Wrote " << output << " (" << size.width << " x " << size.height << ", panels left to right:";
      for (LineAlgorithm algorithm : algorithms) out << " " << lineAlgorithmName(algorithm);
      out << ")\n";
    }
    return 0;
  } catch (const UsageError& e) {
    err << "glass lines: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace glass::course
