# Proves that the layering check can fail: runs core/check_layering.cmake on a fixture tree
# (tests/data/layering/<name>/ with its layers.cmake) and passes only when the check exits
# non-zero AND prints the expected message.
#   cmake -DCHECKER=<core/check_layering.cmake> -DFIXTURE=<dir> -DEXPECT=<regex> -P expect_failure.cmake
foreach(_var CHECKER FIXTURE EXPECT)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "expect_failure.cmake: -D${_var}=... is required")
  endif()
endforeach()
execute_process(
  COMMAND ${CMAKE_COMMAND} -DROOT=${FIXTURE} -DMANIFEST=${FIXTURE}/layers.cmake
          -P ${CHECKER}
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
set(_all "${_out}${_err}")
if(_rc EQUAL 0)
  message(FATAL_ERROR "the layering check passed on ${FIXTURE}, which has an offending include:\n${_all}")
endif()
if(NOT _all MATCHES "${EXPECT}")
  message(FATAL_ERROR "the layering check failed (exit ${_rc}) but without the expected message\n"
    "  expected (regex): ${EXPECT}\n  got:\n${_all}")
endif()
string(REGEX MATCHALL "[^\n]*:[0-9?]+: #[^\n]*" _problems "${_all}")
list(LENGTH _problems _count)
if(NOT _count EQUAL 1)
  message(FATAL_ERROR "expected exactly one violation in ${FIXTURE}, got ${_count}:\n${_all}")
endif()
message(STATUS "the layering check failed as expected (exit ${_rc}): ${_problems}")
