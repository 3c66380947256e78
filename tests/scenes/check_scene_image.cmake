# One scene image test: glass renders SCENE to OUTPUT, and `glass compare` measures it against
# REFERENCE with the limits FAIL_PSNR and FAIL_PERCENT, writing OUTPUT's .diff.png on failure.
string(REGEX REPLACE "\\.png$" ".diff.png" diff "${OUTPUT}")
file(REMOVE "${OUTPUT}" "${diff}")
execute_process(COMMAND "${GLASS}" render "${SCENE}" -o "${OUTPUT}" RESULT_VARIABLE status
                ERROR_VARIABLE messages)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "glass render ${SCENE} failed (status ${status}):\n${messages}")
endif()
if(NOT EXISTS "${REFERENCE}")
  message(FATAL_ERROR "no reference picture ${REFERENCE} (tools/make-scene-references.sh makes it)")
endif()
execute_process(COMMAND "${GLASS}" compare "${OUTPUT}" "${REFERENCE}" --fail-psnr ${FAIL_PSNR}
                        --fail-percent ${FAIL_PERCENT}
                RESULT_VARIABLE status OUTPUT_VARIABLE measures ERROR_VARIABLE messages)
message("${measures}")
if(NOT status EQUAL 0)
  execute_process(COMMAND "${GLASS}" compare "${OUTPUT}" "${REFERENCE}" --diff "${diff}"
                  OUTPUT_QUIET ERROR_QUIET)
  message(FATAL_ERROR "${SCENE} is beyond its limits (PSNR >= ${FAIL_PSNR} dB, at most "
                      "${FAIL_PERCENT}% of pixels off): see ${diff}\n${messages}")
endif()
