# Used by tests/scripts/cli.cmake:
# cmake -DCOMMAND="a;b;c" -DEXPECT_EXIT=0|nonzero -DEXPECT_REGEX=... [-DWORKDIR=...] -P expect.cmake
# Runs COMMAND and fails unless its exit code and its output (stdout + stderr) are as expected.
if(NOT WORKDIR)
  set(WORKDIR ${CMAKE_CURRENT_BINARY_DIR})
endif()
execute_process(COMMAND ${COMMAND} WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(EXPECT_EXIT STREQUAL "nonzero")
  if(code EQUAL 0)
    message(FATAL_ERROR "expected a non-zero exit code, got 0\n${all}")
  endif()
elseif(NOT code EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "expected exit code ${EXPECT_EXIT}, got ${code}\n${all}")
endif()
if(NOT all MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match '${EXPECT_REGEX}':\n${all}")
endif()
message(STATUS "ok: ${all}")
