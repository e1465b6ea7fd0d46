# `flotsam ensemble` (label cli): determinism over --jobs and MPI ranks, resume, a failing member,
# the shared flow, a changed input file
# (tests/scripts/ensemble_check.sh says what each checks).
set(ensemble_work ${CMAKE_CURRENT_BINARY_DIR}/ensemble_work)
set(ensemble_modes reference jobs2 resume failing_member shared_flow discharge_varies member_restart
                   killed input_changed)
find_program(FLOTSAM_MPIRUN mpirun)
if(FLOTSAM_MPIRUN AND MPI_CXX_FOUND)
  list(APPEND ensemble_modes mpirun2)
endif()
foreach(mode ${ensemble_modes})
  add_test(NAME cli.ensemble_${mode}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/ensemble_check.sh ${mode}
                   $<TARGET_FILE:flotsam> ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_ensemble.yaml
                   ${ensemble_work})
  set_tests_properties(cli.ensemble_${mode} PROPERTIES LABELS "cli"
                       ENVIRONMENT "${test_environment}")
  if(mode MATCHES "^(jobs2|resume|mpirun2|member_restart)$")
    set_tests_properties(cli.ensemble_${mode} PROPERTIES FIXTURES_REQUIRED cli_ensemble_reference
                         RESOURCE_LOCK ensemble_work)
  endif()
endforeach()
set_tests_properties(cli.ensemble_reference PROPERTIES FIXTURES_SETUP cli_ensemble_reference)
set_tests_properties(cli.ensemble_killed PROPERTIES SKIP_RETURN_CODE 77)

# Blocking on a bridge of a mesh that is not the paper's channel (tiny_bridge_ensemble.yaml): two
# logs across the flow stop against a low deck in every member, so the bridge, by its name, and
# each of its two gaps block in 2 of 2 members per swept length (Wilson interval [0.342, 1]).
# Its folder is removed first, so that an edited case never meets an older ensemble's folder.
add_test(NAME cli.ensemble_bridge_clean COMMAND ${CMAKE_COMMAND} -E rm -rf
                                                ${CMAKE_CURRENT_BINARY_DIR}/ensemble_bridge)
set_tests_properties(cli.ensemble_bridge_clean PROPERTIES LABELS "cli"
                     FIXTURES_SETUP cli_ensemble_bridge)
add_test(NAME cli.ensemble_bridge_on_a_region_mesh
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:flotsam>;ensemble;${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_bridge_ensemble.yaml;-o;${CMAKE_CURRENT_BINARY_DIR}/ensemble_bridge;--jobs;2;--no-pictures"
                 -DEXPECT_EXIT=0
                 "-DEXPECT_REGEX=blocked footbridge +2/2 +p 1.000 +95% .0.342, 1.000.\n  blocked footbridge gap 1 +2/2 +p 1.000[^\n]*\n  blocked footbridge gap 2 +2/2 +p 1.000.*log_length = 20 m: 2 members, 0 failed\n  blocked footbridge +2/2"
                 -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
set_tests_properties(cli.ensemble_bridge_on_a_region_mesh PROPERTIES LABELS "cli"
                     ENVIRONMENT "${test_environment}" FIXTURES_REQUIRED cli_ensemble_bridge)

# One flood over MPI ranks (finite volumes): the same files bit for bit on 1-4 ranks and after a
# restart moved from 2 to 3 ranks (ranks_check.sh), with one time level (set: the valley's mesh
# takes three by `auto`) and with three (300 s: a cycle retried at half the step between 200 and
# 300 s); the FEM is refused on every rank with a message naming the engine, before anything is
# written.
if(FLOTSAM_MPIRUN AND MPI_CXX_FOUND)
  add_test(NAME cli.run_split_over_ranks_bit_for_bit
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/ranks_check.sh $<TARGET_FILE:flotsam>
                   ${PROJECT_SOURCE_DIR}/examples/dam_break_valley.yaml
                   ${CMAKE_CURRENT_BINARY_DIR}/ranks_work 1 120)
  set_tests_properties(cli.run_split_over_ranks_bit_for_bit PROPERTIES LABELS "cli"
                       ENVIRONMENT "${test_environment}" RUN_SERIAL TRUE)
  add_test(NAME cli.run_split_over_ranks_with_time_levels_bit_for_bit
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/ranks_check.sh $<TARGET_FILE:flotsam>
                   ${PROJECT_SOURCE_DIR}/examples/dam_break_valley.yaml
                   ${CMAKE_CURRENT_BINARY_DIR}/ranks_levels_work 3 300)
  set_tests_properties(cli.run_split_over_ranks_with_time_levels_bit_for_bit PROPERTIES
                       LABELS "cli" ENVIRONMENT "${test_environment}" RUN_SERIAL TRUE)
  # Rain with infiltration, with one time level and with three: each rank infiltrates its cells,
  # the volume summed in the cells' order on every rank (per sub-step; per cycle with levels).
  foreach(levels 1 3)
    add_test(NAME cli.run_split_over_ranks_with_infiltration_${levels}_levels_bit_for_bit
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/ranks_check.sh $<TARGET_FILE:flotsam>
                     ${PROJECT_SOURCE_DIR}/examples/dam_break_valley.yaml
                     ${CMAKE_CURRENT_BINARY_DIR}/ranks_rain_${levels}_work ${levels} 120
                     "  rain: {intensity: 60, infiltration: 20}")
    set_tests_properties(cli.run_split_over_ranks_with_infiltration_${levels}_levels_bit_for_bit
                         PROPERTIES LABELS "cli" ENVIRONMENT "${test_environment}" RUN_SERIAL TRUE)
  endforeach()
  add_test(NAME cli.run_fem_on_two_ranks_is_refused
           COMMAND bash -c
                   "rm -rf ranks2 && ! mpirun --oversubscribe -n 2 \"$0\" run \"$1\" -o ranks2 --end 2 -q >out.txt 2>&1 && grep -q 'flow.engine: fem does not split one flood over MPI ranks (2 were started)' out.txt && test ! -e ranks2 && mpirun -n 1 \"$0\" run \"$1\" -o ranks1 --end 2 -q --overwrite >/dev/null 2>&1 && test -f ranks1/checkpoint.bin || { cat out.txt; exit 1; }"
                   $<TARGET_FILE:flotsam> ${PROJECT_SOURCE_DIR}/examples/bridge_piers.yaml
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/cli_work)
  set_tests_properties(cli.run_fem_on_two_ranks_is_refused PROPERTIES LABELS "cli"
                       ENVIRONMENT "${test_environment};OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1")
endif()
