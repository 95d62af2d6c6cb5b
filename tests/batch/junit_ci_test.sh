#!/usr/bin/env bash
# JUnit XML as a CI server reads it, from `batch --junit` and `check --junit`, run from a working
# directory that holds the suite: classname from the folder and the net (suite.nested.close_turns),
# file relative to the working directory, <properties> with the seed, country, net, parameter files,
# decider and light judge as the runs used them; a failed case's pictures as [[ATTACHMENT|path]] lines
# of its <system-out>, each a PNG that exists at that path relative to the working directory; none for
# a passing case.
# usage: junit_ci_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
mkdir -p "$work/suite/nested"
cd "$work" || fail "cannot enter $work"

# One scenario whose expectation holds and one whose expectation fails (a left blinker at A).
sed -e "s#\.\./\.\./\.\./#$src/#" "$src/tests/batch/data/turns.yaml" > suite/nested/passes.yaml
sed -e "s#\.\./\.\./\.\./#$src/#" -e "s/^name: turns/name: fails/" "$src/tests/batch/data/turns.yaml" \
  > suite/nested/fails.yaml
echo "  - blinker_never: left" >> suite/nested/fails.yaml

"$bin" batch suite/nested --out out/batch --junit reports/batch.xml --set seed=3 --set country=de -q > batch.log 2>&1
code=$?
[ $code -eq 1 ] || fail "batch exit code $code, want 1 (one run failed): $(cat batch.log)"
mkdir -p golden
"$bin" check suite/nested --golden golden --update --out out/update -q > update.log 2>&1  # the failing one is not updated
"$bin" check suite/nested --golden golden --out out/check --junit reports/check.xml --set seed=3 --set country=de > check.log 2>&1
code=$?
[ $code -eq 1 ] || fail "check exit code $code, want 1: $(cat check.log)"

for report in reports/batch.xml reports/check.xml; do
  /usr/bin/python3 - "$report" "$src" <<'PY' || fail "$report (above): $(cat "$report")"
import os, sys, xml.etree.ElementTree as ET
path, src = sys.argv[1:]
suite = ET.parse(path).getroot().find("testsuite")
cases = {c.get("name"): c for c in suite.findall("testcase")}
assert sorted(cases) == ["fails", "passes"], sorted(cases)
for name, c in cases.items():
    assert c.get("classname") == "suite.nested.close_turns", (name, c.get("classname"))
    assert c.get("file") == f"suite/nested/{name}.yaml", (name, c.get("file"))
    props = [(p.get("name"), p.get("value")) for p in c.find("properties").findall("property")]
    assert ("seed", "3") in props and ("country", "de") in props, props
    assert ("decider", "reference") in props and ("light_judge", "reference") in props, props
    assert ("net", f"{src}/sumo_nets/close_turns/close_turns.net.xml") in props, props
    files = [v for k, v in props if k == "parameter_file"]
    assert f"{src}/config/autoware_defaults.yaml" in files, files
assert cases["fails"].find("failure") is not None, ET.tostring(cases["fails"])
out = cases["fails"].find("system-out").text
assert "expectation failed: blinker_never" in out, out
attached = [line[len("[[ATTACHMENT|"):-2] for line in out.splitlines() if line.startswith("[[ATTACHMENT|")]
assert attached, "no attachment line in " + out
assert all(line.endswith("]]") for line in out.splitlines() if line.startswith("[[ATTACHMENT|")), out
for a in attached:
    assert not os.path.isabs(a) and a.startswith("out/") and a.endswith(".png"), a
    assert open(a, "rb").read(8) == b"\x89PNG\r\n\x1a\n", a
assert any(a.endswith("/plots/blinker.png") for a in attached), attached
ok = cases["passes"]
assert ok.find("failure") is None and ok.find("system-out") is None, ET.tostring(ok)
PY
done
echo "ok   batch and check --junit: classname, relative file, properties, a failed run's pictures attached"
