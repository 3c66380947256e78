# Runs the glass build of mipmap_values.c with its fast paths on and off (GLASS_FAST_PATHS=0:
# unsigned bytes halved as raw values in doubles instead of as bytes) and fails unless both print
# the same. Needs no Mesa, so it also runs under the sanitizers (tools/test.sh).
foreach(mode FAST REFERENCE)
  set(environment "")
  if(mode STREQUAL "REFERENCE")
    set(environment GLASS_FAST_PATHS=0)
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${environment} ${GLASS}
                  OUTPUT_FILE ${WORK_DIR}/GLASS_${mode}.txt RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${GLASS} (${mode}) failed: ${status}")
  endif()
  file(SHA256 ${WORK_DIR}/GLASS_${mode}.txt ${mode}_digest)
endforeach()
file(STRINGS ${WORK_DIR}/GLASS_FAST.txt lines)
list(LENGTH lines count)
if(count LESS 1000)
  message(FATAL_ERROR "glass printed only ${count} lines")
endif()
if(NOT FAST_digest STREQUAL REFERENCE_digest)
  message(FATAL_ERROR "glass's GLU prints other values with its fast paths off (GLASS_REFERENCE.txt) than on (GLASS_FAST.txt)")
endif()
message("${count} lines, the same with the fast paths on and off")
