// arnoldweb expression models: the tokens of a potential's text.
#pragma once

#include <string>
#include <vector>

namespace arnoldweb::detail::expression {

enum class Tok { Number, Name, Plus, Minus, Star, Slash, Caret, LParen, RParen, End };

struct Token {
  Tok kind = Tok::End;
  int column = 0;     // 1-based position of its first character
  std::string text;   // as written
  double value = 0;   // Number
};

// Splits the text into tokens (the last one is End); throws ExpressionError
// naming the column of a character that starts no token, a malformed or
// out-of-range number, or "**" (powers are written ^).
std::vector<Token> tokenize(const std::string& text);

// How a token is named in messages: "'+'", "the name \"w\"", "end of input".
std::string describe(const Token& t);

}  // namespace arnoldweb::detail::expression
