// arnoldweb expression models: device code from the lowered form.
//
// The emitted header implements the potential part of the model interface
// (lib/device/models/aw_models.h) in the portable dialect of lib/device (C
// that compiles as OpenCL C, CUDA and C++):
//   aw_model_potential(ux, uy, uz, rp)     V
//   aw_model_force(s, rp)                  F = -grad V into s->f
//   aw_model_force_hessian(s, rp, hess)    F and the Hessian (xx, yy, zz, xy, xz, yz)
// One statement per node, in the order of the node ids (operands before
// their users), each a single + - * / or call, so no compiler may reorder or
// contract anything (the kernels are compiled with contraction off); sin and
// cos go through aw_sincos2pi (one call for both of an argument), exp through
// aw_exp, sqrt through AW_SQRT. The force and the Hessian come from the same
// statements in both force functions, so they agree bit for bit. Parameter i
// is rp->model[parameter_base + i].
#pragma once

#include <string>
#include <vector>

#include "physics/expression/lower.hpp"

namespace arnoldweb::detail::expression {

struct EmitOptions {
  std::string source;                        // the potential as written (a comment)
  std::vector<std::string> parameter_names;  // for the comment
  int parameter_base = 0;                    // first slot in rp->model
  bool kinetic = false;  // include models/aw_expression_kinetic.h: a whole model, not only V
};

std::string emit_device_header(const LoweredForm& form, const EmitOptions& options);

// The C literal of a constant: AW_R(<shortest decimal that reads back exactly>).
std::string c_literal(double v);

}  // namespace arnoldweb::detail::expression
