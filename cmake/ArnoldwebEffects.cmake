# The effects' hooks (docs/design.md, "The effect hooks"): an effect is its
# device header lib/device/effects/aw_fx_<name>.h and its row in the host's
# effect table (lib/src/plan/effects.cpp). The header declares its place on a
# line of its own, AW_EFFECT_ORDER(<n>), may keep a per-lane state
# (`typedef struct {...} aw_fx_<name>_state;`) and defines any of the hooks
#   AW_FN <void|int> aw_fx_<name>_<hook>(aw_config cfg, [aw_fx_<name>_state* me,] aw_fx_core* fx, ...)
# with the parameters of the hook's row below. Generated here from the
# headers:
#   <out>/effects/aw_effect_declarations.h   what the host reads too: each
#       header's declarations block (`#ifndef AW_FX_<NAME>_DECLARATIONS`, plain
#       macros: its feature bits AW_F_*, its record slot AW_OUT_*, its sizes,
#       and its parameters AW_FX_<NAME>_RPARAMS / _IPARAMS, the members it adds
#       to the parameter blocks), read with AW_EFFECT_DECLARATIONS_ONLY;
#       AW_F_ALL, and AW_EFFECTS_RPARAMS / _IPARAMS for aw_param_blocks.h.
#       aw_params.h includes it (embedded for OpenCL and CUDA too). Two bits
#       or two slots of one value, or a bit that is not one bit, stop the
#       configure naming the headers.
#   <out>/effects/aw_effect_hooks.h   the effect headers in order, the lanes'
#       state aw_fx (the core's and every effect's), and per hook one function
#       aw_fx_effects_<hook>(cfg, fx, ...) calling each effect's hook in
#       increasing order (embedded for OpenCL and CUDA like aw_models.h).
# A header with hooks and no order, an order twice, a function aw_fx_<name>_*
# that is not a hook, or an effect without hooks is a configure error naming
# the header. Written only where its content changes: a configure run that
# changes no effect rebuilds nothing.
#
#   arnoldweb_effects(<out-dir> [<effects-dir>])   (default lib/device/effects;
#   another for tests/effects/effect_hooks.cmake)

# hook | return type | parameters after (cfg, fx) | arguments after the effect's (cfg, [me,] core)
set(ARNOLDWEB_EFFECT_HOOKS
  "begin|void|aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out|s, l, rp, ip, out"
  "first_force|int|aw_lstate* s, AW_CONSTANT aw_rparams* rp|s, rp"
  "steps|int|aw_lstate* s, aw_i64 nsteps, AW_CONSTANT aw_rparams* rp|s, nsteps, rp"
  "counts|void|aw_i64 seg_first, AW_CONSTANT aw_iparams* ip|seg_first, ip"
  "window_begin|void||"
  "sample|void|const aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out|s, l, rp, ip, out"
  "flag|void|int* flag|flag"
  "window_end|void|aw_i64 w, const real* dx, const real* dy, const real* dz, aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out|w, dx, dy, dz, l, rp, ip, out"
  "finish|void|aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out|s, l, rp, ip, out"
  "carry_save|void|aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_lanes l|out, ip, l"
  "carry_load|void|aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_lanes l|out, ip, l")

function(arnoldweb_effects out_dir)
  set(dir "${PROJECT_SOURCE_DIR}/lib/device/effects")
  if(ARGC GREATER 1)
    set(dir "${ARGV1}")
  endif()
  set(depends CONFIGURE_DEPENDS)  # a new effect header configures again
  if(CMAKE_SCRIPT_MODE_FILE)
    set(depends "")  # cmake -P (the test) has no configure to repeat
  endif()
  file(GLOB headers ${depends} RELATIVE "${dir}" "${dir}/aw_fx_*.h")
  set(hook_names)
  foreach(row IN LISTS ARNOLDWEB_EFFECT_HOOKS)
    string(REGEX REPLACE "\\|.*" "" hook "${row}")
    list(APPEND hook_names "${hook}")
  endforeach()
  string(REPLACE ";" ", " hooks_text "${hook_names}")
  set(effects)  # "<order>:<name>"
  foreach(h IN LISTS headers)
    string(REGEX REPLACE "^aw_fx_(.*)\\.h$" "\\1" name "${h}")
    file(READ "${dir}/${h}" text)
    string(REGEX MATCHALL "AW_FN (void|int) aw_fx_${name}_[a-z0-9_]+\\(" defined "${text}")
    string(REGEX MATCHALL "(^|\n)AW_EFFECT_ORDER\\([^)\n]*\\)" orders "${text}")
    list(LENGTH orders n)
    if(defined STREQUAL "" AND n EQUAL 0)
      continue()  # a helper of the effects (aw_fx_common.h, aw_fx_carry.h)
    endif()
    if(NOT n EQUAL 1 OR NOT orders MATCHES "AW_EFFECT_ORDER\\(([0-9]+)\\)$")
      message(FATAL_ERROR "${dir}/${h}: an effect declares its place once, on a line of its own: "
                          "AW_EFFECT_ORDER(<n>), its hooks called in increasing n (docs/design.md, \"The effect hooks\")")
    endif()
    math(EXPR order "${CMAKE_MATCH_1}")
    if(defined STREQUAL "")
      message(FATAL_ERROR "${dir}/${h}: AW_EFFECT_ORDER without a hook: define one of "
                          "aw_fx_${name}_<hook>, the hooks: ${hooks_text} (cmake/ArnoldwebEffects.cmake lists their parameters)")
    endif()
    foreach(fn IN LISTS defined)
      string(REGEX REPLACE "^AW_FN (void|int) aw_fx_${name}_([a-z0-9_]+)\\($" "\\2" hook "${fn}")
      if(NOT hook IN_LIST hook_names)
        message(FATAL_ERROR "${dir}/${h}: aw_fx_${name}_${hook} is not a hook (the hooks: ${hooks_text}); "
                            "name a helper otherwise")
      endif()
    endforeach()
    foreach(e IN LISTS effects)
      if(e MATCHES "^${order}:(.*)$")
        message(FATAL_ERROR "${dir}/${h} and aw_fx_${CMAKE_MATCH_1}.h both declare AW_EFFECT_ORDER(${order}): "
                            "the order of the effects is total; give ${name} a free place")
      endif()
    endforeach()
    list(APPEND effects "${order}:${name}")
    set(text_${name} "${text}")
  endforeach()
  list(SORT effects COMPARE NATURAL)

  set(includes "")
  set(members "")
  set(functions "")
  set(names)
  foreach(e IN LISTS effects)
    string(REGEX REPLACE "^[0-9]+:" "" name "${e}")
    list(APPEND names "${name}")
    string(APPEND includes "#include \"effects/aw_fx_${name}.h\"\n")
    if(text_${name} MATCHES "} aw_fx_${name}_state;")
      string(APPEND members "  aw_fx_${name}_state ${name};\n")
      set(me_${name} "&fx->${name}, ")
    else()
      set(me_${name} "")
    endif()
  endforeach()
  foreach(row IN LISTS ARNOLDWEB_EFFECT_HOOKS)
    string(REPLACE "|" ";" row "${row}")
    list(GET row 0 hook)
    list(GET row 1 type)
    list(LENGTH row len)
    set(params "")
    set(args "")
    if(len GREATER 2)
      list(GET row 2 params)
    endif()
    if(len GREATER 3)
      list(GET row 3 args)
    endif()
    if(NOT params STREQUAL "")
      set(params ", ${params}")
    endif()
    if(NOT args STREQUAL "")
      set(args ", ${args}")
    endif()
    set(calls "")
    foreach(name IN LISTS names)
      if(text_${name} MATCHES "AW_FN (void|int) aw_fx_${name}_${hook}\\(")
        set(call "aw_fx_${name}_${hook}(cfg, ${me_${name}}&fx->core${args})")
        if(type STREQUAL "int")
          string(APPEND calls " ||\n         ${call}")
        else()
          string(APPEND calls "  ${call};\n")
        endif()
      endif()
    endforeach()
    if(type STREQUAL "int")
      set(body "  return 0${calls};\n")
    else()
      set(body "${calls}")
    endif()
    string(APPEND functions "AW_FN ${type} aw_fx_effects_${hook}(aw_config cfg, aw_fx* fx${params}) {\n${body}}\n\n")
  endforeach()
  arnoldweb_effect_declarations("${out_dir}" "${dir}" "${headers}")
  string(REPLACE ";" ", " order_text "${names}")
  file(CONFIGURE OUTPUT "${out_dir}/effects/aw_effect_hooks.h" CONTENT
"/* arnoldweb: the effects' hooks, generated by cmake/ArnoldwebEffects.cmake
 * from the headers lib/device/effects/aw_fx_<name>.h (their AW_EFFECT_ORDER):
 * ${order_text}.
 * Each aw_fx_effects_<hook> calls that hook of every effect that has it, in
 * this order (effects/aw_effects.h calls them). */
#ifndef AW_EFFECT_HOOKS_H
#define AW_EFFECT_HOOKS_H

#include \"effects/aw_fx_common.h\"
${includes}
/* What the effects keep per lane between the hooks. */
typedef struct {
  aw_fx_core core;
${members}} aw_fx;

${functions}#endif /* AW_EFFECT_HOOKS_H */
" @ONLY)
endfunction()

# The declarations blocks of the headers (every aw_fx_*.h that has one, the
# carry's among them) gathered for the host: aw_effect_declarations.h.
function(arnoldweb_effect_declarations out_dir dir headers)
  set(includes "")
  set(bits "")      # "<value>:<name>:<header>"
  set(slots "")
  set(rparams "")
  set(iparams "")
  foreach(h IN LISTS headers)
    file(READ "${dir}/${h}" text)
    if(NOT text MATCHES "#ifndef (AW_FX_[A-Z0-9_]+)_DECLARATIONS\n")
      continue()
    endif()
    set(prefix "${CMAKE_MATCH_1}")
    string(APPEND includes "#include \"effects/${h}\"\n")
    string(REGEX MATCHALL "\n#define AW_F_[A-Z0-9_]+ +0x[0-9a-fA-F]+u?" found "${text}")
    foreach(b IN LISTS found)
      string(REGEX REPLACE "^\n#define (AW_F_[A-Z0-9_]+) +(0x[0-9a-fA-F]+)u?$" "\\1;\\2" b "${b}")
      list(GET b 0 name)
      list(GET b 1 hex)
      math(EXPR value "${hex}")
      math(EXPR lowest "${value} & (0 - ${value})")
      if(value EQUAL 0 OR NOT lowest EQUAL value)
        message(FATAL_ERROR "${dir}/${h}: ${name} ${hex} is not one bit: a feature bit is a power of two")
      endif()
      foreach(other IN LISTS bits)
        if(other MATCHES "^${value}:([^:]*):(.*)$")
          message(FATAL_ERROR "${dir}/${h}: ${name} is ${hex}, the bit of ${CMAKE_MATCH_1} (${CMAKE_MATCH_2}): "
                              "give it a free one")
        endif()
      endforeach()
      list(APPEND bits "${value}:${name}:${h}")
    endforeach()
    string(REGEX MATCHALL "\n#define AW_OUT_[A-Z0-9_]+ +[0-9]+" found "${text}")
    foreach(s IN LISTS found)
      string(REGEX REPLACE "^\n#define (AW_OUT_[A-Z0-9_]+) +([0-9]+)$" "\\1;\\2" s "${s}")
      list(GET s 0 name)
      list(GET s 1 value)
      foreach(other IN LISTS slots)
        if(other MATCHES "^${value}:([^:]*):(.*)$")
          message(FATAL_ERROR "${dir}/${h}: ${name} is slot ${value}, that of ${CMAKE_MATCH_1} (${CMAKE_MATCH_2}): "
                              "give it a free one")
        endif()
      endforeach()
      list(APPEND slots "${value}:${name}:${h}")
    endforeach()
    if(text MATCHES "#define ${prefix}_RPARAMS")
      string(APPEND rparams " ${prefix}_RPARAMS")
    endif()
    if(text MATCHES "#define ${prefix}_IPARAMS")
      string(APPEND iparams " ${prefix}_IPARAMS")
    endif()
  endforeach()
  set(all "")
  list(SORT bits COMPARE NATURAL)
  foreach(b IN LISTS bits)
    string(REGEX REPLACE "^[0-9]+:([^:]*):.*$" "\\1" name "${b}")
    if(all STREQUAL "")
      set(all "${name}")
    else()
      string(APPEND all " | ${name}")
    endif()
  endforeach()
  set(slot_checks "")
  foreach(s IN LISTS slots)
    string(REGEX REPLACE "^[0-9]+:([^:]*):(.*)$" "\\1;\\2" s "${s}")
    list(GET s 0 name)
    list(GET s 1 h)
    string(APPEND slot_checks "#if ${name} >= AW_OUT_SLOTS\n#error \"${h}: ${name} is not below AW_OUT_SLOTS (aw_params.h)\"\n#endif\n")
  endforeach()
  file(CONFIGURE OUTPUT "${out_dir}/effects/aw_effect_declarations.h" CONTENT
"/* arnoldweb: what the host and the kernels read of the effects, generated by
 * cmake/ArnoldwebEffects.cmake from the declarations blocks of
 * lib/device/effects/aw_fx_*.h (plain macros: their feature bits, record
 * slots, sizes and parameters). aw_params.h includes it. */
#ifndef AW_EFFECT_DECLARATIONS_H
#define AW_EFFECT_DECLARATIONS_H

#define AW_EFFECT_DECLARATIONS_ONLY
${includes}#undef AW_EFFECT_DECLARATIONS_ONLY

/* every feature bit */
#define AW_F_ALL (${all})

${slot_checks}
/* the members the effects add to the parameter blocks (aw_param_blocks.h) */
#define AW_EFFECTS_RPARAMS${rparams}
#define AW_EFFECTS_IPARAMS${iparams}

#endif /* AW_EFFECT_DECLARATIONS_H */
" @ONLY)
endfunction()
