# granlub_add_module_folders(folder:target ...)
# Adds each folder of the calling directory (a module's tests or benchmarks) when the module's
# library target exists (GRANLUB_MODULES may build a subset) and the folder has a CMakeLists.txt.
function(granlub_add_module_folders)
  foreach(pair ${ARGN})
    string(REPLACE ":" ";" pair ${pair})
    list(GET pair 0 folder)
    list(GET pair 1 target)
    if(TARGET ${target} AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${folder}/CMakeLists.txt)
      add_subdirectory(${folder})
    endif()
  endforeach()
endfunction()
