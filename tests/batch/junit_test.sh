#!/usr/bin/env bash
# signalsim check --junit with scenario file names that hold XML's special characters (<, >, &, ",
# ') and control characters: the JUnit file is well-formed XML (python's xml.etree, a strict parser,
# reads it), names, files and messages read back as they were, each control character but tab, line
# feed and carriage return as a space.
# usage: junit_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
dir=$work/suite
mkdir -p "$dir"

# A scenario that runs (and fails: no golden file, and an expectation that does not hold, so the
# case has <failure> and <system-out>), and one that does not load (<error>).
good=$'t<&"\'\x01>'
bad=$'b<&"\x02'
sed -e "s#\.\./\.\./\.\./#$src/#" "$src/tests/batch/data/turns.yaml" > "$dir/$good.yaml"
echo "  - blinker_never: left" >> "$dir/$good.yaml"
printf 'name: x\nnet: [\n' > "$dir/$bad.yaml"
# The golden folder holds a golden file of one of them (check refuses one that holds none).
mkdir -p "$work/golden" && printf 'time,s_front,kind,from,to,source\n' > "$work/golden/$bad.events.csv"

"$bin" check "$dir" --golden "$work/golden" --out "$work/c" --junit "$work/c.xml" > "$work/c.log" 2>&1
code=$?
[ $code -eq 4 ] || fail "exit code $code, want 4 (a failure and an error): $(cat "$work/c.log")"
[ -s "$work/c.xml" ] || fail "no JUnit file"

python3 - "$work/c.xml" "$dir" "$good" "$bad" <<'PY' || fail "JUnit with special characters (above): $(cat "$work/c.xml")"
import re, sys, xml.etree.ElementTree as ET
path, folder, good, bad = sys.argv[1:]
text = open(path, "rb").read()
assert text.startswith(b'<?xml version="1.0" encoding="UTF-8"?>'), text[:60]
root = ET.parse(path).getroot()  # raises on XML that is not well-formed
as_xml = lambda s: re.sub(r"[\x00-\x08\x0b\x0c\x0e-\x1f]", " ", s)
assert root.tag == "testsuites", root.tag
suite = root.find("testsuite")
assert (suite.get("tests"), suite.get("failures"), suite.get("errors"), suite.get("skipped")) == ("2", "1", "1", "0"), suite.attrib
cases = suite.findall("testcase")
assert [c.get("name") for c in cases] == [as_xml(bad), as_xml(good)], [c.get("name") for c in cases]
assert [c.get("file") for c in cases] == [as_xml(folder + "/" + bad + ".yaml"), as_xml(folder + "/" + good + ".yaml")], \
    [c.get("file") for c in cases]
error = cases[0].find("error")
assert error is not None and "malformed YAML" in error.get("message"), ET.tostring(cases[0])
assert as_xml(bad) + ".yaml" in error.get("message"), error.get("message")
failure = cases[1].find("failure")
assert failure is not None and "no golden file" in failure.get("message"), ET.tostring(cases[1])
assert as_xml(good) + ".events.csv" in failure.get("message"), failure.get("message")
out = cases[1].find("system-out")
assert out is not None and "expectation failed: blinker_never" in out.text, ET.tostring(cases[1])
PY
echo "ok   JUnit XML with <, >, &, quotes and control characters in names is well-formed and reads back"
