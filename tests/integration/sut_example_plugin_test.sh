#!/usr/bin/env bash
# The example plugin examples/cpp_decider (docs/decider.md "The C ABI"), on real libsumo:
#   - its decider (the intersection rule) decides as the reference at every step of every bundled
#     scenario whose only signal sections are intersection turns (close_turns aside: two turns
#     overlap there and the reference's required end comes from an Akima-resampled centre line);
#   - its light judge (stop on a red or amber circle) stops the ego before the line at a red light
#     and lets it go on green; it passes a green light without stopping;
#   - it builds on its own against the installed header (cmake --install), and an installed signalsim
#     finds a bundled plugin in lib/signalsim/plugins (the example under the autoware_core plugin's
#     name), a build tree in its plugins/ folder.
# usage: sut_example_plugin_test.sh SIGNALSIM_BINARY SOURCE_DIR PLUGIN CMAKE BUILD_DIR
set -u
bin=$1
src=$2
plugin=$3
cmake=$4
build=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

agreement() {  # TIMELINE: "rows disagreeing" (0 when blinker == ref_blinker everywhere)
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "blinker") b = i; if ($i == "ref_blinker") r = i } next }
           $b != $r { n++ } END { print (b && r) ? n + 0 : "no ref_blinker column" }' "$1"
}

cd "$src/scenarios" || exit 1
for s in intersection_left intersection_right intersection_straight t_junction_left turn_signal_distance_override tl_*.yaml; do
  s=${s%.yaml}
  "$bin" run "$s.yaml" --out "$work/dec/$s" --quiet --set "decider=lib:$plugin" >/dev/null 2>"$work/$s.err"
  [ $? -le 1 ] || { echo "FAIL $s: $(cat "$work/$s.err")"; failures=$((failures + 1)); continue; }
  n=$(agreement "$work/dec/$s/timeline.csv")
  [ "$n" = 0 ] || { echo "FAIL $s: $n rows where the example's blinker is not the reference's"; failures=$((failures + 1)); }
done

# The light judge: at rest before the line on red (the scenario's stops_before_light), then through on green.
"$bin" run tl_red_stop_then_go.yaml --out "$work/red" --quiet --set "light_judge=lib:$plugin" 2>"$work/red.err" ||
  { echo "FAIL red: $(cat "$work/red.err") $(grep -o '"detail": "[^"]*"' "$work/red/summary.json")"; failures=$((failures + 1)); }
tail -n +2 "$work/red/events.csv" | grep ',light,' | cut -d, -f4,5 | tr '\n' ' ' | grep -q '^none,stop stop,pass ' ||
  { echo "FAIL red: light events are not stop then pass:"; cat "$work/red/events.csv"; failures=$((failures + 1)); }
"$bin" run tl_green_pass.yaml --out "$work/green" --quiet --set "light_judge=lib:$plugin" 2>"$work/green.err" ||
  { echo "FAIL green: $(cat "$work/green.err")"; failures=$((failures + 1)); }
grep -q ',light,none,stop,' "$work/green/events.csv" && { echo "FAIL green: the judge stopped"; failures=$((failures + 1)); }

# Standalone against an installation; the installed binary finds lib/signalsim/plugins.
"$cmake" --install "$build" --prefix "$work/prefix" >/dev/null || { echo "FAIL install"; exit 1; }
[ -f "$work/prefix/include/signalsim/decider_plugin.h" ] || { echo "FAIL the header is not installed"; failures=$((failures + 1)); }
"$cmake" -S "$src/examples/cpp_decider" -B "$work/example" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null &&
  "$cmake" --build "$work/example" >/dev/null || { echo "FAIL the example does not build on its own"; failures=$((failures + 1)); }
mkdir -p "$work/prefix/lib/signalsim/plugins"
cp "$work/example/libsignalsim_cpp_decider.so" "$work/prefix/lib/signalsim/plugins/libsignalsim_autoware_core.so"
"$work/prefix/bin/signalsim" run "$work/prefix/share/signalsim/scenarios/intersection_left.yaml" --out "$work/installed" \
  --quiet --set decider=autoware_core 2>"$work/installed.err" ||
  { echo "FAIL installed autoware_core: $(cat "$work/installed.err")"; failures=$((failures + 1)); }
[ "$(agreement "$work/installed/timeline.csv")" = 0 ] ||
  { echo "FAIL installed autoware_core: no decider under test in the timeline"; failures=$((failures + 1)); }
# A build tree: plugins/ beside the marker; without the plugin there, one line naming where it looked.
mkdir -p "$work/tree/src/app" "$work/tree/plugins" "$work/tree/lib/signalsim"
cp "$build/signalsim-data-dir.txt" "$work/tree/"
cp "$bin" "$work/tree/src/app/signalsim"
cp "$build/lib/signalsim/libsignalsim_libsumo.so" "$work/tree/lib/signalsim/"
"$work/tree/src/app/signalsim" run intersection_left.yaml --out "$work/tree_missing" --quiet --set decider=autoware_core 2>"$work/tree.err"
[ $? -eq 2 ] && grep -qF "$work/tree/plugins/libsignalsim_autoware_core.so is not built" "$work/tree.err" ||
  { echo "FAIL build tree without the plugin: $(cat "$work/tree.err")"; failures=$((failures + 1)); }
cp "$plugin" "$work/tree/plugins/libsignalsim_autoware_core.so"
"$work/tree/src/app/signalsim" run intersection_left.yaml --out "$work/tree_run" --quiet --set decider=autoware_core 2>"$work/tree.err" ||
  { echo "FAIL build tree autoware_core: $(cat "$work/tree.err")"; failures=$((failures + 1)); }

if [ "$failures" -ne 0 ]; then echo "$failures failures"; exit 1; fi
echo "ok: the example agrees with the reference on the intersection scenarios, stops on red, builds on its own"
