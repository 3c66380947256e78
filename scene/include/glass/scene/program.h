// A parsed scene: a list of statements, each standing for one GL call or a short, documented
// sequence of them (docs/scene-format.md gives the calls). The parser builds it, checks it and
// loads the files it names; the interpreter replays it into whatever GL is current.
//
// GL enumerants are stored as plain unsigned values (the GL's own numbers), so this header does
// not pull in a GL header and tools can include it whichever GL they link.
#pragma once

#include "glass/scene/source.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace glass::geometry {
struct IteratedFunctionSystem3;
}

namespace glass::scene {

using GLenumValue = unsigned int;

// A number written in a statement: a constant, or one component of a declared parameter (`$name`)
// whose value may change from frame to frame or be set on the command line.
struct Number {
  double constant = 0.0;
  int parameter = -1; // index into Program::parameters; -1 for a constant
  int component = 0;

  static Number of(double value) { return Number{value, -1, 0}; }
  bool isConstant() const { return parameter < 0; }
};
using Numbers = std::vector<Number>;

// ---- Parameters and animation --------------------------------------------------------------

struct Keyframe {
  double frame = 0.0;
  std::vector<double> value;
  SourceLocation where;
};

// `param NAME v...` (1 to 16 numbers) or `param NAME rotation ANGLE X Y Z`.
struct Parameter {
  enum class Kind { Numbers, Rotation };
  std::string name;
  Kind kind = Kind::Numbers;
  std::vector<double> value; // for a rotation: angle in degrees, then the axis
  std::vector<Keyframe> keys; // from `animate`, sorted by frame
  SourceLocation where;
  bool used = false; // referenced by some statement
};

// ---- Statements ------------------------------------------------------------------------------

struct Statement;
using StatementList = std::vector<Statement>;

// Output and camera.
struct Viewport { Numbers rect; };                       // glViewport(x, y, w, h)
struct ClearColor { Numbers rgba; };                     // glClearColor
struct ClearDepth { Number depth; };                     // glClearDepth
struct ClearStencil { int value = 0; };                  // glClearStencil
struct Clear { unsigned mask = 0; };                     // glClear
struct Perspective { Number fovy; std::optional<Number> aspect; Number zNear, zFar; }; // gluPerspective
struct Frustum { Numbers planes; };                      // glFrustum (l r b t n f)
struct Ortho { Numbers planes; };                        // glOrtho, or gluOrtho2D with 4 values
struct LookAt { Numbers values; };                       // gluLookAt (eye, centre, up)

// Transforms (on the modelview matrix).
struct LoadIdentity {};
struct Translate { Numbers v; };
struct Rotate { Number angle; Numbers axis; };           // glRotate
struct RotateQuaternion { Numbers wxyz; };               // glMultMatrix of the quaternion's matrix
struct RotateByParameter { int parameter = -1; };        // glRotate of a (possibly slerped) rotation
struct Scale { Numbers v; };
struct MultMatrix { Numbers rowMajor; };                 // 16 values, or 6 for a 2D affine map
struct ShadowMatrix { Numbers plane, light; };           // glMultMatrixd of a planar projection
struct Push { };                                         // glPushMatrix + glPushAttrib(all)
struct Pop { };                                          // glPopAttrib + glPopMatrix

// Current vertex attributes (outside begin/end they set the current value, inside they go with
// the next vertex, exactly as in GL).
struct Color { Numbers rgba; };                          // glColor4
struct Normal { Numbers xyz; };                          // glNormal3
struct TexCoord { Numbers stqr; };                       // glTexCoord1..4
struct Vertex { Numbers xyzw; };                         // glVertex2..4
struct EdgeFlag { bool flag = true; };                   // glEdgeFlag

// GL state.
struct Enable { std::vector<GLenumValue> caps; bool enable = true; };
struct ShadeModel { GLenumValue mode = 0; };
struct NamedValues {                                     // one glXxxfv call per entry
  GLenumValue pname = 0;
  Numbers values;
  SourceLocation where;
};
struct Light { int index = 0; std::vector<NamedValues> values; };      // glLightfv
struct LightModel { std::vector<NamedValues> values; };                // glLightModelfv
struct Material { GLenumValue face = 0; std::vector<NamedValues> values; }; // glMaterialfv
struct ColorMaterial { GLenumValue face = 0, mode = 0; };
struct Fog { std::vector<NamedValues> values; };                       // glFogfv / glFogi
struct BlendFunc { GLenumValue source = 0, destination = 0; };
struct AlphaFunc { GLenumValue function = 0; Number reference; };
struct DepthFunc { GLenumValue function = 0; };
struct DepthMask { bool write = true; };
struct DepthRange { Number zNear, zFar; };
struct ColorMask { std::array<bool, 4> rgba{true, true, true, true}; };
struct StencilFunc { GLenumValue function = 0; int reference = 0; unsigned mask = 0xffffffffu; };
struct StencilOp { GLenumValue fail = 0, depthFail = 0, depthPass = 0; };
struct StencilMask { unsigned mask = 0xffffffffu; };
struct CullFace { GLenumValue face = 0; };
struct FrontFace { GLenumValue winding = 0; };
struct PolygonMode { GLenumValue face = 0, mode = 0; };
struct PolygonOffset { Number factor, units; };
struct ClipPlane { int index = 0; Numbers equation; };
struct LineWidth { Number width; };
struct PointSize { Number size; };
struct Scissor { Numbers rect; };
struct LogicOp { GLenumValue op = 0; };

// Textures.
struct BindTexture { int texture = -1; };                // index into Program::textures; -1: none
struct TexEnv { std::optional<GLenumValue> mode; Numbers color; };
struct TexGen { GLenumValue coord = 0; std::optional<GLenumValue> mode; Numbers objectPlane, eyePlane; };

// Shadow mapping (docs/scene-format.md, "shadow_map"): the light's view is
// gluPerspective(fovy, 1, near, far) x gluLookAt(from, to, up).
struct LightView { Numbers from, to, up; Number fovy, zNear, zFar; };
struct ShadowMap {               // the depth of a definition seen from the light, into a depth texture
  int texture = -1;              // index into Program::textures (a depth texture)
  int definition = -1;           // index into Program::definitions: what casts shadows
  LightView light;
  Number offsetFactor, offsetUnits; // glPolygonOffset while drawing the depth
};
struct ShadowTexGen { int texture = -1; LightView light; }; // binds it, eye-linear texgen of the light's view

// Geometry.
struct Begin { GLenumValue mode = 0; StatementList body; };  // glBegin ... glEnd
struct Rect { Numbers corners; };                           // glRect
struct Mesh {                                               // vertex arrays + glDrawElements/Arrays
  GLenumValue mode = 0;
  int positionSize = 3;
  int texcoordSize = 2;
  int colorSize = 3;
  Numbers positions, normals, colors, texcoords;
  std::vector<std::uint32_t> indices;
  bool indexed = false;
};
struct DrawModel {                                          // index into Program::models
  int model = -1;
  bool useMaterials = true;
  std::optional<Number> round; // .wings models: round the marked edges with this radius
};
struct QuadricStyle {                                       // gluQuadric* settings
  GLenumValue drawStyle = 0, normals = 0, orientation = 0;
  bool texture = false;
};
struct Sphere { Number radius; int slices = 32, stacks = 16; QuadricStyle style; };
struct Cylinder { Number base, top, height; int slices = 32, stacks = 1; QuadricStyle style; };
struct Disk { Number inner, outer; int slices = 32, loops = 1; QuadricStyle style; };
struct PartialDisk { Number inner, outer; int slices = 32, loops = 1; Number start, sweep; QuadricStyle style; };
struct GlutShape {                                          // glutSolid* / glutWire*
  enum class Kind { Cube, Sphere, Cone, Torus, Tetrahedron, Octahedron, Dodecahedron, Icosahedron, Teapot, Teacup, Teaspoon };
  Kind kind = Kind::Cube;
  bool wire = false;
  Numbers sizes; // cube: size; sphere: radius; cone: base, height; torus: inner, outer; teapot: size
  int slices = 0, stacks = 0;
};
struct ParametricTorus {                                    // the exam's torus, with (s, t)
  Number major, minor;
  int slices = 48, rings = 24;
};
struct BezierCurve {                                        // glMap1 + glMapGrid1 + glEvalMesh1
  Numbers points;  // order * 3
  Numbers weights; // empty, or order values (rational: GL_MAP1_VERTEX_4)
  int order = 0;
  int segments = 32;
  GLenumValue mode = 0; // GL_LINE or GL_POINT
};
struct BezierPatch {                                        // glMap2 + glMapGrid2 + glEvalMesh2
  Numbers points;  // uorder * vorder * 3, u varying fastest
  Numbers weights; // empty, or uorder * vorder
  int uOrder = 0, vOrder = 0;
  int uSegments = 16, vSegments = 16;
  GLenumValue mode = 0; // GL_FILL, GL_LINE or GL_POINT
  bool texcoords = false;
  bool autoNormal = true;
};

// Iterated function systems (study guide 2.2.2). Drawn through glass::geometry's IFS model
// (geometry/include/glass/geometry/ifs.h), which `glass ifs` shares.
struct AffineStep {
  enum class Kind { Translate, Rotate, Scale, Shear, Matrix };
  Kind kind = Kind::Translate;
  Numbers values; // translate: 2; rotate: 1 (degrees); scale: 2; shear: 1; matrix: 6 (2x3 rows)
};
struct IfsMap {
  std::vector<AffineStep> steps; // composed in the order written, as GL calls would be
  Numbers color;                 // empty: the palette colour of its part
  std::optional<Number> probability;
  SourceLocation where;
};
struct Ifs {
  enum class Mode { Recursive, Chaos };
  Mode mode = Mode::Recursive;
  int depth = 6;
  std::int64_t points = 100000;
  std::uint64_t seed = 1;
  bool partColors = true; // each map's part in its own colour; off: the current colour
  std::vector<IfsMap> maps;
  StatementList base; // the shape drawn at depth 0 (recursive mode)
};

// `ifs3d`: the polyhedral rebuild of a 3D IFS file (geometry/include/glass/geometry/ifs3d.h),
// optionally moved by one map's animation as translation x rotation x scaling.
struct Ifs3d {
  std::shared_ptr<const geometry::IteratedFunctionSystem3> system;
  int depth = 3;
  bool partColors = true;
  int animatedMap = -1; // 0-based; -1: drawn in place
  Number step;          // 0..1 along the animation of animatedMap
};

struct Instance { int definition = -1; }; // glCallList of a `define`d block

struct Statement {
  SourceLocation where;
  int length = 1; // columns of the statement name, for carets
  std::variant<Viewport, ClearColor, ClearDepth, ClearStencil, Clear, Perspective, Frustum, Ortho,
               LookAt, LoadIdentity, Translate, Rotate, RotateQuaternion, RotateByParameter, Scale,
               MultMatrix, ShadowMatrix, Push, Pop, Color, Normal, TexCoord, Vertex, EdgeFlag, Enable,
               ShadeModel, Light, LightModel, Material, ColorMaterial, Fog, BlendFunc, AlphaFunc,
               DepthFunc, DepthMask, DepthRange, ColorMask, StencilFunc, StencilOp, StencilMask,
               CullFace, FrontFace, PolygonMode, PolygonOffset, ClipPlane, LineWidth, PointSize,
               Scissor, LogicOp, BindTexture, TexEnv, TexGen, Begin, Rect, Mesh, DrawModel,
               Sphere, Cylinder, Disk, PartialDisk, GlutShape, ParametricTorus, BezierCurve,
               BezierPatch, Ifs, Instance, Ifs3d, ShadowMap, ShadowTexGen>
      body;
};

// ---- Resources the statements refer to -------------------------------------------------------

// An RGBA8 picture, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

struct TextureDefinition {
  std::string name;
  std::string path; // empty for a procedural texture
  Image image;
  GLenumValue minFilter = 0, magFilter = 0, wrapS = 0, wrapT = 0;
  Numbers borderColor;
  bool mipmaps = false; // built with gluBuild2DMipmaps because minFilter needs them
  SourceLocation where;
  // A shadow map's depth texture (`shadow_map`): no image, GL_DEPTH_COMPONENT of `depthSize`
  // texels a side, compared with r (GL_COMPARE_R_TO_TEXTURE) by compareFunction.
  bool depth = false;
  int depthSize = 0;
  GLenumValue compareFunction = 0, depthTextureMode = 0;
};

// A Wavefront OBJ file or a Wings3D file, flattened to triangles grouped by material.
struct ModelMaterial {
  std::array<float, 4> ambient{0.2f, 0.2f, 0.2f, 1.0f};
  std::array<float, 4> diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  std::array<float, 4> specular{0.0f, 0.0f, 0.0f, 1.0f};
  std::array<float, 4> emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;
  int texture = -1; // index into Program::textures (map_Kd), or -1
};
struct ModelPart {
  int material = -1; // index into Model::materials, or -1 for the current GL material
  std::vector<float> positions, normals, texcoords; // 3, 3 and 2 per vertex; 3 vertices a triangle
};
struct RoundableModel; // a .wings model's polyhedra, rounded when drawn (scene/src/load/wings_model.h)
struct Model {
  std::string path;
  std::shared_ptr<const RoundableModel> roundable; // .wings models only
  std::vector<ModelMaterial> materials;
  std::vector<ModelPart> parts;
  bool hasNormals = false;
};

struct Definition {
  std::string name;
  StatementList body;
  SourceLocation where;
};

struct Program {
  std::shared_ptr<SourceSet> sources; // keeps every location valid
  std::string path;                   // the scene file
  int width = 640, height = 480;      // `size`
  int frames = 1;                     // `frames`
  std::vector<Parameter> parameters;
  std::vector<TextureDefinition> textures;
  std::vector<Model> models;
  std::vector<Definition> definitions;
  StatementList statements;

  int findParameter(const std::string &name) const;
};

} // namespace glass::scene
