# flotsam_module(NAME [FOLDER path] DEPENDS targets...)
# Builds src/NAME/*.cpp (or src/FOLDER/*.cpp) into the static library flotsam_NAME (an interface
# library while the folder holds headers only). Sources are globbed so that adding a file needs
# no CMake edit.
function(flotsam_module name)
  cmake_parse_arguments(ARG "" "FOLDER" "DEPENDS" ${ARGN})
  if(NOT ARG_FOLDER)
    set(ARG_FOLDER ${name})
  endif()
  file(GLOB sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${ARG_FOLDER}/*.cpp)
  if(sources)
    add_library(flotsam_${name} STATIC ${sources})
    target_include_directories(flotsam_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(flotsam_${name} PUBLIC ${ARG_DEPENDS} PRIVATE flotsam_options)
  else()
    add_library(flotsam_${name} INTERFACE)
    target_include_directories(flotsam_${name} INTERFACE ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(flotsam_${name} INTERFACE ${ARG_DEPENDS})
  endif()
endfunction()

# flotsam_test_folder(FOLDER LIBS...)
# Each tests/FOLDER/*.cpp is compiled into one GoogleTest executable test_FOLDER ('/' -> '_'), labelled
# "unit" (the sanitizer build runs these), or "verification" for tests/verification. A file whose first lines hold "// ctest-label: slow"
# goes into its own executable labelled "slow", out of the default `make test`.
# Tests run two at a time on two cores: OpenMP threads that wait by spinning would take the
# other test's core (a 10 s test became 100 s), so waiting threads sleep instead.
set(test_environment "OMP_WAIT_POLICY=PASSIVE")

# Test sources are set-up and assertions around calls into the libraries: in a Release build they
# are compiled at -O1, which halves their compile time (a cold `make test` spends most of its build
# on them); the libraries they call keep the build type's optimisation.
function(flotsam_test_options target)
  target_link_libraries(${target} PRIVATE flotsam_options ${ARGN} GTest::gtest_main GTest::gmock)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()

function(flotsam_test_folder folder)
  file(GLOB files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${folder}/*.cpp)
  set(fast "")
  foreach(f ${files})
    file(STRINGS ${f} head LIMIT_COUNT 5)
    get_filename_component(stem ${f} NAME_WE)
    if(head MATCHES "ctest-label: slow")
      add_executable(slow_${stem} ${f})
      flotsam_test_options(slow_${stem} ${ARGN})
      gtest_discover_tests(slow_${stem} PROPERTIES LABELS "slow" ENVIRONMENT ${test_environment}
                           DISCOVERY_TIMEOUT 60)
    else()
      list(APPEND fast ${f})
    endif()
  endforeach()
  if(fast)
    string(REPLACE "/" "_" target ${folder})
    add_executable(test_${target} ${fast})
    flotsam_test_options(test_${target} ${ARGN})
    if(folder STREQUAL "verification")
      set(kind "verification")
    else()
      set(kind "unit")
      add_dependencies(unit_tests test_${target})
    endif()
    gtest_discover_tests(test_${target} PROPERTIES LABELS "${kind}"
                         ENVIRONMENT ${test_environment} DISCOVERY_TIMEOUT 60)
  endif()
endfunction()
