# The benchmark's frames, byte for byte the same with 1, 2, 3 and 8 rasterizer threads. Its frames
# are far larger than the image tests' (1920 x 1080, up to 250,000 primitives), so they fill
# scenes past the sizes at which the rasterizer hands them to its threads early or in several
# parts (rasterizer/src/tiled_rasterizer.cpp); the images must not depend on where a frame was
# cut.
#
#   cmake -DBENCHMARK=<benchmark program> -DOUTPUT_DIR=<dir> -P benchmark_thread_determinism.cmake
if(NOT BENCHMARK OR NOT OUTPUT_DIR)
  message(FATAL_ERROR "usage: cmake -DBENCHMARK=<program> -DOUTPUT_DIR=<dir> -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
foreach(threads 1 2 3 8)
  set(dir ${OUTPUT_DIR}/threads${threads})
  file(REMOVE_RECURSE ${dir})
  file(MAKE_DIRECTORY ${dir})
  execute_process(COMMAND ${CMAKE_COMMAND} -E env GLASS_THREADS=${threads} ${BENCHMARK} --runs 1 --png ${dir}
                  RESULT_VARIABLE status OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "the benchmark with GLASS_THREADS=${threads} failed (${status})")
  endif()
  file(GLOB pngs RELATIVE ${dir} ${dir}/*.png)
  list(LENGTH pngs count)
  if(count LESS 12)
    message(FATAL_ERROR "the benchmark with GLASS_THREADS=${threads} wrote ${count} frames, not 12")
  endif()
  if(threads EQUAL 1)
    set(first_pngs ${pngs})
    continue()
  endif()
  if(NOT pngs STREQUAL first_pngs)
    message(FATAL_ERROR "GLASS_THREADS=${threads} wrote other frames (${pngs}) than 1 thread (${first_pngs})")
  endif()
  foreach(png IN LISTS pngs)
    file(SHA256 ${OUTPUT_DIR}/threads1/${png} expected)
    file(SHA256 ${dir}/${png} actual)
    if(NOT actual STREQUAL expected)
      message(FATAL_ERROR "${png}: GLASS_THREADS=${threads} wrote other bytes than GLASS_THREADS=1")
    endif()
  endforeach()
endforeach()
message(STATUS "${count} benchmark frames: the same bytes with 1, 2, 3 and 8 threads")
