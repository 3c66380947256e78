// The parser's driver: files, includes, the statement table, blocks and push/pop.
#include "gl_api.h"
#include "parser_impl.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace glass::scene {

namespace {

bool readWholeFile(const std::string &path, std::string &text, std::string &reason) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    reason = "it is a directory";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    reason = std::strerror(errno);
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    reason = "read error";
    return false;
  }
  text = buffer.str();
  return true;
}

std::string canonicalPath(const std::string &path) {
  std::error_code ec;
  std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : canonical.string();
}

} // namespace

std::span<const Parser::StatementKind> Parser::statementKinds() {
  using P = Place;
  static const StatementKind kinds[] = {
      // Scene settings, parameters, structure.
      {"size", &Parser::parseSize, P::TopLevel},
      {"frames", &Parser::parseFrames, P::TopLevel},
      {"param", &Parser::parseParam, P::TopLevel},
      {"animate", &Parser::parseAnimate, P::TopLevel},
      {"include", &Parser::parseInclude, P::Scene},
      {"define", &Parser::parseDefine, P::TopLevel},
      {"instance", &Parser::parseInstance, P::Scene},
      {"end", &Parser::parseEnd, P::BlockEnd},
      {"push", &Parser::parsePush, P::Scene},
      {"pop", &Parser::parsePop, P::Scene},
      // Output and camera.
      {"viewport", &Parser::parseViewport, P::Scene},
      {"clear_color", &Parser::parseClearColor, P::Scene},
      {"clear_depth", &Parser::parseClearDepth, P::Scene},
      {"clear_stencil", &Parser::parseClearStencil, P::Scene},
      {"clear", &Parser::parseClear, P::Scene},
      {"perspective", &Parser::parsePerspective, P::Scene},
      {"frustum", &Parser::parseFrustum, P::Scene},
      {"ortho", &Parser::parseOrtho, P::Scene},
      {"lookat", &Parser::parseLookAt, P::Scene},
      // Transforms.
      {"load_identity", &Parser::parseLoadIdentity, P::Scene},
      {"translate", &Parser::parseTranslate, P::Scene},
      {"rotate", &Parser::parseRotate, P::Scene},
      {"scale", &Parser::parseScale, P::Scene},
      {"matrix", &Parser::parseMatrix, P::Scene},
      {"shadow_matrix", &Parser::parseShadowMatrix, P::Scene},
      // Vertex attributes.
      {"color", &Parser::parseColor, P::Attribute},
      {"normal", &Parser::parseNormal, P::Attribute},
      {"texcoord", &Parser::parseTexCoord, P::Attribute},
      {"material", &Parser::parseMaterial, P::Attribute},
      {"vertex", &Parser::parseVertex, P::Primitive},
      {"edge_flag", &Parser::parseEdgeFlag, P::Primitive},
      // GL state.
      {"enable", &Parser::parseEnable, P::Scene},
      {"disable", &Parser::parseDisable, P::Scene},
      {"shade_model", &Parser::parseShadeModel, P::Scene},
      {"light", &Parser::parseLight, P::Scene},
      {"light_model", &Parser::parseLightModel, P::Scene},
      {"color_material", &Parser::parseColorMaterial, P::Scene},
      {"fog", &Parser::parseFog, P::Scene},
      {"blend_func", &Parser::parseBlendFunc, P::Scene},
      {"alpha_func", &Parser::parseAlphaFunc, P::Scene},
      {"depth_func", &Parser::parseDepthFunc, P::Scene},
      {"depth_mask", &Parser::parseDepthMask, P::Scene},
      {"depth_range", &Parser::parseDepthRange, P::Scene},
      {"color_mask", &Parser::parseColorMask, P::Scene},
      {"stencil_func", &Parser::parseStencilFunc, P::Scene},
      {"stencil_op", &Parser::parseStencilOp, P::Scene},
      {"stencil_mask", &Parser::parseStencilMask, P::Scene},
      {"cull_face", &Parser::parseCullFace, P::Scene},
      {"front_face", &Parser::parseFrontFace, P::Scene},
      {"polygon_mode", &Parser::parsePolygonMode, P::Scene},
      {"polygon_offset", &Parser::parsePolygonOffset, P::Scene},
      {"clip_plane", &Parser::parseClipPlane, P::Scene},
      {"line_width", &Parser::parseLineWidth, P::Scene},
      {"point_size", &Parser::parsePointSize, P::Scene},
      {"scissor", &Parser::parseScissor, P::Scene},
      {"logic_op", &Parser::parseLogicOp, P::Scene},
      // Textures.
      {"texture", &Parser::parseTexture, P::TopLevel},
      {"bind_texture", &Parser::parseBindTexture, P::Scene},
      {"tex_env", &Parser::parseTexEnv, P::Scene},
      {"tex_gen", &Parser::parseTexGen, P::Scene},
      {"shadow_map", &Parser::parseShadowMap, P::TopLevel},
      {"shadow_texgen", &Parser::parseShadowTexGen, P::Scene},
      // Geometry.
      {"begin", &Parser::parseBegin, P::Scene},
      {"rect", &Parser::parseRect, P::Scene},
      {"mesh", &Parser::parseMesh, P::Scene},
      {"model", &Parser::parseModel, P::Scene},
      {"sphere", &Parser::parseSphere, P::Scene},
      {"cylinder", &Parser::parseCylinder, P::Scene},
      {"disk", &Parser::parseDisk, P::Scene},
      {"partial_disk", &Parser::parsePartialDisk, P::Scene},
      {"solid_cube", &Parser::parseGlutShape, P::Scene},
      {"wire_cube", &Parser::parseGlutShape, P::Scene},
      {"solid_sphere", &Parser::parseGlutShape, P::Scene},
      {"wire_sphere", &Parser::parseGlutShape, P::Scene},
      {"solid_cone", &Parser::parseGlutShape, P::Scene},
      {"wire_cone", &Parser::parseGlutShape, P::Scene},
      {"solid_torus", &Parser::parseGlutShape, P::Scene},
      {"wire_torus", &Parser::parseGlutShape, P::Scene},
      {"solid_tetrahedron", &Parser::parseGlutShape, P::Scene},
      {"wire_tetrahedron", &Parser::parseGlutShape, P::Scene},
      {"solid_octahedron", &Parser::parseGlutShape, P::Scene},
      {"wire_octahedron", &Parser::parseGlutShape, P::Scene},
      {"solid_dodecahedron", &Parser::parseGlutShape, P::Scene},
      {"wire_dodecahedron", &Parser::parseGlutShape, P::Scene},
      {"solid_icosahedron", &Parser::parseGlutShape, P::Scene},
      {"wire_icosahedron", &Parser::parseGlutShape, P::Scene},
      {"solid_teapot", &Parser::parseGlutShape, P::Scene},
      {"wire_teapot", &Parser::parseGlutShape, P::Scene},
      {"solid_teacup", &Parser::parseGlutShape, P::Scene},
      {"wire_teacup", &Parser::parseGlutShape, P::Scene},
      {"solid_teaspoon", &Parser::parseGlutShape, P::Scene},
      {"wire_teaspoon", &Parser::parseGlutShape, P::Scene},
      {"parametric_torus", &Parser::parseParametricTorus, P::Scene},
      {"bezier_curve", &Parser::parseBezierCurve, P::Scene},
      {"bezier_patch", &Parser::parseBezierPatch, P::Scene},
      // Iterated function systems.
      {"ifs", &Parser::parseIfs, P::Scene},
      {"map", &Parser::parseMap, P::IfsMap},
      {"ifs3d", &Parser::parseIfs3d, P::Scene},
  };
  return kinds;
}

const char *Parser::blockName(BlockKind kind) {
  switch (kind) {
  case BlockKind::Begin: return "begin";
  case BlockKind::Define: return "define";
  case BlockKind::Ifs: return "ifs";
  }
  return "block";
}

Parser::Parser(Diagnostics &diagnostics, const ParseOptions &options)
    : diagnostics_(diagnostics), options_(options) {
  program_.sources = std::make_shared<SourceSet>();
  diagnostics_.keepSources(program_.sources);
  overrideUsed_.assign(options_.overrides.size(), false);
}

Program Parser::parse(const std::string &path, const std::string *text) {
  program_.path = path;
  std::string contents;
  if (text != nullptr) {
    contents = *text;
  } else {
    std::string reason;
    if (!readWholeFile(path, contents, reason)) {
      diagnostics_.error({}, "cannot read scene '" + path + "': " + reason);
      return std::move(program_);
    }
  }
  const SourceFile &file = program_.sources->add(path, std::move(contents));
  includeStack_.push_back(canonicalPath(path));
  parseFile(file);
  includeStack_.pop_back();
  if (!diagnostics_.full()) checkOverrides();
  // glClearColor only sets the value glClear uses; a scene that never clears after setting it
  // keeps the old background, which is rarely what was meant.
  const Statement *lastClearColor = nullptr;
  for (const Statement &statement : program_.statements) {
    if (std::holds_alternative<ClearColor>(statement.body)) lastClearColor = &statement;
    if (const Clear *clear = std::get_if<Clear>(&statement.body); clear && (clear->mask & GL_COLOR_BUFFER_BIT) != 0) {
      lastClearColor = nullptr;
    }
  }
  if (lastClearColor != nullptr) {
    diagnostics_.warning(lastClearColor->where,
                         "'clear_color' only sets the colour that 'clear' (glClear) fills with; no 'clear' follows it",
                         lastClearColor->length);
  }
  // Keyframes must lie on frames the scene has.
  for (const Parameter &parameter : program_.parameters) {
    for (const Keyframe &key : parameter.keys) {
      if (key.frame > program_.frames - 1 && !diagnostics_.full()) {
        diagnostics_.error(key.where, "key frame " + std::to_string(static_cast<long long>(key.frame)) +
                                          " is after the last frame " +
                                          std::to_string(program_.frames - 1) + " (the scene has 'frames " +
                                          std::to_string(program_.frames) + "')");
      }
    }
  }
  return std::move(program_);
}

void Parser::parseFile(const SourceFile &file) {
  // The lexer's messages wait in their own list and join the others in source order, as the
  // parser reaches their statement. A statement with a lexer error is not parsed: its parse
  // errors would only repeat the problem ("needs 3 numbers" after a malformed number).
  // The lexer stops where the parser will have reached the error limit anyway.
  Diagnostics lexerMessages(std::max(1, diagnostics_.errorLimit() - diagnostics_.errorCount()));
  TokenCursor cursor(tokenize(file, lexerMessages));
  const std::vector<Diagnostic> &pending = lexerMessages.all();
  std::size_t nextPending = 0;
  auto before = [](SourceLocation a, SourceLocation b) {
    return a.line != b.line ? a.line < b.line : a.column <= b.column;
  };
  std::size_t blocksBefore = blocks_.size();
  std::size_t pushesBefore = pushes_.size();
  while (cursor.peek().kind != TokenKind::EndOfFile && !diagnostics_.full()) {
    SourceLocation end = cursor.statementEnd();
    bool lexerError = false;
    while (nextPending < pending.size() && before(pending[nextPending].where, end)) {
      lexerError = lexerError || pending[nextPending].severity == Severity::Error;
      diagnostics_.add(pending[nextPending++]);
    }
    if (cursor.peek().kind == TokenKind::EndOfLine) {
      cursor.next();
    } else if (lexerError) {
      cursor.skipStatement();
    } else {
      parseStatement(cursor);
    }
  }
  while (nextPending < pending.size() && !diagnostics_.full()) diagnostics_.add(pending[nextPending++]);
  if (diagnostics_.full()) return;
  // Blocks and pushes must close in the file that opened them.
  bool included = file.includedFrom().valid();
  while (blocks_.size() > blocksBefore) {
    const OpenBlock &block = blocks_.back();
    diagnostics_.error(block.where, std::string("'") + blockName(block.kind) +
                                        "' is never closed by 'end'" +
                                        (included ? " in this included file" : ""),
                       block.length);
    if (block.kind == BlockKind::Define) definitionIndex_.erase(block.definition.name);
    blocks_.pop_back();
  }
  for (std::size_t i = pushesBefore; i < pushes_.size(); ++i) {
    diagnostics_.error(pushes_[i].where, std::string("'push' is never matched by a 'pop'") +
                                             (included ? " in this included file" : ""), 4);
  }
  pushes_.resize(pushesBefore);
}

void Parser::report(const StatementError &error) {
  Diagnostic &d = diagnostics_.error(error.where, error.message, error.length);
  for (const auto &[where, text] : error.notes) d.note(where, text);
}

bool Parser::checkPlace(const StatementKind &kind, const Token &name) {
  bool inBegin = !blocks_.empty() && blocks_.back().kind == BlockKind::Begin;
  auto complain = [&](const std::string &message) {
    Diagnostic &d = diagnostics_.error(name.where, message, name.length);
    if (!blocks_.empty()) {
      d.note(blocks_.back().where, std::string("the '") + blockName(blocks_.back().kind) +
                                       "' block was opened here", blocks_.back().length);
    }
    return false;
  };
  switch (kind.place) {
  case Place::Scene:
    if (inBegin) {
      return complain("'" + name.text + "' is not allowed between 'begin' and 'end': as in GL, "
                      "only vertex, color, normal, texcoord, material and edge_flag go there");
    }
    return true;
  case Place::TopLevel:
    if (!blocks_.empty()) {
      return complain("'" + name.text + "' is only allowed outside blocks, not inside '" +
                      blockName(blocks_.back().kind) + "'");
    }
    return true;
  case Place::Primitive:
    if (!inBegin) {
      return complain("'" + name.text + "' is only allowed between 'begin' and 'end'");
    }
    return true;
  case Place::Attribute:
  case Place::BlockEnd:
    return true;
  case Place::IfsMap:
    if (blocks_.empty() || blocks_.back().kind != BlockKind::Ifs) {
      return complain("'map' is only allowed directly inside an 'ifs' block");
    }
    return true;
  }
  return true;
}

void Parser::parseStatement(TokenCursor &cursor) {
  const Token &name = cursor.peek();
  if (name.kind != TokenKind::Word) {
    diagnostics_.error(name.where, "expected a statement name, found " + describeToken(name),
                       name.length);
    cursor.skipStatement();
    return;
  }
  const StatementKind *kind = nullptr;
  for (const StatementKind &candidate : statementKinds()) {
    if (candidate.name == name.text) kind = &candidate;
  }
  if (kind == nullptr) {
    std::vector<std::string_view> names;
    for (const StatementKind &candidate : statementKinds()) names.push_back(candidate.name);
    std::string hint = suggestName(name.text, names);
    diagnostics_.error(name.where, "unknown statement '" + name.text + "'" + (hint.empty() ? "" : "; " + hint),
                       name.length);
    cursor.skipStatement();
    return;
  }
  cursor.next();
  if (!checkPlace(*kind, name)) {
    cursor.skipStatement();
    return;
  }
  StatementReader reader(cursor, name, *this);
  try {
    (this->*(kind->method))(reader);
    reader.end();
  } catch (const StatementError &error) {
    report(error);
  }
  cursor.skipStatement();
}

StatementList &Parser::target() {
  return blocks_.empty() ? program_.statements : blocks_.back().body;
}

Parser::OpenBlock *Parser::innermost(BlockKind kind) {
  for (auto it = blocks_.rbegin(); it != blocks_.rend(); ++it) {
    if (it->kind == kind) return &*it;
  }
  return nullptr;
}

std::string Parser::resolvePath(const std::string &written, SourceLocation from) const {
  std::filesystem::path path(written);
  if (path.is_absolute() || from.file == nullptr) return path.lexically_normal().string();
  std::filesystem::path base = std::filesystem::path(from.file->path()).parent_path();
  return (base / path).lexically_normal().string();
}

Parameter *Parser::findParameter(const std::string &name, int &index) {
  int i = program_.findParameter(name);
  if (i < 0) return nullptr;
  index = i;
  program_.parameters[static_cast<std::size_t>(i)].used = true;
  return &program_.parameters[static_cast<std::size_t>(i)];
}

void Parser::noteConstantUse(int index, SourceLocation at) {
  std::size_t i = static_cast<std::size_t>(index);
  if (constantUses_.size() <= i) constantUses_.resize(i + 1);
  if (!constantUses_[i].valid()) constantUses_[i] = at;
}

void Parser::checkOverrides() {
  for (std::size_t i = 0; i < options_.overrides.size(); ++i) {
    if (overrideUsed_[i]) continue;
    std::string declared;
    for (const Parameter &p : program_.parameters) declared += (declared.empty() ? "" : ", ") + p.name;
    diagnostics_.error({}, "--set " + options_.overrides[i].first + ": the scene '" + program_.path +
                               "' declares no parameter '" + options_.overrides[i].first + "'" +
                               (declared.empty() ? " (it declares none)" : " (it declares " + declared + ")"));
  }
}

// ---- Blocks ----------------------------------------------------------------------------------

void Parser::parseEnd(StatementReader &r) {
  r.end();
  closeBlock(r);
}

void Parser::closeBlock(StatementReader &r) {
  if (blocks_.empty()) {
    r.fail(r.statementToken(), "'end' without an open block (begin, define or ifs)");
  }
  // Pushes made inside the block must be popped inside it.
  std::size_t depth = blocks_.back().pushDepth;
  if (pushes_.size() > depth) {
    StatementError error{pushes_.back().where, 4,
                         std::string("'push' is not popped before the 'end' of its '") +
                             blockName(blocks_.back().kind) + "' block",
                         {{r.statementToken().where, "the block ends here"}}};
    pushes_.resize(depth);
    report(error);
  }
  OpenBlock block = std::move(blocks_.back());
  blocks_.pop_back();
  if (block.broken) return; // its mistake was reported where the block opened
  switch (block.kind) {
  case BlockKind::Begin: {
    Begin &begin = std::get<Begin>(block.statement.body);
    begin.body = std::move(block.body);
    checkPrimitive(block.statement);
    target().push_back(std::move(block.statement));
    break;
  }
  case BlockKind::Define: {
    int index = definitionIndex_.at(block.definition.name);
    block.definition.body = std::move(block.body);
    program_.definitions[static_cast<std::size_t>(index)] = std::move(block.definition);
    break;
  }
  case BlockKind::Ifs: {
    Ifs &ifs = std::get<Ifs>(block.statement.body);
    ifs.base = std::move(block.body);
    finishIfs(block, r);
    target().push_back(std::move(block.statement));
    break;
  }
  }
}

void Parser::parseDefine(StatementReader &r) {
  OpenBlock block;
  block.kind = BlockKind::Define;
  block.where = r.statementToken().where;
  block.length = r.statementToken().length;
  block.pushDepth = pushes_.size();
  // A mistake on the `define` line still opens the block, so that its `end` finds it.
  try {
    const Token &nameToken = r.peek();
    std::string name = r.identifier("a name for the definition");
    r.end();
    if (auto it = definitionIndex_.find(name); it != definitionIndex_.end()) {
      throw StatementError{nameToken.where, nameToken.length, "'" + name + "' is already defined",
                           {{program_.definitions[static_cast<std::size_t>(it->second)].where,
                             "first defined here"}}};
    }
    definitionIndex_[name] = static_cast<int>(program_.definitions.size());
    Definition placeholder;
    placeholder.name = name;
    placeholder.where = r.statementToken().where;
    program_.definitions.push_back(placeholder);
    block.definition = placeholder;
  } catch (const StatementError &) {
    block.broken = true;
    blocks_.push_back(std::move(block));
    throw;
  }
  blocks_.push_back(std::move(block));
}

void Parser::parseInstance(StatementReader &r) {
  const Token &nameToken = r.peek();
  std::string name = r.identifier("the name of a definition");
  auto it = definitionIndex_.find(name);
  if (it == definitionIndex_.end()) {
    std::vector<std::string_view> names;
    for (const auto &[known, index] : definitionIndex_) names.push_back(known);
    std::string hint = suggestName(name, names);
    r.fail(nameToken, "no definition called '" + name + "'" +
                          (hint.empty() ? " (a 'define' must come before its instances)" : "; " + hint));
  }
  for (const OpenBlock &block : blocks_) {
    if (block.kind == BlockKind::Define && block.definition.name == name) {
      throw StatementError{nameToken.where, nameToken.length,
                           "'" + name + "' cannot be instanced inside its own definition",
                           {{block.where, "the definition starts here"}}};
    }
  }
  emit(r, Instance{it->second});
}

void Parser::parsePush(StatementReader &r) {
  r.end();
  pushes_.push_back(OpenPush{r.statementToken().where, blocks_.size()});
  emit(r, Push{});
}

void Parser::parsePop(StatementReader &r) {
  r.end();
  if (pushes_.empty()) r.fail(r.statementToken(), "'pop' without a matching 'push'");
  const OpenPush &push = pushes_.back();
  if (push.blockDepth != blocks_.size()) {
    const OpenBlock &block = blocks_.back();
    throw StatementError{r.statementToken().where, r.statementToken().length,
                         std::string("'pop' without a matching 'push' inside this '") +
                             blockName(block.kind) + "' block",
                         {{block.where, "the block was opened here"},
                          {push.where, "the nearest 'push' is outside the block"}}};
  }
  if (push.where.file != r.statementToken().where.file) {
    throw StatementError{r.statementToken().where, r.statementToken().length,
                         "'pop' matches a 'push' in another file; push and pop must be in the same file",
                         {{push.where, "the 'push' is here"}}};
  }
  pushes_.pop_back();
  emit(r, Pop{});
}

// ---- Files -----------------------------------------------------------------------------------

void Parser::parseInclude(StatementReader &r) {
  const Token &pathToken = r.peek();
  std::string written = r.string("the file to include");
  r.end();
  std::string path = resolvePath(written, r.statementToken().where);
  std::string canonical = canonicalPath(path);
  auto cycle = std::find(includeStack_.begin(), includeStack_.end(), canonical);
  if (cycle != includeStack_.end()) {
    std::string chain;
    for (auto it = cycle; it != includeStack_.end(); ++it) {
      chain += std::filesystem::path(*it).filename().string() + " -> ";
    }
    chain += std::filesystem::path(canonical).filename().string();
    r.fail(pathToken, "include cycle: " + chain);
  }
  if (static_cast<int>(includeStack_.size()) >= options_.maxIncludeDepth) {
    r.fail(pathToken, "includes nested more than " + std::to_string(options_.maxIncludeDepth) + " deep");
  }
  std::string text, reason;
  if (!readWholeFile(path, text, reason)) r.fail(pathToken, "cannot read '" + path + "': " + reason);
  const SourceFile &file = program_.sources->add(path, std::move(text), r.statementToken().where);
  includeStack_.push_back(canonical);
  parseFile(file);
  includeStack_.pop_back();
}

Program parseSceneFile(const std::string &path, Diagnostics &diagnostics, const ParseOptions &options) {
  Parser parser(diagnostics, options);
  return parser.parse(path, nullptr);
}

Program parseSceneText(const std::string &path, const std::string &text, Diagnostics &diagnostics,
                       const ParseOptions &options) {
  Parser parser(diagnostics, options);
  return parser.parse(path, &text);
}

int Program::findParameter(const std::string &name) const {
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (parameters[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

} // namespace glass::scene
