# granlub's version string: the project version + `git describe --dirty` of the source tree (else
# the project version alone). It goes into every result's provenance, so it is taken at build
# time, not at configure time: the target granlub_version rewrites the generated source only when
# the string changes (a new commit, or a tree that became dirty or clean), and only that one file
# is recompiled.
set(GRANLUB_VERSION_SOURCE ${PROJECT_BINARY_DIR}/generated/granlub_version.cpp)
set(_granlub_version_args -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT=${GRANLUB_VERSION_SOURCE}
    -DPROJECT_VERSION=${PROJECT_VERSION} -P ${CMAKE_CURRENT_LIST_DIR}/WriteVersion.cmake)
execute_process(COMMAND ${CMAKE_COMMAND} ${_granlub_version_args})  # so that the file exists now
add_custom_target(granlub_version
                  COMMAND ${CMAKE_COMMAND} ${_granlub_version_args}
                  BYPRODUCTS ${GRANLUB_VERSION_SOURCE}
                  COMMENT "granlub version string")
