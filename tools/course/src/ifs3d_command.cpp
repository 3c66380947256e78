// glass ifs3d: homework 3 of the study guide (a 3D fractal from a cloud of points) as a command.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <glass/scene/render.h>

#include "box_counting_table.h"
#include "command_arguments.h"
#include "glass/course/commands.h"
#include "glass/course/ifs3d_file.h"
#include "glass/course/ifs3d_fit.h"
#include "glass/course/ifs3d_view.h"
#include "glass/course/point_cloud.h"
#include "glass/geometry/ifs3d_format.h"
#include "glass/geometry/polar_decomposition.h"
#include "glass/geometry/rotation.h"

namespace glass::course {

namespace g = glass::geometry;

std::string ifs3dHelp() {
  return R"(usage: glass ifs3d COMMAND ...

The study guide's homework 3: a 3D affine fractal given as a cloud of points.
  glass ifs3d points FILE.ifs3 -n N -o CLOUD.txt [--seed S]
      N points of the attractor by the chaos game (seeded: the same seed gives the same file),
      one "x y z" a line: homework clouds, and inputs with known answers.
  glass ifs3d fit CLOUD.txt [-o FOUND.ifs3] [--maps K] [--seed S] [--attempts N] [--work M]
      the K (default 4) affine maps whose attractor the cloud samples, by the collage theorem:
      prints each 3 x 4 matrix and its decomposition T R S, the collage distance, the Chamfer
      distance between the cloud and a cloud regenerated from the maps, and the dimension.
      It makes N whole attempts at most (default 4) while the maps have not converged, and stops
      after M million nearest-neighbour queries (0: no limit); a fit that did not converge says
      so, with the attempts and work spent and how far its best maps are from converging.
  glass ifs3d show FILE.ifs3
      the maps, their decompositions T R S and the fractal dimension (Moran's equation when every
      map is a similarity, else box counting of a million chaos-game points).
  glass ifs3d render FILE.ifs3 -o OUT.png [--depth N] [--view AZIMUTH,ELEVATION] [--size WxH]
      the polyhedral rebuild: the base polyhedron through all K^N compositions of depth N
      (default 3), one light, flat shading, each map's part in its colour.
  glass ifs3d animate FILE.ifs3 --map K --frames N -o frame_%03d.png [--depth N] [--view A,E]
      map K as a motion of the rebuild from itself to its image: scaling first, then rotation by
      quaternion slerp, then translation; prints the matrix of every frame.
  glass ifs3d view [FILE.ifs3] [CLOUD.txt] [--show cloud|attractor|both] [--depth N] ...
      the cloud and the rebuild in a window, turned with the mouse (glass ifs3d view --help).

Clouds: one point a line as x y z (spaces, tabs or commas), # comments, an optional first line
with the number of points. The .ifs3 format (see scenes/ifs/*.ifs3): one `map` a line, as
translate x y z, rotate DEGREES ax ay az, rotate quaternion w x y z, scale s | sx sy sz, or matrix
a11 a12 a13 t1 a21 a22 a23 t2 a31 a32 a33 t3; then optionally color r g b and probability p;
optional name "..." and base cube|tetrahedron|hull|"model.obj" (an OBJ file, relative to the
.ifs3 file).

Examples:
  glass ifs3d points scenes/ifs/homework3.ifs3 -n 50000 -o cloud.txt
  glass ifs3d fit cloud.txt -o found.ifs3
  glass ifs3d render found.ifs3 --depth 3 --view 35,25 -o rebuilt.png
  glass ifs3d animate found.ifs3 --map 2 --frames 24 -o frame_%03d.png
  glass ifs3d view cloud.txt found.ifs3 --show both
)";
}

namespace {

struct Loaded {
  g::IteratedFunctionSystem3 ifs;
  std::string path;
};

std::optional<Loaded> loadIfs3(const std::string& file, std::ostream& err) {
  std::optional<g::IteratedFunctionSystem3> ifs = loadIfs3File(file, err);
  if (!ifs) return std::nullopt;
  return Loaded{std::move(*ifs), file};
}

std::string format(const char* pattern, double a) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, a);
  return text;
}

std::string number(double v) { return format("%.6f", std::abs(v) < 5e-7 ? 0.0 : v); }

void printMatrix(const g::Affine3& a, const std::string& indent, std::ostream& out) {
  for (int r = 0; r < 3; ++r) {
    out << indent << "[";
    for (int c = 0; c < 4; ++c) out << (c == 3 ? " | " : (c ? " " : "")) << format("%10.6f", std::abs(a.m[r][c]) < 5e-7 ? 0.0 : a.m[r][c]);
    out << " ]\n";
  }
}

std::string vector3(const glm::dvec3& v) {
  // Appended piece by piece: GCC 12 misreports operator+ chains on strings (-Wrestrict).
  std::string out = "(";
  out += number(v.x);
  out += ", ";
  out += number(v.y);
  out += ", ";
  out += number(v.z);
  out += ")";
  return out;
}

void printDecomposition(const g::Affine3& map, std::ostream& out) {
  const g::TrsDecomposition d = g::decomposeTrs(map);
  const g::AxisAngle rotation = g::axisAngleFromMatrix(d.rotationMatrix);
  out << "    = T R S with\n";
  out << "      T: translate " << vector3(d.translation) << "\n";
  out << "      R: rotate " << format("%.4f", rotation.angle * 180.0 / std::numbers::pi) << " degrees about "
      << vector3(rotation.axis) << ", quaternion (" << number(d.rotation.w) << ", " << number(d.rotation.x) << ", "
      << number(d.rotation.y) << ", " << number(d.rotation.z) << ")\n";
  if (d.similarity) {
    out << "      S: scale " << number(std::abs(d.scales.x)) << " in every direction";
    if (d.reflection) out << ", with a reflection along " << vector3(d.stretchAxes[2]) << " (scale " << number(d.scales.z) << " there)";
    out << " (a similarity)\n";
  } else {
    out << "      S: scale " << number(d.scales.x) << " along " << vector3(d.stretchAxes[0]) << ", " << number(d.scales.y)
        << " along " << vector3(d.stretchAxes[1]) << ", " << number(d.scales.z) << " along " << vector3(d.stretchAxes[2])
        << (d.reflection ? " (negative: a reflection)" : "") << "\n";
  }
  out << "      T R S recomposes to the matrix within " << format("%.1e", g::Affine3::maxDifference(d.product(), map)) << "\n";
}

void printMaps(const std::vector<g::Affine3>& maps, std::ostream& out) {
  for (std::size_t i = 0; i < maps.size(); ++i) {
    out << "  map " << i + 1 << ": [ L | t ]\n";
    printMatrix(maps[i], "    ", out);
    printDecomposition(maps[i], out);
  }
}

void printDimension(const g::IteratedFunctionSystem3& ifs, std::ostream& out) {
  constexpr std::uint64_t kPoints = 1'000'000;
  const g::IfsDimensionReport report = g::ifsDimension3(ifs, kPoints, 1);
  out << "Dimension:\n";
  if (report.moranDimension) {
    out << "  Every map is a similarity: Moran's equation\n    ";
    for (std::size_t i = 0; i < report.ratios.size(); ++i) out << (i ? " + " : "") << format("%.6g", *report.ratios[i]) << "^d";
    out << " = 1\n  has the root d = " << format("%.10f", *report.moranDimension) << "\n";
  } else if (report.boxCounting) {
    out << "  Not every map is a similarity, so Moran's equation does not apply. Box counting on " << kPoints
        << " chaos-game points:\n";
    printBoxCountingTable(*report.boxCounting, out);
  } else {
    out << "  No dimension: " << report.problem << "\n";
  }
}

// Writes text to path whole or not at all (a temporary file renamed over it).
bool writeWhole(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary);
    if (!file || !(file << text) || !(file.flush())) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      return false;
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) std::filesystem::remove(temporary, error);
  return !error;
}

std::string absolutePath(const std::string& file) {
  std::error_code error;
  const std::filesystem::path path = std::filesystem::absolute(file, error);
  return error ? file : path.lexically_normal().string();
}

void parseView(const std::string& text, Ifs3View& view) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos) throw UsageError("--view takes AZIMUTH,ELEVATION in degrees, like 35,25");
  view.azimuth = parseNumber(text.substr(0, comma), "--view azimuth");
  view.elevation = parseNumber(text.substr(comma + 1), "--view elevation");
  if (!(std::abs(view.elevation) < 90.0)) throw UsageError("--view: the elevation must lie strictly between -90 and 90");
}

// A frame file name pattern must hold exactly one %d (with optional 0 flag and width).
std::string frameName(const std::string& pattern, int frame) {
  char text[4096];
  std::snprintf(text, sizeof text, pattern.c_str(), frame);
  return text;
}
bool validFramePattern(const std::string& pattern) {
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
    if (j >= pattern.size() || pattern[j] != 'd' || j - i > 4) return false;
    ++conversions;
    i = j;
  }
  return conversions == 1 && pattern.size() < 4000;
}

int runPoints(ArgumentList& list, std::ostream& out, std::ostream& err) {
  std::string file, output;
  std::optional<std::uint64_t> count;
  std::uint64_t seed = 1;
  while (!list.empty()) {
    const std::string arg = list.take();
    if (arg == "-n") {
      count = static_cast<std::uint64_t>(parseInteger(list.value(arg), arg, 1, 50'000'000));
    } else if (arg == "-o" || arg == "--output") {
      output = list.value(arg);
    } else if (arg == "--seed") {
      seed = static_cast<std::uint64_t>(parseInteger(list.value(arg), arg, 0, 1LL << 62));
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "' for points (see glass ifs3d --help)");
    } else if (file.empty()) {
      file = arg;
    } else {
      throw UsageError("one IFS file at a time");
    }
  }
  if (file.empty() || !count || output.empty()) throw UsageError("points needs FILE.ifs3, -n N and -o CLOUD.txt");
  const std::optional<Loaded> loaded = loadIfs3(file, err);
  if (!loaded) return 1;
  const auto probabilities = g::chaosGameProbabilities3(loaded->ifs);
  if (!probabilities) {
    err << "glass ifs3d: the maps' probabilities are not usable\n";
    return 1;
  }
  std::vector<glm::dvec3> points;
  points.reserve(*count);
  for (const g::IfsPoint3& p : g::chaosGamePoints3(loaded->ifs, *probabilities, *count, seed)) points.push_back(p.position);
  const std::string header = std::to_string(*count) + " chaos-game points (seed " + std::to_string(seed) + ") of " +
                             (loaded->ifs.name.empty() ? std::filesystem::path(file).filename().string() : loaded->ifs.name);
  if (!writeWhole(output, formatPointCloud(points, header))) {
    err << "glass ifs3d: cannot write " << output << "\n";
    return 1;
  }
  out << "Wrote " << output << ": " << header << "\n";
  return 0;
}

int runFit(ArgumentList& list, std::ostream& out, std::ostream& err) {
  std::string file, output;
  Ifs3FitOptions options;
  while (!list.empty()) {
    const std::string arg = list.take();
    if (arg == "-o" || arg == "--output") {
      output = list.value(arg);
    } else if (arg == "--maps") {
      options.maps = static_cast<int>(parseInteger(list.value(arg), arg, 1, 16));
    } else if (arg == "--seed") {
      options.seed = static_cast<std::uint64_t>(parseInteger(list.value(arg), arg, 0, 1LL << 62));
    } else if (arg == "--attempts") {
      options.attempts = static_cast<int>(parseInteger(list.value(arg), arg, 1, 64));
    } else if (arg == "--work") {
      options.workBudget = static_cast<std::uint64_t>(parseInteger(list.value(arg), arg, 0, 1000000)) * 1000000u;
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "' for fit (see glass ifs3d --help)");
    } else if (file.empty()) {
      file = arg;
    } else {
      throw UsageError("one cloud at a time");
    }
  }
  if (file.empty()) throw UsageError("fit needs a cloud file CLOUD.txt");
  const PointCloud cloud = loadPointCloud(file);
  err << formatCloudMessages(cloud, file);
  if (!cloud.ok()) return 1;
  if (cloud.points.size() < static_cast<std::size_t>(20 * options.maps)) {
    err << "glass ifs3d: " << cloud.points.size() << " points are too few to fit " << options.maps << " maps\n";
    return 1;
  }
  out << file << ": " << cloud.points.size() << " points\n";
  const Ifs3Fit fit = fitIfs3(cloud.points, options);
  out << "The " << fit.maps.size() << " maps found (x' = L x + t), ordered by where they send the cloud's centre:\n";
  printMaps(fit.maps, out);
  g::IteratedFunctionSystem3 found;
  found.name = "fitted to " + std::filesystem::path(file).filename().string();
  for (std::size_t i = 0; i < fit.maps.size(); ++i) found.maps.push_back({fit.maps[i], fit.shares[i], std::nullopt});
  if (fit.isolatedShare > 0.0) {
    out << "Isolated points left out as noise before the fit: "
        << std::llround(fit.isolatedShare * static_cast<double>(cloud.points.size())) << " (" << format("%.2f", 100.0 * fit.isolatedShare)
        << "% of the cloud)\n";
  }
  out << "Collage distance (Chamfer distance between the cloud and the union of its images): "
      << format("%.6f", fit.collageDistance) << "\n";
  if (!fit.converged()) {
    out << "Warning: the collage distance is not well below the cloud's point spacing (" << format("%.6f", fit.pointSpacing)
        << "): the search may have stopped in a local minimum, and some maps may be wrong. Try other seeds (--seed).\n";
    // What the search spent and how far its best maps are from converging, in the cloud's own
    // spacing: the user can tell a near miss (another seed may do) from a cloud no system of
    // this many maps makes, and bound the next run with --attempts or --work.
    const double spacing = fit.pointSpacing > 0.0 ? fit.pointSpacing : 1.0;
    out << "Not converged after " << fit.attempts << (fit.attempts == 1 ? " attempt" : " attempts") << " ("
        << format("%.1f", static_cast<double>(fit.work) / 1e6) << " million nearest-neighbour queries): best collage distance "
        << format("%.6f", fit.trimmedCollageDistance) << " (" << format("%.2f", fit.trimmedCollageDistance / spacing)
        << " point spacings, converged below " << format("%.2f", Ifs3Fit::kCollageBound) << "), its attractor "
        << format("%.6f", fit.regeneratedDistance) << " from the cloud (" << format("%.2f", fit.regeneratedDistance / spacing)
        << " spacings, below " << format("%.2f", Ifs3Fit::kRegeneratedBound) << "). --attempts N or --work M bound the search.\n";
    if (fit.stoppedByBudget) {
      out << "The search stopped at its work budget (" << format("%.1f", static_cast<double>(fit.work) / 1e6)
          << " million nearest-neighbour queries, " << fit.attempts << " attempts); --work M lets it search longer.\n";
    }
  }
  out << "Shares of the cloud (written as the maps' probabilities):";
  for (double share : fit.shares) out << " " << format("%.4f", share);
  out << "\n";
  std::vector<glm::dvec3> regenerated;
  if (auto probabilities = g::chaosGameProbabilities3(found)) {
    for (const g::IfsPoint3& p : g::chaosGamePoints3(found, *probabilities, cloud.points.size(), options.seed))
      regenerated.push_back(p.position);
    out << "Chamfer distance between the cloud and " << regenerated.size()
        << " points regenerated from the maps by the chaos game: " << format("%.6f", chamferDistance(cloud.points, regenerated))
        << "\n";
  }
  out << "Dimension:\n";
  if (auto box = g::boxCountingDimension3(cloud.points)) {
    out << "  Box counting of the cloud:\n";
    printBoxCountingTable(*box, out);
  } else {
    out << "  Too few points for box counting\n";
  }
  bool similar = true;
  std::vector<double> ratios;
  for (const g::Affine3& map : fit.maps) {
    const g::TrsDecomposition d = g::decomposeTrs(map);
    similar = similar && std::abs(d.scales.z) >= 0.98 * d.scales.x;
    ratios.push_back(std::cbrt(std::abs(d.scales.x * d.scales.y * d.scales.z)));
  }
  if (similar) {
    if (auto moran = g::solveMoranEquation(ratios)) {
      out << "  Every map is a similarity within 2% (fitted maps are never exact ones): Moran's equation with the ratios";
      for (double r : ratios) out << " " << format("%.4f", r);
      out << " gives d = " << format("%.4f", *moran) << "\n";
    }
  }
  if (!output.empty()) {
    if (!writeWhole(output, "# " + found.name + ", collage distance " + format("%.6f", fit.collageDistance) + "\n" + g::formatIfs3(found))) {
      err << "glass ifs3d: cannot write " << output << "\n";
      return 1;
    }
    out << "Wrote " << output << "\n";
  }
  return 0;
}

int runShow(ArgumentList& list, std::ostream& out, std::ostream& err) {
  if (list.empty()) throw UsageError("show needs FILE.ifs3");
  const std::string file = list.take();
  if (!list.empty()) throw UsageError("show takes one file");
  const std::optional<Loaded> loaded = loadIfs3(file, err);
  if (!loaded) return 1;
  out << (loaded->ifs.name.empty() ? file : loaded->ifs.name) << ": " << loaded->ifs.maps.size() << " maps\n";
  std::vector<g::Affine3> maps;
  for (const g::IfsMap3& map : loaded->ifs.maps) maps.push_back(map.transform);
  printMaps(maps, out);
  printDimension(loaded->ifs, out);
  return 0;
}

// The options render and animate share.
struct PictureArguments {
  std::string file, output;
  Ifs3View view;
  std::optional<int> map, frames;
};

PictureArguments readPictureArguments(ArgumentList& list, bool animate) {
  PictureArguments a;
  while (!list.empty()) {
    const std::string arg = list.take();
    if (arg == "-o" || arg == "--output") {
      a.output = list.value(arg);
    } else if (arg == "--depth") {
      a.view.depth = static_cast<int>(parseInteger(list.value(arg), arg, 0, 12));
    } else if (arg == "--view") {
      parseView(list.value(arg), a.view);
    } else if (arg == "--size") {
      parseSize(list.value(arg), a.view.width, a.view.height);
    } else if (animate && arg == "--map") {
      a.map = static_cast<int>(parseInteger(list.value(arg), arg, 1, 64));
    } else if (animate && arg == "--frames") {
      a.frames = static_cast<int>(parseInteger(list.value(arg), arg, 2, 10000));
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "' (see glass ifs3d --help)");
    } else if (a.file.empty()) {
      a.file = arg;
    } else {
      throw UsageError("one IFS file at a time");
    }
  }
  if (a.file.empty() || a.output.empty()) throw UsageError("give FILE.ifs3 and -o OUT.png");
  if (a.file.find('"') != std::string::npos) throw UsageError("the file name cannot contain '\"'");
  if (!scene::isSupportedImagePath(animate ? frameName(a.output, 0) : a.output))
    throw UsageError("the output must end in .png, .jpg, .bmp or .tga");
  return a;
}

// The rebuild's size, checked before any drawing.
bool checkTriangles(const g::IteratedFunctionSystem3& ifs, int depth, std::ostream& err) {
  const std::uint64_t base = g::basePolyhedron(ifs).size();
  if (g::ifs3BaseCopies(ifs, depth) > g::kMaxRebuildTriangles / std::max<std::uint64_t>(base, 1)) {
    err << "glass ifs3d: depth " << depth << " would draw " << base << " x " << ifs.maps.size() << "^" << depth
        << " triangles, more than the limit of " << g::kMaxRebuildTriangles << "; lower the depth\n";
    return false;
  }
  return true;
}

int runRender(ArgumentList& list, std::ostream& out, std::ostream& err) {
  PictureArguments a = readPictureArguments(list, false);
  const std::optional<Loaded> loaded = loadIfs3(a.file, err);
  if (!loaded || !checkTriangles(loaded->ifs, a.view.depth, err)) return 1;
  const std::string path = absolutePath(a.file);
  const std::string text = ifs3SceneText(loaded->ifs, path, a.view);
  if (const std::string problem = renderIfs3Picture(text, path + ".scene", a.output); !problem.empty()) {
    err << "glass ifs3d: " << problem << (problem.back() == '\n' ? "" : "\n");
    return 1;
  }
  out << "Wrote " << a.output << " (" << a.view.width << " x " << a.view.height << "): depth " << a.view.depth << ", "
      << g::ifs3BaseCopies(loaded->ifs, a.view.depth) << " copies of the base polyhedron\n";
  return 0;
}

int runAnimate(ArgumentList& list, std::ostream& out, std::ostream& err) {
  PictureArguments a = readPictureArguments(list, true);
  if (!a.map || !a.frames) throw UsageError("animate needs --map K and --frames N");
  if (!validFramePattern(a.output)) throw UsageError("-o needs one %d (like frame_%03d.png) for the frame number");
  const std::optional<Loaded> loaded = loadIfs3(a.file, err);
  if (!loaded || !checkTriangles(loaded->ifs, a.view.depth, err)) return 1;
  if (*a.map > static_cast<int>(loaded->ifs.maps.size())) {
    err << "glass ifs3d: the file has " << loaded->ifs.maps.size() << " maps; there is no map " << *a.map << "\n";
    return 1;
  }
  const g::Affine3& map = loaded->ifs.maps[static_cast<std::size_t>(*a.map - 1)].transform;
  out << "Map " << *a.map << ":\n";
  printMatrix(map, "    ", out);
  printDecomposition(map, out);
  out << "Frames: scaling in the first third, rotation (slerp) in the second, translation in the last.\n";
  const std::string path = absolutePath(a.file);
  a.view.animatedMap = *a.map - 1;
  for (int frame = 0; frame < *a.frames; ++frame) {
    a.view.step = static_cast<double>(frame) / (*a.frames - 1);
    const std::string name = frameName(a.output, frame);
    const std::string problem = renderIfs3Picture(ifs3SceneText(loaded->ifs, path, a.view), path + ".scene", name);
    if (!problem.empty()) {
      err << "glass ifs3d: " << problem << (problem.back() == '\n' ? "" : "\n");
      return 1;
    }
    out << "  frame " << frame << " (t = " << format("%.4f", a.view.step) << ") " << name << ":\n";
    printMatrix(g::decomposeTrs(map).at(a.view.step), "    ", out);
  }
  return 0;
}

}  // namespace

int runIfs3dCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentList list(args);
    if (list.empty()) throw UsageError("give a command: points, fit, show, render, animate or view (see glass ifs3d --help)");
    const std::string command = list.take();
    if (command == "-h" || command == "--help") {
      out << ifs3dHelp();
      return 0;
    }
    if (command == "points") return runPoints(list, out, err);
    if (command == "fit") return runFit(list, out, err);
    if (command == "show") return runShow(list, out, err);
    if (command == "render") return runRender(list, out, err);
    if (command == "animate") return runAnimate(list, out, err);
    throw UsageError("unknown command '" + command + "' (points, fit, show, render, animate, view)");
  } catch (const UsageError& e) {
    err << "glass ifs3d: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace glass::course
