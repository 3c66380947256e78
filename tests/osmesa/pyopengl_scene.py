"""A fixed-function PyOpenGL script on OSMesa (PYOPENGL_PLATFORM=osmesa): lights, a display
list, a texture, glReadPixels into numpy. The test osmesa.pyopengl runs it on glass's
libOSMesa.so.8 and on Mesa's, and compares the pictures.

    pyopengl_scene.py OUTPUT.ppm    (prints GL_VENDOR)
"""
import sys

import numpy
from OpenGL import GL, GLU, arrays, osmesa

WIDTH, HEIGHT = 320, 240


def checker_texture():
    size = 16
    ys, xs = numpy.mgrid[0:size, 0:size]
    on = ((xs // 4 + ys // 4) % 2).astype(numpy.uint8)
    image = numpy.zeros((size, size, 3), numpy.uint8)
    image[..., 0] = 40 + 200 * on
    image[..., 1] = 200 - 150 * on
    image[..., 2] = 60
    texture = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, texture)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST)
    GL.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGB, size, size, 0, GL.GL_RGB,
                    GL.GL_UNSIGNED_BYTE, image)
    return texture


def cube_list():
    faces = [((0, 0, 1), [(-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]),
             ((0, 0, -1), [(1, -1, -1), (-1, -1, -1), (-1, 1, -1), (1, 1, -1)]),
             ((1, 0, 0), [(1, -1, 1), (1, -1, -1), (1, 1, -1), (1, 1, 1)]),
             ((-1, 0, 0), [(-1, -1, -1), (-1, -1, 1), (-1, 1, 1), (-1, 1, -1)]),
             ((0, 1, 0), [(-1, 1, 1), (1, 1, 1), (1, 1, -1), (-1, 1, -1)]),
             ((0, -1, 0), [(-1, -1, -1), (1, -1, -1), (1, -1, 1), (-1, -1, 1)])]
    corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
    cube = GL.glGenLists(1)
    GL.glNewList(cube, GL.GL_COMPILE)
    GL.glBegin(GL.GL_QUADS)
    for normal, vertices in faces:
        GL.glNormal3f(*normal)
        for (s, t), vertex in zip(corners, vertices):
            GL.glTexCoord2f(s, t)
            GL.glVertex3f(*vertex)
    GL.glEnd()
    GL.glEndList()
    return cube


def draw():
    GL.glViewport(0, 0, WIDTH, HEIGHT)
    GL.glClearColor(0.15, 0.15, 0.25, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GLU.gluPerspective(45.0, WIDTH / HEIGHT, 1.0, 30.0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GLU.gluLookAt(0.0, 2.0, 8.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)

    GL.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION, (2.0, 3.0, 4.0, 1.0))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_DIFFUSE, (1.0, 0.95, 0.9, 1.0))
    GL.glLightfv(GL.GL_LIGHT1, GL.GL_POSITION, (-1.0, 0.5, 0.5, 0.0))
    GL.glLightfv(GL.GL_LIGHT1, GL.GL_DIFFUSE, (0.2, 0.3, 0.6, 1.0))
    GL.glEnable(GL.GL_LIGHTING)
    GL.glEnable(GL.GL_LIGHT0)
    GL.glEnable(GL.GL_LIGHT1)
    GL.glMaterialfv(GL.GL_FRONT, GL.GL_SPECULAR, (0.6, 0.6, 0.6, 1.0))
    GL.glMaterialf(GL.GL_FRONT, GL.GL_SHININESS, 30.0)

    texture = checker_texture()
    cube = cube_list()
    GL.glEnable(GL.GL_TEXTURE_2D)
    GL.glTexEnvi(GL.GL_TEXTURE_ENV, GL.GL_TEXTURE_ENV_MODE, GL.GL_MODULATE)
    for i, (x, angle) in enumerate([(-2.2, 20.0), (0.0, 45.0), (2.2, 70.0)]):
        GL.glPushMatrix()
        GL.glTranslatef(x, 0.0, 0.0)
        GL.glRotatef(angle, 0.3, 1.0, 0.2)
        GL.glScalef(0.8, 0.8, 0.8)
        GL.glMaterialfv(GL.GL_FRONT, GL.GL_AMBIENT_AND_DIFFUSE,
                        (0.9 if i == 0 else 0.6, 0.9 if i == 1 else 0.6, 0.9 if i == 2 else 0.6, 1.0))
        GL.glCallList(cube)
        GL.glPopMatrix()
    GL.glDisable(GL.GL_TEXTURE_2D)
    quadric = GLU.gluNewQuadric()
    GL.glPushMatrix()
    GL.glTranslatef(0.0, -1.8, -1.0)
    GLU.gluSphere(quadric, 0.7, 24, 12)
    GL.glPopMatrix()
    GLU.gluDeleteQuadric(quadric)
    GL.glDeleteLists(cube, 1)
    GL.glDeleteTextures([texture])
    GL.glFinish()


def main():
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    if not ctx:
        sys.exit("OSMesaCreateContextExt failed")
    buffer = arrays.GLubyteArray.zeros((HEIGHT, WIDTH, 4))
    if not osmesa.OSMesaMakeCurrent(ctx, buffer, GL.GL_UNSIGNED_BYTE, WIDTH, HEIGHT):
        sys.exit("OSMesaMakeCurrent failed")
    print(GL.glGetString(GL.GL_VENDOR).decode())
    draw()
    GL.glPixelStorei(GL.GL_PACK_ALIGNMENT, 1)
    read = GL.glReadPixels(0, 0, WIDTH, HEIGHT, GL.GL_RGB, GL.GL_UNSIGNED_BYTE)
    pixels = numpy.frombuffer(bytes(read), numpy.uint8).reshape(HEIGHT, WIDTH, 3)
    # OSMesa's buffer holds the same picture after glFinish, bottom row first.
    if not numpy.array_equal(numpy.asarray(buffer)[..., :3], pixels):
        sys.exit("the OSMesa buffer and glReadPixels differ")
    error = GL.glGetError()
    if error != GL.GL_NO_ERROR:
        sys.exit("GL error 0x%04x" % error)
    with open(sys.argv[1], "wb") as out:
        out.write(b"P6\n%d %d\n255\n" % (WIDTH, HEIGHT))
        out.write(pixels[::-1].tobytes())
    osmesa.OSMesaDestroyContext(ctx)


if __name__ == "__main__":
    main()
