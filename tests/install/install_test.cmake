# The install test (cmake -P): installs the build into a fresh prefix, then builds and runs
# program.c the two ways a user would:
#   1. cc program.c $(pkg-config --cflags --libs glass), with PKG_CONFIG_PATH into the prefix; its
#      <GL/gl.h>, <GL/glu.h> and <glass/context.h> must come from the prefix;
#   2. a CMake project with find_package(glass) linking glass::gl (consumer/);
# and runs the installed glass command with an empty environment (3: render and compare).
# Variables: BUILD_DIR, SOURCE_DIR (tests/install), WORK_DIR (scratch), C_COMPILER, BIN_DIR (the
# install's bin directory, relative to the prefix), SCENE (a scene to render).
cmake_minimum_required(VERSION 3.25)

include(${SOURCE_DIR}/../script_steps.cmake)  # run()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

file(GLOB_RECURSE pc_files ${prefix}/*/glass.pc)
if(NOT pc_files)
  message(FATAL_ERROR "no glass.pc installed under ${prefix}")
endif()
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})

# 1. pkg-config, exactly as a user types it.
set(program ${SOURCE_DIR}/program.c)
run("the headers program.c includes"
    sh -c "'${C_COMPILER}' -M '${program}' $(pkg-config --cflags glass)")
# The dependency list names files by the paths the compiler used (pkg-config's include directory
# reads prefix/lib/pkgconfig/../../include); compare real paths.
string(REGEX REPLACE "[ \t\r\n\\]+" ";" dependencies "${output}")
foreach(header GL/gl.h GL/glu.h glass/context.h)
  set(used "")
  foreach(dependency IN LISTS dependencies)
    if(dependency MATCHES "/${header}$")
      get_filename_component(used ${dependency} REALPATH)
      break()
    endif()
  endforeach()
  get_filename_component(expected ${prefix}/include/${header} REALPATH)
  if(NOT used STREQUAL expected)
    message(FATAL_ERROR "<${header}> resolves to '${used}', not ${expected}; "
                        "the compiler saw:\n${output}")
  endif()
endforeach()
run("cc program.c $(pkg-config --cflags --libs glass)"
    sh -c "'${C_COMPILER}' '${program}' $(pkg-config --cflags --libs glass) -o '${WORK_DIR}/program'")
run("the program built with pkg-config" ${WORK_DIR}/program)
message(STATUS "pkg-config build: ${output}")

# 2. find_package(glass).
run("configuring the find_package(glass) project"
    ${CMAKE_COMMAND} -S ${SOURCE_DIR}/consumer -B ${WORK_DIR}/consumer -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_C_COMPILER=${C_COMPILER} -DGLASS_CONSUMER_SOURCE=${program})
run("building the find_package(glass) project" ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run("the program built with find_package(glass)" ${WORK_DIR}/consumer/consumer)
message(STATUS "find_package build: ${output}")

# 3. The installed glass command, with an empty environment (no LD_LIBRARY_PATH): its run path
#    ($ORIGIN-relative, cmake/install.cmake) finds the installed libglass.
run("the installed glass command with an empty environment"
    env -i ${prefix}/${BIN_DIR}/glass render ${SCENE} -o ${WORK_DIR}/scene.png --size 64x48)
if(NOT EXISTS ${WORK_DIR}/scene.png)
  message(FATAL_ERROR "the installed glass command wrote no picture")
endif()
message(STATUS "installed glass command: rendered ${SCENE}")
# `glass compare` loads the image comparison module installed beside it (lib/glass).
run("the installed glass compare with an empty environment"
    env -i ${prefix}/${BIN_DIR}/glass compare ${WORK_DIR}/scene.png ${WORK_DIR}/scene.png --fail-psnr inf)
expect_output("the installed glass compare of a picture with itself" "identical")

# 4. Textbook-style programs (textbook/*.c) that name features by their extensions and use depth
#    textures, shadow comparison and the imaging subset, built unchanged with pkg-config and run;
#    each checks its own pixels and exits non-zero on a difference.
file(GLOB textbook_programs ${SOURCE_DIR}/textbook/*.c)
foreach(source IN LISTS textbook_programs)
  get_filename_component(name ${source} NAME_WE)
  run("cc textbook/${name}.c $(pkg-config --cflags --libs glass)"
      sh -c "'${C_COMPILER}' '${source}' $(pkg-config --cflags --libs glass) -o '${WORK_DIR}/${name}'")
  run("textbook/${name}" ${WORK_DIR}/${name})
  message(STATUS "textbook/${name}: ${output}")
endforeach()
