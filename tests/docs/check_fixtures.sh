#!/usr/bin/env bash
# tools/check_docs on its fixtures: fixtures/good must pass (and stay unwritten: the commands run in
# a copy), fixtures/bad must fail with exactly the failures in fixtures/bad/expected_failures.txt
# (file:line: check), and a missing binary must fail the command check.
# Usage: check_fixtures.sh CHECK_DOCS SIGNALSIM
set -u
check_docs=$1
signalsim=$2
here=$(cd "$(dirname "$0")" && pwd)
status=0
fail() { echo "FAIL: $*"; status=1; }

listing() { (cd "$1" && find . -print | LC_ALL=C sort); }

# 1. The good fixture passes and is left as it was.
before=$(listing "$here/fixtures/good")
out=$(python3 "$check_docs" --root "$here/fixtures/good" --bin "$signalsim" 2>&1)
rc=$?
echo "$out"
[ "$rc" -eq 0 ] || fail "fixtures/good: exit $rc, expected 0"
echo "$out" | grep -q "2 command blocks run (2 passed)" || fail "fixtures/good: expected exactly 2 command blocks to run"
[ "$before" = "$(listing "$here/fixtures/good")" ] || fail "fixtures/good was written to (commands must run in a copy)"

# 2. The bad fixture fails with exactly the expected failures.
out=$(python3 "$check_docs" --root "$here/fixtures/bad" --bin "$signalsim" --timeout 3 2>&1)
rc=$?
echo "$out"
[ "$rc" -eq 1 ] || fail "fixtures/bad: exit $rc, expected 1"
got=$(echo "$out" | sed -nE 's/^([^ :]+:[0-9]+): (cites|commands|links): .*/\1: \2/p' | LC_ALL=C sort)
want=$(grep -v '^#' "$here/fixtures/bad/expected_failures.txt" | LC_ALL=C sort)
if [ "$got" != "$want" ]; then
  fail "fixtures/bad: the failures differ from expected_failures.txt"
  diff <(echo "$want") <(echo "$got") | sed 's/^/  /'
fi
echo "$out" | grep -q "README.md:7: commands: exit 1: false" || fail "fixtures/bad: the failing command is not named with its line"
echo "$out" | grep -A1 "^README.md:28: commands: exit 1: true" | grep -q "expected exit 1, got 0" || fail "fixtures/bad: a wrong expected exit code is not reported"
echo "$out" | grep -q "README.md:32: commands: wrote outside out/ (or /tmp): stray.txt" || fail "fixtures/bad: a write outside out/ is not reported"
echo "$out" | grep -q "timed out after 3 s" || fail "fixtures/bad: the timeout is not reported"

# 3. No binary: the command check fails instead of skipping.
out=$(python3 "$check_docs" --root "$here/fixtures/good" --bin /nonexistent/signalsim --check commands 2>&1)
rc=$?
[ "$rc" -eq 1 ] && echo "$out" | grep -q "no signalsim binary" || fail "a missing binary did not fail the command check: $out"

[ "$status" -eq 0 ] && echo "check_fixtures: all passed"
exit $status
