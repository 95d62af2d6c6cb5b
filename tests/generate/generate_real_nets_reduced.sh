#!/usr/bin/env bash
# generate_real_nets (generate_real_nets.sh) cut down for the sanitized build (tools/test_sanitized,
# where the full test is excluded for its time): a few generated routes on three bundled nets and on
# bologna_acosta with one country, run with `signalsim batch`, so signalsim's instrumented generate
# and per-step code run on real nets; every run passes (arrives, no red crossing, every expectation
# held). The broken-rule and golden parts stay in the full test.
# usage: generate_real_nets_reduced.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$work" || exit 1

mkdir suite
for spec in signal_cross:de roundabout_lefthand:jp roundabout_after_junction:kr; do
  net=${spec%%:*}
  "$bin" generate "$src/sumo_nets/$net/$net.net.xml" --count 2 --seed 3 --country "${spec#*:}" --out "suite/$net" \
    --quiet 2> "$net.err" || fail "generate $net: $(cat "$net.err")"
done
"$bin" generate "$src/sumo_nets/bologna_acosta/acosta_buslanes.net.xml" --count 3 --seed 2 --country de \
  --out suite/acosta_de --quiet || fail "generate acosta"
total=$(ls suite/*/*.yaml | wc -l)
[ "$total" -ge 8 ] || fail "only $total scenarios generated"

"$bin" batch suite/* --out runs --jobs 2 --quiet > batch.out 2>&1
code=$?
python3 "$src/tests/generate/every_run_passes.py" runs || fail "generated scenarios failed (batch exit $code): $(tail -5 batch.out)"
[ "$code" = 0 ] || fail "batch exit $code"
echo "ok   $total generated scenarios on 4 nets pass in SUMO"
