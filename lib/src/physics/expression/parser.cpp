// arnoldweb expression models: recursive-descent parser (parser.hpp).
#include "physics/expression/parser.hpp"

#include <cctype>

#include "physics/expression/lexer.hpp"

namespace arnoldweb::detail::expression {
namespace {

const char* const kFunctions[] = {"sin", "cos", "exp", "sqrt"};

bool is_function(const std::string& s) {
  for (const char* f : kFunctions)
    if (s == f) return true;
  return false;
}

class Parser {
 public:
  Parser(Graph& g, std::vector<Token> tokens, const std::vector<std::string>& parameters)
      : g_(g), t_(std::move(tokens)), params_(parameters) {}

  int parse_all() {
    const int root = expression();
    if (peek().kind == Tok::RParen) throw ExpressionError(peek().column, "')' without a matching '('");
    if (peek().kind != Tok::End)
      throw ExpressionError(peek().column, "expected an operator or the end, found " + describe(peek()) +
                                               (peek().kind == Tok::Name || peek().kind == Tok::Number ||
                                                        peek().kind == Tok::LParen
                                                    ? " (write products with *, e.g. 2*x)"
                                                    : ""));
    return root;
  }

 private:
  const Token& peek() const { return t_[pos_]; }
  const Token& next() { return t_[pos_++]; }

  // builds through the graph, turning a folding failure into an error at `column`
  template <class F>
  int build(int column, F f) {
    try {
      return f();
    } catch (const FoldError& e) {
      throw ExpressionError(column, e.message);
    }
  }

  struct Depth {
    Depth(Parser& p, int column) : p_(p) {
      if (++p_.depth_ > kMaxDepth)
        throw ExpressionError(column, "nested too deeply (more than " + std::to_string(kMaxDepth) + " levels)");
    }
    ~Depth() { --p_.depth_; }
    Parser& p_;
  };

  int expression() {
    int left = term();
    while (peek().kind == Tok::Plus || peek().kind == Tok::Minus) {
      const Token op = next();
      const int right = term();
      left = build(op.column, [&] { return op.kind == Tok::Plus ? g_.add(left, right) : g_.sub(left, right); });
    }
    return left;
  }

  int term() {
    int left = unary();
    while (peek().kind == Tok::Star || peek().kind == Tok::Slash) {
      const Token op = next();
      const int right = unary();
      left = build(op.column, [&] { return op.kind == Tok::Star ? g_.mul(left, right) : g_.div(left, right); });
    }
    return left;
  }

  int unary() {
    if (peek().kind == Tok::Minus || peek().kind == Tok::Plus) {
      const Token op = next();
      Depth d(*this, op.column);
      const int a = unary();
      return op.kind == Tok::Minus ? build(op.column, [&] { return g_.neg(a); }) : a;
    }
    return power();
  }

  int power() {
    const int base = primary();
    if (peek().kind != Tok::Caret) return base;
    const Token caret = next();
    const int n = exponent(caret);
    if (peek().kind == Tok::Caret)
      throw ExpressionError(peek().column, "a power of a power is ambiguous: use parentheses, e.g. (x^2)^3");
    return build(caret.column, [&] { return g_.pow(base, n); });
  }

  int exponent(const Token& caret) {
    bool paren = false;
    if (peek().kind == Tok::LParen) {
      paren = true;
      next();
    }
    int sign = 1;
    if (peek().kind == Tok::Minus || peek().kind == Tok::Plus) sign = next().kind == Tok::Minus ? -1 : 1;
    const Token& t = peek();
    bool integer = t.kind == Tok::Number;
    for (char c : t.text) integer = integer && std::isdigit(static_cast<unsigned char>(c));
    if (!integer)
      throw ExpressionError(t.column, "an exponent must be an integer (e.g. x^2 or x^-1), found " + describe(t));
    if (t.value > kMaxExponent)
      throw ExpressionError(t.column, "exponent " + t.text + " is too large (at most " +
                                          std::to_string(kMaxExponent) + " in magnitude)");
    next();
    if (paren) {
      if (peek().kind != Tok::RParen)
        throw ExpressionError(peek().column, "expected ')' after the exponent, found " + describe(peek()));
      next();
    }
    (void)caret;
    return sign * static_cast<int>(t.value);
  }

  int primary() {
    const Token t = next();
    switch (t.kind) {
      case Tok::Number:
        return g_.constant(t.value);
      case Tok::LParen: {
        Depth d(*this, t.column);
        const int inner = expression();
        close(t);
        return inner;
      }
      case Tok::Name:
        return name(t);
      case Tok::End:
        throw ExpressionError(t.column, pos_ == 1 ? "the expression is empty"
                                                  : "unexpected end: expected a number, a name or '('");
      default:
        throw ExpressionError(t.column, "expected a number, a name or '(', found " + describe(t));
    }
  }

  void close(const Token& open) {
    if (peek().kind != Tok::RParen)
      throw ExpressionError(peek().column, "expected ')' to close the '(' at column " + std::to_string(open.column) +
                                               ", found " + describe(peek()));
    next();
  }

  int name(const Token& t) {
    if (is_function(t.text)) {
      if (peek().kind != Tok::LParen)
        throw ExpressionError(peek().column, t.text + " needs its argument in parentheses, e.g. " + t.text + "(x)");
      const Token open = next();
      Depth d(*this, open.column);
      const int arg = expression();
      close(open);
      return build(t.column, [&] {
        if (t.text == "sin") return g_.sin(arg);
        if (t.text == "cos") return g_.cos(arg);
        if (t.text == "exp") return g_.exp(arg);
        return g_.sqrt(arg);
      });
    }
    if (peek().kind == Tok::LParen)
      throw ExpressionError(t.column, "unknown function \"" + t.text + "\" (functions are sin, cos, exp, sqrt)");
    if (t.text == "x") return g_.var(0);
    if (t.text == "y") return g_.var(1);
    if (t.text == "z") return g_.var(2);
    if (t.text == "pi") return g_.constant(3.141592653589793);
    for (std::size_t i = 0; i < params_.size(); ++i)
      if (params_[i] == t.text) return g_.param(static_cast<int>(i));
    std::string list;
    for (const auto& p : params_) list += (list.empty() ? "" : ", ") + p;
    throw ExpressionError(t.column, "unknown name \"" + t.text + "\" (variables are x, y, z; " +
                                        (list.empty() ? std::string("no parameters are given") : "parameters: " + list) +
                                        ")");
  }

  Graph& g_;
  std::vector<Token> t_;
  const std::vector<std::string>& params_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

bool valid_parameter_name(const std::string& name, std::string* why) {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (name.empty()) return fail("a parameter needs a name");
  if (!(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
    return fail("\"" + name + "\" is not a name (letters, digits and _, not starting with a digit)");
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
      return fail("\"" + name + "\" is not a name (letters, digits and _, not starting with a digit)");
  if (name == "x" || name == "y" || name == "z" || name == "pi")
    return fail("\"" + name + "\" is reserved (x, y, z are the coordinates, pi the number)");
  if (is_function(name)) return fail("\"" + name + "\" is a function name");
  return true;
}

int parse(Graph& g, const std::string& text, const std::vector<std::string>& parameters) {
  if (text.size() > kMaxLength)
    throw ExpressionError(0, "the expression is " + std::to_string(text.size()) + " characters long (at most " +
                                 std::to_string(kMaxLength) + ")");
  Parser p(g, tokenize(text), parameters);
  return p.parse_all();
}

}  // namespace arnoldweb::detail::expression
