#!/bin/bash
# Checks of `flotsam ensemble` on tests/scripts/tiny_ensemble.yaml (registered by ensemble.cmake):
#   reference        --jobs 1: the reference ensemble
#   jobs2            --jobs 2 gives the same summary and tables, byte for byte
#   mpirun2          mpirun -n 2 gives the same summary and tables, byte for byte
#   resume           an interrupted ensemble (two members without their member.txt, one of them
#                    half-written) resumes: the complete members are kept, the others rerun, and
#                    the summary is the reference's
#   failing_member   a member whose drawn input is refused is reported with its inputs, and the
#                    other members complete
set -euo pipefail
mode=$1 flotsam=$2 case=$3 work=$4
mkdir -p "$work" && cd "$work"
same() {  # the files that must not depend on jobs, ranks or resuming
  for f in ensemble_summary.txt ensemble_members.csv ensemble_blocking.csv ensemble_bodies.csv; do
    cmp "reference/$f" "$1/$f" || { echo "FAIL: $1/$f differs from the reference"; exit 1; }
  done
  echo "same as the reference: $1"
}
case $mode in
  reference)
    "$flotsam" ensemble "$case" -o reference --overwrite -q --no-pictures
    grep -q "blocked bridge_1" reference/ensemble_summary.txt ;;
  jobs2)
    "$flotsam" ensemble "$case" -o jobs2 --overwrite -q --jobs 2 --no-pictures >/dev/null
    same jobs2 ;;
  mpirun2)
    root=(); [ "$(id -u)" = 0 ] && root=(--allow-run-as-root)
    mpirun "${root[@]}" --oversubscribe -n 2 "$flotsam" ensemble "$case" -o mpi2 --overwrite -q \
        --no-pictures >/dev/null
    same mpi2 ;;
  resume)
    rm -rf resume && cp -r reference resume
    sed -i "s|$work/reference|$work/resume|g" resume/member_*.yaml
    rm resume/member_0001/member.txt resume/member_0002/member.txt
    rm resume/member_0002/*.vtu                      # half-written
    touch -d '2000-01-01' resume/member_0000/member.txt
    out=$("$flotsam" ensemble "$case" -o resume -q --no-pictures)
    echo "$out" | grep -q "ran 2 members, kept 2" || { echo "FAIL: $out"; exit 1; }
    [ "$(stat -c %Y resume/member_0000/member.txt)" = "$(date -d 2000-01-01 +%s)" ] \
        || { echo "FAIL: a complete member was run again"; exit 1; }
    same resume ;;
  failing_member)
    # log length 0.3 m < width 0.5 m at the first sweep value: those members are refused.
    sed 's/values: \[4, 20\]/values: [0.3, 20]/' "$case" > failing.yaml
    out=$("$flotsam" ensemble failing.yaml -o failing --overwrite -q --no-pictures)
    echo "$out"
    echo "$out" | grep -q "4 members (2 per value x 2 values), 2 failed"
    echo "$out" | grep -q "member_0000 (log_length = 0.3 m, .*seed [0-9]*): .*exceed the shortest"
    echo "$out" | grep -q "log_length = 20 m: 2 members, 0 failed" ;;
esac
