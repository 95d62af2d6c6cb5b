#!/usr/bin/env bash
# signalsim generate twice with the same arguments writes the same bytes (every file, the index
# too); a second run into the same folder replaces the first's files; another seed gives other routes.
# usage: generate_deterministic.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$work" || exit 1
acosta=$src/sumo_nets/bologna_acosta/acosta_buslanes.net.xml

"$bin" generate "$acosta" --count 25 --seed 7 --out gen --country jp --quiet || fail "first generate: exit $?"
cp -r gen first
"$bin" generate "$acosta" --count 25 --seed 7 --out gen --country jp --quiet || fail "second generate: exit $?"
[ "$(ls gen | wc -l)" = 26 ] || fail "expected 25 scenarios and the index, got: $(ls gen)"
diff -r first gen > diff.txt || fail "the same arguments gave other files: $(head -20 diff.txt)"
for f in first/*; do cmp -s "$f" "gen/$(basename "$f")" || fail "$f differs"; done
echo "ok   the same arguments twice: 26 identical files"

# Fewer scenarios into the same folder: the earlier files are gone, the first ones are the same.
"$bin" generate "$acosta" --count 5 --seed 7 --out gen --country jp --quiet || fail "third generate: exit $?"
[ "$(ls gen/*.yaml | wc -l)" = 5 ] || fail "stale files left: $(ls gen)"
for i in 1 2 3 4 5; do
  f=acosta_buslanes_000$i.yaml
  # Only the header's command line (--count 5) differs.
  diff <(grep -v -- "--count" "first/$f") <(grep -v -- "--count" "gen/$f") > /dev/null || fail "$f changed with --count"
done
echo "ok   a second generate into the folder replaces its files; the routes do not depend on --count"

"$bin" generate "$acosta" --count 25 --seed 8 --out other --country jp --quiet || fail "seed 8: exit $?"
same=0
for f in first/*.yaml; do
  a=$(grep "^  route:" "$f"); b=$(grep "^  route:" "other/$(basename "$f")")
  [ "$a" = "$b" ] && same=$((same + 1))
done
[ "$same" -lt 5 ] || fail "seed 8 repeats $same of seed 7's 25 routes in the same files"
echo "ok   another seed: other routes ($same of 25 files with the same route)"
