# The same bytes for any thread count: runs each image-test program with GLASS_THREADS=1, 2, 3
# and 8 and fails unless its four PNGs are identical byte for byte (ARCHITECTURE.md, principle 3).
# Tiles are rasterized by whichever thread takes them first, so a difference here means a pixel
# saw its fragments in another order, or two threads touched the same memory.
#
#   cmake -DPROGRAMS=<program|program|...> -DOUTPUT_DIR=<dir> -P thread_determinism.cmake
string(REPLACE "|" ";" PROGRAMS "${PROGRAMS}")
if(PROGRAMS STREQUAL "")
  message(FATAL_ERROR "no programs to run")
endif()
foreach(program IN LISTS PROGRAMS)
  get_filename_component(name ${program} NAME)
  set(first "")
  foreach(threads 1 2 3 8)
    set(png ${OUTPUT_DIR}/${name}.threads${threads}.png)
    file(REMOVE ${png})
    execute_process(COMMAND ${CMAKE_COMMAND} -E env GLASS_THREADS=${threads} ${program} ${png}
                    RESULT_VARIABLE status)
    if(NOT status EQUAL 0 OR NOT EXISTS ${png})
      message(FATAL_ERROR "${name} with GLASS_THREADS=${threads} failed (${status})")
    endif()
    file(SHA256 ${png} hash)
    if(first STREQUAL "")
      set(first ${hash})
    elseif(NOT hash STREQUAL first)
      message(FATAL_ERROR "${name}: GLASS_THREADS=${threads} wrote other bytes than GLASS_THREADS=1")
    endif()
  endforeach()
  message(STATUS "${name}: the same bytes with 1, 2, 3 and 8 threads")
endforeach()
