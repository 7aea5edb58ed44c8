# granlub_case_section(<module> SOURCES <files...> [INCLUDES <dirs...>])
# A solver module names the sources that declare its case section (the section() that
# cli/full_schema.cpp adds under GRANLUB_HAVE_<MODULE>) and the include folders they need. The
# case-parser fuzzer (tests/core/fuzz) compiles exactly these with core's case model, so it
# parses with the schema `granlub` uses. The modules registered here, in this order, are granlub's
# solver modules (cmake/GranlubSolverList.cmake writes cli's solver list from them). The sources must need nothing but core (no solver engine).
function(granlub_case_section module)
  cmake_parse_arguments(arg "" "" "SOURCES;INCLUDES" ${ARGN})
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "granlub_case_section(${module}) needs SOURCES")
  endif()
  foreach(list SOURCES INCLUDES)
    set(absolute)
    foreach(p ${arg_${list}})
      get_filename_component(p ${p} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
      list(APPEND absolute ${p})
    endforeach()
    set_property(GLOBAL APPEND PROPERTY GRANLUB_CASE_SECTION_${list} ${absolute})
  endforeach()
  set_property(GLOBAL APPEND PROPERTY GRANLUB_CASE_SECTIONS ${module})
endfunction()
