# Shared by the tests of the configure-time generators (tests/models/model_ids.cmake,
# tests/effects/effect_hooks.cmake): each runs its own script once per case
# (cmake -DSOURCE_DIR=<repo> -DCASE=<dir> -P <the script>) and checks its exit
# status and output.
#   awtest_case_files(<dir> <file name, <name> replaced> <first line> <name>=<text> ...)
#       writes one file per item (@SEMI@ in a text stands for ';', which a list's elements cannot hold)
#   awtest_script_case(<name> <0: succeeds, 1: fails> <what the output holds> <case dir>)
#   awtest_script_cases_end(<what> <work dir>)   removes the work dir; fails naming every case that did not hold

function(awtest_case_files dir file_name first_line)
  file(MAKE_DIRECTORY "${dir}")
  foreach(item IN LISTS ARGN)
    string(REGEX REPLACE "^([a-z0-9_]+)=.*$" "\\1" name "${item}")
    string(REGEX REPLACE "^[a-z0-9_]+=(.*)$" "\\1" text "${item}")
    string(REPLACE "@SEMI@" ";" text "${text}")
    string(REPLACE "<name>" "${name}" file "${file_name}")
    file(WRITE "${dir}/${file}" "${first_line}\n${text}\n")
  endforeach()
endfunction()

function(awtest_script_case name must_fail expected dir)
  # CMAKE_CURRENT_LIST_FILE: the calling script (a function does not change it)
  execute_process(COMMAND "${CMAKE_COMMAND}" "-DSOURCE_DIR=${SOURCE_DIR}" "-DCASE=${dir}" -P "${CMAKE_CURRENT_LIST_FILE}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  string(REGEX REPLACE "[ \n]+" " " flat "${out}")
  string(FIND "${flat}" "${expected}" at)
  if((must_fail AND rc EQUAL 0) OR (NOT must_fail AND NOT rc EQUAL 0) OR at EQUAL -1)
    set_property(GLOBAL APPEND_STRING PROPERTY awtest_failed_cases
                 "\n  ${name}: exit ${rc}, expected \"${expected}\"; got: ${flat}")
  else()
    message(STATUS "${name}: ${expected}")
  endif()
endfunction()

function(awtest_script_cases_end what work)
  file(REMOVE_RECURSE "${work}")
  get_property(failed GLOBAL PROPERTY awtest_failed_cases)
  if(failed)
    message(FATAL_ERROR "${what}:${failed}")
  endif()
endfunction()
