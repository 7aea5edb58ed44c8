# granlub_add_test(NAME name SOURCES a.cpp ... [LIBS lib ...] [LABELS unit|physics|integration|slow ...]
#                  [TIMEOUT seconds] [ARGS ...])
# Builds one Boost.Test executable and registers it with CTest, labelled and time-limited.
# Each suite defines BOOST_TEST_MODULE in exactly one of its sources.
# Boost.Test is a test package (.ci/packages): without it the top-level CMakeLists.txt skips the tests.
find_package(Boost 1.74 QUIET COMPONENTS unit_test_framework)

function(granlub_add_test)
  cmake_parse_arguments(T "" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS;ARGS" ${ARGN})
  if(NOT T_NAME OR NOT T_SOURCES)
    message(FATAL_ERROR "granlub_add_test needs NAME and SOURCES")
  endif()
  if(NOT T_LABELS)
    set(T_LABELS unit)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} Boost::unit_test_framework granlub_warnings)
  target_compile_definitions(${T_NAME} PRIVATE BOOST_TEST_DYN_LINK
                             GRANLUB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                             GRANLUB_BINARY_DIR="${PROJECT_BINARY_DIR}")
  set_target_properties(${T_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  add_test(NAME ${T_NAME} COMMAND ${T_NAME} --log_level=warning ${T_ARGS}
           WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT})
endfunction()
