#!/usr/bin/env bash
# Defect 5: every numeric option of every command refuses NaN and infinities (CLI11's own checks let
# NaN through: `--timeout nan` left no working limit), and a range in the message is written as a
# person reads it (CLI11 printed DBL_MAX with std::to_string: 309 digits).
set -u
source "$(dirname "$0")/lib.sh" "$@"
s=$src/scenarios/close_turns.yaml
net=$src/sumo_nets/cross/cross.net.xml
sweep=$src/tests/batch/data/sweep_3x3x2.yaml

# refused NAME VALUE ARGS...: exit 2, one line naming the option, no long digit runs, nothing run.
refused() {
  local name=$1 value=$2; shift 2
  local option=${name%%@*}
  "$bin" "$@" "$option" "$value" >"$work/out" 2>"$work/err"
  local code=$?
  local what="$* $option $value"
  [ $code -eq 2 ] || { fail "$what: exit code $code, want 2"; return; }
  [ "$(wc -l <"$work/err")" -eq 1 ] || { fail "$what: not one line: $(head -c 400 "$work/err")"; return; }
  grep -q -- "$option" "$work/err" || fail "$what: the message does not name $option: $(cat "$work/err")"
  grep -qE '[0-9]{20}' "$work/err" && fail "$what: a number of 20+ digits in: $(head -c 200 "$work/err")"
  [ -s "$work/out" ] && fail "$what: printed output: $(head -c 200 "$work/out")"
  return 0
}

for v in nan NaN inf -inf infinity 1e999; do
  refused --timeout "$v" batch "$s" --out "$work/b"
  refused --timeout "$v" sweep "$sweep" --out "$work/w"
  refused --timeout "$v" check "$s" --golden "$src/tests/golden" --out "$work/c"
  refused --timeout "$v" compare "$s" --out "$work/m"
  refused --tolerance "$v" check "$s" --golden "$src/tests/golden" --out "$work/c"
  refused --time-tolerance "$v" check "$s" --golden "$src/tests/golden" --out "$work/c"
  refused --jobs "$v" batch "$s" --out "$work/b"
  refused --min-length "$v" generate "$net" --count 1 --out "$work/g"
  refused --max-length "$v" generate "$net" --count 1 --out "$work/g"
  refused --max-speed "$v" generate "$net" --count 1 --out "$work/g"
  refused --straight "$v" generate "$net" --count 1 --out "$work/g"
  refused --count "$v" generate "$net" --out "$work/g"
  refused --seed "$v" generate "$net" --count 1 --out "$work/g"
  refused --gui-delay "$v" run "$s" --gui --out "$work/r"
  refused --client-order "$v" run "$s" --connect 127.0.0.1:1 --out "$work/r"
  refused --traci-timeout "$v" run "$s" --connect 127.0.0.1:1 --out "$work/r"
done
[ -e "$work/b/results.csv" ] || [ -e "$work/w/results.csv" ] || [ -e "$work/c/results.csv" ] && fail "a batch ran"
[ -e "$work/g" ] && fail "generate wrote $work/g"
ok "NaN and infinities refused by every numeric option"

# Out of range: the bounds as written, no 309-digit DBL_MAX.
for args in "--timeout -1 batch" "--timeout 0 batch" "--tolerance -1 check" "--time-tolerance -0.5 check"; do
  set -- $args
  option=$1 value=$2 command=$3
  if [ "$command" = batch ]; then "$bin" batch "$s" --out "$work/b" "$option" "$value" 2>"$work/err" >/dev/null
  else "$bin" check "$s" --golden "$src/tests/golden" --out "$work/c" "$option" "$value" 2>"$work/err" >/dev/null; fi
  [ $? -eq 2 ] || fail "$command $option $value: not exit 2"
  grep -qE '[0-9]{20}' "$work/err" && fail "$command $option $value: unreadable range: $(head -c 200 "$work/err")"
  grep -qE -- "$option: $value is out of range: it must be (more than|at least) 0" "$work/err" ||
    fail "$command $option $value: $(cat "$work/err")"
done
"$bin" generate "$net" --count 1 --out "$work/g" --max-speed 99 2>"$work/err" >/dev/null
grep -q -- "--max-speed: 99 is out of range: it must be between 1 and 60" "$work/err" || fail "--max-speed 99: $(cat "$work/err")"
ok "ranges are written readably: $(cat "$work/err")"
finish
