# Sourced by the window tests (tests/cli/gpu/window_*.sh) with $raylab set; it lives outside cpu/ and gpu/
# so that it is not a test itself. Skips (exit 0) where no window can open (no Xvfb, or a raylab built
# without the window), then makes and enters a temporary folder removed on exit, and turns the validation
# layer on for everything the test runs. `bash "$on_xvfb" WxHxD COMMAND...` runs COMMAND on a private X server.
command -v Xvfb >/dev/null || { echo "skip: Xvfb is not installed (apt-get install xvfb)"; exit 0; }
on_xvfb="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/on_xvfb.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
printf 'quit\n' >quit.txt
if env -u DISPLAY -u WAYLAND_DISPLAY "$raylab" --script quit.txt 2>&1 | grep -q "has no window"; then
  echo "skip: this raylab was built without the window (RAYLAB_HEADLESS_ONLY)"
  exit 0
fi
export RAYLAB_VALIDATE=1
