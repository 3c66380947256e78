/* glass: <GL/glext.h>, the extension names of the OpenGL 1.x features glass implements.
 *
 * Programs of the GL 1.x era name core features by the extension they first came in
 * (GL_COMBINE_ARB, glFogCoordfEXT, GL_CLAMP_TO_EDGE_SGIS). This header declares, for every
 * extension in glGetString(GL_EXTENSIONS), its enumerants with the OpenGL registry's values, its
 * PFNGL...PROC function pointer types, and, when GL_GLEXT_PROTOTYPES is defined, its functions;
 * each function is the core command of the same name without the suffix. Extensions whose
 * functionality glass lacks are not declared, so `#ifdef GL_EXT_foo` tells a program what it can
 * use. <GL/gl.h> includes this header unless GL_GLEXT_LEGACY is defined, as Mesa's does.
 */
#ifndef GLASS_GL_GLEXT_H
#define GLASS_GL_GLEXT_H

/* Other headers test these guards; defining them keeps a system glext.h from being mixed in. */
#ifndef __gl_glext_h_
#define __gl_glext_h_ 1
#endif
#ifndef __glext_h_
#define __glext_h_ 1
#endif

#include <GL/gl.h>

#ifndef APIENTRY
#define APIENTRY
#endif
#ifndef APIENTRYP
#define APIENTRYP APIENTRY *
#endif
#ifndef GLAPI
#define GLAPI extern
#endif

#ifdef __cplusplus
extern "C" {
#endif

#ifndef GL_ARB_transpose_matrix
#define GL_ARB_transpose_matrix 1
#define GL_TRANSPOSE_MODELVIEW_MATRIX_ARB        0x84E3
#define GL_TRANSPOSE_PROJECTION_MATRIX_ARB       0x84E4
#define GL_TRANSPOSE_TEXTURE_MATRIX_ARB          0x84E5
#define GL_TRANSPOSE_COLOR_MATRIX_ARB            0x84E6
typedef void (APIENTRYP PFNGLLOADTRANSPOSEMATRIXFARBPROC)(const GLfloat *m);
typedef void (APIENTRYP PFNGLLOADTRANSPOSEMATRIXDARBPROC)(const GLdouble *m);
typedef void (APIENTRYP PFNGLMULTTRANSPOSEMATRIXFARBPROC)(const GLfloat *m);
typedef void (APIENTRYP PFNGLMULTTRANSPOSEMATRIXDARBPROC)(const GLdouble *m);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glLoadTransposeMatrixfARB(const GLfloat *m);
GLAPI void APIENTRY glLoadTransposeMatrixdARB(const GLdouble *m);
GLAPI void APIENTRY glMultTransposeMatrixfARB(const GLfloat *m);
GLAPI void APIENTRY glMultTransposeMatrixdARB(const GLdouble *m);
#endif
#endif /* GL_ARB_transpose_matrix */

#ifndef GL_ARB_multisample
#define GL_ARB_multisample 1
#define GL_MULTISAMPLE_ARB                       0x809D
#define GL_SAMPLE_ALPHA_TO_COVERAGE_ARB          0x809E
#define GL_SAMPLE_ALPHA_TO_ONE_ARB               0x809F
#define GL_SAMPLE_COVERAGE_ARB                   0x80A0
#define GL_SAMPLE_BUFFERS_ARB                    0x80A8
#define GL_SAMPLES_ARB                           0x80A9
#define GL_SAMPLE_COVERAGE_VALUE_ARB             0x80AA
#define GL_SAMPLE_COVERAGE_INVERT_ARB            0x80AB
#define GL_MULTISAMPLE_BIT_ARB                   0x20000000
typedef void (APIENTRYP PFNGLSAMPLECOVERAGEARBPROC)(GLfloat value, GLboolean invert);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glSampleCoverageARB(GLfloat value, GLboolean invert);
#endif
#endif /* GL_ARB_multisample */

#ifndef GL_ARB_depth_texture
#define GL_ARB_depth_texture 1
#define GL_DEPTH_COMPONENT16_ARB                 0x81A5
#define GL_DEPTH_COMPONENT24_ARB                 0x81A6
#define GL_DEPTH_COMPONENT32_ARB                 0x81A7
#define GL_TEXTURE_DEPTH_SIZE_ARB                0x884A
#define GL_DEPTH_TEXTURE_MODE_ARB                0x884B
#endif /* GL_ARB_depth_texture */

#ifndef GL_ARB_shadow
#define GL_ARB_shadow 1
#define GL_TEXTURE_COMPARE_MODE_ARB              0x884C
#define GL_TEXTURE_COMPARE_FUNC_ARB              0x884D
#define GL_COMPARE_R_TO_TEXTURE_ARB              0x884E
#endif /* GL_ARB_shadow */

#ifndef GL_ARB_texture_env_add
#define GL_ARB_texture_env_add 1
#endif /* GL_ARB_texture_env_add */

#ifndef GL_ARB_texture_cube_map
#define GL_ARB_texture_cube_map 1
#define GL_NORMAL_MAP_ARB                        0x8511
#define GL_REFLECTION_MAP_ARB                    0x8512
#define GL_TEXTURE_CUBE_MAP_ARB                  0x8513
#define GL_TEXTURE_BINDING_CUBE_MAP_ARB          0x8514
#define GL_TEXTURE_CUBE_MAP_POSITIVE_X_ARB       0x8515
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_X_ARB       0x8516
#define GL_TEXTURE_CUBE_MAP_POSITIVE_Y_ARB       0x8517
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_Y_ARB       0x8518
#define GL_TEXTURE_CUBE_MAP_POSITIVE_Z_ARB       0x8519
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_ARB       0x851A
#define GL_PROXY_TEXTURE_CUBE_MAP_ARB            0x851B
#define GL_MAX_CUBE_MAP_TEXTURE_SIZE_ARB         0x851C
#endif /* GL_ARB_texture_cube_map */

#ifndef GL_ARB_texture_compression
#define GL_ARB_texture_compression 1
#define GL_COMPRESSED_ALPHA_ARB                  0x84E9
#define GL_COMPRESSED_LUMINANCE_ARB              0x84EA
#define GL_COMPRESSED_LUMINANCE_ALPHA_ARB        0x84EB
#define GL_COMPRESSED_INTENSITY_ARB              0x84EC
#define GL_COMPRESSED_RGB_ARB                    0x84ED
#define GL_COMPRESSED_RGBA_ARB                   0x84EE
#define GL_TEXTURE_COMPRESSION_HINT_ARB          0x84EF
#define GL_TEXTURE_COMPRESSED_IMAGE_SIZE_ARB     0x86A0
#define GL_TEXTURE_COMPRESSED_ARB                0x86A1
#define GL_NUM_COMPRESSED_TEXTURE_FORMATS_ARB    0x86A2
#define GL_COMPRESSED_TEXTURE_FORMATS_ARB        0x86A3
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXIMAGE3DARBPROC)(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLsizei depth, GLint border, GLsizei imageSize, const void *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXIMAGE2DARBPROC)(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLint border, GLsizei imageSize, const void *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXIMAGE1DARBPROC)(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLint border, GLsizei imageSize, const void *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXSUBIMAGE3DARBPROC)(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLsizei imageSize, const void *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXSUBIMAGE2DARBPROC)(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLsizei imageSize, const void *data);
typedef void (APIENTRYP PFNGLCOMPRESSEDTEXSUBIMAGE1DARBPROC)(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLsizei imageSize, const void *data);
typedef void (APIENTRYP PFNGLGETCOMPRESSEDTEXIMAGEARBPROC)(GLenum target, GLint level, void *img);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glCompressedTexImage3DARB(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLsizei depth, GLint border, GLsizei imageSize, const void *data);
GLAPI void APIENTRY glCompressedTexImage2DARB(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLint border, GLsizei imageSize, const void *data);
GLAPI void APIENTRY glCompressedTexImage1DARB(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLint border, GLsizei imageSize, const void *data);
GLAPI void APIENTRY glCompressedTexSubImage3DARB(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLsizei imageSize, const void *data);
GLAPI void APIENTRY glCompressedTexSubImage2DARB(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLsizei imageSize, const void *data);
GLAPI void APIENTRY glCompressedTexSubImage1DARB(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLsizei imageSize, const void *data);
GLAPI void APIENTRY glGetCompressedTexImageARB(GLenum target, GLint level, void *img);
#endif
#endif /* GL_ARB_texture_compression */

#ifndef GL_ARB_texture_border_clamp
#define GL_ARB_texture_border_clamp 1
#define GL_CLAMP_TO_BORDER_ARB                   0x812D
#endif /* GL_ARB_texture_border_clamp */

#ifndef GL_ARB_point_parameters
#define GL_ARB_point_parameters 1
#define GL_POINT_SIZE_MIN_ARB                    0x8126
#define GL_POINT_SIZE_MAX_ARB                    0x8127
#define GL_POINT_FADE_THRESHOLD_SIZE_ARB         0x8128
#define GL_POINT_DISTANCE_ATTENUATION_ARB        0x8129
typedef void (APIENTRYP PFNGLPOINTPARAMETERFARBPROC)(GLenum pname, GLfloat param);
typedef void (APIENTRYP PFNGLPOINTPARAMETERFVARBPROC)(GLenum pname, const GLfloat *params);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glPointParameterfARB(GLenum pname, GLfloat param);
GLAPI void APIENTRY glPointParameterfvARB(GLenum pname, const GLfloat *params);
#endif
#endif /* GL_ARB_point_parameters */

#ifndef GL_ARB_texture_env_combine
#define GL_ARB_texture_env_combine 1
#define GL_COMBINE_ARB                           0x8570
#define GL_COMBINE_RGB_ARB                       0x8571
#define GL_COMBINE_ALPHA_ARB                     0x8572
#define GL_SOURCE0_RGB_ARB                       0x8580
#define GL_SOURCE1_RGB_ARB                       0x8581
#define GL_SOURCE2_RGB_ARB                       0x8582
#define GL_SOURCE0_ALPHA_ARB                     0x8588
#define GL_SOURCE1_ALPHA_ARB                     0x8589
#define GL_SOURCE2_ALPHA_ARB                     0x858A
#define GL_OPERAND0_RGB_ARB                      0x8590
#define GL_OPERAND1_RGB_ARB                      0x8591
#define GL_OPERAND2_RGB_ARB                      0x8592
#define GL_OPERAND0_ALPHA_ARB                    0x8598
#define GL_OPERAND1_ALPHA_ARB                    0x8599
#define GL_OPERAND2_ALPHA_ARB                    0x859A
#define GL_RGB_SCALE_ARB                         0x8573
#define GL_ADD_SIGNED_ARB                        0x8574
#define GL_INTERPOLATE_ARB                       0x8575
#define GL_SUBTRACT_ARB                          0x84E7
#define GL_CONSTANT_ARB                          0x8576
#define GL_PRIMARY_COLOR_ARB                     0x8577
#define GL_PREVIOUS_ARB                          0x8578
#endif /* GL_ARB_texture_env_combine */

#ifndef GL_ARB_texture_env_crossbar
#define GL_ARB_texture_env_crossbar 1
#endif /* GL_ARB_texture_env_crossbar */

#ifndef GL_ARB_texture_env_dot3
#define GL_ARB_texture_env_dot3 1
#define GL_DOT3_RGB_ARB                          0x86AE
#define GL_DOT3_RGBA_ARB                         0x86AF
#endif /* GL_ARB_texture_env_dot3 */

#ifndef GL_ARB_texture_mirrored_repeat
#define GL_ARB_texture_mirrored_repeat 1
#define GL_MIRRORED_REPEAT_ARB                   0x8370
#endif /* GL_ARB_texture_mirrored_repeat */

#ifndef GL_ARB_window_pos
#define GL_ARB_window_pos 1
typedef void (APIENTRYP PFNGLWINDOWPOS2DARBPROC)(GLdouble x, GLdouble y);
typedef void (APIENTRYP PFNGLWINDOWPOS2DVARBPROC)(const GLdouble *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2FARBPROC)(GLfloat x, GLfloat y);
typedef void (APIENTRYP PFNGLWINDOWPOS2FVARBPROC)(const GLfloat *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2IARBPROC)(GLint x, GLint y);
typedef void (APIENTRYP PFNGLWINDOWPOS2IVARBPROC)(const GLint *v);
typedef void (APIENTRYP PFNGLWINDOWPOS2SARBPROC)(GLshort x, GLshort y);
typedef void (APIENTRYP PFNGLWINDOWPOS2SVARBPROC)(const GLshort *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3DARBPROC)(GLdouble x, GLdouble y, GLdouble z);
typedef void (APIENTRYP PFNGLWINDOWPOS3DVARBPROC)(const GLdouble *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3FARBPROC)(GLfloat x, GLfloat y, GLfloat z);
typedef void (APIENTRYP PFNGLWINDOWPOS3FVARBPROC)(const GLfloat *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3IARBPROC)(GLint x, GLint y, GLint z);
typedef void (APIENTRYP PFNGLWINDOWPOS3IVARBPROC)(const GLint *v);
typedef void (APIENTRYP PFNGLWINDOWPOS3SARBPROC)(GLshort x, GLshort y, GLshort z);
typedef void (APIENTRYP PFNGLWINDOWPOS3SVARBPROC)(const GLshort *v);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glWindowPos2dARB(GLdouble x, GLdouble y);
GLAPI void APIENTRY glWindowPos2dvARB(const GLdouble *v);
GLAPI void APIENTRY glWindowPos2fARB(GLfloat x, GLfloat y);
GLAPI void APIENTRY glWindowPos2fvARB(const GLfloat *v);
GLAPI void APIENTRY glWindowPos2iARB(GLint x, GLint y);
GLAPI void APIENTRY glWindowPos2ivARB(const GLint *v);
GLAPI void APIENTRY glWindowPos2sARB(GLshort x, GLshort y);
GLAPI void APIENTRY glWindowPos2svARB(const GLshort *v);
GLAPI void APIENTRY glWindowPos3dARB(GLdouble x, GLdouble y, GLdouble z);
GLAPI void APIENTRY glWindowPos3dvARB(const GLdouble *v);
GLAPI void APIENTRY glWindowPos3fARB(GLfloat x, GLfloat y, GLfloat z);
GLAPI void APIENTRY glWindowPos3fvARB(const GLfloat *v);
GLAPI void APIENTRY glWindowPos3iARB(GLint x, GLint y, GLint z);
GLAPI void APIENTRY glWindowPos3ivARB(const GLint *v);
GLAPI void APIENTRY glWindowPos3sARB(GLshort x, GLshort y, GLshort z);
GLAPI void APIENTRY glWindowPos3svARB(const GLshort *v);
#endif
#endif /* GL_ARB_window_pos */

#ifndef GL_EXT_bgra
#define GL_EXT_bgra 1
#define GL_BGR_EXT                               0x80E0
#define GL_BGRA_EXT                              0x80E1
#endif /* GL_EXT_bgra */

#ifndef GL_EXT_blend_color
#define GL_EXT_blend_color 1
#define GL_CONSTANT_COLOR_EXT                    0x8001
#define GL_ONE_MINUS_CONSTANT_COLOR_EXT          0x8002
#define GL_CONSTANT_ALPHA_EXT                    0x8003
#define GL_ONE_MINUS_CONSTANT_ALPHA_EXT          0x8004
#define GL_BLEND_COLOR_EXT                       0x8005
typedef void (APIENTRYP PFNGLBLENDCOLOREXTPROC)(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glBlendColorEXT(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);
#endif
#endif /* GL_EXT_blend_color */

#ifndef GL_EXT_blend_func_separate
#define GL_EXT_blend_func_separate 1
#define GL_BLEND_DST_RGB_EXT                     0x80C8
#define GL_BLEND_SRC_RGB_EXT                     0x80C9
#define GL_BLEND_DST_ALPHA_EXT                   0x80CA
#define GL_BLEND_SRC_ALPHA_EXT                   0x80CB
typedef void (APIENTRYP PFNGLBLENDFUNCSEPARATEEXTPROC)(GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glBlendFuncSeparateEXT(GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha);
#endif
#endif /* GL_EXT_blend_func_separate */

#ifndef GL_EXT_blend_logic_op
#define GL_EXT_blend_logic_op 1
#endif /* GL_EXT_blend_logic_op */

#ifndef GL_EXT_blend_minmax
#define GL_EXT_blend_minmax 1
#define GL_MIN_EXT                               0x8007
#define GL_MAX_EXT                               0x8008
#define GL_FUNC_ADD_EXT                          0x8006
#define GL_BLEND_EQUATION_EXT                    0x8009
typedef void (APIENTRYP PFNGLBLENDEQUATIONEXTPROC)(GLenum mode);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glBlendEquationEXT(GLenum mode);
#endif
#endif /* GL_EXT_blend_minmax */

#ifndef GL_EXT_blend_subtract
#define GL_EXT_blend_subtract 1
#define GL_FUNC_SUBTRACT_EXT                     0x800A
#define GL_FUNC_REVERSE_SUBTRACT_EXT             0x800B
#endif /* GL_EXT_blend_subtract */

#ifndef GL_EXT_copy_texture
#define GL_EXT_copy_texture 1
typedef void (APIENTRYP PFNGLCOPYTEXIMAGE1DEXTPROC)(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width, GLint border);
typedef void (APIENTRYP PFNGLCOPYTEXIMAGE2DEXTPROC)(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width, GLsizei height, GLint border);
typedef void (APIENTRYP PFNGLCOPYTEXSUBIMAGE1DEXTPROC)(GLenum target, GLint level, GLint xoffset, GLint x, GLint y, GLsizei width);
typedef void (APIENTRYP PFNGLCOPYTEXSUBIMAGE2DEXTPROC)(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y, GLsizei width, GLsizei height);
typedef void (APIENTRYP PFNGLCOPYTEXSUBIMAGE3DEXTPROC)(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glCopyTexImage1DEXT(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width, GLint border);
GLAPI void APIENTRY glCopyTexImage2DEXT(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width, GLsizei height, GLint border);
GLAPI void APIENTRY glCopyTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLint x, GLint y, GLsizei width);
GLAPI void APIENTRY glCopyTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y, GLsizei width, GLsizei height);
GLAPI void APIENTRY glCopyTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height);
#endif
#endif /* GL_EXT_copy_texture */

#ifndef GL_EXT_draw_range_elements
#define GL_EXT_draw_range_elements 1
#define GL_MAX_ELEMENTS_VERTICES_EXT             0x80E8
#define GL_MAX_ELEMENTS_INDICES_EXT              0x80E9
typedef void (APIENTRYP PFNGLDRAWRANGEELEMENTSEXTPROC)(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type, const void *indices);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glDrawRangeElementsEXT(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type, const void *indices);
#endif
#endif /* GL_EXT_draw_range_elements */

#ifndef GL_EXT_fog_coord
#define GL_EXT_fog_coord 1
#define GL_FOG_COORDINATE_SOURCE_EXT             0x8450
#define GL_FOG_COORDINATE_EXT                    0x8451
#define GL_FRAGMENT_DEPTH_EXT                    0x8452
#define GL_CURRENT_FOG_COORDINATE_EXT            0x8453
#define GL_FOG_COORDINATE_ARRAY_TYPE_EXT         0x8454
#define GL_FOG_COORDINATE_ARRAY_STRIDE_EXT       0x8455
#define GL_FOG_COORDINATE_ARRAY_POINTER_EXT      0x8456
#define GL_FOG_COORDINATE_ARRAY_EXT              0x8457
typedef void (APIENTRYP PFNGLFOGCOORDFEXTPROC)(GLfloat coord);
typedef void (APIENTRYP PFNGLFOGCOORDFVEXTPROC)(const GLfloat *coord);
typedef void (APIENTRYP PFNGLFOGCOORDDEXTPROC)(GLdouble coord);
typedef void (APIENTRYP PFNGLFOGCOORDDVEXTPROC)(const GLdouble *coord);
typedef void (APIENTRYP PFNGLFOGCOORDPOINTEREXTPROC)(GLenum type, GLsizei stride, const void *pointer);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glFogCoordfEXT(GLfloat coord);
GLAPI void APIENTRY glFogCoordfvEXT(const GLfloat *coord);
GLAPI void APIENTRY glFogCoorddEXT(GLdouble coord);
GLAPI void APIENTRY glFogCoorddvEXT(const GLdouble *coord);
GLAPI void APIENTRY glFogCoordPointerEXT(GLenum type, GLsizei stride, const void *pointer);
#endif
#endif /* GL_EXT_fog_coord */

#ifndef GL_EXT_multi_draw_arrays
#define GL_EXT_multi_draw_arrays 1
typedef void (APIENTRYP PFNGLMULTIDRAWARRAYSEXTPROC)(GLenum mode, const GLint *first, const GLsizei *count, GLsizei primcount);
typedef void (APIENTRYP PFNGLMULTIDRAWELEMENTSEXTPROC)(GLenum mode, const GLsizei *count, GLenum type, const void *const*indices, GLsizei primcount);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glMultiDrawArraysEXT(GLenum mode, const GLint *first, const GLsizei *count, GLsizei primcount);
GLAPI void APIENTRY glMultiDrawElementsEXT(GLenum mode, const GLsizei *count, GLenum type, const void *const*indices, GLsizei primcount);
#endif
#endif /* GL_EXT_multi_draw_arrays */

#ifndef GL_EXT_packed_pixels
#define GL_EXT_packed_pixels 1
#define GL_UNSIGNED_BYTE_3_3_2_EXT               0x8032
#define GL_UNSIGNED_SHORT_4_4_4_4_EXT            0x8033
#define GL_UNSIGNED_SHORT_5_5_5_1_EXT            0x8034
#define GL_UNSIGNED_INT_8_8_8_8_EXT              0x8035
#define GL_UNSIGNED_INT_10_10_10_2_EXT           0x8036
#endif /* GL_EXT_packed_pixels */

#ifndef GL_EXT_point_parameters
#define GL_EXT_point_parameters 1
#define GL_POINT_SIZE_MIN_EXT                    0x8126
#define GL_POINT_SIZE_MAX_EXT                    0x8127
#define GL_POINT_FADE_THRESHOLD_SIZE_EXT         0x8128
#define GL_DISTANCE_ATTENUATION_EXT              0x8129
typedef void (APIENTRYP PFNGLPOINTPARAMETERFEXTPROC)(GLenum pname, GLfloat param);
typedef void (APIENTRYP PFNGLPOINTPARAMETERFVEXTPROC)(GLenum pname, const GLfloat *params);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glPointParameterfEXT(GLenum pname, GLfloat param);
GLAPI void APIENTRY glPointParameterfvEXT(GLenum pname, const GLfloat *params);
#endif
#endif /* GL_EXT_point_parameters */

#ifndef GL_EXT_rescale_normal
#define GL_EXT_rescale_normal 1
#define GL_RESCALE_NORMAL_EXT                    0x803A
#endif /* GL_EXT_rescale_normal */

#ifndef GL_EXT_secondary_color
#define GL_EXT_secondary_color 1
#define GL_COLOR_SUM_EXT                         0x8458
#define GL_CURRENT_SECONDARY_COLOR_EXT           0x8459
#define GL_SECONDARY_COLOR_ARRAY_SIZE_EXT        0x845A
#define GL_SECONDARY_COLOR_ARRAY_TYPE_EXT        0x845B
#define GL_SECONDARY_COLOR_ARRAY_STRIDE_EXT      0x845C
#define GL_SECONDARY_COLOR_ARRAY_POINTER_EXT     0x845D
#define GL_SECONDARY_COLOR_ARRAY_EXT             0x845E
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3BEXTPROC)(GLbyte red, GLbyte green, GLbyte blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3BVEXTPROC)(const GLbyte *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3DEXTPROC)(GLdouble red, GLdouble green, GLdouble blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3DVEXTPROC)(const GLdouble *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3FEXTPROC)(GLfloat red, GLfloat green, GLfloat blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3FVEXTPROC)(const GLfloat *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3IEXTPROC)(GLint red, GLint green, GLint blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3IVEXTPROC)(const GLint *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3SEXTPROC)(GLshort red, GLshort green, GLshort blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3SVEXTPROC)(const GLshort *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UBEXTPROC)(GLubyte red, GLubyte green, GLubyte blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UBVEXTPROC)(const GLubyte *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UIEXTPROC)(GLuint red, GLuint green, GLuint blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3UIVEXTPROC)(const GLuint *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3USEXTPROC)(GLushort red, GLushort green, GLushort blue);
typedef void (APIENTRYP PFNGLSECONDARYCOLOR3USVEXTPROC)(const GLushort *v);
typedef void (APIENTRYP PFNGLSECONDARYCOLORPOINTEREXTPROC)(GLint size, GLenum type, GLsizei stride, const void *pointer);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glSecondaryColor3bEXT(GLbyte red, GLbyte green, GLbyte blue);
GLAPI void APIENTRY glSecondaryColor3bvEXT(const GLbyte *v);
GLAPI void APIENTRY glSecondaryColor3dEXT(GLdouble red, GLdouble green, GLdouble blue);
GLAPI void APIENTRY glSecondaryColor3dvEXT(const GLdouble *v);
GLAPI void APIENTRY glSecondaryColor3fEXT(GLfloat red, GLfloat green, GLfloat blue);
GLAPI void APIENTRY glSecondaryColor3fvEXT(const GLfloat *v);
GLAPI void APIENTRY glSecondaryColor3iEXT(GLint red, GLint green, GLint blue);
GLAPI void APIENTRY glSecondaryColor3ivEXT(const GLint *v);
GLAPI void APIENTRY glSecondaryColor3sEXT(GLshort red, GLshort green, GLshort blue);
GLAPI void APIENTRY glSecondaryColor3svEXT(const GLshort *v);
GLAPI void APIENTRY glSecondaryColor3ubEXT(GLubyte red, GLubyte green, GLubyte blue);
GLAPI void APIENTRY glSecondaryColor3ubvEXT(const GLubyte *v);
GLAPI void APIENTRY glSecondaryColor3uiEXT(GLuint red, GLuint green, GLuint blue);
GLAPI void APIENTRY glSecondaryColor3uivEXT(const GLuint *v);
GLAPI void APIENTRY glSecondaryColor3usEXT(GLushort red, GLushort green, GLushort blue);
GLAPI void APIENTRY glSecondaryColor3usvEXT(const GLushort *v);
GLAPI void APIENTRY glSecondaryColorPointerEXT(GLint size, GLenum type, GLsizei stride, const void *pointer);
#endif
#endif /* GL_EXT_secondary_color */

#ifndef GL_EXT_separate_specular_color
#define GL_EXT_separate_specular_color 1
#define GL_LIGHT_MODEL_COLOR_CONTROL_EXT         0x81F8
#define GL_SINGLE_COLOR_EXT                      0x81F9
#define GL_SEPARATE_SPECULAR_COLOR_EXT           0x81FA
#endif /* GL_EXT_separate_specular_color */

#ifndef GL_EXT_shadow_funcs
#define GL_EXT_shadow_funcs 1
#endif /* GL_EXT_shadow_funcs */

#ifndef GL_EXT_stencil_wrap
#define GL_EXT_stencil_wrap 1
#define GL_INCR_WRAP_EXT                         0x8507
#define GL_DECR_WRAP_EXT                         0x8508
#endif /* GL_EXT_stencil_wrap */

#ifndef GL_EXT_subtexture
#define GL_EXT_subtexture 1
typedef void (APIENTRYP PFNGLTEXSUBIMAGE1DEXTPROC)(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLenum type, const void *pixels);
typedef void (APIENTRYP PFNGLTEXSUBIMAGE2DEXTPROC)(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLenum type, const void *pixels);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLenum type, const void *pixels);
GLAPI void APIENTRY glTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLenum type, const void *pixels);
#endif
#endif /* GL_EXT_subtexture */

#ifndef GL_EXT_texture3D
#define GL_EXT_texture3D 1
#define GL_PACK_SKIP_IMAGES_EXT                  0x806B
#define GL_PACK_IMAGE_HEIGHT_EXT                 0x806C
#define GL_UNPACK_SKIP_IMAGES_EXT                0x806D
#define GL_UNPACK_IMAGE_HEIGHT_EXT               0x806E
#define GL_TEXTURE_3D_EXT                        0x806F
#define GL_PROXY_TEXTURE_3D_EXT                  0x8070
#define GL_TEXTURE_DEPTH_EXT                     0x8071
#define GL_TEXTURE_WRAP_R_EXT                    0x8072
#define GL_MAX_3D_TEXTURE_SIZE_EXT               0x8073
typedef void (APIENTRYP PFNGLTEXIMAGE3DEXTPROC)(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type, const void *pixels);
typedef void (APIENTRYP PFNGLTEXSUBIMAGE3DEXTPROC)(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void *pixels);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI void APIENTRY glTexImage3DEXT(GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type, const void *pixels);
GLAPI void APIENTRY glTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void *pixels);
#endif
#endif /* GL_EXT_texture3D */

#ifndef GL_EXT_texture_cube_map
#define GL_EXT_texture_cube_map 1
#define GL_NORMAL_MAP_EXT                        0x8511
#define GL_REFLECTION_MAP_EXT                    0x8512
#define GL_TEXTURE_CUBE_MAP_EXT                  0x8513
#define GL_TEXTURE_BINDING_CUBE_MAP_EXT          0x8514
#define GL_TEXTURE_CUBE_MAP_POSITIVE_X_EXT       0x8515
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_X_EXT       0x8516
#define GL_TEXTURE_CUBE_MAP_POSITIVE_Y_EXT       0x8517
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_Y_EXT       0x8518
#define GL_TEXTURE_CUBE_MAP_POSITIVE_Z_EXT       0x8519
#define GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_EXT       0x851A
#define GL_PROXY_TEXTURE_CUBE_MAP_EXT            0x851B
#define GL_MAX_CUBE_MAP_TEXTURE_SIZE_EXT         0x851C
#endif /* GL_EXT_texture_cube_map */

#ifndef GL_EXT_texture_env_add
#define GL_EXT_texture_env_add 1
#endif /* GL_EXT_texture_env_add */

#ifndef GL_EXT_texture_env_combine
#define GL_EXT_texture_env_combine 1
#define GL_COMBINE_EXT                           0x8570
#define GL_COMBINE_RGB_EXT                       0x8571
#define GL_COMBINE_ALPHA_EXT                     0x8572
#define GL_RGB_SCALE_EXT                         0x8573
#define GL_ADD_SIGNED_EXT                        0x8574
#define GL_INTERPOLATE_EXT                       0x8575
#define GL_CONSTANT_EXT                          0x8576
#define GL_PRIMARY_COLOR_EXT                     0x8577
#define GL_PREVIOUS_EXT                          0x8578
#define GL_SOURCE0_RGB_EXT                       0x8580
#define GL_SOURCE1_RGB_EXT                       0x8581
#define GL_SOURCE2_RGB_EXT                       0x8582
#define GL_SOURCE0_ALPHA_EXT                     0x8588
#define GL_SOURCE1_ALPHA_EXT                     0x8589
#define GL_SOURCE2_ALPHA_EXT                     0x858A
#define GL_OPERAND0_RGB_EXT                      0x8590
#define GL_OPERAND1_RGB_EXT                      0x8591
#define GL_OPERAND2_RGB_EXT                      0x8592
#define GL_OPERAND0_ALPHA_EXT                    0x8598
#define GL_OPERAND1_ALPHA_EXT                    0x8599
#define GL_OPERAND2_ALPHA_EXT                    0x859A
#endif /* GL_EXT_texture_env_combine */

#ifndef GL_EXT_texture_lod_bias
#define GL_EXT_texture_lod_bias 1
#define GL_MAX_TEXTURE_LOD_BIAS_EXT              0x84FD
#define GL_TEXTURE_FILTER_CONTROL_EXT            0x8500
#define GL_TEXTURE_LOD_BIAS_EXT                  0x8501
#endif /* GL_EXT_texture_lod_bias */

#ifndef GL_EXT_texture_object
#define GL_EXT_texture_object 1
#define GL_TEXTURE_PRIORITY_EXT                  0x8066
#define GL_TEXTURE_RESIDENT_EXT                  0x8067
#define GL_TEXTURE_1D_BINDING_EXT                0x8068
#define GL_TEXTURE_2D_BINDING_EXT                0x8069
#define GL_TEXTURE_3D_BINDING_EXT                0x806A
typedef GLboolean (APIENTRYP PFNGLARETEXTURESRESIDENTEXTPROC)(GLsizei n, const GLuint *textures, GLboolean *residences);
typedef void (APIENTRYP PFNGLBINDTEXTUREEXTPROC)(GLenum target, GLuint texture);
typedef void (APIENTRYP PFNGLDELETETEXTURESEXTPROC)(GLsizei n, const GLuint *textures);
typedef void (APIENTRYP PFNGLGENTEXTURESEXTPROC)(GLsizei n, GLuint *textures);
typedef GLboolean (APIENTRYP PFNGLISTEXTUREEXTPROC)(GLuint texture);
typedef void (APIENTRYP PFNGLPRIORITIZETEXTURESEXTPROC)(GLsizei n, const GLuint *textures, const GLclampf *priorities);
#ifdef GL_GLEXT_PROTOTYPES
GLAPI GLboolean APIENTRY glAreTexturesResidentEXT(GLsizei n, const GLuint *textures, GLboolean *residences);
GLAPI void APIENTRY glBindTextureEXT(GLenum target, GLuint texture);
GLAPI void APIENTRY glDeleteTexturesEXT(GLsizei n, const GLuint *textures);
GLAPI void APIENTRY glGenTexturesEXT(GLsizei n, GLuint *textures);
GLAPI GLboolean APIENTRY glIsTextureEXT(GLuint texture);
GLAPI void APIENTRY glPrioritizeTexturesEXT(GLsizei n, const GLuint *textures, const GLclampf *priorities);
#endif
#endif /* GL_EXT_texture_object */

#ifndef GL_SGIS_generate_mipmap
#define GL_SGIS_generate_mipmap 1
#define GL_GENERATE_MIPMAP_SGIS                  0x8191
#define GL_GENERATE_MIPMAP_HINT_SGIS             0x8192
#endif /* GL_SGIS_generate_mipmap */

#ifndef GL_SGIS_texture_edge_clamp
#define GL_SGIS_texture_edge_clamp 1
#define GL_CLAMP_TO_EDGE_SGIS                    0x812F
#endif /* GL_SGIS_texture_edge_clamp */

#ifndef GL_SGIS_texture_lod
#define GL_SGIS_texture_lod 1
#define GL_TEXTURE_MIN_LOD_SGIS                  0x813A
#define GL_TEXTURE_MAX_LOD_SGIS                  0x813B
#define GL_TEXTURE_BASE_LEVEL_SGIS               0x813C
#define GL_TEXTURE_MAX_LEVEL_SGIS                0x813D
#endif /* GL_SGIS_texture_lod */

#ifndef GL_NV_blend_square
#define GL_NV_blend_square 1
#endif /* GL_NV_blend_square */

#ifndef GL_IBM_texture_mirrored_repeat
#define GL_IBM_texture_mirrored_repeat 1
#define GL_MIRRORED_REPEAT_IBM                   0x8370
#endif /* GL_IBM_texture_mirrored_repeat */

#ifdef __cplusplus
}
#endif

#endif /* GLASS_GL_GLEXT_H */
