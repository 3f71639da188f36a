# arnoldweb_embed_files(OUTPUT <file.cpp> FUNCTION <name> FILES <name>=<path>...)
# generates a C++ source defining
#   const std::vector<std::pair<const char*, std::string_view>>& <name>();
# that returns every file's name and content, so the installed library never
# reads kernel sources from disk.
function(arnoldweb_embed_files)
  cmake_parse_arguments(E "" "OUTPUT;FUNCTION" "FILES" ${ARGN})
  set(deps)
  set(specs)
  foreach(spec IN LISTS E_FILES)
    string(REPLACE "=" ";" parts "${spec}")
    list(GET parts 1 path)
    list(APPEND deps "${path}")
    list(APPEND specs "${spec}")
  endforeach()
  string(REPLACE ";" "|" specs_arg "${specs}")
  add_custom_command(
    OUTPUT "${E_OUTPUT}"
    COMMAND ${CMAKE_COMMAND} "-DOUTPUT=${E_OUTPUT}" "-DFUNCTION=${E_FUNCTION}"
            "-DSPECS=${specs_arg}" -P "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/EmbedFilesScript.cmake"
    DEPENDS ${deps} "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/EmbedFilesScript.cmake"
    COMMENT "Embedding kernel sources into ${E_FUNCTION}()"
    VERBATIM)
endfunction()
