# The models' ids (cmake/ArnoldwebModels.cmake): read from each descriptor's
# AW_MODEL_ID(<id>); line, in the order of the ids, never from the order of
# the names (a model named before another renumbers none); a descriptor
# without an id, or two with one id, stop the configure naming the files.
#   cmake -DSOURCE_DIR=<repo> -P tests/models/model_ids.cmake   (ctest models.ids)
# With -DCASE=<dir> it reads the ids of the descriptors in <dir> (one case).
if(DEFINED CASE)
  include("${SOURCE_DIR}/cmake/ArnoldwebModels.cmake")
  file(GLOB files RELATIVE "${CASE}" "${CASE}/*.cpp")
  string(REPLACE ".cpp" "" names "${files}")
  list(SORT names)
  arnoldweb_model_ids("${CASE}" "${names}" ids)
  string(REPLACE ";" " " ids "${ids}")
  message("ids: ${ids}")
  return()
endif()

include("${SOURCE_DIR}/tests/support/script_cases.cmake")
set(work "${CMAKE_CURRENT_BINARY_DIR}/model_ids_test")
file(REMOVE_RECURSE "${work}")
# model_case(<name> <0: succeeds, 1: fails> <what the output holds> <model>=<its id lines> ...)
function(model_case name must_fail expected)
  awtest_case_files("${work}/${name}" "<name>.cpp" "// a descriptor" ${ARGN})
  awtest_script_case("${name}" ${must_fail} "${expected}" "${work}/${name}")
endfunction()

# ids as declared, whatever the names' order: "aaa" comes first alphabetically and renumbers none
model_case(names 0 "ids: 0:seibert2011 1:fgl 3:aaa 10:zeta"
           "aaa=AW_MODEL_ID(3)" "seibert2011=AW_MODEL_ID(0)" "fgl=AW_MODEL_ID(1)" "zeta=AW_MODEL_ID(10)")
model_case(clash 1 "fourier.cpp and" "fgl=AW_MODEL_ID(1)" "fourier=AW_MODEL_ID(01)")
model_case(missing 1 "new.cpp: declare the model's id once" "fgl=AW_MODEL_ID(1)" "new=// no id")
model_case(twice 1 "fgl.cpp: declare the model's id once" "fgl=AW_MODEL_ID(1)\nAW_MODEL_ID(2)")
model_case(range 1 "ids are 0 to 999" "fgl=AW_MODEL_ID(1000)")
awtest_script_cases_end("model ids" "${work}")
