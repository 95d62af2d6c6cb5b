#!/bin/sh
# A JSON-lines decider for the fault tests (tests/integration/sut_exec_faults.sh): answers "none" to
# every step and misbehaves at step number AT (default 3, t = 0.30 s at a 0.1 s step) as MODE says.
# usage: sh reply.sh MODE [AT]
mode=$1
at=${2:-3}
n=0
while IFS= read -r line; do
  case $line in
    '{"type":"hello"'*) continue ;;
    '{"type":"bye"'*) exit 0 ;;
  esac
  n=$((n + 1))
  if [ "$mode" = stderr ]; then echo "step $n seen" >&2; fi
  if [ "$n" -eq "$at" ]; then
    case $mode in
      not_json) echo 'this is not json'; continue ;;
      no_blinker) echo '{"blinkers": "left"}'; continue ;;
      bad_blinker) echo '{"blinker": "up"}'; continue ;;
      two_lines) printf '{"blinker": "none"}\n{"blinker": "left"}\n'; continue ;;
      exit) exit 3 ;;
      segv) kill -SEGV $$ ;;
      silent) sleep 60; continue ;;
    esac
  fi
  echo '{"blinker": "none"}'
done
