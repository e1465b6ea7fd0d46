# The town-flood example (examples/town_flood; label slow, out of the default `make test`: it
# needs python3-gdal and python3-numpy). Its inputs are written by make_inputs.py into the build
# tree and the case copied next to them, then the first minute of its flood runs: the mesh from
# the GeoPackage in UTM coordinates, the terrain, the car zones and the gauges in the domain.
set(town_work ${CMAKE_CURRENT_BINARY_DIR}/town_flood_example)
set(town_example ${PROJECT_SOURCE_DIR}/examples/town_flood)
add_test(NAME example.town_flood_inputs
         COMMAND ${FLOTSAM_VTK_PYTHON} ${town_example}/make_inputs.py --out ${town_work}/data)
set_tests_properties(example.town_flood_inputs PROPERTIES FIXTURES_SETUP town_flood_data
                     LABELS "slow")
add_test(NAME example.town_flood_case
         COMMAND ${CMAKE_COMMAND} -E copy ${town_example}/town_flood.yaml ${town_work}/town_flood.yaml)
set_tests_properties(example.town_flood_case PROPERTIES FIXTURES_REQUIRED town_flood_data
                     FIXTURES_SETUP town_flood_case LABELS "slow")
add_test(NAME example.town_flood_first_minute
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:flotsam>;run;town_flood.yaml;-o;run;--end;60;--overwrite;-q"
                 -DEXPECT_EXIT=0 "-DEXPECT_REGEX=bodies: 41 released" -DWORKDIR=${town_work}
                 -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
set_tests_properties(example.town_flood_first_minute PROPERTIES FIXTURES_REQUIRED
                     "town_flood_data;town_flood_case" LABELS "slow" ENVIRONMENT "${test_environment}")
