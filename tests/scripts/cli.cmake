# Tests of the flotsam command line: exit codes and messages (label cli).
set(cli_work ${CMAKE_CURRENT_BINARY_DIR}/cli_work)
file(MAKE_DIRECTORY ${cli_work})

function(flotsam_cli_test name exit regex)
  add_test(NAME cli.${name}
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:flotsam>;${ARGN}"
                   -DEXPECT_EXIT=${exit} "-DEXPECT_REGEX=${regex}" -DWORKDIR=${cli_work}
                   -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
  set_tests_properties(cli.${name} PROPERTIES LABELS "cli" ENVIRONMENT "${test_environment}")
endfunction()

set(examples ${PROJECT_SOURCE_DIR}/examples)
flotsam_cli_test(version 0 "flotsam ${PROJECT_VERSION}" --version)
flotsam_cli_test(help_lists_commands 0 "mesh.*info" --help)
flotsam_cli_test(no_command_is_an_error nonzero "A subcommand is required")
flotsam_cli_test(info_missing_file nonzero "no_such.msh" info no_such.msh)
flotsam_cli_test(mesh_paper_channel 0 "wrote bridge.msh"
                 mesh ${examples}/bridge_piers.yaml -o bridge.msh --vtu bridge.vtu --overwrite)
flotsam_cli_test(info_paper_channel 0 "pier_1" info bridge.msh)
set_tests_properties(cli.mesh_paper_channel PROPERTIES FIXTURES_SETUP cli_mesh)
set_tests_properties(cli.info_paper_channel PROPERTIES FIXTURES_REQUIRED cli_mesh)
# The cells in four parts for four ranks (flow/fv/partition.hpp): the report's four lines.
flotsam_cli_test(info_parts 0
                 "parts +4 .METIS.*\n  cells +[0-9]+ / [0-9]+ / [0-9]+\n  halo cells +[0-9]+ / [0-9]+ / [0-9]+ .*\n  neighbours +[1-3] / [0-9]+ / [1-3] .*\n  cut edges +[0-9]+; imbalance 1.0[0-3]"
                 info bridge.msh --parts 4)
set_tests_properties(cli.info_parts PROPERTIES FIXTURES_REQUIRED cli_mesh)
# The same parts written for ParaView (--parts-vtu): VTK reads a cell array 'part' of 0 .. 3
# whose smallest and largest part are the report's (check_parts_vtu.py).
add_test(NAME cli.info_parts_vtu
         COMMAND bash -c "\"$0\" info bridge.msh --parts 4 --parts-vtu parts.vtu --overwrite > parts.txt && \"$1\" \"$2\" parts.vtu 4 parts.txt"
                 $<TARGET_FILE:flotsam> ${FLOTSAM_VTK_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_parts_vtu.py
         WORKING_DIRECTORY ${cli_work})
set_tests_properties(cli.info_parts_vtu PROPERTIES LABELS "cli" FIXTURES_REQUIRED cli_mesh
                     ENVIRONMENT "${test_environment}")
# A finite-volume case's time levels: `auto` takes three on bridge_blocking.yaml's mesh, 4 m
# cells graded to 0.5 m at the piers (the choice itself: TimeLevels unit tests).
flotsam_cli_test(info_time_levels_auto 0
                 "time levels +3 .auto. .[0-9.]+x fewer cell updates with 3 than with one"
                 info ${examples}/bridge_blocking.yaml)
flotsam_cli_test(mesh_refuses_to_overwrite nonzero "bridge.msh' exists; pass --overwrite"
                 mesh ${examples}/bridge_piers.yaml -o bridge.msh)
set_tests_properties(cli.mesh_refuses_to_overwrite PROPERTIES FIXTURES_REQUIRED cli_mesh)

# Where messages go (issue 40 item 4): the log on standard error, the summary on standard
# output, and both (debug included) appended to --log's file; exit codes 1 for bad input, CLI11's
# (105: a missing file) for a command line it refuses.
file(REMOVE ${cli_work}/overlap.log)
add_test(NAME cli.run_log_on_stderr_summary_on_stdout
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:flotsam>;run;${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_overlapping_logs.yaml;-o;overlap_run;--overwrite;-q;--log;overlap.log"
                 -DEXPECT_EXIT=0 "-DEXPECT_REGEX=simulated +4.0 s" "-DSTDERR_REGEX=warning.*overlap by"
                 "-DSTDOUT_EXCLUDES=overlap by|warning" -DFILE=overlap.log
                 "-DFILE_REGEX=flotsam [0-9.]+ starts.*\\[warning\\] bodies 0 and 1 overlap.*simulated +4.0 s.*results in"
                 -DWORKDIR=${cli_work} -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
set_tests_properties(cli.run_log_on_stderr_summary_on_stdout PROPERTIES LABELS "cli"
                     ENVIRONMENT "${test_environment}")
flotsam_cli_test(bad_input_exits_1 1 "error: .*tiny_missing_mesh.yaml"
                 run ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_missing_mesh.yaml -o missing_mesh_run)
flotsam_cli_test(missing_file_exits_105 105 "File does not exist" info no_such.msh)

# A tiny two-way run, then its pictures at a requested size (issue 6: render test).
flotsam_cli_test(run_tiny_case 0 "bodies: 2 released"
                 run ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml -o tiny_run --overwrite -q)
set_tests_properties(cli.run_tiny_case PROPERTIES FIXTURES_SETUP cli_tiny_run)
flotsam_cli_test(run_refuses_existing_folder nonzero "exists and is not empty"
                 run ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml -o tiny_run -q)
set_tests_properties(cli.run_refuses_existing_folder PROPERTIES FIXTURES_REQUIRED cli_tiny_run)
flotsam_cli_test(render_tiny_run 0 "wrote tiny_run/bodies.png"
                 render tiny_run --width 640 --height 320)
set_tests_properties(cli.render_tiny_run PROPERTIES FIXTURES_REQUIRED cli_tiny_run
                     FIXTURES_SETUP cli_tiny_pictures)
foreach(picture water_surface velocity bodies frames/frame_000002)
  string(REPLACE "/" "_" test_name ${picture})
  add_test(NAME cli.png_${test_name}
           COMMAND ${FLOTSAM_VTK_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_png.py
                   ${cli_work}/tiny_run/${picture}.png 640 320)
  set_tests_properties(cli.png_${test_name} PROPERTIES FIXTURES_REQUIRED cli_tiny_pictures
                       FIXTURES_SETUP cli_tiny_checked LABELS "cli")
endforeach()
flotsam_cli_test(render_not_a_run nonzero "is not a flotsam run folder" render .)

# Stop at t = 2 s, then continue to 4 s from the checkpoint (issue 6: --restart).
flotsam_cli_test(run_tiny_first_half 0 "simulated +2.0 s"
                 run ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml -o tiny_restart --end 2
                 --overwrite -q)
set_tests_properties(cli.run_tiny_first_half PROPERTIES FIXTURES_SETUP cli_tiny_half)
flotsam_cli_test(run_tiny_restart 0 "simulated +4.0 s"
                 run ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml -o tiny_restart --restart -q)
set_tests_properties(cli.run_tiny_restart PROPERTIES FIXTURES_REQUIRED cli_tiny_half)

# With ffmpeg on the machine (not a dependency: `flotsam render` uses it when present), the
# frames also become a movie.
find_program(FLOTSAM_FFMPEG ffmpeg)
if(FLOTSAM_FFMPEG)
  flotsam_cli_test(render_tiny_movie 0 "wrote tiny_run/movie.mp4"
                   render tiny_run --width 320 --height 160)
  # after the picture checks: it draws the same pictures again, at another size
  set_tests_properties(cli.render_tiny_movie PROPERTIES FIXTURES_REQUIRED
                       "cli_tiny_pictures;cli_tiny_checked")
endif()

# A restart checks the case against the checkpoint's (issue 20 item 1): an edited viscosity is
# refused, naming the key with its two values.
file(READ ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml tiny_text)
string(REPLACE "viscosity: 0.05" "viscosity: 0.06" tiny_text "${tiny_text}")
file(WRITE ${cli_work}/tiny_case_edited.yaml "${tiny_text}")
flotsam_cli_test(restart_refuses_an_edited_case nonzero "flow.viscosity: 0.05 then, 0.06 now"
                 run tiny_case_edited.yaml -o tiny_restart --restart -q)
set_tests_properties(cli.restart_refuses_an_edited_case PROPERTIES FIXTURES_REQUIRED cli_tiny_half)
flotsam_cli_test(run_refuses_end_nan nonzero "expected a finite time > 0"
                 run ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml -o tiny_nan --end nan -q)

# A checkpoint is a function of the state alone (issue 20 item 3): valgrind finds no
# uninitialised byte written by a run with a checkpoint.
find_program(FLOTSAM_VALGRIND valgrind)
if(FLOTSAM_VALGRIND)
  add_test(NAME cli.checkpoint_has_no_uninitialised_bytes
           COMMAND ${FLOTSAM_VALGRIND} -q --error-exitcode=3 $<TARGET_FILE:flotsam> run
                   ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml -o tiny_valgrind --end 1
                   --overwrite -q
           WORKING_DIRECTORY ${cli_work})
  set_tests_properties(cli.checkpoint_has_no_uninitialised_bytes PROPERTIES LABELS "cli"
                       ENVIRONMENT "${test_environment}")
endif()

# A large run is announced before it starts (issue 20 item 4), its elements counted in the mesh
# file it reads (the paper's channel: 4,468 triangles); the restart then stops it (no checkpoint).
file(WRITE ${cli_work}/large_run.yaml "name: large
mesh: {file: bridge.msh}
flow:
  initial: {eta: 4}
  boundaries:
    inflow: {type: elevation, value: 4}
    outflow: {type: elevation, value: 4}
    bank_right: {type: wall}
    bank_left: {type: wall}
    pier_1: {type: wall}
    pier_2: {type: wall}
    pier_3: {type: wall}
    pier_4: {type: wall}
time: {end: 2000000, step: 1}
output: {interval: 1000}
")
flotsam_cli_test(run_announces_a_large_run nonzero
                 "flotsam: a large run: 4468 elements, 2e\\+06 steps, 2001 outputs"
                 run large_run.yaml -o large_run_no_checkpoint --restart -q)
set_tests_properties(cli.run_announces_a_large_run PROPERTIES FIXTURES_REQUIRED cli_mesh)

# Bodies placed on top of each other are named in a warning (issue 20 item 6).
file(READ ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml overlap_text)
string(REPLACE "x: 110, y: 40" "x: 101, y: 20" overlap_text "${overlap_text}")
file(WRITE ${cli_work}/tiny_overlap.yaml "${overlap_text}")
flotsam_cli_test(run_names_overlapping_bodies 0 "bodies 0 and 1 overlap by [0-9.]+ m where"
                 run tiny_overlap.yaml -o tiny_overlap --end 1 --overwrite -q)

# `make demo` builds only the program it runs, not the test programs (issue 20 item 8): the one
# `cmake --build` of its recipe names the target flotsam.
add_test(NAME make.demo_builds_only_the_program
         COMMAND bash -c "recipe=$(make -n -C ${PROJECT_SOURCE_DIR} demo BUILD=${CMAKE_BINARY_DIR}); \
                          builds=$(grep -c 'cmake --build' <<< \"$recipe\"); \
                          flotsam=$(grep -cE -- '--target flotsam( |$)' <<< \"$recipe\"); \
                          echo \"cmake --build steps: $builds, of the target flotsam: $flotsam\"; \
                          [ $builds = 1 ] && [ $flotsam = 1 ]")
set_tests_properties(make.demo_builds_only_the_program PROPERTIES LABELS "cli")

# A long table (issue 39 item 10): 200,000 rows inline make a 3.2 MB case that would take about
# 380 MB to read, refused under a 600 MB address-space limit before it is read, naming the file
# and the way out; the same rows from a CSV file run within that limit (on one thread: on two,
# OpenBLAS retries its 128 MB buffer forever under such a limit, a hang left for issue 39).
add_test(NAME cli.long_table_inputs
         COMMAND ${FLOTSAM_VTK_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/write_long_table_case.py
                 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_case.yaml ${cli_work}/long_table 200000)
set_tests_properties(cli.long_table_inputs PROPERTIES LABELS "cli" FIXTURES_SETUP cli_long_table)
add_test(NAME cli.long_inline_table_is_refused_before_reading
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=sh;-c;ulimit -v 600000 && exec $<TARGET_FILE:flotsam> info long_table.yaml"
                 -DEXPECT_EXIT=1
                 "-DEXPECT_REGEX=long_table.yaml: too large to read: a file of 3.18 MB takes about 381 MB of memory to read \\(YAML\\), and this process may use 614 MB; give long tables as CSV files"
                 -DWORKDIR=${cli_work}/long_table -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
add_test(NAME cli.long_table_from_a_file_runs
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=sh;-c;ulimit -v 600000 && exec $<TARGET_FILE:flotsam> run long_table_file.yaml -o run --overwrite -q"
                 -DEXPECT_EXIT=0 "-DEXPECT_REGEX=simulated +4.0 s"
                 -DWORKDIR=${cli_work}/long_table -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
set_tests_properties(cli.long_inline_table_is_refused_before_reading
                     cli.long_table_from_a_file_runs PROPERTIES LABELS "cli" TIMEOUT 60
                     FIXTURES_REQUIRED cli_long_table
                     ENVIRONMENT "${test_environment};OMP_NUM_THREADS=1")
# An ensemble's members run on one rank each; more is refused, naming what splits over ranks.
flotsam_cli_test(ensemble_refuses_ranks_per_member nonzero
                 "each member runs on one rank .got 2.*mpirun -n N flotsam run"
                 ensemble ${examples}/bridge_blocking.yaml --ranks-per-member 2 -o no_members)
