#!/usr/bin/env bash
# `batch --backend slurm` when no Slurm controller answers at the configured address (a slurm.conf of
# the test's own, naming a port on 127.0.0.1 where nothing listens): one line saying so, with
# scontrol's reason, exit 2, nothing written to --out. sbatch alone would retry the controller for
# about 18 s and then blame the submission. Skips (exit 77) without the Slurm client programs.
# usage: slurm_no_controller.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
for program in sbatch squeue scancel scontrol; do
  command -v "$program" >/dev/null || { echo "skipped: $program is not on PATH (tools/setup --slurm)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
cat >"$work/slurm.conf" <<CONF
ClusterName=nobody
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
AuthType=auth/munge
NodeName=localhost CPUs=1 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES State=UP
CONF
export SLURM_CONF=$work/slurm.conf

"$bin" batch "$src/scenarios/intersection_left.yaml" --backend slurm --out "$work/out" >"$work/stdout" 2>"$work/stderr"
code=$?
[ $code -eq 2 ] || fail "exit code $code, want 2: $(cat "$work/stderr")"
[ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "not one line: $(cat "$work/stderr")"
grep -q "^signalsim: --backend slurm: no Slurm controller answers (scontrol ping: Slurmctld(primary) at .* is DOWN)$" \
  "$work/stderr" || fail "$(cat "$work/stderr")"
[ -e "$work/out" ] && fail "--out was created"
echo "ok   no controller: $(cat "$work/stderr")"
