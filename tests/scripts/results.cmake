# Results for QGIS and Python (issue 40): a tiny flood study on geodata (tiny_geo_case.yaml) run
# once, then its UGRID NetCDF file read with xarray against the ParaView files of the same run,
# its debris GeoPackage read with GDAL, and (label qgis, `make test-qgis`: python3-qgis is a
# 620 MB install) both opened in QGIS itself.
set(results_work ${CMAKE_CURRENT_BINARY_DIR}/results_work)
file(MAKE_DIRECTORY ${results_work})
set(results_run ${results_work}/tiny_geo)
set(tiny_geo_origin "2024-06-01 06:30:00")

add_test(NAME results.run_tiny_geo_case
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:flotsam>;run;${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_geo_case.yaml;-o;${results_run};--overwrite;-q"
                 -DEXPECT_EXIT=0 "-DEXPECT_REGEX=flood hazard +largest rating HR"
                 -DWORKDIR=${results_work} -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
set_tests_properties(results.run_tiny_geo_case PROPERTIES LABELS "results"
                     FIXTURES_SETUP tiny_geo_results ENVIRONMENT "${test_environment}")

function(flotsam_results_test name label)
  add_test(NAME results.${name} COMMAND ${FLOTSAM_VTK_PYTHON} ${ARGN})
  set_tests_properties(results.${name} PROPERTIES LABELS "${label}"
                       FIXTURES_REQUIRED tiny_geo_results)
endfunction()

set(scripts ${CMAKE_CURRENT_SOURCE_DIR}/scripts)
flotsam_results_test(ugrid_equals_the_vtu_files results
                     ${scripts}/compare_ugrid_vtk.py ${results_run} tiny_geo
                     --origin ${tiny_geo_origin})
# UGRID structure (mesh topology, start_index, CRS, time decoding) at 5 outputs (0, 6, ..., 24 s).
flotsam_results_test(ugrid_structure results
                     ${scripts}/check_ugrid.py ${results_run}/tiny_geo.nc --expect-times 5)
# 2 logs at 5 outputs (0, 6, ..., 24 s), in the domain to the end.
flotsam_results_test(debris_layers_tracks results
                     ${scripts}/check_debris_gpkg.py ${results_run}/tiny_geo_debris.gpkg
                     --layer tracks --expect-features 10 --expect-epsg 32633)
flotsam_results_test(qgis_opens_the_ugrid_mesh qgis
                     ${scripts}/check_ugrid_qgis.py ${results_run}/tiny_geo.nc --epsg 32633
                     --origin ${tiny_geo_origin})
flotsam_results_test(qgis_opens_the_debris_tracks qgis
                     ${scripts}/check_debris_gpkg.py ${results_run}/tiny_geo_debris.gpkg
                     --layer tracks --expect-features 10 --expect-epsg 32633 --require-qgis)

# The finite-element engine: its fields on the nodes (tiny_fem_geo_case.yaml, UGRID only).
set(fem_run ${results_work}/tiny_fem_geo)
add_test(NAME results.run_tiny_fem_geo_case
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:flotsam>;run;${CMAKE_CURRENT_SOURCE_DIR}/scripts/tiny_fem_geo_case.yaml;-o;${fem_run};--overwrite;-q"
                 -DEXPECT_EXIT=0 "-DEXPECT_REGEX=simulated +4.0 s"
                 -DWORKDIR=${results_work} -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
set_tests_properties(results.run_tiny_fem_geo_case PROPERTIES LABELS "results"
                     FIXTURES_SETUP tiny_fem_geo_results ENVIRONMENT "${test_environment}")
add_test(NAME results.ugrid_structure_fem
         COMMAND ${FLOTSAM_VTK_PYTHON} ${scripts}/check_ugrid.py ${fem_run}/tiny_fem_geo.nc
                 --expect-times 3)
add_test(NAME results.qgis_opens_the_fem_ugrid_mesh
         COMMAND ${FLOTSAM_VTK_PYTHON} ${scripts}/check_ugrid_qgis.py ${fem_run}/tiny_fem_geo.nc
                 --epsg 32633 --origin "2024-06-01 00:00:00")
set_tests_properties(results.ugrid_structure_fem PROPERTIES LABELS "results"
                     FIXTURES_REQUIRED tiny_fem_geo_results)
set_tests_properties(results.qgis_opens_the_fem_ugrid_mesh PROPERTIES LABELS "qgis"
                     FIXTURES_REQUIRED tiny_fem_geo_results)
