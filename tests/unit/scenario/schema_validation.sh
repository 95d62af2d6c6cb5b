#!/usr/bin/env bash
# `signalsim schema scenario|sweep` against the bundled files with a real JSON Schema validator
# (python3-jsonschema, python3-yaml; tools/setup installs them, else the test is skipped: exit 77):
# both schemas are valid draft-07, every bundled scenario and sweep validates, and an unknown key, a
# wrong type or an out-of-range value is refused by the schema as by the loader (schema_validation.py).
# usage: schema_validation.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
if ! python3 -c 'import jsonschema, yaml' 2>/dev/null; then
  echo "skipped: python3 has no jsonschema or yaml module (tools/setup installs python3-jsonschema, python3-yaml)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" schema scenario >"$work/scenario.schema.json" || { echo "FAIL signalsim schema scenario: exit $?"; exit 1; }
"$bin" schema sweep >"$work/sweep.schema.json" || { echo "FAIL signalsim schema sweep: exit $?"; exit 1; }
python3 "$(dirname "$0")/schema_validation.py" "$bin" "$src" "$work"
