# The installed library, used as a deal.II project would: install the build
# into a fresh prefix, configure and build tests/install/example against it
# with find_package(unilateral), run it, and compare its output.
# Variables: BUILD (this build tree), SOURCE (tests/install), WORK (scratch).
file(REMOVE_RECURSE ${WORK})
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD};--prefix;${WORK}/prefix"
    "${CMAKE_COMMAND};-S;${SOURCE}/example;-B;${WORK}/example;-DCMAKE_BUILD_TYPE=Release;-DCMAKE_PREFIX_PATH=${WORK}/prefix"
    "${CMAKE_COMMAND};--build;${WORK}/example")
  execute_process(COMMAND ${step} RESULT_VARIABLE failed
    OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(failed)
    message(FATAL_ERROR "failed: ${step}\n${log}")
  endif()
endforeach()
execute_process(COMMAND ${WORK}/example/obstacle RESULT_VARIABLE failed
  OUTPUT_VARIABLE output ERROR_VARIABLE errors)
file(READ ${SOURCE}/example/obstacle.output expected)
if(failed OR NOT output STREQUAL expected)
  message(FATAL_ERROR "the example's output differs:\n${output}${errors}"
    "expected:\n${expected}")
endif()
message(STATUS "example built against the installed library:\n${output}")
