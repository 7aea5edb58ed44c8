# cmake -DCLANGXX=... -DSRC=<repo> -DOUT=<dir> -DRUNS=N [-DLAUNCHER=ccache] -P build_and_run.cmake
# Builds the case-parser fuzzer with clang (clang/CMakeLists.txt: libFuzzer + AddressSanitizer +
# UBSan, toml++ compiled in) into ${OUT}/build and runs it N times from the seed corpus: the
# shipped cases plus tests/core/fuzz/corpus. Fails on any crash or sanitizer report. ${OUT}/
# sections.cmake is written by CMakeLists.txt at configure time. The long run: README.md here.
file(MAKE_DIRECTORY ${OUT}/corpus)
file(GLOB cases ${SRC}/cases/*/case.toml)
foreach(c ${cases})
  get_filename_component(d ${c} DIRECTORY)
  get_filename_component(n ${d} NAME)
  configure_file(${c} ${OUT}/corpus/${n}.toml COPYONLY)
endforeach()

set(launcher)
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SRC}/tests/core/fuzz/clang -B ${OUT}/build -DCMAKE_CXX_COMPILER=${CLANGXX}
                        -DCMAKE_BUILD_TYPE= ${launcher} -DGRANLUB_SOURCE_DIR=${SRC} -DSECTIONS_FILE=${OUT}/sections.cmake
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the fuzzer's clang build failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${OUT}/build -j2 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the fuzzer failed (${rc})")
endif()

execute_process(COMMAND ${OUT}/build/fuzz_case -runs=${RUNS} -max_len=4096 -seed=1 ${OUT}/corpus
                        ${SRC}/tests/core/fuzz/corpus
                WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the fuzzer found a failure (exit ${rc}); the crashing input is in ${OUT}")
endif()
message(STATUS "fuzz smoke: ${RUNS} runs without a failure")
