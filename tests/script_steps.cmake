# Steps shared by the tests written as CMake scripts (cmake -P): tests/install, tests/osmesa.

# run(<description> <command>...): runs the command; a non-zero exit fails the script with the
# description and everything the command printed. Its standard output is left in `output`.
function(run description)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${description} failed (${status}):\n${out}${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

# expect_output(<description> <regex>): the last run()'s output must match.
function(expect_output description regex)
  if(NOT output MATCHES "${regex}")
    message(FATAL_ERROR "${description}: the output does not match '${regex}':\n${output}")
  endif()
endfunction()
