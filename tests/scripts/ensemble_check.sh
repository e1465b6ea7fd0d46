#!/bin/bash
# Checks of `flotsam ensemble` on tests/scripts/tiny_ensemble.yaml (registered by ensemble.cmake):
#   reference        --jobs 1: the reference ensemble
#   jobs2            --jobs 2 gives the same summary and tables, byte for byte
#   mpirun2          mpirun -n 2 gives the same summary and tables, byte for byte, and rank 0's
#                    progress line counts the members of every rank
#   resume           an interrupted ensemble (two members without their member.txt, one of them
#                    half-written) resumes: the complete members are kept, the others rerun, and
#                    the summary is the reference's
#   failing_member   a member whose drawn input is refused is reported with its inputs, and the
#                    other members complete
#   shared_flow      in one-way mode the members replay one flow computed once: the summary,
#                    tables and every member's body tracks are those of members that compute
#                    their own flow (--no-shared-flow), byte for byte; the flow's file is removed;
#                    the flow fields and folder markers are links to one copy; a member rerun
#                    with `flotsam run` writes the same fields, tracks and .pvd indexes
#   discharge_varies an ensemble varying discharge_scale does not share its flow
#   member_restart   a member's folder continues with `flotsam run --restart --end` from the
#                    checkpoint of its end, as a run of the longer time from the start writes it
#   killed           an ensemble replaying a shared flow, killed (SIGKILL) once its first member
#                    is complete, resumes to the summary and tables of an uninterrupted one: the
#                    complete members kept, the others (one half-written) run again, each
#                    member's .pvd index listing the fields it wrote (skipped, code 77, when the
#                    kill came after the last member)
#   input_changed    an ensemble whose mesh file (an input the case reads) changed is not
#                    resumed: the run is refused, naming the changed input, and nothing in the
#                    folder changes
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
    mpirun "${root[@]}" --oversubscribe -n 2 "$flotsam" ensemble "$case" -o mpi2 --overwrite \
        --no-pictures >/dev/null 2>progress.txt
    same mpi2
    # Rank 0's progress line counts the members of both ranks (2 each).
    tail -1 progress.txt | grep -q "members 4/4 done" || { cat progress.txt; exit 1; } ;;
  resume)
    rm -rf resume && cp -r reference resume
    sed -i "s|$work/reference|$work/resume|g" resume/member_*.yaml
    rm resume/member_0001/member.txt resume/member_0002/member.txt
    rm resume/member_0002/*.vtu                      # half-written
    touch -d '2000-01-01' resume/member_0000/member.txt
    out=$("$flotsam" ensemble "$case" -o resume -q --no-pictures)
    grep -q "ran 2 members, kept 2" <<<"$out" || { echo "FAIL: $out"; exit 1; }
    [ "$(stat -c %Y resume/member_0000/member.txt)" = "$(date -d 2000-01-01 +%s)" ] \
        || { echo "FAIL: a complete member was run again"; exit 1; }
    same resume ;;
  failing_member)
    # log length 0.3 m < width 0.5 m at the first sweep value: those members are refused.
    sed 's/values: \[4, 20\]/values: [0.3, 20]/' "$case" > failing.yaml
    out=$("$flotsam" ensemble failing.yaml -o failing --overwrite -q --no-pictures)
    echo "$out"
    grep -q "4 members (2 per value x 2 values), 2 failed" <<<"$out"
    grep -q "member_0000 (log_length = 0.3 m, .*seed [0-9]*): .*exceed the shortest" <<<"$out"
    grep -q "log_length = 20 m: 2 members, 0 failed" <<<"$out"
    # the value whose members all failed gives no estimate (and no NaN)
    grep -q "blocked bridge_1 *0/0 *no member completed" <<<"$out"
    ! grep -qiw "nan" <<<"$out" || { echo "FAIL: a NaN in the summary"; exit 1; } ;;
  shared_flow)
    sed 's/mode: two-way/mode: one-way/' "$case" > one_way.yaml
    out=$("$flotsam" ensemble one_way.yaml -o shared --overwrite -q --no-pictures)
    grep -q "flow             computed once and shared by the members (one-way" <<<"$out" \
        || { echo "FAIL: $out"; exit 1; }
    out=$("$flotsam" ensemble one_way.yaml -o own --overwrite -q --no-pictures --no-shared-flow)
    grep -q "flow             computed by each member (--no-shared-flow)" <<<"$out" \
        || { echo "FAIL: $out"; exit 1; }
    for f in ensemble_summary.txt ensemble_members.csv ensemble_blocking.csv ensemble_bodies.csv \
        member_000{0,1,2,3}/member_000{0,1,2,3}_bodies.csv; do
      [ -e "own/$f" ] || continue
      cmp "own/$f" "shared/$f" || { echo "FAIL: shared/$f differs from own/$f"; exit 1; }
    done
    [ "$(ls own/member_000*/member_000*_bodies.csv | wc -l)" = 4 ] || { echo "FAIL: tracks"; exit 1; }
    ! ls shared/ensemble_flow_* 2>/dev/null || { echo "FAIL: the shared flow was left"; exit 1; }
    # The members' flow fields are one file linked into each (4 members: 4 names), and a member
    # rerun alone with `flotsam run` (computing its own flow) writes the same bytes.
    [ "$(stat -c %h shared/member_0001/flow_000001.vtu)" = 4 ] \
        || { echo "FAIL: the flow fields are not linked"; exit 1; }
    [ "$(stat -c %h shared/member_0001/.flotsam-output)" = 4 ] \
        || { echo "FAIL: the folders' markers are not linked"; exit 1; }
    "$flotsam" run shared/member_0001.yaml -o rerun --overwrite -q >/dev/null
    for f in flow_000000.vtu flow_000001.vtu flow_000002.vtu boundary.vtp member_0001_bodies.csv \
        member_0001.pvd member_0001_bodies.pvd; do
      cmp "rerun/$f" "shared/member_0001/$f" || { echo "FAIL: rerun/$f differs"; exit 1; }
    done
    echo "shared flow: same summary, tables and tracks; linked fields, as a rerun writes them" ;;
  member_restart)
    rm -rf restart longer && cp -r reference/member_0001 restart
    "$flotsam" run reference/member_0001.yaml -o restart --restart --end 18 -q >/dev/null
    "$flotsam" run reference/member_0001.yaml -o longer --overwrite --end 18 -q >/dev/null
    grep -q 'timestep="18"' restart/member_0001.pvd || { echo "FAIL: no output at 18 s"; exit 1; }
    for f in member_0001.pvd member_0001_bodies.pvd member_0001_bodies.csv member_0001_jams.csv \
        flow_000003.vtu bodies_000003.vtp; do
      cmp "longer/$f" "restart/$f" || { echo "FAIL: restart/$f differs"; exit 1; }
    done
    echo "a member continued from its checkpoint writes what the longer run writes" ;;
  killed)
    # 10 members per value (20): the kill lands among them
    sed -e 's/mode: two-way/mode: one-way/' -e 's/  members: 2$/  members: 10/' "$case" > killed.yaml
    grep -q "members: 10" killed.yaml
    rm -rf whole killed
    "$flotsam" ensemble killed.yaml -o whole -q --no-pictures >/dev/null
    "$flotsam" ensemble killed.yaml -o killed -q --no-pictures >/dev/null 2>&1 &
    pid=$!
    for _ in $(seq 3000); do [ -e killed/member_0000/member.txt ] && break; sleep 0.01; done
    kill -9 "$pid" 2>/dev/null || true
    wait "$pid" || true
    complete=$(ls killed/member_*/member.txt 2>/dev/null | wc -l)
    [ "$complete" -lt 20 ] || { echo "the kill came after the last member"; exit 77; }
    out=$("$flotsam" ensemble killed.yaml -o killed -q --no-pictures)
    grep -q "ran $((20 - complete)) members, kept $complete" <<<"$out" \
        || { echo "FAIL: $out"; exit 1; }
    for f in ensemble_summary.txt ensemble_members.csv ensemble_blocking.csv ensemble_bodies.csv; do
      # (a failed member's message names its case file, in its own folder)
      cmp "whole/$f" <(sed "s|$work/killed/|$work/whole/|g" "killed/$f") \
          || { echo "FAIL: killed/$f differs after resuming"; exit 1; }
    done
    for m in killed/member_00??; do
      m=$(basename "$m")
      cmp "whole/$m/${m}_bodies.csv" "killed/$m/${m}_bodies.csv" \
          || { echo "FAIL: $m's tracks differ"; exit 1; }
      # its index lists every flow field it wrote (a failed member's too, up to its failure)
      [ "$(grep -c '<DataSet' "killed/$m/$m.pvd")" = "$(ls killed/$m/flow_*.vtu | wc -l)" ] \
          || { echo "FAIL: $m's index"; exit 1; }
      grep -q "status failed" "killed/$m/member.txt" || grep -q 'timestep="12"' "killed/$m/$m.pvd" \
          || { echo "FAIL: $m's index ends before 12 s"; exit 1; }
    done
    echo "killed with $complete of 20 members complete; resumed to the same summary" ;;
  input_changed)
    rm -rf inputs && mkdir inputs
    "$flotsam" mesh "$case" -o inputs/river.msh >/dev/null
    awk '/^mesh:/ {print "mesh:\n  file: river.msh"; skip = 1; next}
         /^[a-z]/ {skip = 0} !skip' "$case" > inputs/case.yaml
    grep -q "file: river.msh" inputs/case.yaml
    "$flotsam" ensemble inputs/case.yaml -o inputs/out --overwrite -q --no-pictures >/dev/null
    before=$(cd inputs/out && find . -type f -printf '%p %s %T@\n' | sort | md5sum)
    sed 's/mesh_size: 12/mesh_size: 11/' "$case" > inputs/finer.yaml
    "$flotsam" mesh inputs/finer.yaml -o inputs/river.msh --overwrite >/dev/null
    if out=$("$flotsam" ensemble inputs/case.yaml -o inputs/out -q --no-pictures 2>&1); then
      echo "FAIL: resumed after its mesh file changed: $out"; exit 1
    fi
    grep -q "holds an ensemble of another case, member count or input files (changed: input mesh.file)" <<<"$out" \
        || { echo "FAIL: $out"; exit 1; }
    after=$(cd inputs/out && find . -type f -printf '%p %s %T@\n' | sort | md5sum)
    [ "$before" = "$after" ] || { echo "FAIL: the folder changed"; exit 1; }
    echo "refused: $out" ;;
  discharge_varies)
    sed -e 's/mode: two-way/mode: one-way/' \
        -e 's/inflow: {type: elevation, value: 4.0}/inflow: {type: discharge, value: 240}/' \
        -e 's/restitution: {uniform: \[0.2, 0.8\]}/discharge_scale: {uniform: [0.8, 1.2]}/' \
        "$case" > discharge.yaml
    grep -q "discharge_scale" discharge.yaml
    out=$("$flotsam" ensemble discharge.yaml -o discharge --overwrite -q --no-pictures)
    grep -q "flow             computed by each member (discharge_scale varies the flow)" <<<"$out" \
        || { echo "FAIL: $out"; exit 1; } ;;
esac
