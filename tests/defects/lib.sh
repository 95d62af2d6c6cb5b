# Shared helpers of the defect regression scripts (sourced): $bin, $src, $work, fail, bad_input.
# usage in a script: source "$(dirname "$0")/lib.sh" "$@"   (arguments: SIGNALSIM_BINARY SOURCE_DIR)
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}

# ok MESSAGE: printed when nothing failed since the previous ok.
mark=0
ok() {
  [ $failures -eq $mark ] && echo "ok   $*"
  mark=$failures
  return 0
}

# bad_input NAME PATTERN... -- ARGS...: exit code 2, one stderr line holding every PATTERN (grep -E),
# no timeline.csv in --out and no summary.json there but one with status "error".
bad_input() {
  local name=$1; shift
  local patterns=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do patterns+=("$1"); shift; done
  shift
  local out=$work/$name
  "$bin" "$@" --out "$out" >"$work/$name.stdout" 2>"$work/$name.stderr"
  local code=$? ok=1
  [ "$code" -eq 2 ] || { fail "$name: exit code $code, want 2 ($(head -c 300 "$work/$name.stderr"))"; ok=0; }
  [ "$(wc -l <"$work/$name.stderr")" -eq 1 ] || { fail "$name: stderr is not one line: $(head -c 600 "$work/$name.stderr")"; ok=0; }
  local p
  for p in "${patterns[@]}"; do
    grep -qE -- "$p" "$work/$name.stderr" || { fail "$name: stderr lacks '$p': $(head -c 300 "$work/$name.stderr")"; ok=0; }
  done
  if [ -f "$out/summary.json" ] && ! grep -q '"status": "error"' "$out/summary.json"; then
    fail "$name: a summary.json presents the run as complete"; ok=0
  fi
  [ -f "$out/timeline.csv" ] && { fail "$name: timeline.csv written"; ok=0; }
  [ $ok -eq 1 ] && echo "ok   $name: $(cat "$work/$name.stderr")"
  return 0
}

# A copy of a bundled scenario with absolute paths, so that it can live in $work.
scenario_copy() {  # scenario_copy NAME DEST
  sed -e "s#\.\./sumo_nets#$src/sumo_nets#" -e "s#\.\./config#$src/config#" \
      -e "s#lights/#$src/scenarios/lights/#" "$src/scenarios/$1.yaml" > "$2"
}

finish() {
  if [ $failures -eq 0 ]; then echo "$(basename "$0" .sh): passed"; else echo "$(basename "$0" .sh): $failures failed"; fi
  [ $failures -eq 0 ]
}
