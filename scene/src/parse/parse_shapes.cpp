// Shapes made by GLU, GLUT and the evaluators: quadrics, the GLUT solids, the exam's torus,
// Bezier curves and patches. The positional values follow the GLU/GLUT function's arguments.
#include "gl_api.h"
#include "parser_impl.h"

#include <cmath>

namespace glass::scene {

namespace {

const ParamSpec kQuadricSpecs[] = {
    {"draw_style", ParamKind::Word, 1, 1, names::quadricDrawStyles, ""},
    {"normals", ParamKind::Word, 1, 1, names::quadricNormals, ""},
    {"orientation", ParamKind::Word, 1, 1, names::quadricOrientations, ""},
    {"texture", ParamKind::Boolean, 1, 1, {}, ""},
};

Number positive(StatementReader &r, std::string_view what, bool allowZero = false) {
  const Token &at = r.peek();
  Number n = r.number(what);
  if (n.isConstant() && (allowZero ? n.constant < 0.0 : !(n.constant > 0.0))) {
    r.fail(at, std::string(what) + (allowZero ? " must not be negative" : " must be greater than 0"));
  }
  return n;
}

// The largest evaluator order GL guarantees (GL_MAX_EVAL_ORDER is at least 8).
constexpr int kMaxEvalOrder = 8;
// Slices, stacks, loops, rings and Bezier segments: docs/scene-format.md, "Limits".
constexpr int kMaxDivisions = 4096;

void checkWeights(const StatementReader &r, const ParamValue &weights) {
  for (const Number &w : weights.numbers) {
    if (w.isConstant() && !(w.constant > 0.0)) {
      r.fail(weights.where, weights.length, "weights must be greater than 0");
    }
  }
}

} // namespace

QuadricStyle Parser::readQuadricStyle(NamedParams &params) {
  QuadricStyle style;
  style.drawStyle = params.wordOr("draw_style", GLU_FILL);
  style.normals = params.wordOr("normals", GLU_SMOOTH);
  style.orientation = params.wordOr("orientation", GLU_OUTSIDE);
  style.texture = params.booleanOr("texture", false);
  return style;
}

void Parser::parseSphere(StatementReader &r) {
  Sphere s;
  s.radius = positive(r, "radius", true);
  if (r.peekIsNumber()) s.slices = r.integer("slices", 3, kMaxDivisions);
  if (r.peekIsNumber()) s.stacks = r.integer("stacks", 2, kMaxDivisions);
  NamedParams params = NamedParams::read(r, kQuadricSpecs);
  s.style = readQuadricStyle(params);
  emit(r, s);
}

void Parser::parseCylinder(StatementReader &r) {
  Cylinder c;
  c.base = positive(r, "base radius", true);
  c.top = positive(r, "top radius", true);
  c.height = positive(r, "height", true);
  if (r.peekIsNumber()) c.slices = r.integer("slices", 3, kMaxDivisions);
  if (r.peekIsNumber()) c.stacks = r.integer("stacks", 1, kMaxDivisions);
  NamedParams params = NamedParams::read(r, kQuadricSpecs);
  c.style = readQuadricStyle(params);
  emit(r, c);
}

void Parser::parseDisk(StatementReader &r) {
  Disk d;
  d.inner = positive(r, "inner radius", true);
  d.outer = positive(r, "outer radius");
  if (d.inner.isConstant() && d.outer.isConstant() && d.inner.constant >= d.outer.constant) {
    r.fail(r.statementToken(), "the inner radius of 'disk' must be smaller than the outer radius");
  }
  if (r.peekIsNumber()) d.slices = r.integer("slices", 3, kMaxDivisions);
  if (r.peekIsNumber()) d.loops = r.integer("loops", 1, kMaxDivisions);
  NamedParams params = NamedParams::read(r, kQuadricSpecs);
  d.style = readQuadricStyle(params);
  emit(r, d);
}

void Parser::parsePartialDisk(StatementReader &r) {
  PartialDisk d;
  d.inner = positive(r, "inner radius", true);
  d.outer = positive(r, "outer radius");
  d.slices = r.integer("slices", 3, kMaxDivisions);
  d.loops = r.integer("loops", 1, kMaxDivisions);
  d.start = r.number("start angle in degrees");
  d.sweep = r.number("sweep angle in degrees");
  NamedParams params = NamedParams::read(r, kQuadricSpecs);
  d.style = readQuadricStyle(params);
  emit(r, d);
}

void Parser::parseGlutShape(StatementReader &r) {
  const std::string &name = r.statementName();
  GlutShape shape;
  shape.wire = name.rfind("wire_", 0) == 0;
  std::string_view kind = std::string_view(name).substr(name.find('_') + 1);
  using K = GlutShape::Kind;
  if (kind == "cube") {
    shape.kind = K::Cube;
    shape.sizes = {positive(r, "size")};
  } else if (kind == "sphere") {
    shape.kind = K::Sphere;
    shape.sizes = {positive(r, "radius")};
    shape.slices = r.integer("slices", 3, kMaxDivisions);
    shape.stacks = r.integer("stacks", 2, kMaxDivisions);
  } else if (kind == "cone") {
    shape.kind = K::Cone;
    shape.sizes = {positive(r, "base radius"), positive(r, "height")};
    shape.slices = r.integer("slices", 3, kMaxDivisions);
    shape.stacks = r.integer("stacks", 1, kMaxDivisions);
  } else if (kind == "torus") {
    shape.kind = K::Torus;
    shape.sizes = {positive(r, "inner (tube) radius"), positive(r, "outer (ring) radius")};
    shape.slices = r.integer("sides", 3, kMaxDivisions);
    shape.stacks = r.integer("rings", 3, kMaxDivisions);
  } else if (kind == "teapot" || kind == "teacup" || kind == "teaspoon") {
    shape.kind = kind == "teapot" ? K::Teapot : (kind == "teacup" ? K::Teacup : K::Teaspoon);
    shape.sizes = {positive(r, "size")};
  } else if (kind == "tetrahedron") {
    shape.kind = K::Tetrahedron;
  } else if (kind == "octahedron") {
    shape.kind = K::Octahedron;
  } else if (kind == "dodecahedron") {
    shape.kind = K::Dodecahedron;
  } else {
    shape.kind = K::Icosahedron;
  }
  emit(r, shape);
}

void Parser::parseParametricTorus(StatementReader &r) {
  ParametricTorus t;
  t.major = positive(r, "major radius R");
  t.minor = positive(r, "minor radius r");
  if (r.peekIsNumber()) t.slices = r.integer("slices", 3, kMaxDivisions);
  if (r.peekIsNumber()) t.rings = r.integer("rings", 3, kMaxDivisions);
  emit(r, t);
}

void Parser::parseBezierCurve(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"points", ParamKind::List, 3, 3, {}, ""},
      {"weights", ParamKind::List, 1, 1, {}, ""},
      {"segments", ParamKind::Integer, 1, kMaxDivisions, {}, ""},
      {"mode", ParamKind::Word, 1, 1, names::curveModes, ""},
  };
  NamedParams params = NamedParams::read(r, specs);
  BezierCurve curve;
  const ParamValue *points = params.take("points");
  if (points == nullptr) r.fail(r.statementToken(), "'bezier_curve' needs 'points [x y z ...]'");
  curve.points = points->numbers;
  curve.order = static_cast<int>(points->numbers.size() / 3);
  if (curve.order < 2 || curve.order > kMaxEvalOrder) {
    r.fail(points->where, points->length,
           "a Bezier curve needs 2 to " + std::to_string(kMaxEvalOrder) + " control points (degree 1 to " +
               std::to_string(kMaxEvalOrder - 1) + "), not " + std::to_string(curve.order));
  }
  if (const ParamValue *weights = params.take("weights")) {
    if (static_cast<int>(weights->numbers.size()) != curve.order) {
      r.fail(weights->where, weights->length,
             "weights gives " + std::to_string(weights->numbers.size()) + " numbers for " +
                 std::to_string(curve.order) + " control points");
    }
    checkWeights(r, *weights);
    curve.weights = weights->numbers;
  }
  curve.segments = static_cast<int>(params.integerOr("segments", 32));
  curve.mode = params.wordOr("mode", GL_LINE);
  emit(r, curve);
}

void Parser::parseBezierPatch(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"u_order", ParamKind::Integer, 2, kMaxEvalOrder, {}, ""},
      {"v_order", ParamKind::Integer, 2, kMaxEvalOrder, {}, ""},
      {"points", ParamKind::List, 3, 3, {}, ""},
      {"weights", ParamKind::List, 1, 1, {}, ""},
      {"segments", ParamKind::Numbers, 1, 2, {}, "u [v]"},
      {"mode", ParamKind::Word, 1, 1, names::polygonModes, ""},
      {"texcoords", ParamKind::Boolean, 1, 1, {}, ""},
      {"auto_normal", ParamKind::Boolean, 1, 1, {}, ""},
  };
  NamedParams params = NamedParams::read(r, specs);
  BezierPatch patch;
  const ParamValue *uOrder = params.take("u_order");
  const ParamValue *vOrder = params.take("v_order");
  const ParamValue *points = params.take("points");
  if (uOrder == nullptr || vOrder == nullptr || points == nullptr) {
    r.fail(r.statementToken(), "'bezier_patch' needs u_order, v_order and points [x y z ...]");
  }
  patch.uOrder = static_cast<int>(uOrder->integer);
  patch.vOrder = static_cast<int>(vOrder->integer);
  std::size_t expected = static_cast<std::size_t>(patch.uOrder * patch.vOrder);
  if (points->numbers.size() / 3 != expected) {
    r.fail(points->where, points->length,
           "points gives " + std::to_string(points->numbers.size() / 3) + " control points; u_order " +
               std::to_string(patch.uOrder) + " x v_order " + std::to_string(patch.vOrder) + " needs " +
               std::to_string(expected));
  }
  patch.points = points->numbers;
  if (const ParamValue *weights = params.take("weights")) {
    if (weights->numbers.size() != expected) {
      r.fail(weights->where, weights->length,
             "weights gives " + std::to_string(weights->numbers.size()) + " numbers for " +
                 std::to_string(expected) + " control points");
    }
    checkWeights(r, *weights);
    patch.weights = weights->numbers;
  }
  if (const ParamValue *segments = params.take("segments")) {
    int values[2] = {0, 0};
    for (std::size_t i = 0; i < segments->numbers.size(); ++i) {
      const Number &n = segments->numbers[i];
      if (!n.isConstant() || n.constant != std::floor(n.constant) || n.constant < 1 || n.constant > kMaxDivisions) {
        r.fail(segments->where, segments->length,
               "segments must be whole numbers from 1 to " + std::to_string(kMaxDivisions));
      }
      values[i] = static_cast<int>(n.constant);
    }
    patch.uSegments = values[0];
    patch.vSegments = segments->numbers.size() == 2 ? values[1] : values[0];
  }
  patch.mode = params.wordOr("mode", GL_FILL);
  patch.texcoords = params.booleanOr("texcoords", false);
  patch.autoNormal = params.booleanOr("auto_normal", true);
  emit(r, patch);
}

} // namespace glass::scene
