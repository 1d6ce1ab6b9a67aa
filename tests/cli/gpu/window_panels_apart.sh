#!/usr/bin/env bash
# The panels fit (issue 18): at 1280x720 and 800x500, with a heatmap on so that its legend shows, window
# screenshots' sidecars list every panel's rectangle as drawn ("panels", ui/panel_layout.h); none may
# overlap another or leave the window, and the legend keeps one box whatever the view shows.
set -eu
raylab="$1"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
# The smallest render scale: this test is about the panels, not the image.
xvfb() { timeout 600 bash "$on_xvfb" 1280x720x24 "$raylab" --scale 0.05 --screenshot-dir shots "$@"; }

for size in 1280x720 800x500; do
  printf '%s\n' "set strategy gaussian" "set heatmap traversal-steps" "wait 2" "screenshot-window steps-$size" \
    "set heatmap sort-key" "wait 2" "screenshot-window keys-$size" "set heatmap cache-mean" "wait 2" \
    "screenshot-window cache-$size" quit >"script-$size.txt"
  xvfb --window-size "$size" --script "script-$size.txt" >"run-$size.log" 2>&1 ||
    { echo "FAIL: the $size run exited $?"; tail -20 "run-$size.log"; exit 1; }
  grep -q "validation error" "run-$size.log" && { echo "FAIL: validation errors at $size"; exit 1; }
done

python3 - <<'PY'
import itertools, json
titles = {'Method', 'Timing', 'Speed vs accuracy', 'Scene and camera', 'Heatmap legend'}
def apart(a, b):
    return (a['x'] + a['width'] <= b['x'] or b['x'] + b['width'] <= a['x'] or
            a['y'] + a['height'] <= b['y'] or b['y'] + b['height'] <= a['y'])
for size in ('1280x720', '800x500'):
    w, h = map(int, size.split('x'))
    legends = []
    for view in ('steps', 'keys', 'cache'):
        name = '%s-%s' % (view, size)
        j = json.load(open('shots/%s.json' % name))
        assert (j['image_width'], j['image_height']) == (w, h), (name, j['image_width'], j['image_height'])
        rects = j['panels']['rects']
        assert {r['title'] for r in rects} == titles, (name, sorted(r['title'] for r in rects))
        for r in rects:
            assert r['x'] >= 0 and r['y'] >= 0 and r['x'] + r['width'] <= w and r['y'] + r['height'] <= h, (name, r)
        for a, b in itertools.combinations(rects, 2):
            assert apart(a, b), '%s: %s overlaps %s' % (name, a, b)
        legends.append([r for r in rects if r['title'] == 'Heatmap legend'][0])
    where = [{k: l[k] for k in ('x', 'y', 'width', 'height')} for l in legends]
    assert all(p == where[0] for p in where), '%s: the legend moved between views: %s' % (size, where)
    # At the default size every legend's text fits; smaller windows scroll it (a tenth of 800x500 is too small).
    if size == '1280x720':
        assert all(l['hidden_height'] == 0 for l in legends), '%s: a legend cuts its text off: %s' % (size, legends)
print('ok: 4 panels and the heatmap legend apart and inside at 1280x720 and 800x500; the legend stays put')
PY
