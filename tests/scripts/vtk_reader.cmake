# VTK's own readers (python3-vtk9) read what flotsam writes (labels unit;io):
#   io.vtk_write_samples   writes .vtu/.vtp/.pvd samples into the build tree (fixture setup),
#   io.vtk_read_samples    checks them with tests/scripts/check_vtk.py.
# FLOTSAM_VTK_PYTHON (/usr/bin/python3, which finds Debian's VTK module) is set in
# tests/CMakeLists.txt.

add_executable(write_vtk_samples ${CMAKE_CURRENT_LIST_DIR}/write_vtk_samples.cpp)
target_link_libraries(write_vtk_samples PRIVATE flotsam_options flotsam_io flotsam_bodies)
add_dependencies(unit_tests write_vtk_samples)

set(vtk_samples ${CMAKE_CURRENT_BINARY_DIR}/vtk_samples)
add_test(NAME io.vtk_write_samples COMMAND write_vtk_samples ${vtk_samples})
set_tests_properties(io.vtk_write_samples PROPERTIES FIXTURES_SETUP vtk_samples LABELS "unit;io")
add_test(NAME io.vtk_read_samples
         COMMAND ${FLOTSAM_VTK_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_vtk.py ${vtk_samples})
set_tests_properties(io.vtk_read_samples PROPERTIES FIXTURES_REQUIRED vtk_samples LABELS "unit;io")
