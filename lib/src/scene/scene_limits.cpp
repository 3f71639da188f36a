// arnoldweb scene layer: limits checked before the TOML parser sees a text.
// The parser recurses on nesting and dotted keys (a header of ~35,000 dotted
// parts overflowed its stack) and is slow on multi-megabyte keys, so a scene
// is refused first if it is larger than kMaxSceneBytes, nests arrays and
// tables deeper than kMaxNesting, or has a bare word (a key path or a value
// outside quotes) longer than kMaxWordLength or with more than
// kMaxDottedParts dotted parts. Quoted strings and comments are not limited
// (beyond the size of the scene).
#include "arnoldweb/errors.hpp"
#include "scene/scene_internal.hpp"

namespace arnoldweb::scene_detail {

void check_text_limits(const std::string& text, const std::string& file) {
  if (text.size() > kMaxSceneBytes)
    throw SceneError(file, 0, 0, "",
                     "the scene is " + std::to_string(text.size()) + " bytes; scenes of at most " +
                         std::to_string(kMaxSceneBytes) + " bytes are read");
  enum class In { Code, Comment, Basic, Literal, MultiBasic, MultiLiteral } in = In::Code;
  int line = 1, column = 0;
  int depth = 0;
  std::size_t word = 0, dots = 0;  // the bare word being read
  int word_line = 1, word_column = 1;
  auto fail = [&](int l, int c, const std::string& what) { throw SceneError(file, l, c, "", what); };
  auto end_word = [&] { word = dots = 0; };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      column = 0;
    } else {
      ++column;
    }
    auto starts = [&](const char* s) { return text.compare(i, 3, s) == 0; };
    switch (in) {
      case In::Comment:
        if (c == '\n') in = In::Code;
        continue;
      case In::Basic:
        if (c == '\\') ++i, ++column;
        else if (c == '"' || c == '\n') in = In::Code;
        continue;
      case In::Literal:
        if (c == '\'' || c == '\n') in = In::Code;
        continue;
      case In::MultiBasic:
        if (c == '\\') ++i, ++column;
        else if (starts("\"\"\"")) in = In::Code, i += 2, column += 2;
        continue;
      case In::MultiLiteral:
        if (starts("'''")) in = In::Code, i += 2, column += 2;
        continue;
      case In::Code:
        break;
    }
    switch (c) {
      case '#': in = In::Comment; end_word(); continue;
      case '"':
        in = starts("\"\"\"") ? (i += 2, column += 2, In::MultiBasic) : In::Basic;
        continue;  // a quoted part of a dotted key continues the word
      case '\'':
        in = starts("'''") ? (i += 2, column += 2, In::MultiLiteral) : In::Literal;
        continue;
      case '[': case '{':
        if (++depth > kMaxNesting)
          fail(line, column, "arrays and tables are nested more than " + std::to_string(kMaxNesting) + " deep");
        end_word();
        continue;
      case ']': case '}':
        if (depth > 0) --depth;
        end_word();
        continue;
      case ',': case '=': case '\n': case '\r':
        end_word();
        continue;
      default:
        break;
    }
    if (c == ' ' || c == '\t') continue;  // dotted keys may have spaces around the dots
    if (word == 0) word_line = line, word_column = column;
    if (++word > kMaxWordLength)
      fail(word_line, word_column,
           "a key or bare value longer than " + std::to_string(kMaxWordLength) + " characters");
    if (c == '.' && ++dots >= kMaxDottedParts)
      fail(word_line, word_column, "a key with more than " + std::to_string(kMaxDottedParts) + " dotted parts");
  }
}

}  // namespace arnoldweb::scene_detail
