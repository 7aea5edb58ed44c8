# Fails if a tracked file points at documents a clone of this repository does not have: the
# developers' notes kept next to the checkout (the pattern below) or their file names. The
# project's own pages live in docs/. The brackets keep this file from matching itself.
set(pattern "\\.\\./shar[e]d|shar[e]d/docs|/work/shar[e]d|ca-mod[e]l\\.md|continuum-th[e]ory|seeds-dig[e]st|liggghts-plug[i]n\\.md|dense-cont[a]cts|yad[e]\\.md")
find_program(GIT git)
if(NOT GIT OR NOT EXISTS "${SOURCE_DIR}/.git")
    message("not a git checkout: skipped")
    return()
endif()
# git grep searches exactly the tracked files (their working-tree contents); -I skips binaries.
execute_process(COMMAND ${GIT} grep -n -I -E "${pattern}"
                WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE hits ERROR_VARIABLE err)
if(rc EQUAL 0)
    message(FATAL_ERROR "tracked files point outside the repository; cite the paper and equation, or a page "
                        "under docs/, instead:\n${hits}")
elseif(NOT rc EQUAL 1)
    message(FATAL_ERROR "git grep failed (${rc}): ${err}")
endif()
message("no tracked file points outside the repository")
