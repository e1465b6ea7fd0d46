# `flotsam ensemble` (label cli): determinism over --jobs and MPI ranks, resume, a failing member,
# the shared flow
# (tests/scripts/ensemble_check.sh says what each checks).
set(ensemble_work ${CMAKE_CURRENT_BINARY_DIR}/ensemble_work)
set(ensemble_modes reference jobs2 resume failing_member shared_flow discharge_varies member_restart
                   killed)
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
