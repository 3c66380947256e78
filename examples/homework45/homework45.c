/* Homework 4-5 of the study guide, a model answer with GL, GLU and GLUT only: a room corner
 * (floor and two walls), an object made of cubes in the middle, read from a Wings3D file (by
 * default the L of three cubes l_block.wings; another file may be named on the command line),
 * whose edges marked hard in Wings3D are rounded by rational quadratic Bezier patches (glMap2f,
 * GL_MAP2_VERTEX_4, GL_AUTO_NORMAL): its upright edges into quarter cylinders at its convex
 * corners and concave fillets filling its inner corners; the rims of its top and its bottom
 * (each when all its edges are hard) into quarter cylinders along the sides, which meet an eighth
 * of a sphere at a rounded convex corner, a piece of a torus at a fillet, and each other in a
 * mitre at a sharp corner. The sphere and torus pieces are surfaces of revolution: the rim's quarter circle
 * turned around the upright's axis by the upright's quarter circle, a rational bi-quadratic
 * patch whose weights are products of the two arcs' weights, exact as both arcs are (study
 * guide, section 2.4). An object of several layers of cubes that is not one outline raised (a
 * cube on a slab) is drawn by layers (layered_block.c): its hard uprights rounded layer by layer,
 * the rims of a layer's piece (a rectangle, an L) with nothing above (below) it, or with only
 * rectangles standing on it whose feet are filleted, rounded as above, the feet of those
 * rectangles filled by fillets, its other rims left sharp. A texture runs on across the rounded strips, planar shadows
 * of the object fall on the floor and both walls (shadow matrices, kept on their surface by the
 * stencil buffer); walk mode with collisions, examine mode, three kinds of light, five
 * viewpoints, orthographic or perspective projection.
 *
 * Keys: arrows walk (up/down) and turn (left/right); R/r round more/less; 1-5 viewpoints;
 * w walk mode, e examine mode (drag with the left button); d/p/s directional/point/spot light;
 * o orthographic/perspective; +/- field of view; Esc quits. The right button opens the menu. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <GL/glut.h>

#include "layered_block.h"
#include "plan_block.h"
#include "textured_grid.h"
#include "wings_plan.h"

#define PI 3.14159265358979323846

/* The room: floor y = 0 and walls x = -ROOM, z = -ROOM, up to WALL_HEIGHT. */
#define ROOM 5.0f
#define WALL_HEIGHT 4.0f
/* The object: its floor plan from the Wings3D file when it is one layer of cubes or layers alike
 * (drawn with the rims of its top and its bottom rounded), else its layers (drawn by
 * layered_block.c, the uprights rounded layer by layer); its cells, which the walker may not
 * enter, and its bounding box. */
static struct floor_plan plan;
static struct cube_layers layers;
static int layered, has_cells;
static float block_min[3], block_max[3];
/* The height the texture's t runs from 0 to 1 over on the sides: the object's for one layer of
 * cubes, one unit for several (as s runs one unit along a side), as layered_block.c does. */
static float texture_height;
#define RADIUS_STEP 0.08f
/* How close the walker may come to a wall or to the block. */
#define WALKER_RADIUS 0.3f
/* The top of the walker's head, a little above his eyes: he walks under any part of the object
 * whose bottom is higher. */
#define HEAD_HEIGHT 1.8f
#define STEP 0.25f
#define TURN_DEGREES 5.0f
#define EYE_HEIGHT 1.6f

enum light_kind { DIRECTIONAL, POINT, SPOT };
enum menu_entry {
  MENU_WALK = 1, MENU_EXAMINE, MENU_DIRECTIONAL, MENU_POINT, MENU_SPOT, MENU_PROJECTION,
  MENU_WIDER, MENU_NARROWER, MENU_ROUNDER, MENU_SHARPER, MENU_VIEWPOINT_1
};

static float radius = 0.0f;
static int walking = 1;
static int perspective = 1;
static float field_of_view = 60.0f;
static enum light_kind light = POINT;
static float walker_x, walker_z, walker_yaw; /* yaw 0 looks along -z */
static float examine_azimuth = 30.0f, examine_elevation = 25.0f;
static int drag_x, drag_y, dragging;
static int window_width = 400, window_height = 300;
static GLuint texture;

/* Viewpoints 1-5: where the walker stands and where he looks. */
static const float viewpoints[5][3] = {
  {3.0f, 4.0f, 37.0f}, {2.0f, 2.0f, 0.0f}, {-3.5f, 3.5f, -45.0f}, {4.0f, -3.0f, 127.0f},
  {-2.0f, 4.5f, -24.0f},
};

static void set_viewpoint(int index)
{
  walker_x = viewpoints[index][0];
  walker_z = viewpoints[index][1];
  walker_yaw = viewpoints[index][2];
  walking = 1;
}

/* A checkerboard with a stripe, so that its run across the rounded edges can be seen: eight
 * squares of 8 x 8 texels a row, so that its pattern repeats every quarter of s. */
#define TEXTURE_S_REPEAT 0.25f
static void make_texture(void)
{
  static GLubyte texels[64][64][3];
  for (int row = 0; row < 64; ++row)
    for (int column = 0; column < 64; ++column) {
      int dark = ((row / 8) + (column / 8)) % 2;
      GLubyte value = dark ? 90 : 230;
      texels[row][column][0] = value;
      texels[row][column][1] = (GLubyte)(row < 8 ? 40 : value);
      texels[row][column][2] = (GLubyte)(dark ? 40 : 120);
    }
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
}

/* The object: by layers (layered_block.c) or as its plan raised (plan_block.c), textured when
 * asked (not for its shadows). */
static void block(int textured)
{
  if (textured) {
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  }
  if (layered)
    draw_layered_block(&layers, radius);
  else
    draw_plan_block(&plan, radius, texture_height, TEXTURE_S_REPEAT);
  if (textured) glDisable(GL_TEXTURE_2D);
}

/* The three surfaces as planes a x + b y + c z + d = 0 facing into the room. */
static const float surfaces[3][4] = {{0, 1, 0, 0}, {0, 0, 1, ROOM}, {1, 0, 0, ROOM}};

static void surface(int index)
{
  static const float colors[3][3] = {{0.75f, 0.7f, 0.6f}, {0.6f, 0.7f, 0.8f}, {0.8f, 0.65f, 0.6f}};
  glColor3fv(colors[index]);
  const float size = 2 * ROOM;
  if (index == 0) {
    const float corner[3] = {-ROOM, 0, ROOM}, s[3] = {size, 0, 0}, t[3] = {0, 0, -size};
    textured_grid(corner, s, t, surfaces[0], 20, 0, 1, 0, 1);
  } else if (index == 1) {
    const float corner[3] = {-ROOM, 0, -ROOM}, s[3] = {size, 0, 0}, t[3] = {0, WALL_HEIGHT, 0};
    textured_grid(corner, s, t, surfaces[1], 20, 0, 1, 0, 1);
  } else {
    const float corner[3] = {-ROOM, 0, ROOM}, s[3] = {0, 0, -size}, t[3] = {0, WALL_HEIGHT, 0};
    textured_grid(corner, s, t, surfaces[2], 20, 0, 1, 0, 1);
  }
}

static void light_position(float position[4])
{
  if (light == DIRECTIONAL) {
    position[0] = 1.0f; position[1] = 0.5f; position[2] = 0.7f; position[3] = 0.0f;
  } else {
    position[0] = 3.0f; position[1] = 1.6f; position[2] = 2.5f; position[3] = 1.0f;
  }
}

/* The matrix that flattens everything onto the plane along rays from the light (homogeneous, so
 * the directional light w = 0 is the same formula): M = (plane . light) I - light plane^T,
 * stored column-major for glMultMatrixf. */
static void shadow_matrix(const float plane[4], const float light_at[4], float matrix[16])
{
  float dot = plane[0] * light_at[0] + plane[1] * light_at[1] + plane[2] * light_at[2] +
              plane[3] * light_at[3];
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      matrix[column * 4 + row] = (row == column ? dot : 0.0f) - light_at[row] * plane[column];
}

static void set_light(void)
{
  float position[4];
  light_position(position);
  const float white[4] = {0.9f, 0.9f, 0.9f, 1}, ambient[4] = {0.25f, 0.25f, 0.25f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  if (light == SPOT) {
    float direction[3] = {-position[0], 0.5f - position[1], -position[2]};
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 35.0f);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 8.0f);
  } else {
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
  }
  if (light == DIRECTIONAL) {
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.0f);
  } else {
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.08f);
  }
}

static void set_projection(void)
{
  float aspect = (float)window_width / (float)(window_height > 0 ? window_height : 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (perspective) {
    gluPerspective(field_of_view, aspect, 0.1, 60.0);
  } else {
    /* The orthographic box as wide as the perspective view is at the block's distance. */
    float half = 6.0f * (float)tan(field_of_view * PI / 360.0);
    glOrtho(-half * aspect, half * aspect, -half, half, 0.1, 60.0);
  }
  glMatrixMode(GL_MODELVIEW);
}

static void set_camera(void)
{
  glLoadIdentity();
  if (walking) {
    double yaw = walker_yaw * PI / 180.0;
    gluLookAt(walker_x, EYE_HEIGHT, walker_z, walker_x - sin(yaw), EYE_HEIGHT - 0.15,
              walker_z - cos(yaw), 0, 1, 0);
  } else {
    double azimuth = examine_azimuth * PI / 180.0, elevation = examine_elevation * PI / 180.0;
    double distance = 9.0;
    gluLookAt(distance * cos(elevation) * sin(azimuth), 0.5 + distance * sin(elevation),
              distance * cos(elevation) * cos(azimuth), 0, 0.5, 0, 0, 1, 0);
  }
}

static void display(void)
{
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  set_projection();
  set_camera();
  set_light();

  /* Each surface marks its pixels with its number in the stencil buffer ... */
  glEnable(GL_LIGHTING);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (int index = 0; index < 3; ++index) {
    glStencilFunc(GL_ALWAYS, index + 1, 0xff);
    surface(index);
  }
  /* ... and the block's shadow on it darkens only those pixels, once each (the stencil is
   * zeroed where it fell, so overlapping shadow polygons do not darken twice). */
  float position[4], matrix[16];
  light_position(position);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
  glColor4f(0, 0, 0, 0.5f);
  for (int index = 0; index < 3; ++index) {
    glStencilFunc(GL_EQUAL, index + 1, 0xff);
    shadow_matrix(surfaces[index], position, matrix);
    glPushMatrix();
    glMultMatrixf(matrix);
    block(0);
    glPopMatrix();
  }
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);

  glEnable(GL_LIGHTING);
  glColor3f(1, 1, 1);
  block(1);
  glutSwapBuffers();
}

static void reshape(int width, int height)
{
  window_width = width;
  window_height = height;
  glViewport(0, 0, width, height);
}

/* Whether the walker at (x, z) keeps his distance from the walls, the floor's open edges and the
 * object: from each column of its cells that it fills anywhere between the floor and the top of
 * his head (so that he can walk into an inner corner, and under an overhang whose bottom is above
 * his head), or from its bounding box when it is not cut into cells. */
static int walker_fits(float x, float z)
{
  if (x < -ROOM + WALKER_RADIUS || z < -ROOM + WALKER_RADIUS) return 0;
  if (x > ROOM - WALKER_RADIUS || z > ROOM - WALKER_RADIUS) return 0;
  if (!has_cells)
    return !(x > block_min[0] - WALKER_RADIUS && x < block_max[0] + WALKER_RADIUS &&
             z > block_min[2] - WALKER_RADIUS && z < block_max[2] + WALKER_RADIUS);
  for (int j = 0; j + 1 < layers.z_count; ++j)
    for (int i = 0; i + 1 < layers.x_count; ++i) {
      int filled = 0;
      for (int layer = 0; layer < layers.layer_count && !filled; ++layer)
        filled = cube_layers_filled(&layers, layer, i, j) && layers.height[layer] < HEAD_HEIGHT &&
                 layers.height[layer + 1] > 0;
      if (filled && x > layers.x[i] - WALKER_RADIUS && x < layers.x[i + 1] + WALKER_RADIUS &&
          z > layers.z[j] - WALKER_RADIUS && z < layers.z[j + 1] + WALKER_RADIUS)
        return 0;
    }
  return 1;
}

/* A step that would collide keeps the free part of its motion (x and z tried apart), so the
 * walker slides along a wall or the block instead of stopping dead. */
static void walk(float distance)
{
  double yaw = walker_yaw * PI / 180.0;
  float x = walker_x - distance * (float)sin(yaw), z = walker_z - distance * (float)cos(yaw);
  if (walker_fits(x, walker_z)) walker_x = x;
  if (walker_fits(walker_x, z)) walker_z = z;
}

static void change_radius(float change)
{
  radius += change;
  if (radius < 0) radius = 0;
  const double largest = layered ? layers.max_radius : plan.max_radius;
  if (radius > (float)largest) radius = (float)largest;
}

static void change_field_of_view(float change)
{
  field_of_view += change;
  if (field_of_view < 10) field_of_view = 10;
  if (field_of_view > 120) field_of_view = 120;
}

static void choose(int entry)
{
  switch (entry) {
  case MENU_WALK: walking = 1; break;
  case MENU_EXAMINE: walking = 0; break;
  case MENU_DIRECTIONAL: light = DIRECTIONAL; break;
  case MENU_POINT: light = POINT; break;
  case MENU_SPOT: light = SPOT; break;
  case MENU_PROJECTION: perspective = !perspective; break;
  case MENU_WIDER: change_field_of_view(5); break;
  case MENU_NARROWER: change_field_of_view(-5); break;
  case MENU_ROUNDER: change_radius(RADIUS_STEP); break;
  case MENU_SHARPER: change_radius(-RADIUS_STEP); break;
  default:
    if (entry >= MENU_VIEWPOINT_1 && entry < MENU_VIEWPOINT_1 + 5) set_viewpoint(entry - MENU_VIEWPOINT_1);
    break;
  }
  glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y)
{
  (void)x; (void)y;
  switch (key) {
  case 27: exit(0);
  case 'R': choose(MENU_ROUNDER); break;
  case 'r': choose(MENU_SHARPER); break;
  case 'w': choose(MENU_WALK); break;
  case 'e': choose(MENU_EXAMINE); break;
  case 'd': choose(MENU_DIRECTIONAL); break;
  case 'p': choose(MENU_POINT); break;
  case 's': choose(MENU_SPOT); break;
  case 'o': choose(MENU_PROJECTION); break;
  case '+': choose(MENU_NARROWER); break;
  case '-': choose(MENU_WIDER); break;
  default:
    if (key >= '1' && key <= '5') choose(MENU_VIEWPOINT_1 + (key - '1'));
    break;
  }
}

static void special(int key, int x, int y)
{
  (void)x; (void)y;
  if (!walking) return;
  switch (key) {
  case GLUT_KEY_UP: walk(STEP); break;
  case GLUT_KEY_DOWN: walk(-STEP); break;
  case GLUT_KEY_LEFT: walker_yaw += TURN_DEGREES; break;
  case GLUT_KEY_RIGHT: walker_yaw -= TURN_DEGREES; break;
  }
  glutPostRedisplay();
}

static void mouse(int button, int state, int x, int y)
{
  if (button != GLUT_LEFT_BUTTON) return;
  dragging = state == GLUT_DOWN;
  drag_x = x;
  drag_y = y;
}

/* Examine mode: dragging turns the camera around the block. */
static void motion(int x, int y)
{
  if (!dragging || walking) return;
  examine_azimuth -= 0.5f * (float)(x - drag_x);
  examine_elevation += 0.5f * (float)(y - drag_y);
  if (examine_elevation < 2) examine_elevation = 2;
  if (examine_elevation > 85) examine_elevation = 85;
  drag_x = x;
  drag_y = y;
  glutPostRedisplay();
}

/* The object's file: the first argument GLUT leaves, or the L beside this program's source. An
 * object of one layer of cubes (or of layers alike) is drawn from its floor plan, any other closed
 * object of cubes by layers; both are cut into cells for the walker's collisions when they can
 * be. */
static void load_object(int argc, char **argv)
{
  const char *path = argc > 1 ? argv[1] : HOMEWORK45_MODEL;
  char error[300], plan_error[300];
  struct wings_mesh mesh;
  if (!wings_read_mesh(path, &mesh, error, sizeof error)) {
    fprintf(stderr, "homework45: %s: %s\n", path, error);
    exit(1);
  }
  has_cells = cube_layers_from_mesh(&mesh, &layers, error, sizeof error);
  layered = !floor_plan_from_mesh(&mesh, has_cells && cube_layers_alike(&layers), &plan, plan_error,
                                  sizeof plan_error);
  wings_mesh_free(&mesh);
  if (layered && !has_cells) {
    fprintf(stderr, "homework45: %s: %s\n", path, error);
    exit(1);
  }
  if (!layered && plan.sharp_hard_edges > 0)
    fprintf(stderr, "homework45: %s: %d hard edges stay sharp (this program rounds the upright edges hard "
            "all the way up, and the top's and the bottom's rims along their hard stretches)\n", path,
            plan.sharp_hard_edges);
  if (layered && layers.sharp_hard_edges > 0)
    fprintf(stderr, "homework45: %s: %d hard edges stay sharp (of an object of more than one layer of cubes "
            "this program rounds the upright edges, layer by layer, and the top (bottom) rim of a piece of a "
            "layer (cubes joined side to side, outlined by one loop or several round holes, such as a rectangle, an L or "
            "a ring, its concave corners' uprights rounded) with nothing above (below) it or, above it, only pieces "
            "whose feet it fills with fillets (pieces standing on the layer below, each side inside its top or flush "
            "with its side); it leaves the other edges along the layers' tops and bottoms sharp)\n",
            path, layers.sharp_hard_edges);
  if (layered && layers.radius_limited_by_fillet)
    fprintf(stderr, "homework45: %s: the radius goes up to %g only: the height of a layer whose foot is filleted "
            "or that filleted feet stand on, shared by its fillet and its rounded rims\n", path, layers.max_radius);
  if (layered) {
    block_min[0] = (float)layers.x[0], block_max[0] = (float)layers.x[layers.x_count - 1];
    block_min[1] = (float)layers.height[0], block_max[1] = (float)layers.height[layers.layer_count];
    block_min[2] = (float)layers.z[0], block_max[2] = (float)layers.z[layers.z_count - 1];
    return;
  }
  block_min[0] = (float)plan.min_x, block_max[0] = (float)plan.max_x;
  block_min[1] = (float)plan.bottom, block_max[1] = (float)plan.top;
  block_min[2] = (float)plan.min_z, block_max[2] = (float)plan.max_z;
  texture_height = has_cells && layers.layer_count > 1 ? 1.0f : block_max[1] - block_min[1];
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  load_object(argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL);
  glutInitWindowSize(window_width, window_height);
  glutCreateWindow("Homework 4-5");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutSpecialFunc(special);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);

  glutCreateMenu(choose);
  glutAddMenuEntry("Walk mode (w)", MENU_WALK);
  glutAddMenuEntry("Examine mode (e)", MENU_EXAMINE);
  glutAddMenuEntry("Directional light (d)", MENU_DIRECTIONAL);
  glutAddMenuEntry("Point light (p)", MENU_POINT);
  glutAddMenuEntry("Spot light (s)", MENU_SPOT);
  glutAddMenuEntry("Orthographic/perspective (o)", MENU_PROJECTION);
  glutAddMenuEntry("Wider field of view (-)", MENU_WIDER);
  glutAddMenuEntry("Narrower field of view (+)", MENU_NARROWER);
  glutAddMenuEntry("Rounder edges (R)", MENU_ROUNDER);
  glutAddMenuEntry("Sharper edges (r)", MENU_SHARPER);
  glutAddMenuEntry("Viewpoint 1", MENU_VIEWPOINT_1);
  glutAddMenuEntry("Viewpoint 2", MENU_VIEWPOINT_1 + 1);
  glutAddMenuEntry("Viewpoint 3", MENU_VIEWPOINT_1 + 2);
  glutAddMenuEntry("Viewpoint 4", MENU_VIEWPOINT_1 + 3);
  glutAddMenuEntry("Viewpoint 5", MENU_VIEWPOINT_1 + 4);
  glutAttachMenu(GLUT_RIGHT_BUTTON);

  make_texture();
  set_viewpoint(0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHT0);
  glShadeModel(GL_SMOOTH);
  glutMainLoop();
  return 0;
}
