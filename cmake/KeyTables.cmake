# cmake -DMODE=check|update -DGRANLUB=<granlub> -DSOURCE_DIR=<repository> -P KeyTables.cmake
# `granlub keys --check` (the repo_key_tables test) or `--update` (the key-tables target) on every
# Markdown page git tracks: the key tables between <!-- keys:SECTION --> markers must be what the
# declarations give, and no key table may stand outside markers (cli/key_tables.h).
find_program(GIT git)
if(NOT GIT OR NOT EXISTS "${SOURCE_DIR}/.git")
  message("not a git checkout: skipped")
  return()
endif()
execute_process(COMMAND ${GIT} ls-files "*.md" WORKING_DIRECTORY "${SOURCE_DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "git ls-files failed (${rc}): ${err}")
endif()
string(REPLACE "\n" ";" pages "${out}")
list(TRANSFORM pages PREPEND "${SOURCE_DIR}/")
execute_process(COMMAND "${GRANLUB}" keys --${MODE} ${pages} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "key tables: see above (`cmake --build <build> --target key-tables` rewrites stale ones)")
endif()
list(LENGTH pages n)
message("key tables: ${n} pages, ${MODE}: done")
