// Wings3D's own file format (.wings), read into polyhedra with their marked edges.
//
// A .wings file is the header "#!WINGS-1.0\r\n\032\04", a 32-bit big-endian byte count, and that
// many bytes of term_to_binary({wings, 2, {Shapes, Materials, Props}}, [compressed]) (Wings3D's
// src/wings_ff_wings.erl writes it; erlang_term.h decodes it). Each shape is
//   {object, Name, {winged, Edges, Faces, Vertices, HardEdges}, Props}
// in Wings' winged-edge form: edge number i is the list [{edge, Vs, Ve, Lf, Rf, Ltpr, Ltsu, Rtpr,
// Rtsu} | Attributes], where the attributes {uv_lt, <<U:64/float, V:64/float>>} and {uv_rt, ...}
// are the texture coordinates of Vs in the left face Lf and of Ve in the right face Rf; face
// number i is [] or [{material, Name}]; vertex number i is [<<X:64/float, Y:64/float, Z:64/float>>];
// HardEdges lists the numbers of the hard (marked) edges. A face's vertices are those met walking
// its edges by their successors (Ltsu for the left face, Rtsu for the right), in the reverse order
// of the walk, which is counter-clockwise seen from outside (wings_face:vertices_ccw). Materials
// are {Name, [{opengl, [{diffuse, {R, G, B, A}}, {ambient, ...}, {specular, ...}, {emission, ...},
// {shininess, S}]} | ...]} with S in [0, 1] (GL's shininess is 128 S). Faces listed in an object's
// `holes` property are holes, not faces; everything else in the file (images, lights, views,
// plug-in settings, vertex colours) is read past.
#pragma once

#include "glass/geometry/edge_rounding.h"

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace glass::scene {

struct WingsMaterial {
  std::string name;
  std::array<float, 4> ambient{0.2f, 0.2f, 0.2f, 1.0f};
  std::array<float, 4> diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  std::array<float, 4> specular{0.0f, 0.0f, 0.0f, 1.0f};
  std::array<float, 4> emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;  // GL's 0..128
};

struct WingsObject {
  std::string name;
  geometry::MarkedPolyhedron shape;  // face materials index WingsFile::materials, -1 for none
};

struct WingsFile {
  std::vector<WingsObject> objects;
  std::vector<WingsMaterial> materials;
};

class WingsFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The file's bytes; throws WingsFileError naming what is wrong (which object, which field).
WingsFile parseWingsFile(std::span<const std::uint8_t> bytes);
// Reads and parses a file; the message of a WingsFileError starts with "path: ".
WingsFile readWingsFile(const std::string &path);

} // namespace glass::scene
