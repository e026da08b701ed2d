#!/usr/bin/env bash
# The same study on one thread and on two MPI ranks: identical rows apart from the timing column.
#   mpi_two_ranks.sh MPIEXEC COSSERAT_BINARY STUDY.json WORK_DIR
set -euo pipefail
MPIEXEC=$1 BIN=$2 STUDY=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK"
"$BIN" sweep "$STUDY" --out "$WORK/one.csv" --threads 1 2>/dev/null
# --allow-run-as-root: CI runs as root; --oversubscribe: two ranks may share fewer cores.
"$MPIEXEC" --allow-run-as-root --oversubscribe -np 2 "$BIN" sweep "$STUDY" --out "$WORK/ranks.csv" \
  2> "$WORK/ranks.log"
grep -q "on 2 MPI ranks" "$WORK/ranks.log" || { cat "$WORK/ranks.log"; echo "not run on 2 ranks"; exit 1; }
# A study file with a mistake: its error once, not once per rank, and exit 2.
sed '0,/{/s//{"nosuch_key": 1, /' "$STUDY" > "$WORK/bad.json"
code=0
"$MPIEXEC" --allow-run-as-root --oversubscribe -np 2 "$BIN" sweep "$WORK/bad.json" \
  --out "$WORK/bad.csv" 2> "$WORK/bad.log" || code=$?
[ "$(grep -c "nosuch_key" "$WORK/bad.log")" = 1 ] && [ "$code" = 2 ] ||
  { cat "$WORK/bad.log"; echo "a bad study: exit $code, its error not printed once"; exit 1; }
# srun's tasks that no MPI environment joins would each run the whole study: refused, exit 2.
code=0
SLURM_NTASKS=2 SLURM_STEP_ID=0 SLURM_PROCID=1 "$BIN" sweep "$STUDY" --out "$WORK/slurm.csv" \
  2> "$WORK/slurm.log" || code=$?
[ "$code" = 2 ] && grep -q "no MPI environment joins the tasks" "$WORK/slurm.log" ||
  { cat "$WORK/slurm.log"; echo "unjoined srun tasks: exit $code, not refused"; exit 1; }
# srun --mpi=pmix exports PMIX_RANK but no size: such a task is joined, not refused (here a step
# of one task, which runs the study alone).
SLURM_NTASKS=2 SLURM_STEP_NUM_TASKS=1 SLURM_STEP_ID=0 SLURM_PROCID=0 PMIX_RANK=0 "$BIN" sweep \
  "$STUDY" --out "$WORK/pmix.csv" 2> "$WORK/pmix.log" ||
  { cat "$WORK/pmix.log"; echo "a PMIx task was refused"; exit 1; }
strip() { sed 's/,[^,]*$//' "$1"; }  # drop the last column, wall_time_s
if diff <(strip "$WORK/one.csv") <(strip "$WORK/ranks.csv") > "$WORK/diff.txt"; then
  echo "2 MPI ranks: $(($(wc -l < "$WORK/ranks.csv") - 1)) rows, identical to one thread's"
else
  head "$WORK/diff.txt"; echo "rows differ"; exit 1
fi
