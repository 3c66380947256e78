# The command line of `glass render` and `glass compare`: exit codes, output files, options.
# Run by the test scene_cli with GLASS (the program), SOURCE_DIR (the repository) and WORK (a
# scratch directory).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(scenes "${SOURCE_DIR}/scenes")

include(${CMAKE_CURRENT_LIST_DIR}/glass_command_checks.cmake)  # run(), expect_text()

function(expect_file path)
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "expected the file ${path}")
  endif()
endfunction()

function(expect_no_file path)
  if(EXISTS "${path}")
    message(FATAL_ERROR "expected no file ${path}")
  endif()
endfunction()

# Help and usage.
run(0 text --help)
expect_text("render" "${text}" "glass --help")
expect_text("compare" "${text}" "glass --help")
run(0 text render --help)
expect_text("examples:" "${text}" "glass render --help")
run(0 text compare --help)
expect_text("examples:" "${text}" "glass compare --help")
run(2 text)
run(2 text no_such_command)
run(2 text render)
run(2 text render "${scenes}/sierpinski.scene")
run(2 text render "${scenes}/sierpinski.scene" -o "${WORK}/x.gif")
expect_text("cannot tell the picture format" "${text}" "unknown format")
run(2 text render "${scenes}/sierpinski.scene" -o "${WORK}/x.png" --size 0x10)
run(2 text render "${scenes}/sierpinski.scene" -o "${WORK}/x.png" --ssaa 17)
run(2 text render "${scenes}/sierpinski.scene" -o "${WORK}/x.png" --view sideways)
run(2 text render "${scenes}/sierpinski.scene" -o "${WORK}/x.png" --bogus)
run(2 text render "${scenes}/sierpinski.scene" -o "${WORK}/x.png" --frames 3:1)
run(2 text render "${scenes}/sierpinski.scene" -o "${WORK}/x.png" --frames 1)
expect_text("past the scene's last frame" "${text}" "--frames past the end")
expect_no_file("${WORK}/x.png")

# Every picture format, by extension.
foreach(extension png jpg jpeg bmp tga)
  run(0 text render "${scenes}/sierpinski.scene" -o "${WORK}/sierpinski.${extension}" --size 64x64)
  expect_file("${WORK}/sierpinski.${extension}")
endforeach()

# A missing directory is bad input, and nothing is written.
run(1 text render "${scenes}/sierpinski.scene" -o "${WORK}/no/such/dir/x.png")
expect_no_file("${WORK}/no/such/dir/x.png")

# --size and --ssaa: the picture has the size asked for.
run(0 text render "${scenes}/lighting.scene" -o "${WORK}/small.png" --size 96x32 --ssaa 3)
run(0 text compare "${WORK}/small.png" "${WORK}/small.png")
expect_text("96 x 32" "${text}" "--size with --ssaa")

# --frames: numbered files, no unnumbered one; a printf pattern.
run(0 text render "${scenes}/animation.scene" -o "${WORK}/spin.png" --frames 0:2 --size 80x60)
expect_file("${WORK}/spin_0000.png")
expect_file("${WORK}/spin_0002.png")
expect_no_file("${WORK}/spin_0003.png")
expect_no_file("${WORK}/spin.png")
run(2 text render "${scenes}/animation.scene" -o "${WORK}/spin.png" --frames 0:60)
run(0 text render "${scenes}/animation.scene" -o "${WORK}/frame%02d.png" --frames 7 --size 80x60)
expect_file("${WORK}/frame07.png")
# Frames differ: the teapot turns.
run(1 text compare "${WORK}/spin_0000.png" "${WORK}/spin_0002.png" --fail-psnr inf)

# --set changes the picture; an undeclared name is an error in the scene's terms.
run(0 text render "${scenes}/lighting.scene" -o "${WORK}/spot20.png" --size 192x64)
run(0 text render "${scenes}/lighting.scene" -o "${WORK}/spot8.png" --size 192x64 --set spot_angle=8)
run(1 text compare "${WORK}/spot20.png" "${WORK}/spot8.png" --fail-psnr inf)
run(1 text render "${scenes}/lighting.scene" -o "${WORK}/x.png" --set spot_angel=8)
expect_text("declares no parameter 'spot_angel'" "${text}" "--set of an unknown name")
run(1 text render "${scenes}/lighting.scene" -o "${WORK}/x.png" --set spot_angle=8,9)
expect_no_file("${WORK}/x.png")
# A bad value is one error at the declaration, not one more at every use of the parameter.
run(1 text render "${scenes}/animation.scene" -o "${WORK}/x.png" --set height=abc)
expect_text("animation.scene:7:7: error: --set height=abc: the value must be numbers" "${text}" "--set of a bad value")
expect_text("\n1 error" "${text}" "--set of a bad value, reported once")
expect_no_file("${WORK}/x.png")

# The teaching views.
run(0 text render "${scenes}/room.scene" -o "${WORK}/depth.png" --view depth --size 160x120)
expect_text("depth: drawn between" "${text}" "--view depth")
run(0 text render "${scenes}/showcase.scene" -o "${WORK}/overdraw.png" --view overdraw --size 160x120)
expect_text("overdraw: up to" "${text}" "--view overdraw")
run(0 text render "${scenes}/bezier.scene" -o "${WORK}/wire.png" --view wireframe --size 240x120)
run(0 text render "${scenes}/bezier.scene" -o "${WORK}/filled.png" --size 240x120)
run(1 text compare "${WORK}/wire.png" "${WORK}/filled.png" --fail-psnr inf)

# --trace-vertex: vertex 33 of the matrix stack scene is the red triangle's corner (0, 2, 0),
# which Listing 6's R(45) T(2,0) T(0,-2) takes to (sqrt 2, sqrt 2); the 600 x 600 picture shows
# [-4, 4] x [-4, 4].
run(0 text render "${scenes}/matrix_stack.scene" -o "${WORK}/q1.png" --trace-vertex 33)
expect_text("vertex 33, sent by 'vertex'" "${text}" "--trace-vertex")
expect_text("object  (   0.000000,    2.000000,    0.000000,    1.000000)" "${text}" "--trace-vertex object")
expect_text("eye     (   1.414214,    1.414214,    0.000000,    1.000000)" "${text}" "--trace-vertex eye")
# Single-precision matrices: the window coordinates agree to about 6 digits.
expect_text("window  ( 406.0660" "${text}" "--trace-vertex window")
expect_text(",  406.0660" "${text}" "--trace-vertex window y")
expect_text("colour  (   0.850000,    0.150000,    0.150000,    1.000000)" "${text}" "--trace-vertex colour")
run(0 text render "${scenes}/matrix_stack.scene" -o "${WORK}/q1.png" --trace-vertex 100000)
expect_text("was not reached" "${text}" "--trace-vertex past the end")
