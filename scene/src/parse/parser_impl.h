// The scene parser: reads files statement by statement, with one method per statement (in the
// manner of pbrt-v4's parser), keeps track of blocks (begin/define/ifs ... end) and of push/pop,
// follows includes, and loads the files a scene names.
#pragma once

#include "glass/scene/diagnostics.h"
#include "glass/scene/parser.h"
#include "glass/scene/program.h"
#include "statement_reader.h"

#include <map>
#include <span>
#include <string>
#include <vector>

namespace glass::scene {

class Parser final : public ParameterScope {
public:
  Parser(Diagnostics &diagnostics, const ParseOptions &options);

  Program parse(const std::string &path, const std::string *text);

  Parameter *findParameter(const std::string &name, int &index) override;
  void noteConstantUse(int index, SourceLocation at) override;

  // Where a statement may appear.
  enum class Place {
    Scene,     // anywhere except between begin and end
    TopLevel,  // only outside every block
    Primitive, // only between begin and end
    Attribute, // anywhere, also between begin and end (color, normal, texcoord, material)
    IfsMap,    // only directly inside ifs
    BlockEnd,  // `end`
  };
  using Method = void (Parser::*)(StatementReader &);
  struct StatementKind {
    std::string_view name;
    Method method;
    Place place;
  };

private:
  enum class BlockKind { Begin, Define, Ifs };
  struct OpenBlock {
    BlockKind kind = BlockKind::Begin;
    Statement statement; // the Begin or Ifs being filled
    Definition definition;
    StatementList body;
    SourceLocation where;
    int length = 1;
    std::size_t pushDepth = 0; // open pushes when the block was opened
    bool fileBase = false;     // ifs: the body starts with the base polygon of an IFS file
    bool broken = false;       // its first line had a mistake: closed quietly, not used
  };
  struct OpenPush {
    SourceLocation where;
    std::size_t blockDepth = 0;
  };

  static std::span<const StatementKind> statementKinds();
  static const char *blockName(BlockKind kind);

  void parseFile(const SourceFile &file);
  void parseStatement(TokenCursor &cursor);
  bool checkPlace(const StatementKind &kind, const Token &name);
  void closeBlocksOpenedIn(const SourceFile &file);
  void closeBlock(StatementReader &reader);
  void finishIfs(OpenBlock &block, const StatementReader &reader);
  void checkPrimitive(const Statement &begin);
  void warnIncompletePrimitive(GLenumValue mode, long vertices, const std::string &what, SourceLocation where, int length);
  void report(const StatementError &error);
  void checkOverrides();

  StatementList &target();
  template <typename T> void emit(const StatementReader &reader, T body) {
    Statement statement;
    statement.where = reader.statementToken().where;
    statement.length = reader.statementToken().length;
    statement.body = std::move(body);
    target().push_back(std::move(statement));
  }
  // A path written in the scene, relative to the file that names it.
  std::string resolvePath(const std::string &written, SourceLocation from) const;
  OpenBlock *innermost(BlockKind kind);

  // Scene settings and parameters (parse_scene.cpp).
  void parseSize(StatementReader &r);
  void parseFrames(StatementReader &r);
  void parseParam(StatementReader &r);
  void parseAnimate(StatementReader &r);
  void parseInclude(StatementReader &r);
  void parseDefine(StatementReader &r);
  void parseInstance(StatementReader &r);
  void parseEnd(StatementReader &r);
  void parsePush(StatementReader &r);
  void parsePop(StatementReader &r);

  // Output, camera and transforms (parse_camera.cpp).
  void parseViewport(StatementReader &r);
  void parseClearColor(StatementReader &r);
  void parseClearDepth(StatementReader &r);
  void parseClearStencil(StatementReader &r);
  void parseClear(StatementReader &r);
  void parsePerspective(StatementReader &r);
  void parseFrustum(StatementReader &r);
  void parseOrtho(StatementReader &r);
  void parseLookAt(StatementReader &r);
  void parseLoadIdentity(StatementReader &r);
  void parseTranslate(StatementReader &r);
  void parseRotate(StatementReader &r);
  void parseScale(StatementReader &r);
  void parseMatrix(StatementReader &r);
  void parseShadowMatrix(StatementReader &r);

  // Vertex attributes and GL state (parse_state.cpp).
  void parseColor(StatementReader &r);
  void parseNormal(StatementReader &r);
  void parseTexCoord(StatementReader &r);
  void parseVertex(StatementReader &r);
  void parseEdgeFlag(StatementReader &r);
  void parseEnable(StatementReader &r);
  void parseDisable(StatementReader &r);
  void parseShadeModel(StatementReader &r);
  void parseLight(StatementReader &r);
  void parseLightModel(StatementReader &r);
  void parseMaterial(StatementReader &r);
  void parseColorMaterial(StatementReader &r);
  void parseFog(StatementReader &r);
  void parseBlendFunc(StatementReader &r);
  void parseAlphaFunc(StatementReader &r);
  void parseDepthFunc(StatementReader &r);
  void parseDepthMask(StatementReader &r);
  void parseDepthRange(StatementReader &r);
  void parseColorMask(StatementReader &r);
  void parseStencilFunc(StatementReader &r);
  void parseStencilOp(StatementReader &r);
  void parseStencilMask(StatementReader &r);
  void parseCullFace(StatementReader &r);
  void parseFrontFace(StatementReader &r);
  void parsePolygonMode(StatementReader &r);
  void parsePolygonOffset(StatementReader &r);
  void parseClipPlane(StatementReader &r);
  void parseLineWidth(StatementReader &r);
  void parsePointSize(StatementReader &r);
  void parseScissor(StatementReader &r);
  void parseLogicOp(StatementReader &r);

  // Textures (parse_texture.cpp).
  void parseTexture(StatementReader &r);
  void parseBindTexture(StatementReader &r);
  void parseTexEnv(StatementReader &r);
  void parseTexGen(StatementReader &r);
  // Shadow mapping (parse_shadow_map.cpp).
  void parseShadowMap(StatementReader &r);
  void parseShadowTexGen(StatementReader &r);
  // The texture named `nameToken`, or an error that names the defined ones.
  int findTexture(StatementReader &r, const Token &nameToken, const std::string &name);
  // A texture definition with the name read next (`what` says what is expected there), or an
  // error for `none` and for a name already defined.
  TextureDefinition readNewTextureName(StatementReader &r, const std::string &what);
  int addTexture(TextureDefinition texture); // its index in Program::textures

  // Geometry (parse_geometry.cpp, parse_shapes.cpp).
  void parseBegin(StatementReader &r);
  void parseRect(StatementReader &r);
  void parseMesh(StatementReader &r);
  void parseModel(StatementReader &r);
  void parseSphere(StatementReader &r);
  void parseCylinder(StatementReader &r);
  void parseDisk(StatementReader &r);
  void parsePartialDisk(StatementReader &r);
  void parseGlutShape(StatementReader &r);
  void parseParametricTorus(StatementReader &r);
  void parseBezierCurve(StatementReader &r);
  void parseBezierPatch(StatementReader &r);

  // Iterated function systems (parse_ifs.cpp).
  void parseIfs(StatementReader &r);
  void parseMap(StatementReader &r);
  void parseIfs3d(StatementReader &r); // parse_ifs3d.cpp

  QuadricStyle readQuadricStyle(NamedParams &params);

  Diagnostics &diagnostics_;
  ParseOptions options_;
  Program program_;
  std::vector<OpenBlock> blocks_;
  std::vector<OpenPush> pushes_;
  std::vector<std::string> includeStack_; // canonical paths of the files being read
  std::vector<SourceLocation> includeSites_;
  std::map<std::string, int, std::less<>> definitionIndex_;
  std::map<std::string, int, std::less<>> textureIndex_;
  std::map<int, LightView> shadowLights_; // by texture index: the light of each `shadow_map`
  std::vector<SourceLocation> constantUses_; // per parameter: where first used as a constant
  std::vector<bool> overrideUsed_;
  bool sizeSeen_ = false, framesSeen_ = false;
  SourceLocation sizeWhere_, framesWhere_;
};

} // namespace glass::scene
