/* The homework's object when it is more than one layer of cubes: any closed solid whose faces lie
 * in planes x, y or z = constant, cut by the planes through its vertices into a grid of cells,
 * each in the solid or out of it. Between two consecutive heights of its vertices lies a layer:
 * a prism over the cells it fills, its footprint. Its upright edges at the footprint's corners
 * are rounded one layer at a time when they are marked hard in Wings3D; the edges along the
 * layers' tops and bottoms stay sharp, but for the top rim of a piece of a layer's footprint
 * outlined by loops (a rectangle, an L, a ring) with nothing above it (a cube standing on a slab, an L
 * on a slab) or only rectangles with filleted feet (the slab under a cube), the bottom rim of one
 * with nothing below it (the slab on the floor) and the foot of a rectangle standing on the layer
 * below, each of its sides inside that layer's top or flush with its side (a cube in the middle,
 * on the side or at the corner of a slab). */
#ifndef HOMEWORK45_CUBE_LAYERS_H
#define HOMEWORK45_CUBE_LAYERS_H

#include <stddef.h>

#include "wings_mesh.h"

enum { CAPPED_TOP = 1, CAPPED_BOTTOM = 2, FILLETED_FOOT = 4 };

struct cube_layers {
  int x_count, z_count; /* grid lines: the distinct x and z of the vertices */
  int layer_count;      /* the distinct heights less one */
  double *x, *z;        /* ascending */
  double *height;       /* ascending, layer_count + 1 of them */
  unsigned char *filled;  /* [layer][j][i]: whether the cell from x[i] to x[i + 1] and z[j] to
                             z[j + 1] is in the solid in that layer */
  unsigned char *rounded; /* [layer][j][i]: whether the upright through grid point (x[i], z[j])
                             is a corner of the layer's footprint and marked hard there */
  unsigned char *capped;  /* [layer][j][i]: CAPPED_TOP when cell (i, j) lies in a piece of the
                             layer's footprint (its cells joined side to side) outlined by one
                             loop, with nothing above but pieces whose feet are filleted, its
                             concave corners' uprights rounded and the edges round its top all
                             hard (but under the pieces on it): that rim is rounded too, meeting
                             the uprights in eighths of a sphere (rounded convex corners) and
                             quarters of a torus (concave ones), and itself in mitres (sharp
                             convex corners), and ending at a standing corner (below);
                             CAPPED_BOTTOM the same below (nothing under it, its bottom rim hard);
                             FILLETED_FOOT when the piece is a rectangle standing on the layer
                             below (that layer fills the cells under it, this one leaves the ring
                             of cells round it empty), each of its sides either inside the lower
                             layer's top (which fills the ring's cells beyond it, every edge
                             along that foot hard) or flush with the lower layer's side (which
                             fills none of them), at least one inside: the concave edges along
                             its foot are filled by a quarter cylinder of radius R (a fillet),
                             turning round its corners between two sides inside and ending at a
                             standing corner, where a side inside meets a flush one (its upright
                             rounded, the lower piece's top rim rounded), against the lower
                             layer's rim in a quarter of a torus; also when the piece is not a
                             rectangle, by the same rules (the fillets meeting at a concave
                             corner in an eighth of a sphere round a rounded upright, in a
                             mitre at a sharp one) */
  double max_radius;      /* half the closest spacing of the grid lines: the corners' quarter
                             circles keep apart; for a layer with a filleted foot also its height
                             shared by the fillet and its rounded rims, and for a piece with
                             filleted pieces on it its height shared by its rounded rims */
  int radius_limited_by_fillet; /* whether that last bound is the smaller */
  int sharp_hard_edges;   /* hard edges left sharp: the creases along the layers' tops and
                             bottoms but the capped pieces' rims and filleted feet */
};

/* The cells of a mesh's object. Returns 0 and writes the reason into `error` when the object is
 * not a closed solid of faces in planes x, y or z = constant. */
int cube_layers_from_mesh(const struct wings_mesh *mesh, struct cube_layers *layers, char *error, size_t error_size);
void cube_layers_free(struct cube_layers *layers);

/* Whether cell (i, j) of `layer` is in the solid (0 outside the grid). */
int cube_layers_filled(const struct cube_layers *layers, int layer, int i, int j);
/* Whether every layer has the same footprint: the object is one floor plan raised from its
 * bottom to its top. */
int cube_layers_alike(const struct cube_layers *layers);
/* Whether the upright at grid point (i, j) is rounded in `layer` (0 outside the grid). */
int cube_layers_rounded(const struct cube_layers *layers, int layer, int i, int j);
/* Which of the top (CAPPED_TOP) and bottom (CAPPED_BOTTOM) rims of cell (i, j) of `layer` are
 * rounded (0 outside the grid). */
int cube_layers_capped(const struct cube_layers *layers, int layer, int i, int j);

#endif
