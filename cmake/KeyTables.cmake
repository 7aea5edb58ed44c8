# cmake -DMODE=check|update -DGRANLUB=<granlub> -DSOURCE_DIR=<repository> -P KeyTables.cmake
# `granlub keys --check` (the repo_key_tables test) or `--update` (the key-tables target) on every
# Markdown page git tracks: the key tables between <!-- keys:SECTION --> markers must be what the
# declarations give, and no key table may stand outside markers (cli/key_tables.h).
cmake_minimum_required(VERSION 3.16)
include(${CMAKE_CURRENT_LIST_DIR}/TrackedFiles.cmake)
require_git_checkout()
tracked_files(pages "*.md")
list(TRANSFORM pages PREPEND "${SOURCE_DIR}/")
execute_process(COMMAND "${GRANLUB}" keys --${MODE} ${pages} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "key tables: see above (`cmake --build <build> --target key-tables` rewrites stale ones)")
endif()
list(LENGTH pages n)
message("key tables: ${n} pages, ${MODE}: done")
