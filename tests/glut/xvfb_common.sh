# What the real-window tests (xvfb_window.sh, xvfb_view_key.sh) share; sourced after they set
# `bin` and `work`: a fresh WORK_DIR to work in, fail, await, Listing 5 started in a window and
# screenshots of the window.
. "$(dirname "$0")/../shell_test_support.sh"

# The window's content now, as a PNG.
screenshot() {
  xwd -id "$window" -silent >shot.xwd
  convert xwd:shot.xwd "png:$1"
}

# Polls (up to 20 s) until COMMAND succeeds.
await() {
  tries=0
  until "$@" >/dev/null 2>&1; do
    tries=$((tries + 1))
    [ "$tries" -lt 200 ] || fail "timed out waiting for: $*"
    sleep 0.1
  done
}

# Starts Listing 5 in a real window (in the background: its process in `pid`, its X window in
# `window`), four presses of the space bar taking it to step 4, which it writes to snapshot.png;
# it then waits two minutes for the test's key presses.
start_listing5_at_step4() {
  printf 'key space\nkey space\nkey space\nkey space\nsnapshot snapshot.png\nwait 120000\n' >events.txt
  unset SDL_VIDEODRIVER
  GLASS_GLUT_EVENTS=events.txt "$bin/glut_listing5" >out.txt 2>err.txt &
  pid=$!
  await test -s snapshot.png
  window=$(xdotool search --sync --name "Sierpinski triangle" | head -n 1)
  [ -n "$window" ] || fail "no window named Sierpinski triangle"
}
