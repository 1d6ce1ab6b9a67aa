# Sourced by the CLI scripts that check refusals. refuse MODE WHAT EXPECTED-TEXT ARGS...: `$raylab MODE ARGS...`
# must exit 2 with EXPECTED-TEXT in its output (kept in $dir/refused.log); anything else fails the script.
refuse() {
  local mode=$1 what=$2 text=$3
  shift 3
  set +e
  "$raylab" "$mode" "$@" >"$dir/refused.log" 2>&1
  local rc=$?
  set -e
  [ $rc -eq 2 ] && grep -q -- "$text" "$dir/refused.log" || { echo "FAIL: $what: exit $rc"; cat "$dir/refused.log"; exit 1; }
  echo "ok: refused $what"
}
