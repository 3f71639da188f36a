// arnoldweb expression models: device code from the lowered form (emitter.hpp).
#include "physics/expression/emitter.hpp"

#include <set>
#include <sstream>

namespace arnoldweb::detail::expression {

std::string c_literal(double v) {
  std::string t = number_text(v);
  if (t.find_first_of(".e") == std::string::npos) t += ".0";  // AW_R(2) would be "2f" in float
  return "AW_R(" + t + ")";
}

namespace {

class Writer {
 public:
  Writer(const LoweredForm& form, const EmitOptions& options) : g_(form.graph), opt_(options) {}

  // the statements that compute `roots`, into out (the body of one function)
  void statements(const std::vector<int>& roots, std::ostringstream& out) {
    std::vector<bool> need(static_cast<std::size_t>(g_.size()), false);
    std::vector<int> stack(roots.begin(), roots.end());
    while (!stack.empty()) {
      const int id = stack.back();
      stack.pop_back();
      if (need[static_cast<std::size_t>(id)]) continue;
      need[static_cast<std::size_t>(id)] = true;
      if (g_[id].a >= 0) stack.push_back(g_[id].a);
      if (g_[id].b >= 0) stack.push_back(g_[id].b);
    }
    std::set<int> sincos_done;
    for (int id = 0; id < g_.size(); ++id) {
      if (!need[static_cast<std::size_t>(id)]) continue;
      const Node& n = g_[id];
      switch (n.op) {
        case Op::Const:
        case Op::U:
          break;  // written where used
        case Op::Param:
          out << "  const lreal t" << id << " = AW_LSPLAT(rp->model[" << opt_.parameter_base + n.k << "]);\n";
          break;
        case Op::SinTurns:
        case Op::CosTurns:
          if (sincos_done.insert(n.a).second)
            out << "  lreal s" << n.a << ", c" << n.a << ";\n  aw_sincos2pi(" << name(n.a) << ", &s" << n.a
                << ", &c" << n.a << ");\n";
          break;
        case Op::Add:
        case Op::Sub:
        case Op::Mul:
        case Op::Div: {
          const char* sym = n.op == Op::Add ? " + " : n.op == Op::Sub ? " - " : n.op == Op::Mul ? " * " : " / ";
          out << "  const lreal t" << id << " = " << name(n.a) << sym << name(n.b) << ";\n";
          break;
        }
        case Op::Neg:
          out << "  const lreal t" << id << " = -" << name(n.a) << ";\n";
          break;
        case Op::Exp:
          out << "  const lreal t" << id << " = aw_exp(" << name(n.a) << ");\n";
          break;
        case Op::Sqrt:
          out << "  const lreal t" << id << " = AW_SQRT(" << name(n.a) << ");\n";
          break;
        default:
          throw ExpressionError(0, "internal: the emitter needs the lowered form");
      }
    }
  }

  // an operand: a literal, a coordinate, a sin/cos variable or a statement's name
  std::string name(int id) const {
    const Node& n = g_[id];
    switch (n.op) {
      case Op::Const:
        return c_literal(n.value);
      case Op::U:
        return n.k == 0 ? "ux" : n.k == 1 ? "uy" : "uz";
      case Op::SinTurns:
        return "s" + std::to_string(n.a);
      case Op::CosTurns:
        return "c" + std::to_string(n.a);
      default:
        return "t" + std::to_string(id);
    }
  }

  // a root, as an lreal
  std::string value(int id) const {
    return g_[id].op == Op::Const ? "AW_LSPLAT(" + c_literal(g_[id].value) + ")" : name(id);
  }

  // the coordinates a function's statements read
  void read_coordinates(const std::vector<int>& roots, std::ostringstream& out) const {
    unsigned vars = 0;
    for (int r : roots) vars |= g_[r].vars;
    static const char* const names[] = {"ux", "uy", "uz"};
    for (int i = 0; i < 3; ++i)
      if (vars & (1u << i)) out << "  const lreal " << names[i] << " = s->" << names[i] << ";\n";
  }

 private:
  const Graph& g_;
  const EmitOptions& opt_;
};

}  // namespace

std::string emit_device_header(const LoweredForm& form, const EmitOptions& options) {
  Writer w(form, options);
  std::ostringstream out;
  out << "/* arnoldweb expression model: generated from model.potential (lib/src/physics/expression/).\n"
      << " *   V = " << options.source << "\n";
  for (std::size_t i = 0; i < options.parameter_names.size(); ++i)
    out << " *   " << options.parameter_names[i] << " = rp->model[" << options.parameter_base + static_cast<int>(i)
        << "]\n";
  out << " * One statement per operation, in a fixed order; see docs/models.md. */\n"
      << "#ifndef AW_EXPRESSION_MODEL_H\n#define AW_EXPRESSION_MODEL_H\n\n"
      << "#include \"aw_exp.h\"\n#include \"aw_math.h\"\n#include \"aw_state.h\"\n";
  if (options.kinetic) out << "#include \"kinetic/aw_expression_kinetic.h\"\n";
  out << "\n";

  const std::vector<int> v{form.value};
  out << "AW_FN lreal aw_model_potential(lreal ux, lreal uy, lreal uz, AW_CONSTANT aw_rparams* rp) {\n";
  w.statements(v, out);
  out << "  return " << w.value(form.value) << ";\n}\n\n";

  const std::vector<int> f(form.force.begin(), form.force.end());
  out << "AW_FN void aw_model_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) {\n";
  w.read_coordinates(f, out);
  w.statements(f, out);
  out << "  s->fx = " << w.value(form.force[0]) << ";\n  s->fy = " << w.value(form.force[1])
      << ";\n  s->fz = " << w.value(form.force[2]) << ";\n}\n\n";

  std::vector<int> fh = f;
  fh.insert(fh.end(), form.hessian.begin(), form.hessian.end());
  out << "AW_FN void aw_model_force_hessian(aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal* hess) {\n";
  w.read_coordinates(fh, out);
  w.statements(fh, out);
  out << "  s->fx = " << w.value(form.force[0]) << ";\n  s->fy = " << w.value(form.force[1])
      << ";\n  s->fz = " << w.value(form.force[2]) << ";\n";
  for (std::size_t i = 0; i < 6; ++i) out << "  hess[" << i << "] = " << w.value(form.hessian[i]) << ";\n";
  out << "}\n\n#endif /* AW_EXPRESSION_MODEL_H */\n";
  return out.str();
}

}  // namespace arnoldweb::detail::expression
