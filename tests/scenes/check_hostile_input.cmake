# Hostile input on the command line of `glass render`: 100 MB of random bytes as a scene, control
# characters in a scene, the limits of docs/scene-format.md ("Limits") at and past their ends.
# Each must end in messages and exit status 1 (or a picture when within the limits), never a
# crash, and no byte of the file that a terminal would act on may reach the terminal.
# Run by the test scene_hostile_input with GLASS, RANDOM_BYTES (the generator) and WORK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
string(ASCII 27 escape)

include(${CMAKE_CURRENT_LIST_DIR}/glass_command_checks.cmake)  # run(), expect_text()

# render(<expected status> <output variable> <scene>): a 64 x 64 render of the scene.
function(render expected out scene)
  run(${expected} text render "${scene}" -o "${WORK}/out.png" --size 64x64)
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

function(expect_no_escape haystack what)
  string(FIND "${haystack}" "${escape}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${what}: a raw ESC byte reached the terminal")
  endif()
endfunction()

# 100 MB of random bytes: 20 errors and the words that say the run stopped there.
execute_process(COMMAND "${RANDOM_BYTES}" "${WORK}/random.scene" 104857600 RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "random_bytes failed (${status})")
endif()
render(1 text "${WORK}/random.scene")
file(REMOVE "${WORK}/random.scene")
expect_text("20 errors (stopped at the limit of 20)" "${text}" "random bytes")
string(REGEX MATCHALL ": error: " errors "${text}")
list(LENGTH errors count)
if(NOT count EQUAL 20)
  message(FATAL_ERROR "random bytes: ${count} messages shown for 20 errors counted\n${text}")
endif()
expect_no_escape("${text}" "random bytes")
if(EXISTS "${WORK}/out.png")
  message(FATAL_ERROR "random bytes: a picture was written")
endif()

# An ESC sequence in a statement's name: shown as \x1b, in the message and in the source line.
file(WRITE "${WORK}/escape.scene" "${escape}[2Jclear 1\n")
render(1 text "${WORK}/escape.scene")
expect_no_escape("${text}" "escape sequence")
expect_text("\\x1b[2Jclear" "${text}" "escape sequence")

# Limits: Bezier segments 1 to 4096, slices 3 to 4096 (docs/scene-format.md, "Limits").
file(WRITE "${WORK}/segments.scene" "bezier_curve points [ 0 0 0  1 1 0 ] segments 4096\n")
render(0 text "${WORK}/segments.scene")
file(WRITE "${WORK}/segments.scene" "bezier_curve points [ 0 0 0  1 1 0 ] segments 4097\n")
render(1 text "${WORK}/segments.scene")
expect_text("4096" "${text}" "bezier_curve segments 4097")
file(WRITE "${WORK}/segments.scene"
     "bezier_patch u_order 2 v_order 2 points [ 0 0 0  1 0 0  0 1 0  1 1 0 ] segments 4097 1\n")
render(1 text "${WORK}/segments.scene")
expect_text("from 1 to 4096" "${text}" "bezier_patch segments 4097")
file(WRITE "${WORK}/slices.scene" "sphere 1 4097 8\n")
render(1 text "${WORK}/slices.scene")
expect_text("4096" "${text}" "sphere slices 4097")

# An OBJ face index beyond 2^31 is reported as written, not wrapped round.
file(WRITE "${WORK}/huge.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n")
file(WRITE "${WORK}/huge.scene" "model \"huge.obj\"\n")
render(1 text "${WORK}/huge.scene")
expect_text("a face names vertex 99999999999999999999, but the file has 3" "${text}" "OBJ index")
