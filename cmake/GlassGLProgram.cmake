# GL programs built twice from one source.
#
# A GL program is a plain C (or C++) program that uses only <GL/gl.h>, <GL/glu.h> and
# <glass/context.h> (glassCreateContext, glassMakeCurrent, glassWritePNG, glassDestroyContext).
#
#   glass_add_gl_program(<name> [GLASS_ONLY] SOURCES <file>...)
#
# builds
#   <name>       against glass: libglass (glass::gl) and glass's own GL headers;
#   <name>_mesa  against Mesa: the system's GL headers, libOSMesa and libGLU, with glass/context.h
#                implemented on OSMesa by tools/reference/osmesa_context.c. Only when pkg-config
#                finds osmesa and glu (GLASS_HAVE_MESA is then ON), and not for GLASS_ONLY
#                programs, which use glass's own extensions that Mesa does not have.
# Mesa is the independent oracle: its picture of a program is the reference glass must match.

set(GLASS_HAVE_MESA OFF)
if(GLASS_BUILD_REFERENCE)
  find_package(PkgConfig QUIET)
  if(PKG_CONFIG_FOUND)
    pkg_check_modules(MESA_GL QUIET IMPORTED_TARGET osmesa glu)
  endif()
  find_path(GLASS_STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb)
  set(GLASS_CONTEXT_HEADER ${PROJECT_SOURCE_DIR}/pipeline/include/glass/context.h)
  if(MESA_GL_FOUND AND GLASS_STB_INCLUDE_DIR AND EXISTS ${GLASS_CONTEXT_HEADER})
    set(GLASS_HAVE_MESA ON)
    # The Mesa builds must see glass/context.h but none of glass's GL headers, so the header is
    # copied alone into a directory of its own (re-copied whenever it changes).
    set(GLASS_MESA_INCLUDE_DIR ${PROJECT_BINARY_DIR}/mesa_include)
    configure_file(${GLASS_CONTEXT_HEADER} ${GLASS_MESA_INCLUDE_DIR}/glass/context.h COPYONLY)
    message(STATUS "Mesa reference builds: on (OSMesa ${MESA_GL_osmesa_VERSION})")
  else()
    message(STATUS "Mesa reference builds: off (needs libosmesa6-dev, libglu1-mesa-dev, libstb-dev "
                   "and pipeline/include/glass/context.h)")
  endif()
endif()

# Every <name>_mesa program, so that tools/make-references.sh can build them in one go.
if(NOT TARGET mesa_programs)
  add_custom_target(mesa_programs)
endif()

function(glass_add_gl_program name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "GLASS_ONLY" "" "SOURCES")
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "glass_add_gl_program(${name}): no SOURCES")
  endif()

  # tools/reference/include: run_gl_program() (gl_program.h) and the shared random numbers (lcg.h).
  set(support_include ${PROJECT_SOURCE_DIR}/tools/reference/include)

  add_executable(${name} ${ARG_SOURCES})
  target_include_directories(${name} PRIVATE ${support_include})
  target_link_libraries(${name} PRIVATE glass::gl m)

  if(GLASS_HAVE_MESA AND NOT ARG_GLASS_ONLY)
    add_executable(${name}_mesa ${ARG_SOURCES})
    target_include_directories(${name}_mesa PRIVATE ${support_include})
    # OSMesa first: the program's and libGLU's gl* calls must bind to OSMesa's entry points.
    target_link_libraries(${name}_mesa PRIVATE glass_osmesa_context PkgConfig::MESA_GL m)
    # GLUT shapes come from freeglut, after OSMesa so that freeglut's gl* calls bind to OSMesa.
    if(TARGET glass_mesa_freeglut)
      target_link_libraries(${name}_mesa PRIVATE glass_mesa_freeglut
                            $<TARGET_OBJECTS:glass_mesa_freeglut>)
    endif()
    add_dependencies(mesa_programs ${name}_mesa)
  endif()
endfunction()
