# Writes generated/crumple/version.hpp at every build (the target crumple_version), so that the
# git revision stored in every output file is the one the binary was built from, not the one
# CMake was configured at. A working tree with uncommitted changes to tracked files is marked
# "+dirty". configure_file leaves the header untouched when nothing changed, so an unchanged
# revision recompiles nothing. Called with -DSOURCE_DIR, -DOUTPUT, -DTEMPLATE, -DPROJECT_VERSION.
execute_process(COMMAND git rev-parse --short=12 HEAD
  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE CRUMPLE_GIT_REV
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rev_failed)
if(rev_failed OR NOT CRUMPLE_GIT_REV)
  set(CRUMPLE_GIT_REV "unknown")
else()
  execute_process(COMMAND git diff --quiet HEAD --
    WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE dirty ERROR_QUIET)
  if(dirty EQUAL 1)
    string(APPEND CRUMPLE_GIT_REV "+dirty")
  endif()
endif()
configure_file(${TEMPLATE} ${OUTPUT} @ONLY)
