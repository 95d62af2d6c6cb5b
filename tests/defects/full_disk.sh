#!/usr/bin/env bash
# Defect 7: a full disk. A single run whose file cannot be written (its .tmp is /dev/full: every
# write fails with ENOSPC) exits 2 with one line, leaves no .tmp file and no summary.json that
# passes for a finished run. A batch on a small tmpfs that fills up (as root, when a tmpfs can be
# mounted; else that part is skipped): the runs that finished before keep their rows in results.csv,
# the runs that hit the full disk are error rows, no .tmp file and no empty summary.json is left.
set -u
source "$(dirname "$0")/lib.sh" "$@"
s=$src/scenarios/close_turns.yaml

for file in timeline.csv events.csv summary.json; do
  out=$work/full_$file
  "$bin" run "$s" --out "$out" --quiet >/dev/null  # a finished run there first
  ln -s /dev/full "$out/$file.tmp"
  "$bin" run "$s" --out "$out" --quiet >"$work/full.out" 2>"$work/full.err"
  code=$?
  [ $code -eq 2 ] || fail "$file on a full disk: exit code $code, want 2"
  [ "$(wc -l <"$work/full.err")" -eq 1 ] || fail "$file on a full disk: stderr is not one line: $(cat "$work/full.err")"
  grep -q "$file: cannot write: No space left on device" "$work/full.err" || fail "$file on a full disk: $(cat "$work/full.err")"
  leftovers=$(find "$out" -name '*.tmp')
  [ -z "$leftovers" ] || fail "$file on a full disk: left $leftovers"
  # (The old code could rename the /dev/full link into place: read a bounded amount, never the device.)
  if [ -L "$out/summary.json" ]; then
    fail "$file on a full disk: summary.json is the /dev/full link renamed into place"
  elif [ -e "$out/summary.json" ] && ! head -c 65536 "$out/summary.json" | grep -q '"status": "error"'; then
    fail "$file on a full disk: summary.json does not say error"
  fi
  for other in timeline.csv events.csv; do [ -e "$out/$other" ] && fail "$file on a full disk: $other of a run that did not finish"; done
done
ok "a run whose output cannot be written: exit 2, one line, no .tmp, no complete-looking summary"

# The batch on a tmpfs that fills up.
mnt=$work/tmpfs
mkdir -p "$mnt"
if ! mount -t tmpfs -o size=400k tmpfs "$mnt" 2>/dev/null; then
  echo "skip the batch part: cannot mount a tmpfs here (not root, or no CAP_SYS_ADMIN)"
  finish || exit 1
  exit 77
fi
trap 'umount "$mnt" 2>/dev/null; rm -rf "$work"' EXIT
mkdir -p "$work/suite"
for i in 01 02 03 04 05 06 07 08 09 10 11 12; do scenario_copy close_turns "$work/suite/close_turns_$i.yaml"; done
"$bin" batch "$work/suite" --out "$mnt/b" --jobs 1 --quiet >"$work/batch.out" 2>"$work/batch.err"
code=$?
[ $code -eq 4 ] || fail "batch on a full disk: exit code $code, want 4 ($(head -c 300 "$work/batch.err"))"
python3 - "$mnt/b/results.csv" <<'PY' || fail "results.csv on a full disk (above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
status = [r["status"] for r in rows]
print("   results.csv:", " ".join(status))
assert len(rows) == 12, f"{len(rows)} rows, want 12"
assert status[0] == "passed", "the first run should have had room"
assert "error" in status, "no run hit the full disk: the tmpfs is too big for the test"
first_error = status.index("error")
assert all(s == "passed" for s in status[:first_error]), status
for r in rows:
    if r["status"] == "error":
        assert "No space left on device" in r["error"] or "cannot" in r["error"], r["error"]
PY
leftovers=$(find "$mnt/b" -name '*.tmp' -o -name '.results.reserve')
[ -z "$leftovers" ] || fail "batch on a full disk left: $leftovers"
empty=$(find "$mnt/b" -name summary.json -empty)
[ -z "$empty" ] || fail "batch on a full disk left empty summaries: $empty"
for d in "$mnt"/b/runs/*; do
  if [ -e "$d/summary.json" ] && grep -q '"status": "passed"' "$d/summary.json"; then
    for f in timeline.csv events.csv; do [ -s "$d/$f" ] || fail "$d: passed but $f is missing or empty"; done
  fi
done
ok "a batch on a full disk: finished rows kept, error rows for the rest, nothing half-written left"
finish
