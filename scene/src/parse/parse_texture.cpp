// Texture statements: `texture` defines a texture object from an image file (or a checkerboard),
// `bind_texture`, `tex_env` and `tex_gen` set GL state.
#include "gl_api.h"
#include "load/image_file.h"
#include "parser_impl.h"

namespace glass::scene {

namespace {

bool needsMipmaps(GLenumValue minFilter) { return minFilter != GL_NEAREST && minFilter != GL_LINEAR; }

void constantColor(const StatementReader &r, const ParamValue *value, double out[4]) {
  if (value == nullptr) return;
  for (std::size_t i = 0; i < value->numbers.size(); ++i) {
    if (!value->numbers[i].isConstant()) {
      r.fail(value->where, value->length, std::string(value->spec->name) + " must be constant numbers");
    }
    out[i] = value->numbers[i].constant;
  }
  if (value->numbers.size() == 3) out[3] = 1.0;
}

} // namespace

void Parser::parseTexture(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"min_filter", ParamKind::Word, 1, 1, names::minFilters, ""},
      {"mag_filter", ParamKind::Word, 1, 1, names::magFilters, ""},
      {"wrap_s", ParamKind::Word, 1, 1, names::wrapModes, ""},
      {"wrap_t", ParamKind::Word, 1, 1, names::wrapModes, ""},
      {"border_color", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"size", ParamKind::Integer, 1, 4096, {}, ""},
      {"squares", ParamKind::Integer, 1, 1024, {}, ""},
      {"color1", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"color2", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
  };
  TextureDefinition texture = readNewTextureName(r, "a name for the texture");
  const Token &sourceToken = r.peek();
  bool checker = false;
  if (r.peekIsWord("checker")) {
    r.take();
    checker = true;
  } else if (sourceToken.kind == TokenKind::String) {
    texture.path = resolvePath(r.take().text, sourceToken.where);
  } else {
    r.fail(sourceToken, "'texture " + texture.name + "' expects an image file name in quotes, or 'checker'; found " +
                            describeToken(sourceToken));
  }
  NamedParams params = NamedParams::read(r, specs);
  // GL's defaults (section 3.8 of the 1.1 specification): the minification filter is
  // nearest_mipmap_linear, which needs mipmaps, so they are built unless a plain filter is chosen.
  texture.minFilter = params.wordOr("min_filter", GL_NEAREST_MIPMAP_LINEAR);
  texture.magFilter = params.wordOr("mag_filter", GL_LINEAR);
  texture.wrapS = params.wordOr("wrap_s", GL_REPEAT);
  texture.wrapT = params.wordOr("wrap_t", GL_REPEAT);
  texture.mipmaps = needsMipmaps(texture.minFilter);
  if (const ParamValue *border = params.take("border_color")) {
    texture.borderColor = border->numbers;
    if (texture.borderColor.size() == 3) texture.borderColor.push_back(Number::of(1.0));
  }
  if (checker) {
    double first[4] = {1, 1, 1, 1}, second[4] = {0.1, 0.1, 0.1, 1};
    int size = static_cast<int>(params.integerOr("size", 64));
    int squares = static_cast<int>(params.integerOr("squares", 8));
    constantColor(r, params.take("color1"), first);
    constantColor(r, params.take("color2"), second);
    texture.image = makeCheckerImage(size, squares, first, second);
    params.requireAllUsed(r);
  } else {
    params.requireAllUsed(r, "with an image file (size, squares, color1 and color2 belong to 'checker')");
    std::string reason;
    if (!loadImageFile(texture.path, texture.image, reason)) {
      r.fail(sourceToken, "cannot read texture image '" + texture.path + "': " + reason);
    }
  }
  addTexture(std::move(texture));
}

TextureDefinition Parser::readNewTextureName(StatementReader &r, const std::string &what) {
  const Token &nameToken = r.peek();
  TextureDefinition texture;
  texture.name = r.identifier(what);
  texture.where = r.statementToken().where;
  if (texture.name == "none") r.fail(nameToken, "'none' is reserved: 'bind_texture none' unbinds");
  if (auto it = textureIndex_.find(texture.name); it != textureIndex_.end()) {
    throw StatementError{nameToken.where, nameToken.length, "texture '" + texture.name + "' is already defined",
                         {{program_.textures[static_cast<std::size_t>(it->second)].where, "first defined here"}}};
  }
  return texture;
}

int Parser::addTexture(TextureDefinition texture) {
  const int index = static_cast<int>(program_.textures.size());
  textureIndex_[texture.name] = index;
  program_.textures.push_back(std::move(texture));
  return index;
}

void Parser::parseBindTexture(StatementReader &r) {
  const Token &nameToken = r.peek();
  std::string name = r.identifier("a texture name (or none)");
  if (name == "none") {
    emit(r, BindTexture{-1});
    return;
  }
  emit(r, BindTexture{findTexture(r, nameToken, name)});
}

int Parser::findTexture(StatementReader &r, const Token &nameToken, const std::string &name) {
  auto it = textureIndex_.find(name);
  if (it == textureIndex_.end()) {
    std::vector<std::string_view> known;
    for (const auto &[textureName, index] : textureIndex_) known.push_back(textureName);
    std::string hint = suggestName(name, known);
    r.fail(nameToken, "no texture called '" + name + "'" +
                          (hint.empty() ? " (define it first with 'texture " + name + " \"file.png\"')" : "; " + hint));
  }
  return it->second;
}

void Parser::parseTexEnv(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"mode", ParamKind::Word, 1, 1, names::texEnvModes, ""},
      {"color", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
  };
  if (r.atEnd()) r.fail(r.peek(), "'tex_env' needs 'mode' or 'color'");
  NamedParams params = NamedParams::read(r, specs);
  TexEnv env;
  if (const ParamValue *mode = params.take("mode")) env.mode = mode->word;
  if (const ParamValue *color = params.take("color")) {
    env.color = color->numbers;
    if (env.color.size() == 3) env.color.push_back(Number::of(1.0));
  }
  emit(r, env);
}

void Parser::parseTexGen(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"mode", ParamKind::Word, 1, 1, names::texGenModes, ""},
      {"object_plane", ParamKind::Numbers, 4, 4, {}, "a b c d"},
      {"eye_plane", ParamKind::Numbers, 4, 4, {}, "a b c d"},
  };
  TexGen gen;
  gen.coord = r.word(names::texGenCoords, "texture coordinate");
  if (r.atEnd()) r.fail(r.peek(), "'tex_gen' needs 'mode', 'object_plane' or 'eye_plane'");
  NamedParams params = NamedParams::read(r, specs);
  std::string context;
  if (const ParamValue *mode = params.take("mode")) {
    gen.mode = mode->word;
    // Each mode reads its own plane (GL 1.1 section 2.10.4); sphere_map reads none.
    if (mode->word == GL_OBJECT_LINEAR) {
      params.take("object_plane");
      context = "with mode object_linear (it uses object_plane)";
    } else if (mode->word == GL_EYE_LINEAR) {
      params.take("eye_plane");
      context = "with mode eye_linear (it uses eye_plane)";
    } else {
      context = "with mode sphere_map (it uses no plane)";
    }
  } else {
    params.take("object_plane"), params.take("eye_plane");
  }
  params.requireAllUsed(r, context);
  for (const ParamValue &value : params.values()) {
    if (value.spec->name == "object_plane") gen.objectPlane = value.numbers;
    if (value.spec->name == "eye_plane") gen.eyePlane = value.numbers;
  }
  emit(r, gen);
}

} // namespace glass::scene
