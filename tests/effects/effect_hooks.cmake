# The effects' hooks (cmake/ArnoldwebEffects.cmake): generated in the order
# each effect header declares (AW_EFFECT_ORDER), never in the order of the
# names; a header's state and hooks found by their names; a header with hooks
# and no order, an order twice, two effects at one place, a function named
# like a hook that is not one, or an order without hooks stop the configure
# naming the header; the declarations blocks gathered (the bits' union, the
# parameters), a bit that is not one and a bit or a slot taken twice refused.
#   cmake -DSOURCE_DIR=<repo> -P tests/effects/effect_hooks.cmake   (ctest effects.hooks)
# With -DCASE=<dir> it generates the hooks of the headers in <dir> and prints
# the generated files (one case).
cmake_minimum_required(VERSION 3.20)  # the project's policies (IN_LIST)
if(DEFINED CASE)
  set(PROJECT_SOURCE_DIR "${SOURCE_DIR}")
  include("${SOURCE_DIR}/cmake/ArnoldwebEffects.cmake")
  arnoldweb_effects("${CASE}/out" "${CASE}")
  file(READ "${CASE}/out/effects/aw_effect_hooks.h" text)
  file(READ "${CASE}/out/effects/aw_effect_declarations.h" declarations)
  message("${text}${declarations}")
  return()
endif()

include("${SOURCE_DIR}/tests/support/script_cases.cmake")
set(work "${CMAKE_CURRENT_BINARY_DIR}/effect_hooks_test")
file(REMOVE_RECURSE "${work}")
# effect_case(<name> <0: succeeds, 1: fails> <what the output holds> <effect>=<its header's text, @SEMI@ for ;> ...)
function(effect_case name must_fail expected)
  awtest_case_files("${work}/${name}" "aw_fx_<name>.h" "/* an effect */" ${ARGN})
  awtest_script_case("${name}" ${must_fail} "${expected}" "${work}/${name}")
endfunction()

set(zeta_hooks "AW_EFFECT_ORDER(5)\ntypedef struct { lreal x@SEMI@ } aw_fx_zeta_state@SEMI@\nAW_FN void aw_fx_zeta_sample(aw_config cfg, aw_fx_zeta_state* me, aw_fx_core* fx, ...) {}\nAW_FN void aw_fx_zeta_finish(aw_config cfg, aw_fx_zeta_state* me, aw_fx_core* fx, ...) {}")
set(alpha_hooks "AW_EFFECT_ORDER(20)\nAW_FN void aw_fx_alpha_finish(aw_config cfg, aw_fx_core* fx, ...) {}\nAW_FN int aw_fx_alpha_steps(aw_config cfg, aw_fx_core* fx, ...) { return 0@SEMI@ }")
# the order declared, not the names': zeta (5) before alpha (20); zeta's state passed, alpha has none
effect_case(order 0 "aw_fx_zeta_finish(cfg, &fx->zeta, &fx->core, s, l, rp, ip, out); aw_fx_alpha_finish(cfg, &fx->core, s, l, rp, ip, out);"
            "zeta=${zeta_hooks}" "alpha=${alpha_hooks}")
effect_case(state 0 "typedef struct { aw_fx_core core; aw_fx_zeta_state zeta; } aw_fx;" "zeta=${zeta_hooks}" "alpha=${alpha_hooks}")
effect_case(includes 0 "#include \"effects/aw_fx_zeta.h\" #include \"effects/aw_fx_alpha.h\"" "zeta=${zeta_hooks}" "alpha=${alpha_hooks}")
# a hook no effect has is an empty call list; an int hook is "the first effect that takes it"
effect_case(empty 0 "AW_FN void aw_fx_effects_window_begin(aw_config cfg, aw_fx* fx) { }" "alpha=${alpha_hooks}")
effect_case(taken 0 "return 0 || aw_fx_alpha_steps(cfg, &fx->core, s, nsteps, rp);" "alpha=${alpha_hooks}")
# a helper (no order, no hook) is no effect
effect_case(helper 0 "#include \"effects/aw_fx_alpha.h\" /* What" "alpha=${alpha_hooks}" "common=AW_FN void aw_helper(void) {}")
effect_case(no-order 1 "aw_fx_new.h: an effect declares its place once" "new=AW_FN void aw_fx_new_sample(aw_config cfg) {}")
effect_case(twice 1 "aw_fx_new.h: an effect declares its place once"
            "new=AW_EFFECT_ORDER(1)\nAW_EFFECT_ORDER(2)\nAW_FN void aw_fx_new_sample(aw_config cfg) {}")
effect_case(clash 1 "both declare AW_EFFECT_ORDER(20)" "alpha=${alpha_hooks}"
            "beta=AW_EFFECT_ORDER(20)\nAW_FN void aw_fx_beta_sample(aw_config cfg) {}")
effect_case(not-a-hook 1 "aw_fx_new_smaple is not a hook (the hooks: begin, first_force"
            "new=AW_EFFECT_ORDER(3)\nAW_FN void aw_fx_new_smaple(aw_config cfg) {}")
effect_case(no-hook 1 "aw_fx_new.h: AW_EFFECT_ORDER without a hook" "new=AW_EFFECT_ORDER(3)\nAW_FN void aw_new_helper(void) {}")
# the declarations blocks: the bits' union, the parameters' members; a bit that is not one, or a
# bit or a slot taken twice, stop the configure naming both headers
macro(declared effect lines)
  string(TOUPPER "${effect}" up)
  set(decl_${effect} "#ifndef AW_FX_${up}_DECLARATIONS\n#define AW_FX_${up}_DECLARATIONS\n${lines}\n#endif\n${alpha_hooks}")
  string(REPLACE "alpha" "${effect}" decl_${effect} "${decl_${effect}}")
endmacro()
declared(alpha "#define AW_F_ALPHA 0x2u\n#define AW_OUT_ALPHA 1\n#define AW_FX_ALPHA_IPARAMS aw_i64 alpha_n@SEMI@")
declared(gamma "#define AW_F_GAMMA 0x8u /* its comment */\n#define AW_FX_GAMMA_RPARAMS real gamma_x@SEMI@")
string(REPLACE "AW_EFFECT_ORDER(20)" "AW_EFFECT_ORDER(30)" decl_gamma "${decl_gamma}")
effect_case(bits 0 "#define AW_F_ALL (AW_F_ALPHA | AW_F_GAMMA)" "alpha=${decl_alpha}" "gamma=${decl_gamma}")
effect_case(params 0 "#define AW_EFFECTS_RPARAMS AW_FX_GAMMA_RPARAMS #define AW_EFFECTS_IPARAMS AW_FX_ALPHA_IPARAMS"
            "alpha=${decl_alpha}" "gamma=${decl_gamma}")
effect_case(slot-check 0 "#if AW_OUT_ALPHA >= AW_OUT_SLOTS" "alpha=${decl_alpha}")
declared(beta "#define AW_F_BETA 0x6u")
string(REPLACE "AW_EFFECT_ORDER(20)" "AW_EFFECT_ORDER(40)" decl_beta "${decl_beta}")
effect_case(not-one-bit 1 "aw_fx_beta.h: AW_F_BETA 0x6 is not one bit" "beta=${decl_beta}")
declared(beta "#define AW_F_BETA 0x2u")
string(REPLACE "AW_EFFECT_ORDER(20)" "AW_EFFECT_ORDER(40)" decl_beta "${decl_beta}")
effect_case(bit-twice 1 "AW_F_BETA is 0x2, the bit of AW_F_ALPHA (aw_fx_alpha.h)" "alpha=${decl_alpha}" "beta=${decl_beta}")
declared(beta "#define AW_F_BETA 0x10u\n#define AW_OUT_BETA 1")
string(REPLACE "AW_EFFECT_ORDER(20)" "AW_EFFECT_ORDER(40)" decl_beta "${decl_beta}")
effect_case(slot-twice 1 "AW_OUT_BETA is slot 1, that of AW_OUT_ALPHA (aw_fx_alpha.h)" "alpha=${decl_alpha}" "beta=${decl_beta}")
awtest_script_cases_end("effect hooks" "${work}")
