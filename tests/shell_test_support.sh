# What the shell test scripts share, sourced once they have set `work`:
#   . "$(dirname "$0")/../shell_test_support.sh"
# a fresh WORK_DIR, made the current directory, and `fail MESSAGE`, which ends the test.
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}
