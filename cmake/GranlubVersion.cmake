# granlub's version string: `git describe` of the source tree, else the project version.
execute_process(COMMAND git describe --tags --always --dirty
                WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
                OUTPUT_VARIABLE GRANLUB_GIT_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET RESULT_VARIABLE _granlub_git_rc)
if(_granlub_git_rc EQUAL 0 AND GRANLUB_GIT_DESCRIBE)
  set(GRANLUB_VERSION_STRING "${PROJECT_VERSION}+g${GRANLUB_GIT_DESCRIBE}")
else()
  set(GRANLUB_VERSION_STRING "${PROJECT_VERSION}")
endif()
