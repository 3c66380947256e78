/* Frame times on heavy frames at 1920 x 1080, for glass (benchmark) and for Mesa
 * (benchmark_mesa, the same source). Not a test: the numbers depend on the machine.
 *
 * Frames, each drawn from client vertex arrays with glDrawArrays, smooth colours, no lighting:
 *   small_triangles  250,000 triangles of about 18 pixels scattered with random depths, depth test
 *   large_triangles  64 triangles of about half the screen each, tilted in depth, depth test
 *   lines            200,000 width-1 lines up to 64 pixels long
 * A frame is glClear, the draw call and glFinish. Each frame is drawn once to warm up, then RUNS
 * times; the median time is reported, with the fastest and slowest.
 *
 * Usage: benchmark [--png DIR]   (--png also writes each frame to DIR/<frame>.png, to look at) */
#include <GL/gl.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <glass/context.h>

#include "lcg.h"

enum { WIDTH = 1920, HEIGHT = 1080, RUNS = 7 };

typedef struct {
  const char *name;
  GLenum mode;
  int primitives;
  int verticesPerPrimitive;
  int depthTest;
  GLfloat *positions; /* x, y, z per vertex */
  GLubyte *colors;    /* r, g, b, a per vertex */
} Frame;

static void allocate(Frame *frame)
{
  const size_t vertices = (size_t)frame->primitives * (size_t)frame->verticesPerPrimitive;
  frame->positions = malloc(vertices * 3 * sizeof(GLfloat));
  frame->colors = malloc(vertices * 4);
  if (!frame->positions || !frame->colors) {
    fprintf(stderr, "benchmark: out of memory\n");
    exit(1);
  }
}

static void setVertex(Frame *frame, size_t v, float x, float y, float z, Lcg *random)
{
  frame->positions[3 * v] = x;
  frame->positions[3 * v + 1] = y;
  frame->positions[3 * v + 2] = z;
  for (int c = 0; c < 3; ++c) frame->colors[4 * v + c] = (GLubyte)(40 + lcg_below(random, 216));
  frame->colors[4 * v + 3] = 255;
}

/* Triangles about 6 pixels across at random places and depths (z in [-1, 1], ortho). */
static Frame smallTriangles(void)
{
  Frame frame = {"small_triangles", GL_TRIANGLES, 250000, 3, 1, NULL, NULL};
  Lcg random = {1u};
  allocate(&frame);
  for (int t = 0; t < frame.primitives; ++t) {
    const float x = lcg_range(&random, 0.0f, WIDTH), y = lcg_range(&random, 0.0f, HEIGHT);
    const float z = lcg_range(&random, -0.9f, 0.9f);
    for (int k = 0; k < 3; ++k)
      setVertex(&frame, 3 * (size_t)t + k, x + lcg_range(&random, -3.0f, 3.0f) * 2.0f,
                y + lcg_range(&random, -3.0f, 3.0f) * 2.0f, z, &random);
  }
  return frame;
}

/* Triangles with corners spread over and beyond the screen, each tilted in depth, so that they
 * cut through each other and the depth test decides most pixels many times over. */
static Frame largeTriangles(void)
{
  Frame frame = {"large_triangles", GL_TRIANGLES, 64, 3, 1, NULL, NULL};
  Lcg random = {2u};
  allocate(&frame);
  for (int t = 0; t < frame.primitives; ++t)
    for (int k = 0; k < 3; ++k)
      setVertex(&frame, 3 * (size_t)t + k, lcg_range(&random, -0.3f * WIDTH, 1.3f * WIDTH),
                lcg_range(&random, -0.3f * HEIGHT, 1.3f * HEIGHT),
                lcg_range(&random, -0.95f, 0.95f), &random);
  return frame;
}

static Frame lines(void)
{
  Frame frame = {"lines", GL_LINES, 200000, 2, 0, NULL, NULL};
  Lcg random = {3u};
  allocate(&frame);
  for (int l = 0; l < frame.primitives; ++l) {
    const float x = lcg_range(&random, 0.0f, WIDTH), y = lcg_range(&random, 0.0f, HEIGHT);
    setVertex(&frame, 2 * (size_t)l, x, y, 0.0f, &random);
    setVertex(&frame, 2 * (size_t)l + 1, x + lcg_range(&random, -45.0f, 45.0f),
              y + lcg_range(&random, -45.0f, 45.0f), 0.0f, &random);
  }
  return frame;
}

static double now_ms(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static double drawFrame(const Frame *frame)
{
  const double start = now_ms();
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (frame->depthTest)
    glEnable(GL_DEPTH_TEST);
  else
    glDisable(GL_DEPTH_TEST);
  glVertexPointer(3, GL_FLOAT, 0, frame->positions);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, frame->colors);
  glDrawArrays(frame->mode, 0, frame->primitives * frame->verticesPerPrimitive);
  glFinish();
  return now_ms() - start;
}

static int byValue(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The "model name" line of /proc/cpuinfo, or "unknown CPU". */
static void cpuModel(char *model, size_t size)
{
  char line[512];
  FILE *cpuinfo = fopen("/proc/cpuinfo", "r");
  snprintf(model, size, "unknown CPU");
  if (!cpuinfo) return;
  while (fgets(line, sizeof line, cpuinfo)) {
    const char *colon = strchr(line, ':');
    if (strncmp(line, "model name", 10) == 0 && colon) {
      snprintf(model, size, "%s", colon + 2);
      model[strcspn(model, "\n")] = '\0';
      break;
    }
  }
  fclose(cpuinfo);
}

int main(int argc, char **argv)
{
  const char *pngDir = NULL;
  char model[256], path[1024];
  GlassContext *ctx;
  Frame frames[3];

  if (argc == 3 && strcmp(argv[1], "--png") == 0)
    pngDir = argv[2];
  else if (argc != 1) {
    fprintf(stderr, "usage: %s [--png DIR]\n", argv[0]);
    return 2;
  }

  ctx = glassCreateContext(WIDTH, HEIGHT);
  if (!ctx || !glassMakeCurrent(ctx)) {
    fprintf(stderr, "benchmark: cannot create a %d x %d context\n", WIDTH, HEIGHT);
    return 1;
  }
  glViewport(0, 0, WIDTH, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);

  cpuModel(model, sizeof model);
  printf("renderer:   %s, %s\n", (const char *)glGetString(GL_RENDERER),
         (const char *)glGetString(GL_VERSION));
  printf("machine:    %s, %ld hardware threads\n", model, sysconf(_SC_NPROCESSORS_ONLN));
  printf("resolution: %d x %d\n", WIDTH, HEIGHT);
  printf("threads:    LP_NUM_THREADS=%s GLASS_THREADS=%s\n",
         getenv("LP_NUM_THREADS") ? getenv("LP_NUM_THREADS") : "(unset)",
         getenv("GLASS_THREADS") ? getenv("GLASS_THREADS") : "(unset)");
  printf("timing:     median of %d frames after 1 warm-up frame, ms\n", RUNS);

  frames[0] = smallTriangles();
  frames[1] = largeTriangles();
  frames[2] = lines();
  for (int f = 0; f < 3; ++f) {
    double times[RUNS];
    drawFrame(&frames[f]);
    for (int r = 0; r < RUNS; ++r) times[r] = drawFrame(&frames[f]);
    qsort(times, RUNS, sizeof times[0], byValue);
    printf("frame %-16s %8d primitives  median %9.2f ms  (min %.2f, max %.2f)\n", frames[f].name,
           frames[f].primitives, times[RUNS / 2], times[0], times[RUNS - 1]);
    fflush(stdout);
    if (pngDir) {
      snprintf(path, sizeof path, "%s/%s.png", pngDir, frames[f].name);
      if (!glassWritePNG(ctx, path)) fprintf(stderr, "benchmark: cannot write %s\n", path);
    }
    free(frames[f].positions);
    free(frames[f].colors);
  }

  glassDestroyContext(ctx);
  return 0;
}
