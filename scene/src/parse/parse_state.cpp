// Vertex attributes and GL state statements. Ranges the GL specification rejects with
// GL_INVALID_VALUE are checked here already when the value is a constant, so that the message
// points at the number.
#include "gl_api.h"
#include "parser_impl.h"

namespace glass::scene {

namespace {

NamedValues namedNumbers(const ParamValue &value, GLenumValue pname) {
  return NamedValues{pname, value.numbers, value.where};
}

NamedValues namedWord(const ParamValue &value, GLenumValue pname) {
  return NamedValues{pname, {Number::of(static_cast<double>(value.word))}, value.where};
}

NamedValues namedBoolean(const ParamValue &value, GLenumValue pname) {
  return NamedValues{pname, {Number::of(value.boolean ? 1.0 : 0.0)}, value.where};
}

// A colour of 3 numbers gets alpha 1.
Numbers rgba(Numbers values) {
  if (values.size() == 3) values.push_back(Number::of(1.0));
  return values;
}

void checkRange(const StatementReader &r, const ParamValue &value, double min, double max,
                const std::string &rule) {
  for (const Number &n : value.numbers) {
    if (n.isConstant() && (n.constant < min || n.constant > max)) {
      r.fail(value.where, value.length, std::string(value.spec->name) + " " + rule);
    }
  }
}

} // namespace

void Parser::parseColor(StatementReader &r) { emit(r, Color{rgba(r.numbers("r g b [a]", 3, 4))}); }

void Parser::parseNormal(StatementReader &r) { emit(r, Normal{r.numbers("x y z", 3, 3)}); }

void Parser::parseTexCoord(StatementReader &r) { emit(r, TexCoord{r.numbers("s [t [r [q]]]", 1, 4)}); }

void Parser::parseVertex(StatementReader &r) { emit(r, Vertex{r.numbers("x y [z [w]]", 2, 4)}); }

void Parser::parseEdgeFlag(StatementReader &r) { emit(r, EdgeFlag{r.boolean("the edge flag")}); }

void Parser::parseEnable(StatementReader &r) {
  Enable enable;
  enable.enable = r.statementName() == "enable";
  do {
    enable.caps.push_back(r.word(names::capabilities, "capability"));
  } while (!r.atEnd());
  emit(r, enable);
}

void Parser::parseDisable(StatementReader &r) { parseEnable(r); }

void Parser::parseShadeModel(StatementReader &r) {
  emit(r, ShadeModel{r.word(names::shadeModels, "shade model")});
}

void Parser::parseLight(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"ambient", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"diffuse", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"specular", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"position", ParamKind::Numbers, 4, 4, {}, "x y z w; w = 0 for a directional light"},
      {"spot_direction", ParamKind::Numbers, 3, 3, {}, "x y z"},
      {"spot_exponent", ParamKind::Numbers, 1, 1, {}, "0 to 128"},
      {"spot_cutoff", ParamKind::Numbers, 1, 1, {}, "0 to 90 degrees, or 180"},
      {"constant_attenuation", ParamKind::Numbers, 1, 1, {}, ""},
      {"linear_attenuation", ParamKind::Numbers, 1, 1, {}, ""},
      {"quadratic_attenuation", ParamKind::Numbers, 1, 1, {}, ""},
  };
  static const std::pair<const char *, GLenumValue> pnames[] = {
      {"ambient", GL_AMBIENT},
      {"diffuse", GL_DIFFUSE},
      {"specular", GL_SPECULAR},
      {"position", GL_POSITION},
      {"spot_direction", GL_SPOT_DIRECTION},
      {"spot_exponent", GL_SPOT_EXPONENT},
      {"spot_cutoff", GL_SPOT_CUTOFF},
      {"constant_attenuation", GL_CONSTANT_ATTENUATION},
      {"linear_attenuation", GL_LINEAR_ATTENUATION},
      {"quadratic_attenuation", GL_QUADRATIC_ATTENUATION},
  };
  Light light;
  light.index = r.integer("the light number", 0, 7);
  if (r.atEnd()) {
    r.fail(r.peek(), "'light " + std::to_string(light.index) +
                         "' needs parameters, for example 'light 0 position 0 5 5 1 diffuse 1 1 1'");
  }
  NamedParams params = NamedParams::read(r, specs);
  for (const ParamValue &value : params.values()) {
    std::string_view name = value.spec->name;
    if (name == "spot_exponent") checkRange(r, value, 0.0, 128.0, "must be between 0 and 128");
    if (name == "spot_cutoff") {
      const Number &n = value.numbers[0];
      if (n.isConstant() && !((n.constant >= 0.0 && n.constant <= 90.0) || n.constant == 180.0)) {
        r.fail(value.where, value.length, "spot_cutoff must be between 0 and 90 degrees, or 180 (no spot)");
      }
    }
    if (name.find("attenuation") != std::string_view::npos) {
      checkRange(r, value, 0.0, 1e300, "must not be negative");
    }
  }
  // In the order written, so that the GL calls come in the order the reader sees them.
  for (const ParamValue &value : params.values()) {
    for (const auto &[name, pname] : pnames) {
      if (value.spec->name != name) continue;
      NamedValues entry = namedNumbers(value, pname);
      if (pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR) entry.values = rgba(entry.values);
      light.values.push_back(entry);
    }
  }
  emit(r, light);
}

void Parser::parseLightModel(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"ambient", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"local_viewer", ParamKind::Boolean, 1, 1, {}, ""},
      {"two_side", ParamKind::Boolean, 1, 1, {}, ""},
      {"color_control", ParamKind::Word, 1, 1, names::colorControls, ""},
  };
  if (r.atEnd()) r.fail(r.peek(), "'light_model' needs parameters: ambient, local_viewer, two_side or color_control");
  NamedParams params = NamedParams::read(r, specs);
  LightModel model;
  for (const ParamValue &value : params.values()) {
    std::string_view name = value.spec->name;
    if (name == "ambient") model.values.push_back(NamedValues{GL_LIGHT_MODEL_AMBIENT, rgba(value.numbers), value.where});
    if (name == "local_viewer") model.values.push_back(namedBoolean(value, GL_LIGHT_MODEL_LOCAL_VIEWER));
    if (name == "two_side") model.values.push_back(namedBoolean(value, GL_LIGHT_MODEL_TWO_SIDE));
    if (name == "color_control") model.values.push_back(namedWord(value, GL_LIGHT_MODEL_COLOR_CONTROL));
  }
  emit(r, model);
}

void Parser::parseMaterial(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"ambient", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"diffuse", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"ambient_and_diffuse", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"specular", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"emission", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
      {"shininess", ParamKind::Numbers, 1, 1, {}, "0 to 128"},
  };
  Material material;
  material.face = GL_FRONT_AND_BACK;
  if (r.peek().kind == TokenKind::Word) {
    GLenumValue face = 0;
    if (lookupEnum(names::faces, r.peek().text, face)) {
      r.take();
      material.face = face;
    }
  }
  if (r.atEnd()) {
    r.fail(r.peek(), "'material' needs parameters, for example 'material diffuse 0.8 0.2 0.2 shininess 40'");
  }
  NamedParams params = NamedParams::read(r, specs);
  for (const ParamValue &value : params.values()) {
    std::string_view name = value.spec->name;
    if (name == "shininess") {
      checkRange(r, value, 0.0, 128.0, "must be between 0 and 128");
      material.values.push_back(namedNumbers(value, GL_SHININESS));
      continue;
    }
    GLenumValue pname = name == "ambient"    ? GL_AMBIENT
                        : name == "diffuse"  ? GL_DIFFUSE
                        : name == "specular" ? GL_SPECULAR
                        : name == "emission" ? GL_EMISSION
                                             : GL_AMBIENT_AND_DIFFUSE;
    material.values.push_back(NamedValues{pname, rgba(value.numbers), value.where});
  }
  emit(r, material);
}

void Parser::parseColorMaterial(StatementReader &r) {
  ColorMaterial cm;
  cm.face = r.word(names::faces, "face");
  cm.mode = r.word(names::colorMaterialModes, "material property");
  emit(r, cm);
}

void Parser::parseFog(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"mode", ParamKind::Word, 1, 1, names::fogModes, ""},
      {"density", ParamKind::Numbers, 1, 1, {}, "not negative"},
      {"start", ParamKind::Numbers, 1, 1, {}, ""},
      {"end", ParamKind::Numbers, 1, 1, {}, ""},
      {"color", ParamKind::Numbers, 3, 4, {}, "r g b [a]"},
  };
  if (r.atEnd()) r.fail(r.peek(), "'fog' needs parameters: mode, density, start, end or color");
  NamedParams params = NamedParams::read(r, specs);
  Fog fog;
  std::string context;
  if (const ParamValue *mode = params.take("mode")) {
    fog.values.push_back(namedWord(*mode, GL_FOG_MODE));
    // Linear fog uses start and end, the exponential modes use density (GL 1.1 section 3.9).
    if (mode->word == GL_LINEAR) {
      params.take("start"), params.take("end");
      context = "with mode linear (linear fog uses start and end)";
    } else {
      params.take("density");
      context = std::string("with mode ") + (mode->word == GL_EXP ? "exp" : "exp2") + " (it uses density)";
    }
  } else {
    params.take("start"), params.take("end"), params.take("density");
  }
  params.take("color");
  params.requireAllUsed(r, context);
  for (const ParamValue &value : params.values()) {
    std::string_view name = value.spec->name;
    if (name == "density") {
      checkRange(r, value, 0.0, 1e300, "must not be negative");
      fog.values.push_back(namedNumbers(value, GL_FOG_DENSITY));
    }
    if (name == "start") fog.values.push_back(namedNumbers(value, GL_FOG_START));
    if (name == "end") fog.values.push_back(namedNumbers(value, GL_FOG_END));
    if (name == "color") fog.values.push_back(NamedValues{GL_FOG_COLOR, rgba(value.numbers), value.where});
  }
  emit(r, fog);
}

void Parser::parseBlendFunc(StatementReader &r) {
  BlendFunc b;
  b.source = r.word(names::blendSourceFactors, "source factor");
  b.destination = r.word(names::blendDestinationFactors, "destination factor");
  emit(r, b);
}

void Parser::parseAlphaFunc(StatementReader &r) {
  AlphaFunc a;
  a.function = r.word(names::compareFunctions, "comparison");
  a.reference = r.number("reference value 0 to 1");
  emit(r, a);
}

void Parser::parseDepthFunc(StatementReader &r) {
  emit(r, DepthFunc{r.word(names::compareFunctions, "comparison")});
}

void Parser::parseDepthMask(StatementReader &r) { emit(r, DepthMask{r.boolean("the depth write mask")}); }

void Parser::parseDepthRange(StatementReader &r) {
  DepthRange d;
  d.zNear = r.number("near");
  d.zFar = r.number("far");
  emit(r, d);
}

void Parser::parseColorMask(StatementReader &r) {
  ColorMask m;
  for (int i = 0; i < 4; ++i) m.rgba[static_cast<std::size_t>(i)] = r.boolean("each of the four colour masks (r g b a)");
  emit(r, m);
}

void Parser::parseStencilFunc(StatementReader &r) {
  StencilFunc s;
  s.function = r.word(names::compareFunctions, "comparison");
  s.reference = r.integer("the reference value", 0, 255);
  s.mask = r.atEnd() ? 0xffffffffu : static_cast<unsigned>(r.integer("the mask", 0, 255));
  emit(r, s);
}

void Parser::parseStencilOp(StatementReader &r) {
  StencilOp s;
  s.fail = r.word(names::stencilOps, "stencil operation when the stencil test fails");
  s.depthFail = r.word(names::stencilOps, "stencil operation when the depth test fails");
  s.depthPass = r.word(names::stencilOps, "stencil operation when both pass");
  emit(r, s);
}

void Parser::parseStencilMask(StatementReader &r) {
  emit(r, StencilMask{static_cast<unsigned>(r.integer("the stencil write mask", 0, 255))});
}

void Parser::parseCullFace(StatementReader &r) { emit(r, CullFace{r.word(names::cullFaces, "face")}); }

void Parser::parseFrontFace(StatementReader &r) { emit(r, FrontFace{r.word(names::windings, "winding")}); }

void Parser::parsePolygonMode(StatementReader &r) {
  PolygonMode p;
  p.face = r.word(names::faces, "face");
  p.mode = r.word(names::polygonModes, "mode");
  emit(r, p);
}

void Parser::parsePolygonOffset(StatementReader &r) {
  PolygonOffset p;
  p.factor = r.number("factor");
  p.units = r.number("units");
  emit(r, p);
}

void Parser::parseClipPlane(StatementReader &r) {
  ClipPlane c;
  c.index = r.integer("the clip plane number", 0, 5);
  c.equation = r.numbers("plane a b c d, keeping points where ax + by + cz + d >= 0", 4, 4);
  emit(r, c);
}

void Parser::parseLineWidth(StatementReader &r) {
  const Token &at = r.peek();
  LineWidth w{r.number("width in pixels")};
  if (w.width.isConstant() && !(w.width.constant > 0.0)) r.fail(at, "the line width must be greater than 0");
  emit(r, w);
}

void Parser::parsePointSize(StatementReader &r) {
  const Token &at = r.peek();
  PointSize s{r.number("size in pixels")};
  if (s.size.isConstant() && !(s.size.constant > 0.0)) r.fail(at, "the point size must be greater than 0");
  emit(r, s);
}

void Parser::parseScissor(StatementReader &r) { emit(r, Scissor{r.numbers("x y width height", 4, 4)}); }

void Parser::parseLogicOp(StatementReader &r) { emit(r, LogicOp{r.word(names::logicOps, "logic operation")}); }

} // namespace glass::scene
