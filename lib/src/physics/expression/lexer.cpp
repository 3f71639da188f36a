// arnoldweb expression models: the tokens of a potential's text (lexer.hpp).
#include "physics/expression/lexer.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "physics/expression/graph.hpp"

namespace arnoldweb::detail::expression {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const int column = static_cast<int>(i) + 1;
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++i;
      continue;
    }
    Token t;
    t.column = column;
    if (is_digit(c) || (c == '.' && i + 1 < text.size() && is_digit(text[i + 1]))) {
      std::size_t j = i;
      while (j < text.size() && is_digit(text[j])) ++j;
      if (j < text.size() && text[j] == '.') {
        ++j;
        while (j < text.size() && is_digit(text[j])) ++j;
      }
      if (j < text.size() && (text[j] == 'e' || text[j] == 'E')) {
        std::size_t k = j + 1;
        if (k < text.size() && (text[k] == '+' || text[k] == '-')) ++k;
        if (k >= text.size() || !is_digit(text[k]))
          throw ExpressionError(column, "malformed number \"" + text.substr(i, k - i) +
                                            "\": an exponent needs digits (e.g. 1e-3)");
        while (k < text.size() && is_digit(text[k])) ++k;
        j = k;
      }
      t.kind = Tok::Number;
      t.text = text.substr(i, j - i);
      errno = 0;
      t.value = std::strtod(t.text.c_str(), nullptr);
      if (errno == ERANGE || !std::isfinite(t.value))
        throw ExpressionError(column, "number \"" + t.text + "\" is out of the range of double precision");
      i = j;
    } else if (is_name_start(c)) {
      std::size_t j = i;
      while (j < text.size() && is_name_char(text[j])) ++j;
      t.kind = Tok::Name;
      t.text = text.substr(i, j - i);
      i = j;
    } else {
      switch (c) {
        case '+':
          t.kind = Tok::Plus;
          break;
        case '-':
          t.kind = Tok::Minus;
          break;
        case '*':
          if (i + 1 < text.size() && text[i + 1] == '*')
            throw ExpressionError(column, "powers are written ^ (e.g. cos(x)^2), not **");
          t.kind = Tok::Star;
          break;
        case '/':
          t.kind = Tok::Slash;
          break;
        case '^':
          t.kind = Tok::Caret;
          break;
        case '(':
          t.kind = Tok::LParen;
          break;
        case ')':
          t.kind = Tok::RParen;
          break;
        default: {
          const bool printable = static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
          throw ExpressionError(column, printable ? std::string("unexpected character '") + c +
                                                        "' (allowed: numbers, names, + - * / ^ and parentheses)"
                                                  : "unexpected non-ASCII or control character (byte " +
                                                        std::to_string(static_cast<unsigned char>(c)) + ")");
        }
      }
      t.text = std::string(1, c);
      ++i;
    }
    out.push_back(t);
  }
  Token end;
  end.kind = Tok::End;
  end.column = static_cast<int>(text.size()) + 1;
  out.push_back(end);
  return out;
}

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::End:
      return "end of input";
    case Tok::Number:
      return "the number " + t.text;
    case Tok::Name:
      return "the name \"" + t.text + "\"";
    default:
      return "'" + t.text + "'";
  }
}

}  // namespace arnoldweb::detail::expression
