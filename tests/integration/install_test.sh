#!/usr/bin/env bash
# cmake --install into a temporary prefix, then the installed binary alone, from another working
# directory: it lists the presets of P/share/signalsim (or of $SIGNALSIM_DATA_DIR), runs a bundled
# scenario with the same timeline and events as the build tree's binary, plots with the installed
# python/signalsim-plot (when matplotlib is there), and a missing data dir or libsumo module is one
# line and exit 2.
# usage: install_test.sh CMAKE_COMMAND BUILD_DIR SOURCE_DIR BUILD_TREE_SIGNALSIM
set -u
cmake=$1
build=$(cd "$2" && pwd) || exit 1
src=$(cd "$3" && pwd) || exit 1
build_bin=$(cd "$(dirname "$4")" && pwd)/$(basename "$4")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
unset SIGNALSIM_DATA_DIR SIGNALSIM_CONFIG_DIR SIGNALSIM_PLOT_TOOL

prefix=$work/prefix
"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || fail "cmake --install: $(cat "$work/install.log")"
bin=$prefix/bin/signalsim
data=$prefix/share/signalsim
[ -x "$bin" ] || fail "no executable $bin"
for f in config/autoware_defaults.yaml config/countries/jp.yaml data/autoware_keys.yaml python/signalsim_plot/cli.py \
         scenarios/intersection_left.yaml sumo_nets/cross/cross.net.xml; do
  [ -f "$data/$f" ] || fail "not installed: share/signalsim/$f"
done
[ -f "$prefix/lib/signalsim/libsignalsim_libsumo.so" ] || fail "not installed: lib/signalsim/libsignalsim_libsumo.so"
[ -x "$data/python/signalsim-plot" ] || fail "share/signalsim/python/signalsim-plot is not executable"
[ -z "$(find "$prefix" -name __pycache__ -o -name 'signalsim-data-dir.txt')" ] || fail "stray files installed"
# No path of the source or build tree's data, plugins or libsumo module is compiled into the binary
# (a sanitized build names its own source files, unity files of the build tree among them: harmless).
if command -v readelf > /dev/null; then
  tree_paths=(-e "$src/config" -e "$src/python" -e "$src/tools" -e "$build/plugins" -e "$build/lib" -e "$build/signalsim-data-dir")
  ! readelf -p .rodata "$bin" | grep -qF "${tree_paths[@]}" \
    || fail "a source or build tree path is compiled in: $(readelf -p .rodata "$bin" | grep -F "${tree_paths[@]}")"
fi
echo "ok   installed: bin/signalsim and share/signalsim/{config,python/signalsim-plot,python/signalsim_plot,scenarios,sumo_nets}"

mkdir -p "$work/elsewhere" && cd "$work/elsewhere" || fail "cd"
# The presets listed are the installed ones: every file named lies in P, and the codes are the source's.
"$bin" countries > countries.txt 2> countries.err || fail "countries: exit $?: $(cat countries.err)"
listed=$(grep -Eo '\(([^)]*)\.yaml\)$' countries.txt | tr -d '()')
[ -n "$listed" ] || fail "countries lists no preset: $(cat countries.txt)"
for path in $listed; do
  case $path in "$data"/config/countries/*) ;; *) fail "preset not from the prefix: $path" ;; esac
done
codes=$(grep -Eo '^[a-z]+ ' countries.txt | tr -d ' ' | tr '\n' ' ')
expected=$(cd "$src/config/countries" && ls *.yaml | sed 's/\.yaml$//' | tr '\n' ' ')
[ "$codes" = "$expected" ] || fail "codes '$codes', expected '$expected'"
echo "ok   countries from another folder lists P/share/signalsim's presets: $codes"

# A bundled scenario, installed copy, run from here: same timeline and events as the build tree's run.
"$bin" run "$data/scenarios/intersection_left.yaml" --out left > run.out 2> run.err \
  || fail "run: exit $?: $(cat run.err)"
"$build_bin" run "$src/scenarios/intersection_left.yaml" --out "$work/left_build" > /dev/null 2>&1 \
  || fail "build tree run failed"
for f in timeline.csv events.csv; do
  cmp -s "left/$f" "$work/left_build/$f" || fail "$f differs from the build tree's run"
done
echo "ok   installed intersection_left passes; timeline and events identical to the build tree's"

# --strict-params reads the installed table of Autoware's keys (share/signalsim/data).
"$bin" run "$data/scenarios/intersection_left.yaml" --out strict --quiet --strict-params \
  --params "$src/tests/data/autoware_launch/behavior_path_planner.param.yaml" 2> strict.err ||
  fail "--strict-params with the installed table: exit $?: $(cat strict.err)"
echo "ok   --strict-params checks autoware_launch's file against the installed table"

# SIGNALSIM_DATA_DIR: a copy of the data with one more preset; the extra one is listed and usable.
cp -r "$data" "$work/data"
cat > "$work/data/config/countries/zz.yaml" <<'YAML'
code: zz
name: Testland
parameters:
  turn_signal_search_time: 2.5
YAML
SIGNALSIM_DATA_DIR=$work/data "$bin" countries > zz.txt 2> zz.err || fail "countries with SIGNALSIM_DATA_DIR: $(cat zz.err)"
grep -qF "zz  Testland  ($work/data/config/countries/zz.yaml)" zz.txt || fail "extra preset not listed: $(cat zz.txt)"
! grep -qF "$data/" zz.txt || fail "SIGNALSIM_DATA_DIR set, yet the prefix's presets listed"
! "$bin" countries | grep -q '^zz ' || fail "zz listed without SIGNALSIM_DATA_DIR"
SIGNALSIM_DATA_DIR=$work/data "$bin" run "$data/scenarios/intersection_left.yaml" --set country=zz --out zz_run \
  > /dev/null 2> zz_run.err || fail "run --set country=zz: exit $?: $(cat zz_run.err)"
echo "ok   SIGNALSIM_DATA_DIR: the extra preset is listed and runs; the prefix's are not used"

# No data: one line, exit 2, naming what was tried.
expect_no_data() {  # expect_no_data WHAT PATTERN COMMAND...
  local what=$1 pattern=$2
  shift 2
  "$@" > none.out 2> none.err
  local code=$?
  [ "$code" = 2 ] || fail "$what: exit code $code, expected 2"
  [ "$(wc -l < none.err)" = 1 ] || fail "$what: expected one stderr line, got: $(cat none.err)"
  grep -qF "$pattern" none.err || fail "$what: message: $(cat none.err)"
  [ ! -s none.out ] || fail "$what: output written: $(cat none.out)"
}
expect_no_data "SIGNALSIM_DATA_DIR wrong" \
  "signalsim: SIGNALSIM_DATA_DIR=$work/nothing: not a signalsim data directory (no config/countries in it)" \
  env SIGNALSIM_DATA_DIR="$work/nothing" "$bin" countries
mkdir -p "$work/lone/bin" && cp "$bin" "$work/lone/bin/"
marker_above=""
for d in "$work" $(dirname "$work") /; do [ -e "$d/signalsim-data-dir.txt" ] && marker_above=$d; done
if [ -z "$marker_above" ]; then
  expect_no_data "binary without its share/signalsim" \
    "signalsim: $work/lone/bin/signalsim: no data directory: $work/lone/share/signalsim has no config/countries" \
    "$work/lone/bin/signalsim" run "$data/scenarios/intersection_left.yaml" --out lone_run
  [ ! -e lone_run ] || fail "lone binary: output folder written"
  expect_no_data "binary without its libsumo module" \
    "cannot load signalsim's libsumo module: $work/lone/lib/signalsim/libsignalsim_libsumo.so: cannot open shared object file" \
    env SIGNALSIM_DATA_DIR="$data" "$work/lone/bin/signalsim" run "$data/scenarios/intersection_left.yaml" --out lone_module
  mkdir -p "$work/moved/build/bin" && cp "$bin" "$work/moved/build/bin/"
  echo "$work/moved/src" > "$work/moved/build/signalsim-data-dir.txt"
  expect_no_data "build tree marker naming a moved source tree" \
    "signalsim: $work/moved/build/signalsim-data-dir.txt: names the source tree '$work/moved/src', which has no config/countries" \
    "$work/moved/build/bin/signalsim" countries
  echo "ok   no data directory: one line, exit 2 (a wrong SIGNALSIM_DATA_DIR, a binary without share/, a stale marker)"
else
  echo "ok   a wrong SIGNALSIM_DATA_DIR: one line, exit 2 (lone binary skipped: a build tree marker in $marker_above)"
fi

# --plot with the installed python/signalsim-plot.
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  "$bin" run "$data/scenarios/intersection_left.yaml" --out plotted --plot > plot.out 2> plot.err \
    || fail "run --plot: exit $?: $(cat plot.err)"
  for f in blinker speed; do [ -s "plotted/plots/$f.png" ] || fail "no plots/$f.png: $(cat plot.out plot.err)"; done
  echo "ok   run --plot from the installed tree writes plots/"
  # the HTML report: its script and style are files of the installed package, inlined into the page
  "$bin" batch "$data/scenarios/intersection_left.yaml" --out reported --quiet --report > report.out 2> report.err \
    || fail "batch --report: exit $?: $(cat report.err)"
  grep -q 'document.body.dataset.rendered' reported/report.html || fail "report.html without its script: $(cat report.err)"
  grep -q 'table.heat' reported/report.html || fail "report.html without its style"
  echo "ok   batch --report from the installed tree writes report.html with its script and style"
else
  echo "skip run --plot: no matplotlib"
fi
echo "ok   install"
