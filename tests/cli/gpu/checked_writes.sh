#!/usr/bin/env bash
# Nothing lost without a word (issue 23): a render whose PNG or stats cannot be written exits 1 naming the
# file and the reason (/dev/full: no space; /proc: no temporary file), never "wrote ...". On a nearly full
# disk (a tmpfs of a few pages: needs root, as CI has; without it those parts skip, saying so) a render and a
# bench fail the same way and leave no cut-off file under a final name, and no temporary file either. (A file
# size limit, ulimit -f, would need no root, but Mesa 25's lavapipe then dies of SIGBUS on its own memfd.)
set -eu
raylab="$1"
dir=$(mktemp -d)
mounts=()
cleanup() {
  for m in "${mounts[@]}"; do umount "$m" 2>/dev/null || true; done
  rm -rf "$dir"
}
trap cleanup EXIT
# small_disk FOLDER KIB: FOLDER becomes a tmpfs of KIB KiB; false where mounting is not allowed.
small_disk() {
  mkdir -p "$1"
  mount -t tmpfs -o size="$2k" tmpfs "$1" 2>/dev/null || return 1
  mounts+=("$1")
}
render=(render --scene cornell --size 32x16 --frames 1)

# expect_failure RC LOG NAME: the run exited 1 naming NAME and did not claim to have written it.
expect_failure() {
  local rc=$1 log=$2 name=$3
  [ "$rc" -eq 1 ] || { echo "FAIL: exit $rc, not 1, writing $name"; cat "$log"; exit 1; }
  grep -q "cannot write $name" "$log" || { echo "FAIL: no message naming $name"; cat "$log"; exit 1; }
  if grep -q "^wrote $name\|^stats in $name" "$log"; then echo "FAIL: claimed to have written $name"; cat "$log"; exit 1; fi
}

set +e
"$raylab" "${render[@]}" --out /dev/full >"$dir/full.log" 2>&1; expect_failure $? "$dir/full.log" /dev/full
grep -q "No space left on device" "$dir/full.log" || { echo "FAIL: ENOSPC not reported"; cat "$dir/full.log"; exit 1; }
"$raylab" "${render[@]}" --out "$dir/a.png" --stats /dev/full >"$dir/stats.log" 2>&1; expect_failure $? "$dir/stats.log" /dev/full
"$raylab" "${render[@]}" --out "$dir/a.png" --stats /proc/x.json >"$dir/proc.log" 2>&1; expect_failure $? "$dir/proc.log" /proc/x.json
set -e
[ -c /dev/full ] || { echo "FAIL: /dev/full is no longer a character device"; exit 1; }
[ ! -e /proc/x.json ] || { echo "FAIL: /proc/x.json exists"; exit 1; }
echo "ok: /dev/full and /proc refused with exit 1"

if ! small_disk "$dir/small" 4; then
  echo "skip: no tmpfs can be mounted here (not root): the full-disk render and bench are not checked"
  exit 0
fi
# A disk of one 4 KiB page: the PNG (about 1 KiB) fits, the stats JSON (about 5 KiB) cannot be written whole.
set +e
"$raylab" "${render[@]}" --out "$dir/small/a.png" --stats "$dir/small/a.json" >"$dir/small.log" 2>&1
expect_failure $? "$dir/small.log" "$dir/small/a.json"
set -e
grep -q "No space left on device" "$dir/small.log" || { echo "FAIL: ENOSPC not reported"; cat "$dir/small.log"; exit 1; }
leftover=$(ls -A "$dir/small" | grep -v '^a\.png$' || true)
[ -z "$leftover" ] || { echo "FAIL: left behind: $leftover"; exit 1; }
echo "ok: a render over the file size limit exits 1 and leaves no a.json"

# A bench sweep of 5 cells on a 20 KiB disk: sweep.json (about 5 KiB) fits, a record is about 5 KiB, so
# the JSONL fails after a few cells. The bench stops with exit 1 naming results.jsonl; the JSONL ends on a
# whole record, there is no results.csv, and nothing temporary is left.
set +e
small_disk "$dir/bench" 20
"$raylab" bench --cases cornell@front --strategies dead-last,fixed,two-point \
  --size 32x16 --timed-frames 1 --warmup 0 --reference-spp 1 --rounds 1 --out-dir "$dir/bench" >"$dir/bench.log" 2>&1
expect_failure $? "$dir/bench.log" "$dir/bench/results.jsonl"
set -e
grep -q -- "--resume $dir/bench" "$dir/bench.log" || { echo "FAIL: no hint to resume"; cat "$dir/bench.log"; exit 1; }
[ ! -e "$dir/bench/results.csv" ] || { echo "FAIL: a results.csv from a sweep that did not end"; exit 1; }
leftover=$(ls -A "$dir/bench" | grep -v '^results\.jsonl$\|^sweep\.json$' || true)
[ -z "$leftover" ] || { echo "FAIL: left behind in the bench folder: $leftover"; exit 1; }
python3 - "$dir/bench" <<'PY'
import json, sys
folder = sys.argv[1]
sweep = json.load(open(folder + '/sweep.json'))  # whole: it parses
assert len(sweep['definition']['cells']) == 5, len(sweep['definition']['cells'])
text = open(folder + '/results.jsonl').read()
assert text == '' or text.endswith('\n'), 'results.jsonl ends in a cut-off record'
records = [json.loads(line) for line in text.splitlines()]
assert len(records) < 5, len(records)  # how many fit depends on the records' sizes
assert [r['cell'] for r in records] == list(range(len(records))), [r['cell'] for r in records]
print('ok: the bench over the file size limit exits 1 after', len(records), 'whole records, no results.csv')
PY
