# The fast paths give the reference path's bytes: runs each image-test program with
# GLASS_FAST_PATHS=0 (the reference path alone) and with the fast paths on, and fails unless the
# two PNGs are identical byte for byte (docs/pipeline.md, "Fast paths").
#
#   cmake -DPROGRAMS=<program|program|...> -DOUTPUT_DIR=<dir> -P fast_paths.cmake
string(REPLACE "|" ";" PROGRAMS "${PROGRAMS}")
if(PROGRAMS STREQUAL "")
  message(FATAL_ERROR "no programs to run")
endif()
set(failed "")
foreach(program IN LISTS PROGRAMS)
  get_filename_component(name ${program} NAME)
  set(hashes "")
  foreach(switch 0 1)
    set(png ${OUTPUT_DIR}/${name}.fast${switch}.png)
    file(REMOVE ${png})
    execute_process(COMMAND ${CMAKE_COMMAND} -E env GLASS_FAST_PATHS=${switch} ${program} ${png}
                    RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
    if(NOT status EQUAL 0 OR NOT EXISTS ${png})
      message(FATAL_ERROR "${name} with GLASS_FAST_PATHS=${switch} failed (${status})")
    endif()
    file(SHA256 ${png} hash)
    list(APPEND hashes ${hash})
  endforeach()
  list(GET hashes 0 reference)
  list(GET hashes 1 fast)
  if(NOT reference STREQUAL fast)
    list(APPEND failed ${name})
  endif()
endforeach()
list(LENGTH PROGRAMS count)
if(failed)
  message(FATAL_ERROR "the fast paths wrote other bytes than the reference path (GLASS_FAST_PATHS=0) "
                      "for: ${failed}; the two pictures are in ${OUTPUT_DIR}")
endif()
message(STATUS "${count} programs: the same bytes with the fast paths on and off")
