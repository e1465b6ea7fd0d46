#!/usr/bin/env bash
# Runs on a shared machine (docs/performance.md "Shared machines"): examples/bridge_piers.yaml,
# 600 s, with the FEM engine and with `engine: fv` (BUILD_DIR/bench_runs/bridge_piers_fv.yaml,
# written by make bench),
#   * beside a busy core (`yes`, started here): 1 thread (--fixed-threads) against 2 threads as
#     `flotsam run` chooses, alternated ROUNDS times; and 2 threads fixed once;
#   * alone, then two runs started together: the time of each, as chosen and fixed.
# usage: bench/shared_machine.sh BUILD_DIR [ROUNDS]
set -euo pipefail
build=$1
rounds=${2:-3}
work=$build/bench_runs/shared
mkdir -p "$work"
declare -A case_file=([fem]=examples/bridge_piers.yaml [fv]=$build/bench_runs/bridge_piers_fv.yaml)
run() {  # label, threads, engine, output, flotsam options...
  local label=$1 threads=$2 engine=$3 out=$4
  shift 4
  OMP_NUM_THREADS=$threads /usr/bin/time -f "$engine $label: %e s" \
    "$build/flotsam" run "${case_file[$engine]}" -o "$work/$out" --end 600 --overwrite -q "$@" \
    2>&1 | grep -E "^$engine "
}
yes > /dev/null &
busy=$!
trap 'kill $busy 2>/dev/null || true' EXIT
sleep 1
for engine in fem fv; do run "busy core, 2 threads fixed" 2 $engine $engine --fixed-threads; done
for r in $(seq "$rounds"); do
  for engine in fem fv; do
    run "busy core, 1 thread" 1 $engine $engine --fixed-threads
    run "busy core, 2 threads chosen" 2 $engine $engine
  done
done
kill $busy
sleep 1
for engine in fem fv; do
  run "alone, chosen" 2 $engine $engine
  run "alone, fixed" 2 $engine $engine --fixed-threads
  for mode in chosen fixed; do
    option=$([ $mode = fixed ] && echo --fixed-threads || true)
    run "one of two together, $mode" 2 $engine ${engine}_a $option &
    run "one of two together, $mode" 2 $engine ${engine}_b $option &
    wait
  done
done
