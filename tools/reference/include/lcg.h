/* Pseudo-random numbers that are the same on every build and every C library: a 32-bit linear
 * congruential generator, x' = 1664525 x + 1013904223 mod 2^32 (Numerical Recipes, ch. 7.1).
 * GL test programs use it instead of rand() so that glass and Mesa draw the same input. */
#ifndef GLASS_TOOLS_LCG_H
#define GLASS_TOOLS_LCG_H

#include <stdint.h>

typedef struct {
  uint32_t state;
} Lcg;

static inline uint32_t lcg_next(Lcg *g) {
  g->state = g->state * 1664525u + 1013904223u;
  return g->state;
}

/* Uniform in [0, 1): the top 24 bits (the low bits of an LCG are the least random), which a
 * float holds exactly. */
static inline float lcg_unit(Lcg *g) {
  return (float)(lcg_next(g) >> 8) * (1.0f / 16777216.0f);
}

static inline float lcg_range(Lcg *g, float low, float high) {
  return low + (high - low) * lcg_unit(g);
}

/* Uniform integer in [0, n), n > 0. */
static inline int lcg_below(Lcg *g, int n) {
  return (int)((lcg_next(g) >> 8) % (uint32_t)n);
}

#endif
