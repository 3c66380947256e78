// Shadow mapping: `shadow_map` renders a definition's depth from a light into a depth texture,
// `shadow_texgen` binds it with the texture coordinate generation that looks it up.
#include "gl_api.h"
#include "parser_impl.h"

namespace glass::scene {

namespace {

LightView readLightView(const StatementReader &r, NamedParams &params) {
  LightView light;
  const ParamValue *from = params.take("from");
  const ParamValue *to = params.take("to");
  const ParamValue *fov = params.take("fov");
  const ParamValue *zNear = params.take("near");
  const ParamValue *zFar = params.take("far");
  if (!from || !to || !fov || !zNear || !zFar) {
    r.fail(r.statementToken(), "'shadow_map' needs the light's view: 'from X Y Z to X Y Z fov DEGREES near N far F'");
  }
  light.from = from->numbers;
  light.to = to->numbers;
  const ParamValue *up = params.take("up");
  light.up = up ? up->numbers : Numbers{Number::of(0.0), Number::of(1.0), Number::of(0.0)};
  light.fovy = fov->numbers[0];
  light.zNear = zNear->numbers[0];
  light.zFar = zFar->numbers[0];
  return light;
}

} // namespace

void Parser::parseShadowMap(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"from", ParamKind::Numbers, 3, 3, {}, "x y z"},
      {"to", ParamKind::Numbers, 3, 3, {}, "x y z"},
      {"up", ParamKind::Numbers, 3, 3, {}, "x y z"},
      {"fov", ParamKind::Numbers, 1, 1, {}, "degrees"},
      {"near", ParamKind::Numbers, 1, 1, {}, "distance"},
      {"far", ParamKind::Numbers, 1, 1, {}, "distance"},
      {"size", ParamKind::Integer, 1, 4096, {}, ""},
      {"offset", ParamKind::Numbers, 2, 2, {}, "factor units"},
      {"compare_func", ParamKind::Word, 1, 1, names::compareFunctions, ""},
      {"depth_mode", ParamKind::Word, 1, 1, names::depthTextureModes, ""},
      {"filter", ParamKind::Word, 1, 1, names::magFilters, ""},
  };
  TextureDefinition texture = readNewTextureName(r, "a name for the shadow map's texture");
  // `casters DEFINITION` comes first: the named parameters after it take only GL names.
  if (!r.peekIsWord("casters")) r.fail(r.peek(), "'shadow_map " + texture.name + "' expects 'casters DEFINITION' next");
  r.take();
  const Token &castersToken = r.peek();
  const std::string casters = r.identifier("the name of the definition that casts shadows");
  const auto definition = definitionIndex_.find(casters);
  if (definition == definitionIndex_.end()) {
    std::vector<std::string_view> known;
    for (const auto &[name, index] : definitionIndex_) known.push_back(name);
    const std::string hint = suggestName(casters, known);
    r.fail(castersToken, "no definition called '" + casters + "'" +
                             (hint.empty() ? " (a 'define' must come before the shadow map)" : "; " + hint));
  }
  NamedParams params = NamedParams::read(r, specs);
  ShadowMap map;
  map.definition = definition->second;
  map.light = readLightView(r, params);
  if (const ParamValue *offset = params.take("offset")) {
    map.offsetFactor = offset->numbers[0];
    map.offsetUnits = offset->numbers[1];
  } else {
    map.offsetFactor = Number::of(2.0);
    map.offsetUnits = Number::of(4.0);
  }
  texture.depth = true;
  texture.depthSize = static_cast<int>(params.integerOr("size", 512));
  texture.compareFunction = params.wordOr("compare_func", GL_LEQUAL);
  texture.depthTextureMode = params.wordOr("depth_mode", GL_LUMINANCE);
  texture.minFilter = texture.magFilter = params.wordOr("filter", GL_NEAREST);
  // Outside the light's view nothing is in shadow: a border depth of 1 passes every lequal test.
  texture.wrapS = texture.wrapT = GL_CLAMP_TO_BORDER;
  texture.borderColor = {Number::of(1.0), Number::of(1.0), Number::of(1.0), Number::of(1.0)};
  params.requireAllUsed(r);

  map.texture = addTexture(std::move(texture));
  shadowLights_[map.texture] = map.light;
  emit(r, map);
}

void Parser::parseShadowTexGen(StatementReader &r) {
  const Token &nameToken = r.peek();
  const std::string name = r.identifier("the name of a shadow map");
  const int texture = findTexture(r, nameToken, name);
  const auto light = shadowLights_.find(texture);
  if (light == shadowLights_.end()) {
    r.fail(nameToken, "texture '" + name + "' is not a shadow map (made by 'shadow_map')");
  }
  r.end();
  emit(r, ShadowTexGen{texture, light->second});
}

} // namespace glass::scene
