# Run at every build (target unilateral_revision): writes OUTPUT, a header
# with the git commit of SOURCE_DIR and whether tracked files have
# uncommitted changes, and rewrites it only when that changed, so that only
# source/base/version.cc is compiled again after a commit. Several builds
# run it at once (ctest -j builds each test's target in its own process):
# each writes its own temporary file, and git takes no lock.
set(revision "unknown")
set(local_changes "false")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse --short=12 HEAD
    OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE head_result ERROR_QUIET)
  if(head_result EQUAL 0 AND NOT head STREQUAL "")
    set(revision "${head}")
    execute_process(COMMAND ${GIT_EXECUTABLE} --no-optional-locks -C ${SOURCE_DIR} status --porcelain --untracked-files=no
      OUTPUT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE
      RESULT_VARIABLE status_result ERROR_QUIET)
    if(status_result EQUAL 0 AND NOT status STREQUAL "")
      set(local_changes "true")
    endif()
  endif()
endif()
string(RANDOM LENGTH 16 unique)
set(temporary "${OUTPUT}.${unique}.new")
file(WRITE ${temporary}
  "// Written by cmake/revision.cmake at build time.\n"
  "#pragma once\n"
  "#define UNILATERAL_GIT_REVISION \"${revision}\"\n"
  "#define UNILATERAL_GIT_LOCAL_CHANGES ${local_changes}\n")
configure_file(${temporary} ${OUTPUT} COPYONLY)
file(REMOVE ${temporary})
