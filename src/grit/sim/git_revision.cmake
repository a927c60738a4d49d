# Writes git_revision.cpp from git_revision.cpp.in with `git describe --always --dirty` of SOURCE_DIR.
# Run at every build (cmake -P, from the grit_git_revision target); configure_file leaves the file
# untouched when the revision is unchanged, so only a new revision recompiles it.
# Inputs: SOURCE_DIR, TEMPLATE, OUTPUT, GIT_EXECUTABLE (may be empty).
set(GRIT_GIT_REVISION "unknown")
if(GIT_EXECUTABLE AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --abbrev=10
                  WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE GRIT_GIT_REVISION OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(GRIT_GIT_REVISION STREQUAL "")
    set(GRIT_GIT_REVISION "unknown")
  endif()
endif()
configure_file(${TEMPLATE} ${OUTPUT} @ONLY)
