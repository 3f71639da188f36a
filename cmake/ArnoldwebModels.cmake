# The built-in models (docs/models.md, "Adding a model"): a model is its device
# header lib/device/models/aw_<name>.h and its descriptor
# lib/src/physics/models/<name>.cpp (parameters, capabilities, help, its id).
# Everything else about it is generated here from the list of headers:
#   <out>/models/aw_models.h   the device core's dispatch on -DAW_MODEL=<id>
#                              (embedded for OpenCL and CUDA; the cpu backend's
#                              kernel variants are made from its #define lines)
#   <out>/model_list.inc       AW_MODEL_ENTRY(<name>, <id>) per model, for the
#                              host's model table (physics/model_table.cpp)
#   <out>/host_model_<name>.cpp  the header compiled for the host (its potential,
#                              initial states and speed, physics/host_model.hpp)
# Ids: each descriptor declares its model's id on a line "AW_MODEL_ID(<id>);"
# (physics/model_descriptor.hpp); a model's id never changes, so a new model
# renumbers none. A descriptor without one, or two models with one id, is a
# configure error naming the files. The models are listed in the order of their
# ids (the paper's, 0, first). Generated files are written only where their
# content changes (configure_file, file(CONFIGURE)): a configure run that changes
# no model rebuilds nothing.
#
#   arnoldweb_models(<sources-var> <out-dir>)
#   arnoldweb_model_ids(<descriptor-dir> <names> <out-var>)  "<id>:<name>" by id
set(ARNOLDWEB_DEFAULT_MODEL seibert2011)

function(arnoldweb_model_ids descriptor_dir names out_var)
  set(pairs)
  set(taken "")
  foreach(name IN LISTS names)
    set(descriptor "${descriptor_dir}/${name}.cpp")
    file(READ "${descriptor}" text)
    string(REGEX MATCHALL "(^|\n)AW_MODEL_ID\\([^)]*\\)" lines "${text}")
    list(LENGTH lines n)
    if(NOT n EQUAL 1 OR NOT lines MATCHES "AW_MODEL_ID\\(([0-9]+)\\)$")
      message(FATAL_ERROR "${descriptor}: declare the model's id once, on a line of its own: AW_MODEL_ID(<id>); "
                          "with an id no other model has (taken:${taken}; docs/models.md, \"Adding a model\")")
    endif()
    math(EXPR id "${CMAKE_MATCH_1}")  # 007 is 7
    if(id GREATER_EQUAL 1000)
      message(FATAL_ERROR "${descriptor}: AW_MODEL_ID(${id}): ids are 0 to 999 (1000 is an expression model)")
    endif()
    foreach(pair IN LISTS pairs)
      if(pair MATCHES "^${id}:(.*)$")
        message(FATAL_ERROR "${descriptor} and ${descriptor_dir}/${CMAKE_MATCH_1}.cpp both declare "
                            "AW_MODEL_ID(${id}): a model id is never shared or given again; give ${name} a free one "
                            "(taken:${taken})")
      endif()
    endforeach()
    string(APPEND taken " ${id} ${name}")
    list(APPEND pairs "${id}:${name}")
  endforeach()
  list(SORT pairs COMPARE NATURAL)
  set(${out_var} ${pairs} PARENT_SCOPE)
endfunction()

function(arnoldweb_models sources_var out_dir)
  set(device_dir "${PROJECT_SOURCE_DIR}/lib/device/models")
  set(descriptor_dir "${PROJECT_SOURCE_DIR}/lib/src/physics/models")
  file(GLOB headers CONFIGURE_DEPENDS RELATIVE "${device_dir}" "${device_dir}/aw_*.h")
  file(GLOB descriptors CONFIGURE_DEPENDS RELATIVE "${descriptor_dir}" "${descriptor_dir}/*.cpp")
  set(names)
  foreach(h IN LISTS headers)
    string(REGEX REPLACE "^aw_(.*)\\.h$" "\\1" name "${h}")
    if(NOT name MATCHES "^[a-z][a-z0-9_]*$")
      message(FATAL_ERROR "lib/device/models/${h}: a model's name is lower case letters, digits and _")
    endif()
    if(NOT "${name}.cpp" IN_LIST descriptors)
      message(FATAL_ERROR "lib/device/models/${h} has no descriptor: add lib/src/physics/models/${name}.cpp "
                          "(docs/models.md, \"Adding a model\")")
    endif()
    list(APPEND names "${name}")
  endforeach()
  foreach(d IN LISTS descriptors)
    string(REGEX REPLACE "\\.cpp$" "" name "${d}")
    if(NOT name IN_LIST names)
      message(FATAL_ERROR "lib/src/physics/models/${d} has no device header lib/device/models/aw_${name}.h")
    endif()
  endforeach()
  list(SORT names)
  arnoldweb_model_ids("${descriptor_dir}" "${names}" models)

  set(defines "")
  set(dispatch "")
  set(entries "")
  set(sources)
  foreach(model IN LISTS models)
    string(REGEX REPLACE "^([0-9]+):(.*)$" "\\1;\\2" model "${model}")
    list(GET model 0 id)
    list(GET model 1 name)
    string(TOUPPER "${name}" upper)
    string(APPEND defines "#define AW_MODEL_${upper} ${id}\n")
    if(dispatch STREQUAL "")
      string(APPEND dispatch "#if AW_MODEL == AW_MODEL_${upper}\n")
    else()
      string(APPEND dispatch "#elif AW_MODEL == AW_MODEL_${upper}\n")
    endif()
    string(APPEND dispatch "#include \"models/aw_${name}.h\"\n")
    string(APPEND entries "AW_MODEL_ENTRY(${name}, ${id})\n")
    set(MODEL "${name}")
    set(MODEL_ID "${id}")
    configure_file("${PROJECT_SOURCE_DIR}/lib/src/physics/host_model.cpp.in" "${out_dir}/host_model_${name}.cpp"
                   @ONLY)
    list(APPEND sources "${out_dir}/host_model_${name}.cpp"
                        "${descriptor_dir}/${name}.cpp")
  endforeach()
  string(TOUPPER "${ARNOLDWEB_DEFAULT_MODEL}" default_upper)
  file(CONFIGURE OUTPUT "${out_dir}/models/aw_models.h" CONTENT
"/* arnoldweb: the models' dispatch, generated by cmake/ArnoldwebModels.cmake
 * from the headers in lib/device/models/ (the model interface: aw_model.h).
 * Kernels are compiled with -DAW_MODEL=<id>; 1000 is an expression model,
 * whose header the host emits at run time. */
#ifndef AW_MODELS_H
#define AW_MODELS_H

${defines}
#ifndef AW_MODEL
#define AW_MODEL AW_MODEL_${default_upper}
#endif

${dispatch}#elif AW_MODEL == 1000
#include \"models/aw_expression.h\"
#else
#error \"unknown AW_MODEL\"
#endif

#endif /* AW_MODELS_H */
" @ONLY)
  file(CONFIGURE OUTPUT "${out_dir}/model_list.inc" CONTENT
"/* arnoldweb: the built-in models, generated by cmake/ArnoldwebModels.cmake:
 * AW_MODEL_ENTRY(name, id) for lib/device/models/aw_<name>.h and its
 * descriptor lib/src/physics/models/<name>.cpp. */
${entries}" @ONLY)
  set(${sources_var} ${sources} PARENT_SCOPE)
endfunction()
