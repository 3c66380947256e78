#!/bin/sh
# GLUT programs run headless (SDL_VIDEODRIVER=dummy, set by ctest) with GLASS_GLUT_SNAPSHOT and
# GLASS_GLUT_EVENTS, their snapshots checked with png_probe (pixel coordinates from the top left).
#   glut_tests.sh CASE BIN_DIR WORK_DIR SOURCE_DIR
set -eu

case_name=$1
bin=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"

probe() { "$bin/glut_png_probe" "$@"; }

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# run PROGRAM EVENTS-TEXT [ARGS...]: the program with the events (may be empty) and
# GLASS_GLUT_SNAPSHOT=snapshot.png; its stdout in out.txt, stderr in err.txt; the status in $status.
run() {
  program=$1
  printf '%s' "$2" >events.txt
  shift 2
  status=0
  GLASS_GLUT_SNAPSHOT=snapshot.png GLASS_GLUT_EVENTS=events.txt "$bin/$program" "$@" \
    >out.txt 2>err.txt || status=$?
  cat err.txt >&2
}

expect_text() {  # FILE TEXT
  grep -F -- "$2" "$1" >/dev/null || { echo "--- $1:" >&2; cat "$1" >&2; fail "$1 lacks: $2"; }
}

case $case_name in
listing5)
  # The guide's Listing 5 as printed: four presses of the space bar draw step 4, which must be
  # the picture glass draws off-screen for the same calls.
  run glut_listing5 "key space
key space
key space
key space
"
  [ "$status" -eq 0 ] || fail "listing5 exited with $status"
  expect_text out.txt "Press space bar -> the next step; esc -> to quit."
  "$bin/glut_listing5_offscreen" 4 offscreen.png
  probe snapshot.png size 500 500 same offscreen.png count 255 255 255 20000 200000
  # Escape ends it the way the listing says: exit(1).
  run glut_listing5 "key escape
"
  [ "$status" -eq 1 ] || fail "escape: listing5 exited with $status, expected 1"
  ;;
single_buffer_flush)
  # GLUT_SINGLE (the default) and glFlush: the first frame is the white square at the bottom left.
  run glut_keys_and_reshape ""
  [ "$status" -eq 0 ] || fail "exited with $status"
  probe snapshot.png size 200 200 pixel 5 195 255 255 255 pixel 30 195 0 0 0 \
    count 255 255 255 400 400
  ;;
timer_animation)
  # Double-buffered, glutTimerFunc re-armed from inside: the 5th frame shows a bar 100 pixels
  # long; the red that the display callback flushes before drawing is never shown.
  GLASS_GLUT_FRAMES=5 run glut_timer_animation ""
  [ "$status" -eq 0 ] || fail "exited with $status"
  probe snapshot.png size 200 100 pixel 95 50 255 255 0 pixel 105 50 0 0 128 \
    count 255 255 0 2000 2000 count 255 0 0 0 0
  GLASS_GLUT_FRAMES=9 run glut_timer_animation ""
  probe snapshot.png count 255 255 0 3600 3600
  ;;
menu)
  # The right button's menu chosen by entry number: its callback changes the picture.
  run glut_menu_colors "snapshot before.png
menu 1
snapshot red.png
menu 3 2
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  probe before.png size 320 240 pixel 5 5 0 0 0 pixel 90 70 255 255 255
  probe red.png pixel 5 5 255 0 0 pixel 90 70 255 255 255 pixel 160 120 255 255 255
  probe snapshot.png pixel 5 5 255 0 0 pixel 90 70 255 0 0 pixel 160 120 255 255 255
  ;;
menu_by_pointer)
  # The pop-up drawn over the picture and picked with the pointer: it opens on the right
  # button, a submenu opens beside its entry, a press outside closes it without a callback, and
  # the picture under it is unchanged.
  run glut_menu_colors "snapshot before.png
mouse right down 20 20
snapshot open.png
mouse left down 300 230
mouse left up 300 230
snapshot closed.png
mouse right down 20 20
motion 40 85
snapshot submenu.png
motion 200 106
mouse right up 200 106
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  probe open.png differ before.png count 178 178 178 2000 40000
  probe closed.png same before.png
  probe submenu.png differ open.png
  # Triangle chosen: the top corners of the square are black again.
  probe snapshot.png pixel 90 70 0 0 0 pixel 160 120 255 255 255
  ;;
keyboard)
  # Special keys move the square; characters colour it; Ctrl+G arrives as character 7 with
  # GLUT_ACTIVE_CTRL.
  run glut_keys_and_reshape "special right
special right
special up
key r
snapshot red.png
key ctrl+g
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  probe red.png pixel 45 165 255 0 0 pixel 5 195 0 0 0 count 255 0 0 400 400
  probe snapshot.png pixel 45 165 0 0 255 count 0 0 255 400 400
  ;;
reshape)
  # The reshape callback runs with the first size and again with the new one; the picture
  # has the new size.
  run glut_keys_and_reshape "reshape 300 120
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  expect_text out.txt "reshape 200 200"
  expect_text out.txt "reshape 300 120"
  probe snapshot.png size 300 120 pixel 5 115 255 255 255 pixel 25 115 0 0 0
  ;;
two_windows)
  # Two windows with their own contexts; closing the second under
  # GLUT_ACTION_CONTINUE_EXECUTION runs its close callback and leaves the first.
  run glut_two_windows "window 1
snapshot first.png
window 2
snapshot second.png
close
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  probe first.png size 160 120 pixel 2 2 0 153 0 pixel 80 100 255 255 255
  probe second.png size 100 80 pixel 2 2 0 0 153 pixel 30 50 255 0 0 pixel 50 40 255 255 0
  expect_text out.txt "window 2 closed; current window 2"
  probe snapshot.png same first.png
  ;;
subwindows)
  # Sub-windows: each draws with its own context into its rectangle of the main window (the
  # blue one holding a red one of its own); the pointer's events go to the window under it, in
  # that window's coordinates, a drag to the window it began in; keys to the window under the
  # pointer; crossing from one window into another calls both entry callbacks.
  run glut_subwindows "motion 50 150
mouse left down 50 150
motion 200 150
mouse left up 200 150
motion 200 150
mouse left down 180 120
mouse left up 180 120
key x
motion 5 5
key y
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  printf '%s\n' "corner 5 at 270 170, a sub-window of no window: 0
windows 1 2 3 4; parent of 4 is 3, 1 has 3 children
reshape main 300 200
entry window 1 left
entry window 2 entered
mouse window 2 button 0 down at 40 140
motion window 2 at 190 140
mouse window 2 button 0 up at 190 140
entry window 2 left
entry window 3 entered
entry window 3 left
entry window 4 entered
mouse window 4 button 0 down at 10 10
mouse window 4 button 0 up at 10 10
key x window 4 at 10 10
entry window 4 left
entry window 1 entered
key y window 1 at 5 5" >expected.txt
  diff expected.txt out.txt >&2 || fail "the callbacks' calls differ from expected.txt"
  # Grey main window, green sub-window with its white triangle low in it, blue one with red.
  probe snapshot.png size 300 200 pixel 5 5 128 128 128 pixel 20 20 0 153 0 pixel 75 175 255 255 255 \
    pixel 75 105 0 153 0 pixel 160 20 0 0 153 pixel 180 120 204 0 0 pixel 295 195 128 128 128 \
    pixel 271 171 255 255 0 pixel 289 189 255 255 0 pixel 269 171 0 0 153 count 255 255 0 400 400
  # Moved, hidden, the green one destroyed; then the main window reshaped, whose callback lays
  # the sub-windows out again in the same pass.
  run glut_subwindows "motion 180 120
key p
snapshot moved.png
key h
snapshot hidden.png
key d
snapshot destroyed.png
reshape 400 300
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  probe moved.png pixel 180 120 0 0 153 pixel 220 40 204 0 0 count 204 0 0 2000 2000
  probe hidden.png pixel 220 40 0 0 153 count 204 0 0 0 0 pixel 20 20 0 153 0
  probe destroyed.png pixel 20 20 128 128 128 count 0 153 0 0 0
  probe snapshot.png size 400 300 pixel 195 20 128 128 128 pixel 205 20 0 0 153 \
    pixel 385 285 0 0 153 pixel 395 295 128 128 128
  ;;
display_string)
  # glutInitDisplayString: the words give glutInitDisplayMode's bits (GLUT_DOUBLE 2, GLUT_DEPTH
  # 16, GLUT_STENCIL 32, GLUT_ACCUM 4, GLUT_ALPHA 8); numbers do not change glass's one
  # configuration; "samples" alone (at most 4 by the specification) is met without multisampling.
  run glut_display_string "" "rgb double depth>=16 stencil~2 acc samples"
  [ "$status" -eq 0 ] || fail "exited with $status"
  expect_text out.txt "mode 54"
  expect_text out.txt "double-buffered 1"
  run glut_display_string "" "	rgba  alpha single "
  [ "$status" -eq 0 ] || fail "exited with $status"
  expect_text out.txt "mode 8"
  expect_text out.txt "double-buffered 0"
  # A word GLUT does not know gets freeglut's warning; the others still count.
  run glut_display_string "" "double bogus=3"
  [ "$status" -eq 0 ] || fail "exited with $status"
  expect_text err.txt "Display string token not recognized:  bogus=3"
  expect_text out.txt "mode 2"
  # A multisample window is a wish (GLUT 3.7, glutInitDisplayMode): without multisampling,
  # glass makes a window without it, as freeglut does where there is none.
  run glut_display_string "" "rgb samples>=2"
  [ "$status" -eq 0 ] || fail "'rgb samples>=2' exited with $status"
  expect_text out.txt "mode 128"
  # What glass cannot have fails at glutCreateWindow, as the same bits of glutInitDisplayMode do.
  for words in "index" "stereo"; do
    run glut_display_string "" "$words"
    [ "$status" -eq 1 ] || fail "'$words' exited with $status"
    expect_text err.txt "FBConfig with necessary capabilities not found"
  done
  ;;
display_mode_buffers)
  # The buffers of a window follow its display mode as Mesa's visuals under X do (freeglut 3.4
  # with Mesa 22 on Xvfb printed the same, but for 32 depth bits where only GLUT_DEPTH is asked,
  # a 4-sample window for GLUT_MULTISAMPLE and blended alpha 111 for GLUT_ALPHA alone):
  # depth with GLUT_DEPTH or GLUT_STENCIL, stencil with GLUT_STENCIL, accumulation with
  # GLUT_ACCUM, alpha bitplanes with GLUT_ALPHA; without a depth buffer the depth test does
  # nothing (the later, far square shows); without alpha bitplanes alpha reads 1 after a clear
  # with alpha 0.25, and blending by (1 - destination alpha, destination alpha) keeps the grey.
  # GLUT_MULTISAMPLE gets a window without multisampling.
  check_mode() {  # MODE TEXT...: each TEXT in the output
    mode=$1
    shift
    run glut_display_mode_buffers "" "$mode"
    [ "$status" -eq 0 ] || fail "mode $mode exited with $status"
    for text in "$@"; do expect_text out.txt "$text"; done
  }
  no_alpha() { check_mode "$@" "GL alpha 0 GLUT alpha 0 buffer 24" "cleared 128 128 128 255" "blended 128 128 128 255"; }
  alpha() { check_mode "$@" "GL alpha 8 GLUT alpha 8 buffer 32" "cleared 128 128 128 64" "blended 223 223 223 "; }
  no_alpha 0 "GL depth 0 stencil 0 accum 0 sample buffers 0" "GLUT depth 0 stencil 0 accum 0" "pixel 0 255 0"
  no_alpha 2 "GL depth 0 stencil 0 accum 0" "GLUT depth 0 stencil 0 accum 0" "pixel 0 255 0"
  no_alpha 18 "GL depth 24 stencil 0 accum 0" "GLUT depth 24 stencil 0 accum 0" "pixel 255 0 0"
  no_alpha 34 "GL depth 24 stencil 8 accum 0" "GLUT depth 24 stencil 8 accum 0" "pixel 255 0 0"
  no_alpha 4 "GL depth 0 stencil 0 accum 16" "GLUT depth 0 stencil 0 accum 16" "pixel 0 255 0"
  no_alpha 54 "GL depth 24 stencil 8 accum 16" "GLUT depth 24 stencil 8 accum 16" "pixel 255 0 0"
  no_alpha 146 "GL depth 24 stencil 0 accum 0 sample buffers 0" "samples 0" "pixel 255 0 0"
  alpha 8 "GL depth 0 stencil 0 accum 0" "pixel 0 255 0"
  alpha 26 "GL depth 24 stencil 0 accum 0" "pixel 255 0 0" "blended 223 223 223 112"
  alpha 62 "GL depth 24 stencil 8 accum 16" "pixel 255 0 0" "blended 223 223 223 112"
  ;;
front_buffer)
  # A double-buffered window's two colour buffers (programs/front_buffer.c): drawing starts on
  # the back buffer, the swap copies it to the front, an XOR square drawn into the front buffer
  # and flushed is shown at once and leaves the back buffer alone, GL_FRONT_AND_BACK blends into
  # each buffer's own pixels, glPopAttrib restores the draw buffer, and a swap shows the back
  # buffer again. freeglut 3.4 with Mesa 22 on Xvfb printed the same but for the front buffer's
  # pixels: its front buffer starts black and a swap does not change it (its screen shows that
  # buffer after the XOR square), where GLX's swap makes the back buffer's contents the front's.
  run glut_front_buffer "key r
key f
snapshot xor.png
key r
key b
key r
key p
key s
key r
"
  [ "$status" -eq 0 ] || fail "exited with $status"
  printf '%s\n' "created: double buffer 1, draw GL_BACK, read GL_BACK
frame
front: (0 0 102) (255 0 0) (0 0 102)
back: (0 0 102) (255 0 0) (0 0 102)
front: (0 255 102) (255 0 0) (0 0 102)
back: (0 0 102) (255 0 0) (0 0 102)
both: double buffer 1, draw GL_FRONT_AND_BACK, read GL_BACK
front: (0 255 102) (255 0 0) (128 128 179)
back: (0 0 102) (255 0 0) (128 128 179)
pushed: double buffer 1, draw GL_FRONT, read GL_BACK
popped: double buffer 1, draw GL_BACK, read GL_BACK
swapped
front: (0 0 102) (255 0 0) (128 128 179)
back: (0 0 102) (255 0 0) (128 128 179)" >expected.txt
  diff expected.txt out.txt >&2 || fail "the answers differ from expected.txt"
  # The XOR square over the red and the blue halves, shown after the flush; at the end the back
  # buffer swapped in, with the blended square at the bottom right.
  probe xor.png size 100 100 pixel 50 50 0 255 102 pixel 40 50 255 255 0 pixel 25 50 255 0 0 \
    pixel 80 5 0 0 102
  probe snapshot.png pixel 50 50 0 0 102 pixel 80 80 128 128 179
  ;;
game_mode)
  # Game mode: the asked size, depth and rate; the window at the screen's corner with a context
  # of that size; entering again replaces the window; leaving destroys it (and with no window
  # left the headless run has nothing to take a snapshot of).
  run glut_game_mode "snapshot first.png
key e
" "320x240:16@75"
  [ "$status" -eq 0 ] || fail "exited with $status"
  printf '%s\n' "before: active 0 possible 1 320 x 240 depth 16 refresh 75 changed 0
window 1, 320 x 240 at 0 0
entered: active 1 possible 1 320 x 240 depth 16 refresh 75 changed 1
window 2, 320 x 240 at 0 0
entered: active 1 possible 1 320 x 240 depth 16 refresh 75 changed 1" >expected.txt
  diff expected.txt out.txt >&2 || fail "game mode queries differ from expected.txt"
  probe first.png size 320 240 pixel 5 5 0 0 153 pixel 160 120 255 0 0 count 255 0 0 19200 19200
  probe snapshot.png same first.png
  run glut_game_mode "key l
" ":32"
  expect_text out.txt "left: active 0 possible 1"
  expect_text out.txt "depth 32"
  expect_text err.txt "there is no window to take the snapshot of"
  ;;
absent_features)
  # Joysticks, spaceballs, tablets, overlays, colour maps, video resizing, multi-pointer input:
  # the calls are there, the callbacks kept and never called, the queries say "none".
  run glut_absent_features ""
  [ "$status" -eq 0 ] || fail "exited with $status"
  printf '%s\n' "asked 1.4 flags 0 profile 0
overlay possible 0, colour -1, video resize 0, multisample values none 0
proc glutSwapBuffers found, glActiveTexture found, gluPerspective missing, glutNoSuch missing
options: rendering context 0, direct 2, skip stale motion 0 -> 1, 0, 1
device callbacks called 0 times" >expected.txt
  diff expected.txt out.txt >&2 || fail "the answers differ from expected.txt"
  expect_text err.txt "glutSetMenuFont: bitmap font"
  # A context glass cannot make: freeglut's message, at glutCreateWindow.
  run glut_absent_features "" core
  [ "$status" -eq 1 ] || fail "core: exited with $status"
  expect_text out.txt "asked 3.3 flags 0 profile 1"
  expect_text err.txt "Unable to create OpenGL 3.3 context (flags 0, profile 1): glass provides OpenGL 1.4"
  ;;
errors)
  # freeglut's messages and exit status.
  run glut_glut_errors "" before-init
  [ "$status" -eq 1 ] || fail "before-init exited with $status"
  expect_text err.txt "freeglut  ERROR:  Function <glutCreateWindow> called without first calling 'glutInit'."
  run glut_glut_errors "" no-window
  [ "$status" -eq 1 ] || fail "no-window exited with $status"
  expect_text err.txt "freeglut (glut_glut_errors):  ERROR:  Function <glutPostRedisplay> called with no current window defined."
  run glut_glut_errors "" no-display-callback
  [ "$status" -eq 1 ] || fail "no-display-callback exited with $status"
  expect_text err.txt "ERROR:  No display callback registered for window 1"
  run glut_glut_errors "mouse right sideways 1 2
"
  [ "$status" -eq 1 ] || fail "bad events file: exited with $status"
  expect_text err.txt "events.txt:1:13: expected down or up, not 'sideways'"
  [ ! -e snapshot.png ] || fail "a snapshot was written despite the bad events file"
  # No display and no GLASS_GLUT_SNAPSHOT: freeglut's message, and the variable named.
  status=0
  env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER -u GLASS_GLUT_SNAPSHOT -u GLASS_GLUT_EVENTS \
    "$bin/glut_glut_errors" >out.txt 2>err.txt || status=$?
  [ "$status" -eq 1 ] || fail "no display: exited with $status"
  expect_text err.txt "freeglut (glut_glut_errors): failed to open display ''"
  expect_text err.txt "GLASS_GLUT_SNAPSHOT"
  ;;
teaching_views)
  # GLASS_VIEW on the unchanged Listing 5 (step 4), headless: the Sierpinski triangles share
  # edges but, by the fill rule, no pixel, so the overdraw view has only counts 0 and 1 and as
  # many pixels of count 1 (dark blue) as the program's picture has white ones.
  "$bin/glut_listing5_offscreen" 4 offscreen.png
  probe offscreen.png count 255 255 255 20000 200000
  for view in overdraw depth wireframe normals mipmap; do
    GLASS_VIEW=$view run glut_listing5 "key space
key space
key space
key space
"
    [ "$status" -eq 0 ] || fail "listing5 with GLASS_VIEW=$view exited with $status"
    mv snapshot.png "$view.png"
    probe "$view.png" size 500 500 differ offscreen.png
  done
  probe overdraw.png count 0 120 210 0 0 count 0 180 120 0 0 count 30 40 140 20000 200000
  GLASS_VIEW=overdraw "$bin/glut_listing5_offscreen" 4 overdraw_offscreen.png
  probe overdraw.png same overdraw_offscreen.png
  # The triangles lie in the plane z = 0: one depth, drawn black; the rest is white.
  probe depth.png count 0 0 0 20000 200000 count 255 255 255 20000 250000
  # The wireframe: edges only, far fewer pixels than the filled triangles.
  probe wireframe.png count 255 255 255 2000 20000
  # Listing 5 gives no normal: every triangle has the current normal (0, 0, 1), facing the eye,
  # shown as (128, 128, 255); it has no texture: its fragments are the mipmap view's grey.
  probe normals.png count 128 128 255 20000 200000 count 0 0 0 20000 250000
  probe mipmap.png count 96 96 96 20000 200000 count 0 0 0 20000 250000
  # GLASS_STATS: each glFlush of the single-buffered window ends a frame; step 4 (the last) draws
  # 3^4 = 81 triangles of 3 vertices, in the plane z = 0 that the depth test never rejects.
  GLASS_STATS=1 run glut_listing5 "key space
key space
key space
key space
"
  [ "$status" -eq 0 ] || fail "listing5 with GLASS_STATS exited with $status"
  expect_text err.txt "glass stats, frame 4:"
  expect_text err.txt "  vertices                        243"
  expect_text err.txt "  primitives                       81   (0 points, 0 lines, 81 triangles)"
  expect_text err.txt "  depth test failed                 0"
  # GLASS_TRACE_VERTEX: vertex 0 of frame 0 is the first corner (1, 0, 0) of step 0's triangle.
  GLASS_TRACE_VERTEX=0 run glut_listing5 ""
  [ "$status" -eq 0 ] || fail "listing5 with GLASS_TRACE_VERTEX exited with $status"
  expect_text err.txt "glass trace: vertex 0 of frame 0"
  expect_text err.txt "  object  (   1.000000,    0.000000,    0.000000,    1.000000)   as given"
  # Unset again, the program's own picture.
  run glut_listing5 "key space
key space
key space
key space
"
  probe snapshot.png same offscreen.png
  ;;
teaching_view_key)
  # Ctrl+Alt+V steps through glass's views in any GLUT window (off, depth, overdraw, wireframe,
  # normals, mipmap, off; with Shift backwards): each picture is the one GLASS_VIEW gives
  # off-screen, byte for byte, and off again is the program's own.
  run glut_listing5 "key space
key space
key space
key space
key ctrl+alt+v
snapshot depth.png
key ctrl+alt+v
snapshot overdraw.png
key ctrl+alt+v
snapshot wireframe.png
key ctrl+alt+v
snapshot normals.png
key ctrl+alt+v
snapshot mipmap.png
key ctrl+alt+v
snapshot off.png
key ctrl+alt+shift+v
snapshot back.png
"
  [ "$status" -eq 0 ] || fail "listing5 exited with $status"
  "$bin/glut_listing5_offscreen" 4 offscreen.png
  probe off.png same offscreen.png
  for view in depth overdraw wireframe normals mipmap; do
    GLASS_VIEW=$view "$bin/glut_listing5_offscreen" 4 "${view}_offscreen.png" 2>/dev/null
    probe "$view.png" same "${view}_offscreen.png" differ offscreen.png
    expect_text err.txt "glass: Ctrl+Alt+V: view $view"
  done
  probe back.png same mipmap_offscreen.png
  expect_text err.txt "glass: Ctrl+Alt+V: the program's picture"
  # The program's keyboard callbacks see its own keys, never the view key.
  run glut_keys_and_reshape "key r
key ctrl+alt+v
key ctrl+alt+v
key g
"
  [ "$status" -eq 0 ] || fail "keys_and_reshape exited with $status"
  expect_text out.txt "key 114 modifiers 0"
  expect_text out.txt "key up 114"
  expect_text out.txt "key 103 modifiers 0"
  if grep -F -e "key 22" -e "key up 22" out.txt >/dev/null; then fail "the program saw Ctrl+Alt+V"; fi
  # Two presses: the overdraw view, of the 20 x 20 square, one fragment a pixel (dark blue).
  probe snapshot.png size 200 200 count 30 40 140 400 400 count 0 0 0 39600 39600
  ;;
window_position)
  # glutGet(GLUT_WINDOW_X/Y) says where the window is: where -geometry put it, and where the
  # system placed it when the program asked for no place (a number, never the -1 of an unknown
  # query, and no warning).
  run glut_keys_and_reshape "key p
" -geometry +10+20
  [ "$status" -eq 0 ] || fail "keys_and_reshape exited with $status"
  expect_text out.txt "position 10 20"
  run glut_keys_and_reshape "key p
"
  [ "$status" -eq 0 ] || fail "keys_and_reshape exited with $status"
  grep -E '^position [0-9]+ [0-9]+$' out.txt >/dev/null || fail "no placed position in: $(cat out.txt)"
  # A new window's cursor is GLUT_CURSOR_INHERIT (100), as in freeglut.
  expect_text out.txt "cursor 100"
  if grep -F "missing enum" err.txt >/dev/null; then fail "glutGet warned about its own query"; fi
  ;;
callback_order)
  # As freeglut on X: a window that appears away from (0, 0) is told its position before its
  # first reshape (freeglut takes X's first ConfigureNotify for a move from (0, 0)), and closing
  # a pop-up without a choice draws the window again (freeglut's pop-ups are windows of their
  # own; taking one away exposes the program's window). xvfb_differential.sh checks the same
  # against freeglut itself.
  run glut_timer_window "key q
"
  [ "$status" -eq 0 ] || fail "timer_window exited with $status"
  first_two=$(grep -v '^glutGet' out.txt | head -n 2 | tr '\n' ' ')
  [ "$first_two" = "position 10 10 reshape 300 200 " ] ||
    fail "not the position, then the reshape: $(cat out.txt)"
  run glut_spin_menu "mouse right down 30 30
mouse right up 30 30
mouse left down 250 200
mouse left up 250 200
key q
"
  [ "$status" -eq 0 ] || fail "spin_menu exited with $status"
  grep -A 1 "menu status 0 at 250 200" out.txt | tail -n 1 | grep -q "^display angle 0" ||
    fail "no display after the pop-up closed: $(cat out.txt)"
  ;;
key_repeat)
  # glutIgnoreKeyRepeat is the current window's (GLUT 3.7, freeglut), glutSetKeyRepeat all
  # windows', on by default, as freeglut answers glutDeviceGet. (The repeats themselves, as a
  # release and a press each, need a held key: xvfb_differential.sh, case key_repeat.)
  run glut_key_repeat "window 1
key g
key i
key r
key R
key q
"
  [ "$status" -eq 0 ] || fail "key_repeat exited with $status"
  expect_text out.txt "ignore key repeat 0, key repeat 1; in the second window: ignore key repeat 0"
  expect_text out.txt "ignore key repeat 1, key repeat 1; in the second window: ignore key repeat 0"
  expect_text out.txt "ignore key repeat 1, key repeat 0; in the second window: ignore key repeat 0"
  [ "$(grep -c "key repeat 1;" out.txt)" -eq 3 ] || fail "not back on: $(cat out.txt)"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok: $case_name"
