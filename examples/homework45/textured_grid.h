/* A flat textured rectangle drawn as a grid of quads, so that point and spot lights (computed at
 * vertices, GL 1.x section 2.14) show their fall-off across it. */
#ifndef HOMEWORK45_TEXTURED_GRID_H
#define HOMEWORK45_TEXTURED_GRID_H

/* The rectangle corner + s edge_s + t edge_t (s, t in [0, 1]) cut into n x n quads, each a
 * GL_QUAD_STRIP row, with the normal `normal` and the texture coordinates running from
 * (texture_s0, texture_t0) at the corner to (texture_s1, texture_t1) at the opposite one. */
void textured_grid(const float corner[3], const float edge_s[3], const float edge_t[3], const float normal[3], int n,
                   float texture_s0, float texture_s1, float texture_t0, float texture_t1);

#endif
