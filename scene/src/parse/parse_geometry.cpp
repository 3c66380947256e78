// Geometry given vertex by vertex: begin/end, rect, indexed meshes, OBJ and Wings3D models.
#include "gl_api.h"
#include "load/obj_model.h"
#include "load/wings_model.h"
#include "parser_impl.h"

#include <cctype>
#include <optional>

namespace glass::scene {

void Parser::parseBegin(StatementReader &r) {
  // A mistake on the `begin` line still opens the block, so that its `end` finds it.
  GLenumValue mode = GL_POINTS;
  std::optional<StatementError> mistake;
  try {
    mode = r.word(names::primitiveModes, "primitive type");
    r.end();
  } catch (const StatementError &error) {
    mistake = error;
  }
  OpenBlock block;
  block.broken = mistake.has_value();
  block.kind = BlockKind::Begin;
  block.statement.where = r.statementToken().where;
  block.statement.length = r.statementToken().length;
  block.statement.body = Begin{mode, {}};
  block.where = r.statementToken().where;
  block.length = r.statementToken().length;
  block.pushDepth = pushes_.size();
  blocks_.push_back(std::move(block));
  if (mistake) throw *mistake;
}

// GL silently drops vertices that do not make a whole primitive (OpenGL 1.1 section 2.6.1);
// a scene that does so almost always has a mistake, so say it, as a warning.
void Parser::checkPrimitive(const Statement &statement) {
  const Begin &begin = std::get<Begin>(statement.body);
  long vertices = 0;
  for (const Statement &s : begin.body) vertices += std::holds_alternative<Vertex>(s.body) ? 1 : 0;
  std::string mode = enumName(names::primitiveModes, begin.mode);
  warnIncompletePrimitive(begin.mode, vertices, "'begin " + mode + "' has", statement.where, statement.length);
}

// `what` says who sends the vertices: "'begin triangles' has", "'mesh triangles' sends".
void Parser::warnIncompletePrimitive(GLenumValue mode, long vertices, const std::string &what, SourceLocation where,
                                     int length) {
  auto warn = [&](const std::string &text) {
    diagnostics_.warning(where, what + " " + std::to_string(vertices) + (vertices == 1 ? " vertex: " : " vertices: ") + text,
                         length);
  };
  auto leftover = [&](long group, const char *noun) {
    long whole = vertices / group;
    long rest = vertices % group;
    if (rest != 0) {
      warn("GL draws " + std::to_string(whole) + " " + noun + (whole == 1 ? "" : "s") + " and ignores the last " +
           std::to_string(rest));
    }
  };
  if (vertices == 0) {
    warn("nothing is drawn");
    return;
  }
  switch (mode) {
  case GL_LINES: leftover(2, "line"); break;
  case GL_TRIANGLES: leftover(3, "triangle"); break;
  case GL_QUADS: leftover(4, "quad"); break;
  case GL_LINE_STRIP:
  case GL_LINE_LOOP:
    if (vertices < 2) warn("a line needs at least 2; nothing is drawn");
    break;
  case GL_TRIANGLE_STRIP:
  case GL_TRIANGLE_FAN:
  case GL_POLYGON:
    if (vertices < 3) warn("at least 3 are needed; nothing is drawn");
    break;
  case GL_QUAD_STRIP:
    if (vertices < 4) warn("at least 4 are needed; nothing is drawn");
    else if (vertices % 2 != 0) warn("GL ignores the last, unpaired vertex");
    break;
  default: break;
  }
}

void Parser::parseRect(StatementReader &r) { emit(r, Rect{r.numbers("x1 y1 x2 y2", 4, 4)}); }

void Parser::parseMesh(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"positions", ParamKind::List, 1, 1, {}, ""},
      {"position_size", ParamKind::Integer, 2, 4, {}, ""},
      {"normals", ParamKind::List, 1, 1, {}, ""},
      {"colors", ParamKind::List, 1, 1, {}, ""},
      {"color_size", ParamKind::Integer, 3, 4, {}, ""},
      {"texcoords", ParamKind::List, 1, 1, {}, ""},
      {"texcoord_size", ParamKind::Integer, 1, 4, {}, ""},
      {"indices", ParamKind::IndexList, 1, 1, {}, ""},
  };
  Mesh mesh;
  mesh.mode = r.word(names::primitiveModes, "primitive type");
  NamedParams params = NamedParams::read(r, specs);
  mesh.positionSize = static_cast<int>(params.integerOr("position_size", 3));
  mesh.colorSize = static_cast<int>(params.integerOr("color_size", 3));
  mesh.texcoordSize = static_cast<int>(params.integerOr("texcoord_size", 2));
  const ParamValue *positions = params.take("positions");
  if (positions == nullptr) r.fail(r.statementToken(), "'mesh' needs 'positions [ ... ]'");
  auto grouped = [&](const ParamValue *value, int size, const char *what) -> std::size_t {
    if (value->numbers.size() % static_cast<std::size_t>(size) != 0) {
      r.fail(value->where, value->length,
             std::string(what) + " holds " + std::to_string(value->numbers.size()) +
                 " numbers, not a multiple of " + std::to_string(size) + " (" + what + " per vertex: " +
                 std::to_string(size) + ")");
    }
    return value->numbers.size() / static_cast<std::size_t>(size);
  };
  std::size_t count = grouped(positions, mesh.positionSize, "positions");
  mesh.positions = positions->numbers;
  auto attribute = [&](const char *name, int size, Numbers &out) {
    const ParamValue *value = params.take(name);
    if (value == nullptr) return;
    std::size_t n = grouped(value, size, name);
    if (n != count) {
      r.fail(value->where, value->length,
             std::string(name) + " gives " + std::to_string(n) + " vertices but positions give " + std::to_string(count));
    }
    out = value->numbers;
  };
  attribute("normals", 3, mesh.normals);
  attribute("colors", mesh.colorSize, mesh.colors);
  attribute("texcoords", mesh.texcoordSize, mesh.texcoords);
  if (const ParamValue *indices = params.take("indices")) {
    for (std::uint32_t index : indices->indices) {
      if (index >= count) {
        r.fail(indices->where, indices->length,
               "index " + std::to_string(index) + " is out of range: the mesh has " + std::to_string(count) +
                   " vertices (indices count from 0)");
      }
    }
    mesh.indices = indices->indices;
    mesh.indexed = true;
  }
  warnIncompletePrimitive(mesh.mode, static_cast<long>(mesh.indexed ? mesh.indices.size() : count),
                          "'mesh " + enumName(names::primitiveModes, mesh.mode) + "' sends", r.statementToken().where,
                          r.statementToken().length);
  emit(r, mesh);
}

namespace {

bool isWingsPath(const std::string &path) {
  const std::string suffix = ".wings";
  if (path.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(path[path.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

} // namespace

void Parser::parseModel(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"materials", ParamKind::Boolean, 1, 1, {}, ""},
      {"round", ParamKind::Numbers, 1, 1, {}, "radius"},
  };
  const Token &pathToken = r.peek();
  const std::string written = r.string("the model file (.obj or .wings)");
  std::string path = resolvePath(written, pathToken.where);
  NamedParams params = NamedParams::read(r, specs);
  DrawModel draw;
  draw.useMaterials = params.booleanOr("materials", true);
  const bool wings = isWingsPath(path);
  // One load per file, however often the scene draws it.
  for (std::size_t i = 0; i < program_.models.size(); ++i) {
    if (program_.models[i].path == path) draw.model = static_cast<int>(i);
  }
  if (draw.model < 0) {
    Model model;
    std::string reason;
    const bool loaded = wings ? loadWingsModel(path, model, reason) : loadObjModel(path, model, program_.textures, reason);
    if (!loaded) r.fail(pathToken, "cannot load model '" + written + "': " + reason);
    if (wings) {
      for (const std::string &warning : wingsModelWarnings(*model.roundable))
        diagnostics_.warning(pathToken.where, "model '" + written + "': " + warning, pathToken.length);
    }
    draw.model = static_cast<int>(program_.models.size());
    program_.models.push_back(std::move(model));
  }
  if (const ParamValue *round = params.take("round")) {
    if (!wings) r.fail(round->where, round->length, "'round' rounds the marked edges of a Wings3D (.wings) model; '" + written + "' is not one");
    draw.round = round->numbers[0];
    // A constant radius is checked now; one from a parameter when each frame is drawn.
    if (draw.round->isConstant()) {
      const double radius = draw.round->constant;
      const Model &model = program_.models[static_cast<std::size_t>(draw.model)];
      try {
        if (radius < 0.0) throw geometry::RoundingError("the radius must be 0 or more");
        if (radius > 0.0) model.roundable->rounded.partsFor(*model.roundable, radius);
      } catch (const geometry::RoundingError &error) {
        r.fail(round->where, round->length, "cannot round '" + written + "' with radius " + formatModelNumber(radius) + ": " + error.what());
      }
    }
  }
  emit(r, draw);
}

} // namespace glass::scene
