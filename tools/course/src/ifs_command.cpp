// glass ifs: homework 2 of the study guide as a command.
#include <glass/context.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "box_counting_table.h"
#include "command_arguments.h"
#include "glass/course/commands.h"
#include "glass/course/exact_number.h"
#include "glass/course/ifs_picture.h"
#include "glass/geometry/ifs_dimension.h"
#include "glass/geometry/ifs_format.h"

namespace glass::course {

namespace g = glass::geometry;

std::string ifsHelp() {
  return R"(usage: glass ifs FILE [-o OUT.png] [--depth N | --points N] [--seed S] [--size WxH] [--dimension]

The study guide's homework 2 (section 2.2): the fractal of an iterated function system, drawn
  --depth N    deterministically: the base figure through each of the r^N compositions of the r
               maps, by recursion on GL's matrix stack (the guide's Listings 4 and 5); the default,
               with a depth that shows the detail the picture can hold
  --points N   by the chaos game (the guide's "probability approach"): N points, each the image
               of the previous one under a map drawn at random with its probability
each map's part of the fractal in its own colour, in the file's window widened to the picture's
shape as Listing 5's resizeWindow does (the fractal is never stretched).

  --dimension  the fractal dimension: when every map is a similarity, the root of the Moran
               equation r1^d + ... + rk^d = 1 (the guide's equation 4); otherwise the maps that are
               not similarities are named and a box-counting estimate from chaos-game points
               (the rendered ones with --points) is given instead
  --size WxH   picture size (default 800x800)
  --seed S     the chaos game's seed (default 1); the same seed gives the same picture

The file format (see scenes/ifs/*.ifs): one `map` per line as translate, rotate, scale, shear or
matrix a11 a12 a13 a21 a22 a23, optional color r g b and probability p; optional name, window and
base (square, triangle, polygon).

Examples:
  glass ifs scenes/ifs/sierpinski.ifs --depth 7 -o sierpinski.png --dimension
  glass ifs scenes/ifs/test_question_3.ifs --dimension
  glass ifs scenes/ifs/fern.ifs --points 2000000 --size 600x800 -o fern.png --dimension
)";
}

namespace {

// The matrix rows, in the guide's exact forms when every entry has one, else as decimals.
std::string mapDescription(const g::IfsMap& map) {
  const auto& m = map.transform.m;
  bool exact = true;
  for (const auto& row : m)
    for (double v : row) exact = exact && !exactForm(v).empty();
  auto number = [exact](double v) { return exact ? compact(v) : decimal(v); };
  return std::string("[") + number(m[0][0]) + " " + number(m[0][1]) + " " + number(m[0][2]) + "; " +
         number(m[1][0]) + " " + number(m[1][1]) + " " + number(m[1][2]) + "]";
}

void printDimension(const g::IteratedFunctionSystem& ifs, const g::IfsDimensionReport& report,
                    std::uint64_t points, std::ostream& out) {
  out << "Dimension:\n";
  for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
    out << "  map " << i + 1 << " " << mapDescription(ifs.maps[i]) << ": ";
    if (report.ratios[i]) {
      out << "a similarity with ratio " << describe(*report.ratios[i]) << "\n";
    } else {
      out << "not a similarity (it stretches some directions more than others)\n";
    }
  }
  if (report.moranDimension) {
    out << "  Every map is a similarity: the Moran equation (equation 4)\n    ";
    for (std::size_t i = 0; i < report.ratios.size(); ++i) {
      out << (i ? " + " : "") << "(" << compact(*report.ratios[i]) << ")^d";
    }
    char text[64];
    std::snprintf(text, sizeof text, "%.10f", *report.moranDimension);
    out << " = 1\n  has the root d = " << text << " (by bisection; the similarity dimension)\n";
    return;
  }
  if (report.boxCounting) {
    const g::BoxCountingEstimate& box = *report.boxCounting;
    out << "  Not every map is a similarity, so the Moran equation does not apply. Box counting on " << points
        << " chaos-game points:\n";
    printBoxCountingTable(box, out);
    return;
  }
  out << "  No dimension: " << report.problem << "\n";
}

}  // namespace

int runIfsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentList list(args);
    std::string file, output;
    std::optional<int> depth;
    std::optional<std::uint64_t> points;
    std::uint64_t seed = 1;
    int width = 800, height = 800;
    bool dimension = false;
    while (!list.empty()) {
      const std::string arg = list.take();
      if (arg == "-h" || arg == "--help") {
        out << ifsHelp();
        return 0;
      } else if (arg == "-o" || arg == "--output") {
        output = list.value(arg);
      } else if (arg == "--depth") {
        depth = static_cast<int>(parseInteger(list.value(arg), arg, 0, 30));
      } else if (arg == "--points") {
        points = static_cast<std::uint64_t>(
            parseInteger(list.value(arg), arg, 1, static_cast<long long>(g::kMaxChaosGamePoints)));
      } else if (arg == "--seed") {
        seed = static_cast<std::uint64_t>(parseInteger(list.value(arg), arg, 0, 1LL << 62));
      } else if (arg == "--size") {
        parseSize(list.value(arg), width, height);
      } else if (arg == "--dimension") {
        dimension = true;
      } else if (!arg.empty() && arg[0] == '-') {
        throw UsageError(std::string("unknown option '") + arg + "' (see glass ifs --help)");
      } else if (file.empty()) {
        file = arg;
      } else {
        throw UsageError(std::string("one IFS file at a time ('") + file + "', then '" + arg + "')");
      }
    }
    if (file.empty()) throw UsageError("give an IFS file, like scenes/ifs/sierpinski.ifs");
    if (depth && points) throw UsageError("--depth draws by recursion, --points by the chaos game: choose one");
    if (output.empty() && !dimension) throw UsageError("nothing to do: give -o OUT.png and/or --dimension");

    std::ifstream in(file, std::ios::binary);
    if (!in) {
      err << "glass ifs: cannot read " << file << "\n";
      return 1;
    }
    std::ostringstream text;
    text << in.rdbuf();
    const g::IfsParseResult parsed = g::parseIfs(text.str());
    if (!parsed.ok()) {
      err << g::formatIfsErrors(parsed, file, text.str());
      return 1;
    }
    const g::IteratedFunctionSystem& ifs = parsed.ifs;
    out << (ifs.name.empty() ? file : ifs.name) << ": " << ifs.maps.size() << (ifs.maps.size() == 1 ? " map" : " maps")
        << "\n";

    if (!output.empty()) {
      IfsPicture picture;
      picture.width = width;
      picture.height = height;
      picture.seed = seed;
      if (points) {
        picture.method = IfsPicture::Method::ChaosGame;
        picture.points = *points;
      } else {
        picture.depth = depth.value_or(defaultIfsDepth(ifs, std::max(width, height)));
      }
      if (const std::string problem = checkIfsPicture(ifs, picture); !problem.empty()) {
        err << "glass ifs: " << problem << "\n";
        return 1;
      }
      GlassContext* previous = glassGetCurrentContext();
      GlassContext* context = glassCreateContext(width, height);
      if (context == nullptr || !glassMakeCurrent(context)) {
        err << "glass ifs: cannot create a " << width << " x " << height << " GL context\n";
        glassDestroyContext(context);
        return 1;
      }
      drawIfsPicture(ifs, picture);
      const bool written = glassWritePNG(context, output.c_str()) != 0;
      glassDestroyContext(context);
      glassMakeCurrent(previous);
      if (!written) {
        err << "glass ifs: cannot write " << output << "\n";
        return 1;
      }
      out << "Wrote " << output << " (" << width << " x " << height << "): ";
      if (picture.method == IfsPicture::Method::Depth) {
        out << "depth " << picture.depth << ", " << g::ifsBaseCopies(ifs, picture.depth)
            << " copies of the base figure through the matrix stack\n";
      } else {
        out << picture.points << " chaos-game points, seed " << seed << "; probabilities";
        const std::vector<double> probabilities = *g::chaosGameProbabilities(ifs);
        for (double p : probabilities) out << " " << decimal(p);
        out << "\n";
      }
    }
    if (dimension) {
      const std::uint64_t cloud = points.value_or(2'000'000);
      printDimension(ifs, g::ifsDimension(ifs, cloud, seed), cloud, out);
    }
    return 0;
  } catch (const UsageError& e) {
    err << "glass ifs: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace glass::course
