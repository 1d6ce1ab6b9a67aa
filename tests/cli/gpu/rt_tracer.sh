#!/usr/bin/env bash
# `--tracer rt`: on a device without VK_KHR_acceleration_structure / VK_KHR_ray_tracing_pipeline (Debian 12's
# lavapipe) render exits 2 naming what is missing; on one with them it renders, and its stats say that the
# figures of our traversal loop are not available. `raylab devices` says which case this device is.
set -u
raylab="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
devices=$("$raylab" devices) || { echo "raylab devices failed"; exit 1; }
echo "$devices"
first_rt=$(echo "$devices" | grep -m1 '^  rt tracer:')
RAYLAB_VALIDATE=1 "$raylab" render --scene temple --view openings --size 37x23 --frames 2 --tracer rt \
  --out "$dir/a.png" --stats "$dir/a.json" 2>"$dir/err"
rc=$?
cat "$dir/err"
if echo "$first_rt" | grep -q 'no (lacks'; then
  [ "$rc" -eq 2 ] || { echo "expected exit 2 without ray tracing, got $rc"; exit 1; }
  grep -q 'VK_KHR_ray_tracing_pipeline' "$dir/err" && grep -q 'VK_KHR_acceleration_structure' "$dir/err" \
    || { echo "the message must name the missing extensions"; exit 1; }
  grep -q 'lacks' "$dir/err" || { echo "the message must say what the device lacks"; exit 1; }
  echo "ok: exit 2 without ray tracing"
  exit 0
fi
[ "$rc" -eq 0 ] || { echo "render --tracer rt failed with $rc on a device with ray tracing"; exit 1; }
python3 - "$dir/a.json" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
assert stats['settings']['tracer'] == 'rt', stats['settings']
assert stats['rays_traced'] > 37 * 23, stats['rays_traced']
for b in stats['frames'][0]['bounces']:
    assert b['virtual_warp_efficiency'] == 'not available with the rt tracer', b
    assert b['mean_traversal_steps'] == 'not available with the rt tracer', b
print('ok: rt render', stats['rays_per_second'])
PY
