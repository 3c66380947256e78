# The README's recipe for building the study guide's Listing 5 on glass, tested as a student
# follows it: glass installed into a fresh prefix, then Listing 5 built three ways, with
#   1. cc listing5.c $(pkg-config --cflags --libs glass)
#   2. cc listing5.c $(pkg-config --cflags --libs glut)
#   3. cc -I$P/include listing5.c -L$P/lib -Wl,-rpath,$P/lib -lglut -lGLU -lGL (a freeglut
#      Makefile's libraries, pointed at glass's prefix)
# Each runs headless and must show the picture glass draws off-screen for the same calls.
# Variables: BUILD_DIR, LIBDIR (relative), SOURCE_DIR (tests/glut), BIN_DIR (the test programs),
# WORK_DIR (scratch), C_COMPILER.
cmake_minimum_required(VERSION 3.25)

function(run description)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${description} failed (${status}):\n${out}${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

set(libdir ${prefix}/${LIBDIR})
foreach(name libglut.so.3 libglut.so)
  if(NOT IS_SYMLINK ${libdir}/${name} OR NOT EXISTS ${libdir}/${name})
    message(FATAL_ERROR "${libdir}/${name} is not a name of the installed libglass")
  endif()
endforeach()

set(listing ${SOURCE_DIR}/programs/listing5.c)
set(ENV{PKG_CONFIG_PATH} ${libdir}/pkgconfig)
run("cc listing5.c $(pkg-config --cflags --libs glass)"
    sh -c "'${C_COMPILER}' '${listing}' $(pkg-config --cflags --libs glass) -o '${WORK_DIR}/with_glass_pc'")
run("cc listing5.c $(pkg-config --cflags --libs glut)"
    sh -c "'${C_COMPILER}' '${listing}' $(pkg-config --cflags --libs glut) -o '${WORK_DIR}/with_glut_pc'")
run("cc -I include listing5.c -L lib -lglut -lGLU -lGL"
    ${C_COMPILER} -I${prefix}/include ${listing} -L${libdir} -Wl,-rpath,${libdir}
    -lglut -lGLU -lGL -o ${WORK_DIR}/with_lglut)

# The libglass a program loads is the prefix's.
run("ldd" ldd ${WORK_DIR}/with_lglut)
if(NOT output MATCHES "libglass[^\n]*=> ${libdir}/")
  message(FATAL_ERROR "with_lglut does not load the prefix's libglass:\n${output}")
endif()

file(WRITE ${WORK_DIR}/events.txt "key space\nkey space\nkey space\nkey space\n")
run("Listing 5's calls off-screen" ${BIN_DIR}/glut_listing5_offscreen 4 ${WORK_DIR}/offscreen.png)
set(ENV{SDL_VIDEODRIVER} dummy)
set(ENV{GLASS_GLUT_EVENTS} ${WORK_DIR}/events.txt)
foreach(program with_glass_pc with_glut_pc with_lglut)
  set(ENV{GLASS_GLUT_SNAPSHOT} ${WORK_DIR}/${program}.png)
  run("${program}, headless" ${WORK_DIR}/${program})
  run("${program}'s picture against the off-screen one"
      ${BIN_DIR}/glut_png_probe ${WORK_DIR}/${program}.png same ${WORK_DIR}/offscreen.png)
  message(STATUS "${program}: the same picture as off-screen")
endforeach()
