#!/bin/bash
# One flood split over MPI ranks (issue 41; flow/fv/rank_split.hpp), checked bit for bit: a dam
# break down a dry valley with logs released into it (examples/dam_break_valley.yaml, 120 s:
# the front crosses the parts' edges, logs are carried across them and strand), run on one
# process and under `mpirun --oversubscribe -n 2, 3, 4` (one thread each): every file the runs
# write (fields, envelopes, bodies, tables, checkpoint, .pvd indexes) identical to the one-process
# run's, and the summary says the flood was split. Then a restart moved from 2 to 3 ranks: 0-60 s
# on 2, 60-120 s on 3, identical to the run that never stopped. With TIME_LEVELS, the case runs
# with flow.fv.time_levels: TIME_LEVELS added under its `engine: fv` (without, its own: `auto`),
# to END s (the restart moved at half of it).
# With FLOW (a line of YAML), it is added under `flow:` too (e.g. rain with infiltration).
# Usage: ranks_check.sh FLOTSAM CASE WORK [TIME_LEVELS [END [FLOW]]]
set -u
flotsam=$1 case=$2 work=$3 levels=${4:-} end=${5:-120} flow=${6:-}
half=$((end / 2))
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
if [ -n "$levels" ]; then
  sed "s/^  engine: fv\$/  engine: fv\n  fv: {time_levels: $levels}\n$flow/" "$case" > levels.yaml
  grep -q "time_levels: $levels" levels.yaml || { echo "$case: no '  engine: fv' line"; exit 1; }
  case=$work/levels.yaml
fi
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

same() {  # same files, byte for byte
  if ! diff <(cd "$1" && ls) <(cd "$2" && ls); then echo "$2: not the same files as $1"; exit 1; fi
  for f in $(cd "$1" && ls); do
    cmp -s "$1/$f" "$2/$f" || { echo "$2/$f differs from $1/$f"; exit 1; }
  done
  echo "$2: $(ls "$2" | wc -l) files identical to $1's"
}

"$flotsam" run "$case" --end $end -o one -q > one.txt 2>&1 || { cat one.txt; exit 1; }
# the retry's path is to be crossed (by the case as it is; with FLOW added it need not be)
if [ "${levels:-1}" -gt 1 ] && [ -z "$flow" ] && grep -q "(0 retried" one.txt; then
  echo "no cycle retried at half the step by $end s: choose an END that has one"; exit 1
fi
for n in 2 3 4; do
  mpirun --oversubscribe -n $n "$flotsam" run "$case" --end $end -o ranks$n -q > ranks$n.txt 2>&1 \
    || { cat ranks$n.txt; exit 1; }
  grep -q "^MPI ranks  *$n: rank 0 advanced" ranks$n.txt || { echo "not split"; cat ranks$n.txt; exit 1; }
  same one ranks$n
done
mpirun --oversubscribe -n 2 "$flotsam" run "$case" --end $half -o moved -q > moved.txt 2>&1 \
  || { cat moved.txt; exit 1; }
mpirun --oversubscribe -n 3 "$flotsam" run "$case" --end $end -o moved -q --restart >> moved.txt 2>&1 \
  || { cat moved.txt; exit 1; }
same one moved
