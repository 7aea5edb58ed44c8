# include()d by the scripts that check the repository's tracked files (cmake -P; SOURCE_DIR set):
#   require_git_checkout()              returns from the calling script, saying "not a git checkout:
#                                       skipped", where there is no git or no checkout (a tarball)
#   tracked_files(out pathspec...)      the tracked files matching the pathspecs, repository-relative
#   tracked_matching(out regex pathspec...)  those of them with a line matching the extended regex
#                                       (git grep -E; binaries skipped), working-tree contents
find_program(GIT git)

macro(require_git_checkout)
  if(NOT GIT OR NOT EXISTS "${SOURCE_DIR}/.git")
    message("not a git checkout: skipped")
    return()
  endif()
endmacro()

function(_git_lines out ok_codes)
  execute_process(COMMAND ${GIT} ${ARGN} WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE rc
                  OUTPUT_VARIABLE lines ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc IN_LIST ok_codes)
    message(FATAL_ERROR "git ${ARGV2} failed (${rc}): ${err}")
  endif()
  string(REPLACE "\n" ";" lines "${lines}")
  list(SORT lines)
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

function(tracked_files out)
  _git_lines(lines "0" ls-files -- ${ARGN})
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

# 1 from git grep is "no match": an empty list.
function(tracked_matching out regex)
  _git_lines(lines "0;1" grep -l -I -E "${regex}" -- ${ARGN})
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

# Fails the script when a tracked file has a line matching the extended regex, listing each such
# line (file:line: text) under `why`; otherwise prints `ok`.
function(forbid_tracked_text regex why ok)
  execute_process(COMMAND ${GIT} grep -n -I -E "${regex}" WORKING_DIRECTORY "${SOURCE_DIR}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE hits ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${why}:\n${hits}")
  elseif(NOT rc EQUAL 1)
    message(FATAL_ERROR "git grep failed (${rc}): ${err}")
  endif()
  message("${ok}")
endfunction()
