# Sourced by the window tests (tests/cli/gpu/window_*.sh) with $raylab set; it lives outside cpu/ and gpu/
# so that it is not a test itself. Skips (exit 0) where no window can open (no xvfb-run, or a raylab built
# without the window), then makes and enters a temporary folder removed on exit, and turns the validation
# layer on for everything the test runs.
command -v xvfb-run >/dev/null || { echo "skip: xvfb-run is not installed (apt-get install xvfb)"; exit 0; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
printf 'quit\n' >quit.txt
if env -u DISPLAY -u WAYLAND_DISPLAY "$raylab" --script quit.txt 2>&1 | grep -q "has no window"; then
  echo "skip: this raylab was built without the window (RAYLAB_HEADLESS_ONLY)"
  exit 0
fi
export RAYLAB_VALIDATE=1
