# Results for QGIS and Python (issue 40): a tiny flood study on geodata (tiny_geo_case.yaml) run
# once, then its UGRID NetCDF file read with xarray against the ParaView files of the same run,
# its debris GeoPackage read with GDAL, and (label qgis, `make test-qgis`: python3-qgis is a
# 620 MB install) both opened in QGIS itself; the finite-element engine's UGRID file likewise.
set(results_work ${CMAKE_CURRENT_BINARY_DIR}/results_work)
file(MAKE_DIRECTORY ${results_work})
set(scripts ${CMAKE_CURRENT_SOURCE_DIR}/scripts)

# results.run_<case>: runs scripts/<case>_case.yaml into results_work/<case>, expecting `regex`
# in its output; the fixture <case>_results for the checks of its files.
function(flotsam_results_run case regex)
  add_test(NAME results.run_${case}_case
           COMMAND ${CMAKE_COMMAND}
                   "-DCOMMAND=$<TARGET_FILE:flotsam>;run;${scripts}/${case}_case.yaml;-o;${results_work}/${case};--overwrite;-q"
                   -DEXPECT_EXIT=0 "-DEXPECT_REGEX=${regex}"
                   -DWORKDIR=${results_work} -P ${PROJECT_SOURCE_DIR}/cmake/expect.cmake)
  set_tests_properties(results.run_${case}_case PROPERTIES LABELS "results"
                       FIXTURES_SETUP ${case}_results ENVIRONMENT "${test_environment}")
endfunction()

# results.<name>: a Python check (the arguments after `label`) of the files of run `case`.
function(flotsam_results_test name case label)
  add_test(NAME results.${name} COMMAND ${FLOTSAM_VTK_PYTHON} ${ARGN})
  set_tests_properties(results.${name} PROPERTIES LABELS "${label}"
                       FIXTURES_REQUIRED ${case}_results)
endfunction()

flotsam_results_run(tiny_geo "flood hazard +largest rating HR")
set(results_run ${results_work}/tiny_geo)
set(tiny_geo_origin "2024-06-01 06:30:00")
flotsam_results_test(ugrid_equals_the_vtu_files tiny_geo results
                     ${scripts}/compare_ugrid_vtk.py ${results_run} tiny_geo
                     --origin ${tiny_geo_origin})
# UGRID structure (mesh topology, start_index, CRS, time decoding) at 5 outputs (0, 6, ..., 24 s).
flotsam_results_test(ugrid_structure tiny_geo results
                     ${scripts}/check_ugrid.py ${results_run}/tiny_geo.nc --expect-times 5)
# 2 logs at 5 outputs (0, 6, ..., 24 s), in the domain to the end.
flotsam_results_test(debris_layers_tracks tiny_geo results
                     ${scripts}/check_debris_gpkg.py ${results_run}/tiny_geo_debris.gpkg
                     --layer tracks --expect-features 10 --expect-epsg 32633)
flotsam_results_test(qgis_opens_the_ugrid_mesh tiny_geo qgis
                     ${scripts}/check_ugrid_qgis.py ${results_run}/tiny_geo.nc --epsg 32633
                     --origin ${tiny_geo_origin})
flotsam_results_test(qgis_opens_the_debris_tracks tiny_geo qgis
                     ${scripts}/check_debris_gpkg.py ${results_run}/tiny_geo_debris.gpkg
                     --layer tracks --expect-features 10 --expect-epsg 32633 --require-qgis)

# The finite-element engine: its fields on the nodes (tiny_fem_geo_case.yaml, UGRID only).
flotsam_results_run(tiny_fem_geo "simulated +4.0 s")
set(fem_run ${results_work}/tiny_fem_geo)
flotsam_results_test(ugrid_structure_fem tiny_fem_geo results
                     ${scripts}/check_ugrid.py ${fem_run}/tiny_fem_geo.nc --expect-times 3)
flotsam_results_test(qgis_opens_the_fem_ugrid_mesh tiny_fem_geo qgis
                     ${scripts}/check_ugrid_qgis.py ${fem_run}/tiny_fem_geo.nc --epsg 32633
                     --origin "2024-06-01 00:00:00")
