#!/usr/bin/env bash
# The interactive window under Xvfb, on the default device (lavapipe) with validation on: a script switches
# through every key strategy and every heatmap view, resizes the window and takes both kinds of screenshot.
# The PNGs exist, have the window's size, are not blank, and the one with the panels differs from the render
# alone; the render's sidecar, loaded back (--settings), reproduces the render exactly.
set -eu
raylab="$1"
repo="$2"
source "$(dirname "$0")/../window_test_setup.sh"  # skips without a window; temporary folder; validation on
# Generous: the scripted run walks every setting combination (about 500 frames) and shares two cores with
# the other tests.
xvfb() { timeout 600 bash "$on_xvfb" 1280x720x24 "$raylab" "$@"; }

# The names come from the program itself: the render help lists the strategies, and a script with a wrong
# heatmap is rejected with the list of views (before any window opens).
strategies=$("$raylab" render --help | sed -n 's/.*--strategy \([a-z|-]*\).*/\1/p' | tr '|' ' ')
printf 'set heatmap ?\n' >probe.txt
probe=$("$raylab" --script probe.txt 2>&1 || true)
heatmaps=$(sed -n 's/.*must be one of \([a-z|-]*\).*/\1/p' <<<"$probe" | tr '|' ' ')
[ -n "$strategies" ] && [ -n "$heatmaps" ] || { echo "FAIL: cannot list strategies/heatmaps"; echo "$probe"; exit 1; }

{
  echo "set bounces 2"
  for s in $strategies; do printf 'set strategy %s\nwait 1\n' "$s"; done
  echo "set strategy gaussian"
  for h in $heatmaps; do printf 'set heatmap %s\nwait 1\nscreenshot heat-%s\n' "$h" "$h"; done
  echo "set heatmap none"
  # The reported crash: a cache view showing, then a strategy without a cache. The window shows the render
  # and says why instead.
  printf 'set strategy gaussian\nset heatmap cache-mean\nwait 1\nset strategy fixed\nwait 1\n'
  printf 'screenshot-window unavailable\nset heatmap none\n'
  # Every kernel x sort x strategy x heatmap, one frame each: unavailable views must not crash either.
  for k in wavefront megakernel; do
    echo "set kernel $k"
    for so in none bitonic radix; do
      echo "set sort $so"
      for s in $strategies; do
        echo "set strategy $s"
        for h in $heatmaps; do printf 'set heatmap %s\nwait 1\n' "$h"; done
      done
    done
  done
  printf 'set kernel wavefront\nset sort radix\nset strategy gaussian\nset heatmap none\n'
  printf 'set size 200x120\nwait 2\nscreenshot-window resized\nset size 160x90\nwait 1\n'  # resizing
  echo "camera 0.3 1.6 9 0 1.2 0"
  echo "wait 2"
  echo "screenshot render"
  echo "screenshot-window window"
  echo "quit"
} >script.txt
size=(--window-size 160x90 --scale 1 --screenshot-dir shots)
start=$(date +%s)
xvfb "${size[@]}" --script script.txt >run.log 2>&1 || { echo "FAIL: the scripted window exited $?"; tail -20 run.log; exit 1; }
if grep -q "validation error" run.log; then echo "FAIL: validation errors"; grep "validation error" run.log | head; exit 1; fi
echo "scripted run: $(( $(date +%s) - start )) s; $(tail -1 run.log)"

# Second run: start from the render's sidecar and render as many frames as it had accumulated.
frames=$(python3 -c "import json,sys; print(json.load(open('shots/render.json'))['settings']['frames'])")
printf 'wait %d\nscreenshot again\nquit\n' "$((frames - 1))" >again.txt
xvfb "${size[@]}" --settings shots/render.json --script again.txt >again.log 2>&1 || { echo "FAIL: the --settings run exited $?"; tail -20 again.log; exit 1; }

# `raylab render --settings` does the same headless, once the render command takes --settings.
headless=skipped
if "$raylab" render --settings shots/render.json --out headless.png >render.log 2>&1; then headless=headless.png
elif ! grep -q "unknown option '--settings'" render.log; then echo "FAIL: render --settings"; cat render.log; exit 1; fi

# imgui.ini keeps the last settings: a run that changes them, one that comes back to them, one with --reset.
printf 'set strategy ema\nwait 1\nquit\n' >ini1.txt
printf 'wait 1\nscreenshot remembered\nquit\n' >ini2.txt
xvfb "${size[@]}" --ini lab.ini --script ini1.txt >ini.log 2>&1 || { echo "FAIL: ini run 1"; tail ini.log; exit 1; }
grep -q '"strategy":"ema"' lab.ini || { echo "FAIL: imgui.ini does not keep the settings"; cat lab.ini; exit 1; }
xvfb "${size[@]}" --ini lab.ini --script ini2.txt >>ini.log 2>&1 || { echo "FAIL: ini run 2"; tail ini.log; exit 1; }
mv shots/remembered.json remembered.json
xvfb "${size[@]}" --ini lab.ini --reset --script ini2.txt >>ini.log 2>&1 || { echo "FAIL: ini run 3"; tail ini.log; exit 1; }
python3 -c "
import json
assert json.load(open('remembered.json'))['settings']['strategy'] == 'ema', 'imgui.ini settings not restored'
assert json.load(open('shots/remembered.json'))['settings']['strategy'] == 'none', '--reset did not start clean'"

# Timing as headless: the window's stages cover its GPU frame time (before the timestamp fix each stage read
# ~0.05 ms of a 400 ms frame) and its rays/s match a headless render of the same settings (they were off by
# a factor of 260). What time stays outside the stages is shown as its own bar; judged as below.
# On a loaded CPU the gaps between stages (the driver's thread waiting for a core) can pass 5% for a while:
# up to three tries, each with the window and then headless, and one must meet it. The original fault read 4%.
# (5% failed all three tries once, at the end of a ctest -j2 run on an idle 2-core machine: the window's frame
# 91-95% covered, headless 99.5%; run alone the window's reads 99.6%.)
# The whole frame in one submission (--render-budget-ms 1000, as on a fast device): a window that renders a
# frame's steps over several UI frames keeps drawing its panels between them, and on two loaded cores that
# thread's time shows up as gaps inside the submissions' GPU spans (frames in steps are tested in
# tests/gpu/test_render_invariant.cpp, window_frame_log.sh and window_matches_headless.sh). Under AddressSanitizer the host side runs several times slower while the driver's
# threads do not, so there the figures are printed, not judged.
# On a quiet machine the window's stages once covered only 78-86% of its frame (headless 99.5%): lavapipe
# took a deferred timestamp late, on its rasterizer threads, while the next stage already ran. GpuTimer now
# waits for each timestamp on CPU devices (renderer/vk/gpu_timer.cpp), and the window reads 97-98% as
# headless does; the window must cover 80% and headless 90%, and their stage sums agree within 0.67-1.5x.
# The faults this guards against read 0.01% covered and rays/s 260x apart.
printf 'set bounces 4\nwait 3\nscreenshot timing\nquit\n' >timing.txt
sanitized=0
ldd "$raylab" | grep -q libasan && sanitized=1
timing_ok=0
for attempt in 1 2 3; do
  xvfb --window-size 320x180 --scale 1 --render-budget-ms 1000 --screenshot-dir shots --script timing.txt >timing.log 2>&1 ||
    { echo "FAIL: timing run"; tail timing.log; exit 1; }
  "$raylab" render --settings shots/timing.json --stats timing-headless.json --out timing-headless.png >>timing.log 2>&1 ||
    { echo "FAIL: headless timing run"; tail timing.log; exit 1; }
  if python3 - <<'PY'
import json, sys
w = json.load(open('shots/timing.json'))['stats']
h = json.load(open('timing-headless.json'))['frames'][-1]
ok = True
for name, f, least in (('window', w, 0.8), ('headless', h, 0.9)):
    cover = f['stage_sum_ms'] / f['gpu_frame_ms']
    print('%s: GPU frame %.1f ms, stages %.1f ms (%.1f%%), unattributed %.1f ms, %.3g rays/s' %
          (name, f['gpu_frame_ms'], f['stage_sum_ms'], 100 * cover, f['unattributed_ms'], f['rays_per_second']))
    assert abs(f['stage_sum_ms'] + f['unattributed_ms'] - f['gpu_frame_ms']) < 1e-6 * f['gpu_frame_ms'] + 1e-9
    ok = ok and cover >= least
stages = w['stage_sum_ms'] / h['stage_sum_ms']
ratio = w['rays_per_second'] / h['rays_per_second']
print('window/headless: stages %.2fx, rays/s %.2fx' % (stages, ratio))
sys.exit(0 if ok and 0.67 < stages < 1.5 and 0.25 < ratio < 4 else 1)
PY
  then timing_ok=1; break; fi
  [ $sanitized -eq 0 ] || { echo "sanitizer build: timing figures above not judged"; timing_ok=1; break; }
  echo "timing attempt $attempt missed (stages under 80% of the window's frame or 90% of headless's, or stages or rays/s apart)"
done
[ $timing_ok -eq 1 ] || { echo "FAIL: the window's stages do not account for its frame time"; exit 1; }

# A hostile imgui.ini (settings out of range) is checked like the command line: the lab says why and
# starts from the defaults instead of allocating for -5 bounces.
python3 -c "
import json
s = json.load(open('remembered.json'))['settings']
s['bounces'] = -5
open('hostile.ini', 'w').write('[Raylab][State]\\nsettings=' + json.dumps(s) + '\\n')"
xvfb "${size[@]}" --ini hostile.ini --script ini2.txt >hostile.log 2>&1 || { echo "FAIL: hostile ini run"; tail hostile.log; exit 1; }
grep -q "ignoring the saved settings.*--bounces must be between 1 and 32, got -5" hostile.log ||
  { echo "FAIL: the hostile imgui.ini was not refused with the range"; cat hostile.log; exit 1; }
python3 -c "
import json
assert json.load(open('shots/remembered.json'))['settings']['bounces'] == 4, 'hostile ini settings were used'"

# Unasked files go to the config folder ($XDG_CONFIG_HOME/raylab), never the working directory.
mkdir -p cwd cfg
printf 'wait 1\nscreenshot default-place\nquit\n' >place.txt
(cd cwd && XDG_CONFIG_HOME="$dir/cfg" timeout 120 bash "$on_xvfb" 1280x720x24 "$raylab" --window-size 160x90 \
   --script ../place.txt >../place.log 2>&1) || { echo "FAIL: default-place run"; tail place.log; exit 1; }
[ -s cfg/raylab/screenshots/default-place.png ] || { echo "FAIL: screenshot not in the config folder"; ls -R cfg cwd; exit 1; }
grep -qF '$XDG_CONFIG_HOME/raylab/screenshots' "$repo/README.md" ||
  { echo "FAIL: README.md does not say screenshots go to \$XDG_CONFIG_HOME/raylab/screenshots"; exit 1; }
[ -z "$(ls -A cwd)" ] || { echo "FAIL: the window wrote into the working directory: $(ls -A cwd)"; exit 1; }

# A scene file that cannot be loaded exits 3 from a script as from the command line.
printf 'set scene %s/missing.gltf\nquit\n' "$dir" >missing.txt
code=0; xvfb "${size[@]}" --script missing.txt >missing.log 2>&1 || code=$?
[ $code -eq 3 ] && grep -q "missing.txt:1:" missing.log || { echo "FAIL: set scene missing.gltf exited $code"; cat missing.log; exit 1; }

# Without a display the window mode says so and renders headless, pointing to `raylab render`, for a
# time budget (10 s) so that the image shows the scene rather than noise.
out=$(env -u DISPLAY -u WAYLAND_DISPLAY "$raylab" --size 32x18 --out nodisplay.png 2>&1) || { echo "FAIL: no-display fallback"; echo "$out"; exit 1; }
grep -q "no display" <<<"$out" && grep -q "raylab render" <<<"$out" && grep -q "accumulating for 10 s" <<<"$out" &&
  [ -s nodisplay.png ] ||
  { echo "FAIL: no-display message or image missing"; echo "$out"; exit 1; }

python3 - "$strategies" "$heatmaps" "$headless" <<'PY'
import json, struct, sys, zlib

def read_png(path):
    """RGBA8 pixels of a non-interlaced 8-bit PNG (what stb_image_write produces)."""
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path + ': not a PNG'
    pos, idat, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
            assert depth == 8 and ctype in (2, 6), (path, depth, ctype)
            bpp = 4 if ctype == 6 else 3
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, b''.join(rows)

def variance(pixels):
    values = pixels[0::4] + pixels[1::4] + pixels[2::4]
    mean = sum(values) / len(values)
    return sum((v - mean) ** 2 for v in values) / len(values)

strategies, heatmaps, headless = sys.argv[1].split(), sys.argv[2].split(), sys.argv[3]
shots = {name: read_png('shots/%s.png' % name) for name in ['render', 'window', 'again'] + ['heat-' + h for h in heatmaps]}
LEGEND = 53  # a heatmap render carries its legend strip below the image (app/heatmap_legend_image.h, 160 wide)
for name, (w, h, px) in shots.items():
    heat = name.startswith('heat-') and name != 'heat-none'
    assert (w, h) == (160, 90 + (LEGEND if heat else 0)), '%s is %dx%d, not the window size 160x90' % (name, w, h)
    sidecar = json.load(open('shots/%s.json' % name))
    for key in ('settings', 'stats', 'device', 'git_revision', 'camera'):
        assert key in sidecar, '%s.json has no %s' % (name, key)
    assert sidecar['image_height'] == h, '%s.json gives the height %s for a %d-high PNG' % (name, sidecar['image_height'], h)
    if heat:
        legend = sidecar['heatmap']
        assert legend['view'] == name[5:] and len(legend['range']) == 2 and legend['unit'], (name, legend)
        assert legend['scale'] in ('linear', 'log', 'categorical'), (name, legend)
        text = sum(1 for i in range(90 * w * 4, len(px), 4) if px[i:i + 3] == bytes((230, 230, 230)))
        assert text > 50, '%s: no legend text burned in below the heatmap (%d text pixels)' % (name, text)
    else:
        assert sidecar.get('heatmap') is None, '%s.json describes a heatmap it does not show' % name
resized = read_png('shots/resized.png')
# A view the strategy cannot show (cache-mean under fixed): the sidecar records what was shown (none) and
# what was asked, so `render --settings` of it re-renders the picture (issue 38).
unavailable = json.load(open('shots/unavailable.json'))
gone = unavailable['settings']
assert (gone['strategy'], gone['heatmap']) == ('fixed', 'none'), gone
assert unavailable['heatmap_not_shown']['asked'] == 'cache-mean', unavailable.get('heatmap_not_shown')
assert resized[:2] == (200, 120), 'after resizing the window shot is %dx%d, not 200x120' % resized[:2]
assert variance(shots['render'][2]) > 1.0, 'the render is blank'
assert variance(shots['window'][2]) > 1.0, 'the window shot is blank'
assert shots['window'][2] != shots['render'][2], 'the window shot shows no panels'
assert shots['again'][2] == shots['render'][2], 'the sidecar did not reproduce the render'
if headless != 'skipped':
    assert read_png(headless)[2] == shots['render'][2], 'render --settings did not reproduce the render'
print('ok: %d strategies, %d heatmaps, %d screenshots; window %dx%d; headless re-render %s' %
      (len(strategies), len(heatmaps), len(shots), 160, 90, 'matches' if headless != 'skipped' else 'not wired yet'))
PY
