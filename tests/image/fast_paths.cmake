# The fast paths write the same bytes as the reference path: runs each image-test program with
# GLASS_FAST_PATHS=0 (every fragment through the reference path) and with the fast paths on,
# and fails unless the two PNGs are identical byte for byte (docs/pipeline.md, "Fast paths").
#
#   cmake -DPROGRAMS=<program|program|...> -DOUTPUT_DIR=<dir> -P fast_paths.cmake
string(REPLACE "|" ";" PROGRAMS "${PROGRAMS}")
if(PROGRAMS STREQUAL "")
  message(FATAL_ERROR "no programs to run")
endif()
set(differing "")
foreach(program IN LISTS PROGRAMS)
  get_filename_component(name ${program} NAME)
  set(hashes "")
  foreach(fast 0 1)
    set(png ${OUTPUT_DIR}/${name}.fast${fast}.png)
    file(REMOVE ${png})
    execute_process(COMMAND ${CMAKE_COMMAND} -E env GLASS_FAST_PATHS=${fast} ${program} ${png}
                    RESULT_VARIABLE status)
    if(NOT status EQUAL 0 OR NOT EXISTS ${png})
      message(FATAL_ERROR "${name} with GLASS_FAST_PATHS=${fast} failed (${status})")
    endif()
    file(SHA256 ${png} hash)
    list(APPEND hashes ${hash})
  endforeach()
  list(GET hashes 0 reference)
  list(GET hashes 1 fast)
  if(NOT reference STREQUAL fast)
    list(APPEND differing ${name})
  endif()
endforeach()
list(LENGTH PROGRAMS count)
if(differing)
  message(FATAL_ERROR "the fast paths wrote other bytes than the reference path: ${differing} "
                      "(both pictures are in ${OUTPUT_DIR})")
endif()
message(STATUS "${count} programs: the same bytes with the fast paths off and on")
