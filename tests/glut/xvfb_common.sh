# What the real-window tests (xvfb_window.sh, xvfb_view_key.sh) share; sourced after they set
# `bin` and `work`: a fresh WORK_DIR to work in, fail, await and screenshots of the window.
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

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
