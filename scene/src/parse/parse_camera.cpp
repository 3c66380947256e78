// Output, camera and transform statements.
#include "gl_api.h"
#include "parser_impl.h"

namespace glass::scene {

namespace {

// Checks a constant against a range when it is known while parsing; parameters are checked
// when the frame is drawn.
void requirePositive(const StatementReader &r, const Number &n, const Token &at, const char *what) {
  if (n.isConstant() && !(n.constant > 0.0)) r.fail(at, std::string(what) + " must be greater than 0");
}

} // namespace

void Parser::parseViewport(StatementReader &r) {
  emit(r, Viewport{r.numbers("x y width height", 4, 4)});
}

void Parser::parseClearColor(StatementReader &r) {
  Numbers rgba = r.numbers("r g b [a]", 3, 4);
  if (rgba.size() == 3) rgba.push_back(Number::of(1.0));
  emit(r, ClearColor{rgba});
}

void Parser::parseClearDepth(StatementReader &r) { emit(r, ClearDepth{r.number("depth")}); }

void Parser::parseClearStencil(StatementReader &r) {
  emit(r, ClearStencil{r.integer("the stencil clear value", 0, 255)});
}

void Parser::parseClear(StatementReader &r) {
  unsigned mask = 0;
  while (!r.atEnd()) mask |= r.word(names::clearBuffers, "buffer");
  if (mask == 0) mask = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
  emit(r, Clear{mask});
}

void Parser::parsePerspective(StatementReader &r) {
  Perspective p;
  const Token &fovyToken = r.peek();
  p.fovy = r.number("field of view in degrees");
  if (p.fovy.isConstant() && !(p.fovy.constant > 0.0 && p.fovy.constant < 180.0)) {
    r.fail(fovyToken, "the field of view must be between 0 and 180 degrees");
  }
  const Token &aspectToken = r.peek();
  if (r.peekIsWord("auto")) {
    r.take();
  } else {
    p.aspect = r.number("aspect ratio (or auto)");
    requirePositive(r, *p.aspect, aspectToken, "the aspect ratio");
  }
  const Token &nearToken = r.peek();
  p.zNear = r.number("near distance");
  requirePositive(r, p.zNear, nearToken, "the near distance of a perspective projection");
  const Token &farToken = r.peek();
  p.zFar = r.number("far distance");
  if (p.zNear.isConstant() && p.zFar.isConstant() && !(p.zFar.constant > p.zNear.constant)) {
    r.fail(farToken, "the far distance must be greater than the near distance");
  }
  emit(r, p);
}

void Parser::parseFrustum(StatementReader &r) {
  const Token &first = r.peek();
  Numbers planes = r.numbers("left right bottom top near far", 6, 6);
  if (planes[4].isConstant() && planes[5].isConstant() &&
      !(planes[4].constant > 0.0 && planes[5].constant > 0.0)) {
    r.fail(first, "near and far of 'frustum' must both be greater than 0 (glFrustum gives GL_INVALID_VALUE)");
  }
  emit(r, Frustum{planes});
}

void Parser::parseOrtho(StatementReader &r) {
  Numbers planes = r.numbers("left right bottom top [near far]", 4, 6);
  if (planes.size() == 5) r.fail(r.peek(), "'ortho' takes 4 numbers (as gluOrtho2D) or 6 (as glOrtho), not 5");
  emit(r, Ortho{planes});
}

void Parser::parseLookAt(StatementReader &r) {
  emit(r, LookAt{r.numbers("eye x y z, centre x y z, up x y z", 9, 9)});
}

void Parser::parseLoadIdentity(StatementReader &r) {
  r.end();
  emit(r, LoadIdentity{});
}

void Parser::parseTranslate(StatementReader &r) { emit(r, Translate{r.numbers("x y z", 3, 3)}); }

void Parser::parseRotate(StatementReader &r) {
  const Token &first = r.peek();
  if (first.kind == TokenKind::Reference) {
    int index = 0;
    Parameter *parameter = findParameter(first.text, index);
    if (parameter != nullptr && parameter->kind == Parameter::Kind::Rotation) {
      r.take();
      emit(r, RotateByParameter{index});
      return;
    }
  }
  if (r.peekIsWord("quaternion")) {
    r.take();
    Numbers q = r.numbers("w x y z", 4, 4);
    bool constant = true;
    double norm2 = 0.0;
    for (const Number &n : q) {
      constant = constant && n.isConstant();
      norm2 += n.constant * n.constant;
    }
    if (constant && norm2 == 0.0) r.fail(first, "the quaternion 0 0 0 0 is no rotation");
    emit(r, RotateQuaternion{q});
    return;
  }
  Rotate rotate;
  rotate.angle = r.number("angle in degrees");
  const Token &axisToken = r.peek();
  rotate.axis = r.numbers("axis x y z", 3, 3);
  bool constant = rotate.axis[0].isConstant() && rotate.axis[1].isConstant() && rotate.axis[2].isConstant();
  if (constant && rotate.axis[0].constant == 0.0 && rotate.axis[1].constant == 0.0 &&
      rotate.axis[2].constant == 0.0) {
    r.fail(axisToken, "the rotation axis 0 0 0 has no direction");
  }
  emit(r, rotate);
}

void Parser::parseScale(StatementReader &r) {
  Numbers v = r.numbers("x y z, or one factor for all three", 1, 3);
  if (v.size() == 2) r.fail(r.peek(), "'scale' takes 1 number (the same factor for x, y and z) or 3, not 2");
  if (v.size() == 1) v = {v[0], v[0], v[0]};
  emit(r, Scale{v});
}

void Parser::parseMatrix(StatementReader &r) {
  const Token &first = r.peek();
  Numbers values;
  if (first.kind == TokenKind::ListOpen) {
    values = r.list("the matrix", 1);
  } else {
    values = r.numbers("16 numbers row by row, or 6 for a 2D affine map", 6, 16);
  }
  if (values.size() != 16 && values.size() != 6) {
    r.fail(first, "'matrix' takes 16 numbers (a 4x4 matrix row by row) or 6 (a 2D affine map a11 a12 a13 "
                  "a21 a22 a23), not " + std::to_string(values.size()));
  }
  emit(r, MultMatrix{values});
}

void Parser::parseShadowMatrix(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"plane", ParamKind::Numbers, 4, 4, {}, "a b c d of the plane ax + by + cz + d = 0"},
      {"light", ParamKind::Numbers, 4, 4, {}, "x y z w; w = 0 for a directional light"},
  };
  NamedParams params = NamedParams::read(r, specs);
  const ParamValue *plane = params.take("plane");
  const ParamValue *light = params.take("light");
  if (plane == nullptr || light == nullptr) {
    r.fail(r.statementToken(), "'shadow_matrix' needs 'plane A B C D' and 'light X Y Z W'");
  }
  emit(r, ShadowMatrix{plane->numbers, light->numbers});
}

} // namespace glass::scene
