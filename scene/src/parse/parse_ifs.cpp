// `ifs ... end`: an iterated function system (study guide, section 2.2.2), its maps, and the base
// shape drawn at depth 0. The maps read as in the IFS file format of `glass ifs`
// (glass/geometry/ifs_format.h), and `ifs file "x.ifs"` reads such a file.
#include "gl_api.h"
#include "parser_impl.h"

#include <glass/geometry/ifs.h>
#include <glass/geometry/ifs_format.h>

#include <cmath>
#include "glass/geometry/portable_math.h"

namespace glass::scene {

namespace {

// The recursion pushes one modelview matrix per level, and GL promises a modelview stack of 32.
constexpr int kMaxDepth = 24;

const EnumName kIfsModes[] = {{"recursive", 0}, {"chaos", 1}};

// The maps and base polygon of an IFS file, as if written inline.
void appendFileMaps(const geometry::IteratedFunctionSystem &system, Ifs &ifs, SourceLocation where) {
  for (const geometry::IfsMap &source : system.maps) {
    IfsMap map;
    map.where = where;
    AffineStep step;
    step.kind = AffineStep::Kind::Matrix;
    for (const auto &row : source.transform.m) {
      for (double v : row) step.values.push_back(Number::of(v));
    }
    map.steps.push_back(std::move(step));
    if (source.color) {
      map.color = {Number::of(source.color->r), Number::of(source.color->g), Number::of(source.color->b),
                   Number::of(1.0)};
    }
    if (source.probability) map.probability = Number::of(*source.probability);
    ifs.maps.push_back(std::move(map));
  }
}

Statement basePolygon(const std::vector<glm::dvec2> &corners, SourceLocation where) {
  Statement begin;
  begin.where = where;
  Begin polygon{corners.size() == 3 ? GLenumValue(GL_TRIANGLES) : GLenumValue(GL_POLYGON), {}};
  for (const glm::dvec2 &corner : corners) {
    Statement vertex;
    vertex.where = where;
    vertex.body = Vertex{{Number::of(corner.x), Number::of(corner.y), Number::of(0.0)}};
    polygon.body.push_back(std::move(vertex));
  }
  begin.body = std::move(polygon);
  return begin;
}

} // namespace

void Parser::parseIfs(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"mode", ParamKind::Word, 1, 1, kIfsModes, ""},
      {"depth", ParamKind::Integer, 0, kMaxDepth, {}, ""},
      {"points", ParamKind::Integer, 1, static_cast<long long>(geometry::kMaxChaosGamePoints), {}, ""},
      {"seed", ParamKind::Integer, 0, 2147483647, {}, ""},
      {"colors", ParamKind::Boolean, 1, 1, {}, ""},
      {"file", ParamKind::String, 1, 1, {}, ""},
  };
  OpenBlock block;
  block.kind = BlockKind::Ifs;
  block.statement.where = r.statementToken().where;
  block.statement.length = r.statementToken().length;
  block.where = r.statementToken().where;
  block.length = r.statementToken().length;
  block.pushDepth = pushes_.size();
  Ifs ifs;
  // A mistake on the `ifs` line still opens the block, so that its maps and `end` find it.
  try {
    NamedParams params = NamedParams::read(r, specs);
    ifs.mode = params.wordOr("mode", 0) == 0 ? Ifs::Mode::Recursive : Ifs::Mode::Chaos;
    ifs.partColors = params.booleanOr("colors", true);
    if (ifs.mode == Ifs::Mode::Recursive) {
      ifs.depth = static_cast<int>(params.integerOr("depth", 6));
    } else {
      ifs.points = params.integerOr("points", 100000);
      ifs.seed = static_cast<std::uint64_t>(params.integerOr("seed", 1));
    }
    const ParamValue *file = params.take("file");
    params.requireAllUsed(r, ifs.mode == Ifs::Mode::Recursive
                                 ? "in mode recursive (points and seed belong to mode chaos)"
                                 : "in mode chaos (depth belongs to mode recursive)");
    if (file != nullptr) {
      std::string path = resolvePath(file->string, file->where);
      geometry::IfsParseResult loaded = geometry::loadIfsFile(path);
      if (!loaded.ok()) {
        const geometry::IfsParseError &first = loaded.errors.front();
        r.fail(file->where, file->length,
               "cannot use IFS file '" + path + "': " +
                   (first.line > 0 ? "line " + std::to_string(first.line) + ":" + std::to_string(first.column) + ": " : "") +
                   first.message);
      }
      appendFileMaps(loaded.ifs, ifs, file->where);
      // The file's step-0 figure, unless the block draws its own.
      block.body.push_back(basePolygon(loaded.ifs.base, file->where));
      block.fileBase = true;
    }
  } catch (const StatementError &) {
    block.broken = true;
    block.statement.body = std::move(ifs);
    blocks_.push_back(std::move(block));
    throw;
  }
  block.statement.body = std::move(ifs);
  blocks_.push_back(std::move(block));
}

void Parser::parseMap(StatementReader &r) {
  IfsMap map;
  map.where = r.statementToken().where;
  SourceLocation colorWhere, probabilityWhere;
  OpenBlock &block = blocks_.back();
  if (block.fileBase) {
    r.fail(r.statementToken(), "this 'ifs' reads its maps from a file; 'map' cannot add to them");
  }
  while (!r.atEnd()) {
    const Token &word = r.peek();
    if (word.kind != TokenKind::Word) {
      r.fail(word, "'map' expects translate, rotate, scale, shear, matrix, color or probability, found " +
                       describeToken(word));
    }
    r.take();
    AffineStep step;
    if (word.text == "translate") {
      step.kind = AffineStep::Kind::Translate;
      step.values = r.numbers("x y", 2, 2);
    } else if (word.text == "rotate") {
      step.kind = AffineStep::Kind::Rotate;
      step.values = {r.number("angle in degrees, counter-clockwise")};
    } else if (word.text == "scale") {
      step.kind = AffineStep::Kind::Scale;
      step.values = r.numbers("sx [sy]", 1, 2);
      if (step.values.size() == 1) step.values.push_back(step.values[0]);
    } else if (word.text == "shear") {
      step.kind = AffineStep::Kind::Shear;
      step.values = {r.number("h, as in x' = x + h y")};
    } else if (word.text == "matrix") {
      step.kind = AffineStep::Kind::Matrix;
      step.values = r.numbers("a11 a12 a13 a21 a22 a23, the 2x3 affine matrix row by row", 6, 6);
    } else if (word.text == "color") {
      if (!map.color.empty()) {
        throw StatementError{word.where, word.length, "'color' is given twice in this map", {{colorWhere, "first given here"}}};
      }
      colorWhere = word.where;
      map.color = r.numbers("r g b [a]", 3, 4);
      if (map.color.size() == 3) map.color.push_back(Number::of(1.0));
      continue;
    } else if (word.text == "probability") {
      if (map.probability) {
        throw StatementError{word.where, word.length, "'probability' is given twice in this map",
                             {{probabilityWhere, "first given here"}}};
      }
      probabilityWhere = word.where;
      const Token &at = r.peek();
      map.probability = r.number("probability");
      if (map.probability->isConstant() && !(map.probability->constant >= 0.0)) {
        r.fail(at, "a probability must not be negative");
      }
      continue;
    } else {
      static const std::string_view known[] = {"translate", "rotate", "scale", "shear", "matrix", "color", "probability"};
      std::string hint = suggestName(word.text, known);
      r.fail(word, "unknown part '" + word.text + "' of 'map'; " +
                       (hint.empty() ? "expected translate, rotate, scale, shear, matrix, color or probability" : hint));
    }
    if (!map.color.empty() || map.probability) {
      r.fail(word, "'" + word.text + "' must come before color and probability: they end the map");
    }
    map.steps.push_back(std::move(step));
  }
  if (map.steps.empty()) {
    r.fail(r.statementToken(), "'map' needs a transformation: translate, rotate, scale, shear or matrix");
  }
  std::get<Ifs>(block.statement.body).maps.push_back(std::move(map));
}

void Parser::finishIfs(OpenBlock &block, const StatementReader &r) {
  Ifs &ifs = std::get<Ifs>(block.statement.body);
  auto fail = [&](const std::string &message) {
    throw StatementError{block.where, block.length, message, {{r.statementToken().where, "the block ends here"}}};
  };
  // A file's base polygon stands in only when the block draws nothing of its own.
  if (block.fileBase && ifs.base.size() > 1) ifs.base.erase(ifs.base.begin());
  if (ifs.maps.empty()) fail("'ifs' needs at least one 'map'");
  std::size_t withProbability = 0;
  for (const IfsMap &map : ifs.maps) withProbability += map.probability ? 1 : 0;
  if (ifs.mode == Ifs::Mode::Recursive) {
    for (const IfsMap &map : ifs.maps) {
      if (map.probability && !block.fileBase) {
        throw StatementError{map.where, 3, "probabilities are used only by 'ifs mode chaos'",
                             {{block.where, "this 'ifs' is recursive"}}};
      }
    }
    double copies = portable::pow(static_cast<double>(ifs.maps.size()), ifs.depth);
    if (copies > static_cast<double>(geometry::kMaxIfsBaseCopies)) {
      fail("'ifs' with " + std::to_string(ifs.maps.size()) + " maps at depth " + std::to_string(ifs.depth) +
           " would draw " + std::to_string(static_cast<long long>(copies)) + " copies of its base shape; the limit is " +
           std::to_string(geometry::kMaxIfsBaseCopies) + " (lower the depth)");
    }
    // Listing 4 draws the triangle (1,0), (0,1), (0,0) at step 0.
    if (ifs.base.empty()) ifs.base.push_back(basePolygon({{1.0, 0.0}, {0.0, 1.0}, {0.0, 0.0}}, block.where));
  } else {
    if (block.fileBase && ifs.base.size() == 1) ifs.base.clear();
    if (!ifs.base.empty()) {
      throw StatementError{ifs.base.front().where, ifs.base.front().length,
                           "the chaos game draws points: a base shape is used only by 'ifs mode recursive'",
                           {{block.where, "this 'ifs' is in mode chaos"}}};
    }
    if (withProbability != 0 && withProbability != ifs.maps.size()) {
      fail("give a probability to every map or to none (then each map's share follows its area, |det|)");
    }
  }
}

} // namespace glass::scene
