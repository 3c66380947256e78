/* The first object of a Wings3D file (.wings) as a mesh: its vertices' positions, its edges in
 * winged-edge form (two vertices, the faces on their left and right) and which edges are marked
 * hard. wings_plan.c and cube_layers.c read the homework's object from it. */
#ifndef HOMEWORK45_WINGS_MESH_H
#define HOMEWORK45_WINGS_MESH_H

#include <stddef.h>

struct winged_edge {
  long vs, ve, lf, rf;
};

struct wings_mesh {
  long vertex_count, edge_count, face_count;
  double (*position)[3];
  struct winged_edge *edges;
  int *hard; /* per edge: whether it is marked hard */
};

/* Reads the first object of a .wings file. Returns 0 and writes the reason into `error` when the
 * file cannot be read or holds no such object. */
int wings_read_mesh(const char *path, struct wings_mesh *mesh, char *error, size_t error_size);
void wings_mesh_free(struct wings_mesh *mesh);

/* Writes the message into `error` (of `size` bytes) and returns 0, for `return wings_failed(...)`. */
int wings_failed(char *error, size_t size, const char *format, ...);

#endif
