# The fast paths give the reference path's bytes: runs each image-test program with
# GLASS_FAST_PATHS=0 (the reference path alone) and with the fast paths on, and fails unless the
# two PNGs are identical byte for byte (docs/pipeline.md, "Fast paths").
#
# The same comparison serves for the SIMD targets: with -DVARIABLE=GLASS_SIMD_TARGET and
# -DTARGET_LISTER=<simd_target_names>, the values are the targets the lister says this processor
# runs (the first, "scalar", is the reference), and the lister also checks, run with each value,
# that glass really picked that target.
#
#   cmake -DPROGRAMS=<program|program|...> -DOUTPUT_DIR=<dir>
#         [-DVARIABLE=<name> -DVALUES=<reference|other|...> | -DTARGET_LISTER=<program>]
#         -P fast_paths.cmake
string(REPLACE "|" ";" PROGRAMS "${PROGRAMS}")
if(PROGRAMS STREQUAL "")
  message(FATAL_ERROR "no programs to run")
endif()
if(NOT DEFINED VARIABLE)
  set(VARIABLE GLASS_FAST_PATHS)
  set(VALUES "0|1")
endif()
if(DEFINED TARGET_LISTER)
  execute_process(COMMAND ${TARGET_LISTER} RESULT_VARIABLE status OUTPUT_VARIABLE VALUES
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${TARGET_LISTER} failed (${status})")
  endif()
  string(REPLACE " " ";" VALUES "${VALUES}")
  foreach(value IN LISTS VALUES)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env ${VARIABLE}=${value} ${TARGET_LISTER} --chosen
                    OUTPUT_VARIABLE chosen OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT chosen STREQUAL value)
      message(FATAL_ERROR "${VARIABLE}=${value} ran the target '${chosen}'")
    endif()
  endforeach()
else()
  string(REPLACE "|" ";" VALUES "${VALUES}")
endif()
list(LENGTH VALUES value_count)
if(value_count LESS 2)
  message(STATUS "only ${VALUES} to run: nothing to compare")
endif()
list(GET VALUES 0 reference_value)

set(failed "")
foreach(program IN LISTS PROGRAMS)
  get_filename_component(name ${program} NAME)
  set(reference "")
  foreach(value IN LISTS VALUES)
    set(png ${OUTPUT_DIR}/${name}.${value}.png)
    file(REMOVE ${png})
    execute_process(COMMAND ${CMAKE_COMMAND} -E env ${VARIABLE}=${value} ${program} ${png}
                    RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
    if(NOT status EQUAL 0 OR NOT EXISTS ${png})
      message(FATAL_ERROR "${name} with ${VARIABLE}=${value} failed (${status})")
    endif()
    file(SHA256 ${png} hash)
    if(value STREQUAL reference_value)
      set(reference ${hash})
    elseif(NOT hash STREQUAL reference)
      list(APPEND failed "${name} (${value})")
    endif()
  endforeach()
endforeach()
list(LENGTH PROGRAMS count)
if(failed)
  message(FATAL_ERROR "other bytes than with ${VARIABLE}=${reference_value} for: ${failed}; "
                      "the pictures are in ${OUTPUT_DIR}")
endif()
message(STATUS "${count} programs: the same bytes with ${VARIABLE} = ${VALUES}")
