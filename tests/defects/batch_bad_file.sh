#!/usr/bin/env bash
# Defect 9: in `batch` and `check`, a scenario file that does not load (malformed YAML, an unknown
# key) is an error row with its one-line message, as an unconnected route already was; the other
# scenarios run. It used to abort the whole batch (exit 2, nothing run). A bad --set still is bad
# input of the command (exit 2, nothing run). Exit codes: 4 when a run errored.
set -u
source "$(dirname "$0")/lib.sh" "$@"
suite=$work/suite
mkdir -p "$suite"
scenario_copy close_turns "$suite/a_good.yaml"
printf 'name: broken\nego: [unclosed\n' > "$suite/b_malformed.yaml"
scenario_copy close_turns "$suite/c_unknown_key.yaml"
sed -i 's/^seed: 1$/seed: 1\nsede: 2/' "$suite/c_unknown_key.yaml"
key_line=$(grep -n '^sede:' "$suite/c_unknown_key.yaml" | cut -d: -f1)
scenario_copy close_turns "$suite/d_unconnected.yaml"
sed -i 's/^  route: .*/  route: [in_S, out_N]/' "$suite/d_unconnected.yaml"
scenario_copy tl_green_pass "$suite/e_good.yaml"

"$bin" batch "$suite" --out "$work/b" --jobs 2 >"$work/b.out" 2>"$work/b.err"
code=$?
[ $code -eq 4 ] || fail "batch: exit code $code, want 4 ($(cat "$work/b.err"))"
python3 - "$work/b/results.csv" "$suite" "$key_line" <<'PY' || fail "batch results.csv (above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
suite, key_line = sys.argv[2], sys.argv[3]
got = [(r["scenario"], r["status"]) for r in rows]
print("   results.csv:", got)
assert [s for _, s in got] == ["passed", "error", "error", "error", "passed"], got
assert rows[1]["scenario"] == "b_malformed" and rows[1]["error"].startswith(f"{suite}/b_malformed.yaml:3: malformed YAML"), rows[1]["error"]
assert rows[2]["error"] == f"{suite}/c_unknown_key.yaml:{key_line}: unknown key 'sede'", rows[2]["error"]
assert "not connected" in rows[3]["error"], rows[3]["error"]
PY
grep -q "^5 runs: 2 passed, 0 failed, 0 without expectations, 3 errors" "$work/b.out" || fail "batch summary: $(cat "$work/b.out")"
# The same batch gives the same results.csv with one job (but for wall_time).
"$bin" batch "$suite" --out "$work/b1" --jobs 1 --quiet >/dev/null 2>&1
cut_wall() { python3 -c 'import csv,sys; [print([v for k,v in r.items() if k!="wall_time"]) for r in csv.DictReader(open(sys.argv[1]))]' "$1"; }
[ "$(cut_wall "$work/b/results.csv" | sed "s#$work/b1\?/##g")" = "$(cut_wall "$work/b1/results.csv" | sed "s#$work/b1\?/##g")" ] ||
  fail "--jobs 1 and --jobs 2 differ"
ok "batch: the bad files are error rows with their message, the others ran (exit 4)"

# A bad --set is the command's own bad input: exit 2, nothing runs.
"$bin" batch "$suite" --out "$work/s" --set no_such_parameter=1 >/dev/null 2>"$work/s.err"
code=$?
[ $code -eq 2 ] || fail "batch with a bad --set: exit code $code, want 2"
[ -e "$work/s/results.csv" ] && fail "batch with a bad --set ran"
ok "a bad --set is still bad input (exit 2): $(cat "$work/s.err")"

# check: the bad files are JUnit errors, the good ones are compared; exit 4.
golden=$work/golden
mkdir -p "$golden"
cp "$src/tests/golden/close_turns.events.csv" "$golden/a_good.events.csv"
cp "$src/tests/golden/tl_green_pass.events.csv" "$golden/e_good.events.csv"
"$bin" check "$suite" --golden "$golden" --out "$work/c" --junit "$work/c.xml" >"$work/c.out" 2>"$work/c.err"
code=$?
[ $code -eq 4 ] || fail "check: exit code $code, want 4 ($(cat "$work/c.out" "$work/c.err"))"
grep -q "^ok    a_good: " "$work/c.out" || fail "check: a_good: $(cat "$work/c.out")"
grep -q "^ok    e_good: " "$work/c.out" || fail "check: e_good: $(cat "$work/c.out")"
grep -q "^ERROR b_malformed: run error: .*b_malformed.yaml:3: malformed YAML" "$work/c.out" || fail "check: b_malformed: $(cat "$work/c.out")"
grep -q "^check: 5 scenarios, 2 passed, 0 failed, 3 errors" "$work/c.out" || fail "check summary: $(tail -1 "$work/c.out")"
grep -q 'tests="5" failures="0" errors="3"' "$work/c.xml" || fail "JUnit: $(head -3 "$work/c.xml")"
ok "check: the bad files are errors (JUnit <error>), the others compared (exit 4)"
finish
