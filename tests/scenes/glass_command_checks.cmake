# The checks the command-line test scripts share: running the `glass` program (GLASS) with an
# expected exit status, and finding a text in what it printed.

# run(<expected status> <name of output variable> args...)
function(run expected out)
  execute_process(COMMAND "${GLASS}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE stdout
                  ERROR_VARIABLE stderr)
  if(NOT status STREQUAL "${expected}")
    string(REPLACE ";" " " shown "${ARGN}")
    message(FATAL_ERROR "glass ${shown}: expected status ${expected}, got ${status}\n${stdout}${stderr}")
  endif()
  set(${out} "${stdout}${stderr}" PARENT_SCOPE)
endfunction()

function(expect_text text haystack what)
  string(FIND "${haystack}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${what}: expected to find\n  ${text}\nin\n${haystack}")
  endif()
endfunction()
