# cmake -DCLANGXX=... -DSRC=<repo> -DOUT=<dir> -DRUNS=N -P build_and_run.cmake
# Builds the case-parser fuzzer with clang (libFuzzer + AddressSanitizer + UBSan) and runs it N
# times from the shipped cases as corpus. Fails on any crash or sanitizer report.
file(MAKE_DIRECTORY ${OUT}/corpus)
file(GLOB cases ${SRC}/cases/*/case.toml)
foreach(c ${cases})
  get_filename_component(d ${c} DIRECTORY)
  get_filename_component(n ${d} NAME)
  configure_file(${c} ${OUT}/corpus/${n}.toml COPYONLY)
endforeach()
# Only what the parser needs: the case model and the key declarations.
set(core_sources ${SRC}/core/src/case.cpp ${SRC}/core/src/common_sections.cpp ${SRC}/core/src/schema.cpp
                 ${SRC}/core/src/text.cpp)
execute_process(COMMAND pkg-config --cflags tomlplusplus OUTPUT_VARIABLE toml_flags OUTPUT_STRIP_TRAILING_WHITESPACE)
execute_process(COMMAND pkg-config --libs tomlplusplus OUTPUT_VARIABLE toml_libs OUTPUT_STRIP_TRAILING_WHITESPACE)
separate_arguments(toml_flags)
separate_arguments(toml_libs)
set(exe ${OUT}/fuzz_case)
set(stamp_sources ${core_sources} ${SRC}/tests/core/fuzz/fuzz_case.cpp)
set(rebuild TRUE)
if(EXISTS ${exe})
  set(rebuild FALSE)
  foreach(s ${stamp_sources})
    if(${s} IS_NEWER_THAN ${exe})
      set(rebuild TRUE)
    endif()
  endforeach()
endif()
if(rebuild)
  message(STATUS "building ${exe} with ${CLANGXX}")
  execute_process(COMMAND ${CLANGXX} -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined
                          -fno-sanitize-recover=undefined -I${SRC}/core/include -I${SRC}/core/src ${toml_flags}
                          ${stamp_sources} ${toml_libs} -lfmt -o ${exe}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "building the fuzzer failed (${rc})")
  endif()
endif()
execute_process(COMMAND ${exe} -runs=${RUNS} -max_len=4096 -seed=1 ${OUT}/corpus
                WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the fuzzer found a failure (exit ${rc}); the crashing input is in ${OUT}")
endif()
message(STATUS "fuzz smoke: ${RUNS} runs without a failure")
