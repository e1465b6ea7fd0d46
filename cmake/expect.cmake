# Used by tests/scripts/cli.cmake:
# cmake -DCOMMAND="a;b;c" -DEXPECT_EXIT=0|nonzero -DEXPECT_REGEX=... [-DWORKDIR=...]
#       [-DSTDERR_REGEX=...] [-DSTDOUT_EXCLUDES=...] [-DFILE=... -DFILE_REGEX=...] -P expect.cmake
# Runs COMMAND and fails unless its exit code and its output (stdout + stderr) are as expected;
# optionally stderr alone must match STDERR_REGEX, stdout must not match STDOUT_EXCLUDES, and
# the file FILE (relative to WORKDIR) must match FILE_REGEX.
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
if(STDERR_REGEX AND NOT err MATCHES "${STDERR_REGEX}")
  message(FATAL_ERROR "standard error does not match '${STDERR_REGEX}':\n${err}")
endif()
if(STDOUT_EXCLUDES AND out MATCHES "${STDOUT_EXCLUDES}")
  message(FATAL_ERROR "standard output matches '${STDOUT_EXCLUDES}':\n${out}")
endif()
if(FILE)
  file(READ ${WORKDIR}/${FILE} text)
  if(NOT text MATCHES "${FILE_REGEX}")
    message(FATAL_ERROR "${FILE} does not match '${FILE_REGEX}':\n${text}")
  endif()
endif()
message(STATUS "ok: ${all}")
