/* Reading the homework's object from a .wings file: Wings3D's layout (src/wings_ff_wings.erl):
 * "#!WINGS-1.0\r\n\032\04", a 32-bit size, then term_to_binary({wings, 2, {Shapes, Materials,
 * Props}}); each shape is {object, Name, {winged, Edges, Faces, Vertices, HardEdges}, Props}, the
 * winged-edge form: each edge a list holding {edge, Vs, Ve, Lf, Rf, Ltpr, Ltsu, Rtpr, Rtsu}, each
 * vertex a list starting with <<X/float, Y/float, Z/float>>, each hard edge an edge's number. A
 * face runs counter-clockwise seen from outside along its left edges from Vs to Ve and along its
 * right edges from Ve to Vs. The object's Props may list faces that are holes: {holes, Faces}. */
#include "wings_mesh.h"

#include "erlang_term.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HEADER "#!WINGS-1.0\r\n\032\04"
#define HEADER_LENGTH 15

int wings_failed(char *error, size_t size, const char *format, ...)
{
  va_list args;
  va_start(args, format);
  vsnprintf(error, size, format, args);
  va_end(args);
  return 0;
}

static unsigned char *read_file(const char *path, size_t *size)
{
  FILE *file = fopen(path, "rb");
  if (!file) return NULL;
  unsigned char *data = NULL;
  size_t used = 0, capacity = 0;
  for (;;) {
    if (used == capacity) {
      capacity = capacity ? 2 * capacity : 65536;
      unsigned char *grown = realloc(data, capacity);
      if (!grown) break;
      data = grown;
    }
    const size_t got = fread(data + used, 1, capacity - used, file);
    used += got;
    if (got == 0) break;
  }
  const int ok = !ferror(file) && data;
  fclose(file);
  if (!ok) {
    free(data);
    return NULL;
  }
  *size = used;
  return data;
}

static const struct term *tagged(const struct term *t, const char *tag, size_t arity)
{
  return t->kind == TERM_TUPLE && t->length == arity && term_is_atom(&t->items[0], tag) ? t : NULL;
}

static int index_in(const struct term *t, long count, long *out)
{
  if (t->kind != TERM_INTEGER || t->integer < 0 || t->integer >= count) return 0;
  *out = (long)t->integer;
  return 1;
}

static double big_endian_double(const unsigned char *bytes)
{
  unsigned long long bits = 0;
  for (int i = 0; i < 8; ++i) bits = bits << 8 | bytes[i];
  double value;
  memcpy(&value, &bits, sizeof value);
  return value;
}

/* The first object's vertices and edges. */
static int read_object(const struct term *root, struct wings_mesh *object, char *error, size_t size)
{
  const struct term *file = tagged(root, "wings", 3);
  if (!file || file->items[1].kind != TERM_INTEGER || file->items[1].integer != 2)
    return wings_failed(error, size, "not a version 2 {wings, 2, {Shapes, Materials, Props}} term");
  const struct term *content = &file->items[2];
  if (content->kind != TERM_TUPLE || content->length < 1 || content->items[0].kind != TERM_LIST)
    return wings_failed(error, size, "no list of shapes");
  const struct term *shapes = &content->items[0];
  if (shapes->length == 0) return wings_failed(error, size, "the file has no object");
  const struct term *shape = tagged(&shapes->items[0], "object", 4);
  const struct term *winged = shape ? tagged(&shape->items[2], "winged", 5) : NULL;
  if (!winged) return wings_failed(error, size, "object 1 is not {object, Name, {winged, ...}, Props}");
  const struct term *edges = &winged->items[1], *faces = &winged->items[2], *vertices = &winged->items[3];
  const struct term *hard = &winged->items[4];
  if (edges->kind != TERM_LIST || faces->kind != TERM_LIST || vertices->kind != TERM_LIST ||
      hard->kind != TERM_LIST)
    return wings_failed(error, size, "object 1: its edges, faces, vertices or hard edges are not lists");
  object->vertex_count = (long)vertices->length;
  object->edge_count = (long)edges->length;
  object->face_count = (long)faces->length;
  object->position = calloc(vertices->length + 1, sizeof *object->position);
  object->edges = calloc(edges->length + 1, sizeof *object->edges);
  object->hard = calloc(edges->length + 1, sizeof *object->hard);
  if (!object->position || !object->edges || !object->hard) return wings_failed(error, size, "out of memory");
  for (size_t v = 0; v < vertices->length; ++v) {
    const struct term *item = &vertices->items[v];
    const struct term *at = item->kind == TERM_LIST && item->length > 0 ? &item->items[0] : NULL;
    if (!at || at->kind != TERM_BINARY || at->length != 24)
      return wings_failed(error, size, "object 1, vertex %zu: no <<X, Y, Z>> position of three floats", v);
    for (int k = 0; k < 3; ++k) object->position[v][k] = big_endian_double(at->bytes + 8 * k);
    if (!isfinite(object->position[v][0]) || !isfinite(object->position[v][1]) || !isfinite(object->position[v][2]))
      return wings_failed(error, size, "object 1, vertex %zu: a coordinate is not finite", v);
  }
  for (size_t e = 0; e < edges->length; ++e) {
    const struct term *item = &edges->items[e];
    const struct term *record = NULL;
    for (size_t k = 0; item->kind == TERM_LIST && k < item->length && !record; ++k)
      record = tagged(&item->items[k], "edge", 9);
    struct winged_edge *out = &object->edges[e];
    if (!record) return wings_failed(error, size, "object 1, edge %zu: no {edge, Vs, Ve, Lf, Rf, ...} record", e);
    if (!index_in(&record->items[1], object->vertex_count, &out->vs) ||
        !index_in(&record->items[2], object->vertex_count, &out->ve) ||
        !index_in(&record->items[3], object->face_count, &out->lf) ||
        !index_in(&record->items[4], object->face_count, &out->rf))
      return wings_failed(error, size, "object 1, edge %zu: a vertex or face number out of range", e);
  }
  for (size_t h = 0; h < hard->length; ++h) {
    long e;
    if (!index_in(&hard->items[h], object->edge_count, &e))
      return wings_failed(error, size, "object 1, hard edge %zu: not an edge's number", h);
    object->hard[e] = 1;
  }
  /* Wings3D keeps a hole as a face listed in the object's {holes, Faces} property: around it the
   * object is open, and an open object bounds no cubes. */
  const struct term *props = &shape->items[3];
  for (size_t p = 0; props->kind == TERM_LIST && p < props->length; ++p) {
    const struct term *holes = tagged(&props->items[p], "holes", 2);
    if (!holes || holes->items[1].kind != TERM_LIST || holes->items[1].length == 0) continue;
    long f;
    if (!index_in(&holes->items[1].items[0], object->face_count, &f))
      return wings_failed(error, size, "object 1, holes: not a face's number");
    return wings_failed(error, size, "object 1, face %ld: a hole (listed in the object's holes property), so the "
                        "object is not closed (a closed object made of cubes is expected)", f);
  }
  return 1;
}

static int by_face_then_vertex(const void *a, const void *b)
{
  const long *p = a, *q = b;
  return p[0] != q[0] ? (p[0] > q[0]) - (p[0] < q[0]) : (p[1] > q[1]) - (p[1] < q[1]);
}

/* Whether the object is a closed surface facing out: no edge has one face on both sides; each
 * face's edges close into loops (every vertex of a face meets an even number of its edges); and
 * the volume the faces enclose, a third of the sum over faces of the area vector (Newell's, half
 * the sum of Vs x Ve over the face's edges walked counter-clockwise) dotted with a point of the
 * face, is positive, else the faces run clockwise seen from outside. */
static int check_closed(const struct wings_mesh *object, char *error, size_t size)
{
  long *ends = malloc(8 * (size_t)object->edge_count * sizeof *ends + 1);
  double (*area)[3] = calloc((size_t)object->face_count + 1, sizeof *area);
  double (*point)[3] = calloc((size_t)object->face_count + 1, sizeof *point);
  int ok = ends && area && point ? 1 : wings_failed(error, size, "out of memory");
  for (long e = 0; ok && e < object->edge_count; ++e) {
    const struct winged_edge *edge = &object->edges[e];
    if (edge->lf == edge->rf) {
      ok = wings_failed(error, size, "object 1, edge %ld: face %ld on both of its sides (a closed object is expected)",
                        e, edge->lf);
      break;
    }
    const long pairs[8] = {edge->lf, edge->vs, edge->lf, edge->ve, edge->rf, edge->vs, edge->rf, edge->ve};
    memcpy(&ends[8 * e], pairs, sizeof pairs);
    const double *a = object->position[edge->vs], *b = object->position[edge->ve];
    const double cross[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    for (int k = 0; k < 3; ++k) {
      area[edge->lf][k] += cross[k] / 2;
      area[edge->rf][k] -= cross[k] / 2;
      point[edge->lf][k] = point[edge->rf][k] = a[k];
    }
  }
  if (ok) {
    qsort(ends, 4 * (size_t)object->edge_count, 2 * sizeof *ends, by_face_then_vertex);
    for (size_t k = 0; ok && k < 4 * (size_t)object->edge_count;) {
      size_t same = k;
      while (same < 4 * (size_t)object->edge_count && ends[2 * same] == ends[2 * k] &&
             ends[2 * same + 1] == ends[2 * k + 1])
        ++same;
      if ((same - k) % 2)
        ok = wings_failed(error, size, "object 1, face %ld: its edges do not close into a loop at vertex %ld (a "
                          "closed object is expected)", ends[2 * k], ends[2 * k + 1]);
      k = same;
    }
  }
  double volume = 0;
  for (long f = 0; ok && f < object->face_count; ++f)
    volume += (area[f][0] * point[f][0] + area[f][1] * point[f][1] + area[f][2] * point[f][2]) / 3;
  if (ok && volume < 0)
    ok = wings_failed(error, size, "object 1 is inside out: its faces run clockwise seen from outside (the volume "
                      "they enclose is %g)", volume);
  free(ends);
  free(area);
  free(point);
  return ok;
}

int wings_read_mesh(const char *path, struct wings_mesh *mesh, char *error, size_t error_size)
{
  memset(mesh, 0, sizeof *mesh);
  size_t size = 0;
  unsigned char *data = read_file(path, &size);
  if (!data) return wings_failed(error, error_size, "cannot read the file");
  if (size < HEADER_LENGTH + 4 || memcmp(data, HEADER, HEADER_LENGTH) != 0) {
    free(data);
    return wings_failed(error, error_size, "not a Wings3D file (no #!WINGS-1.0 header)");
  }
  const size_t stated = (size_t)data[15] << 24 | (size_t)data[16] << 16 | (size_t)data[17] << 8 | data[18];
  if (stated != size - HEADER_LENGTH - 4) {
    free(data);
    return wings_failed(error, error_size, "the header states %zu bytes of data, the file has %zu", stated,
                        size - HEADER_LENGTH - 4);
  }
  struct term *root = erlang_term_decode(data + HEADER_LENGTH + 4, stated, error, error_size);
  if (!root) {
    free(data);
    return 0;
  }
  int ok = read_object(root, mesh, error, error_size);
  if (ok && mesh->vertex_count == 0) ok = wings_failed(error, error_size, "object 1 has no vertices");
  if (ok) ok = check_closed(mesh, error, error_size);
  erlang_term_free(root);
  free(data);
  if (!ok) wings_mesh_free(mesh);
  return ok;
}

void wings_mesh_free(struct wings_mesh *mesh)
{
  free(mesh->position);
  free(mesh->edges);
  free(mesh->hard);
  mesh->position = NULL;
  mesh->edges = NULL;
  mesh->hard = NULL;
  mesh->vertex_count = mesh->edge_count = mesh->face_count = 0;
}
