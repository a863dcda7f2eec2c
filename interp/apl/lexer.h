// The tokens of an APL statement (APL\360 User's Manual, chapter 1: names, numbers, literals,
// the function symbols). Numbers side by side are one constant vector; `⍝` starts a comment.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "interp/apl/glyphs.h"
#include "interp/apl/value.h"

namespace igds::apl {

enum class TokenKind {
  number,         // a numeric constant, one number or a vector of them (`literal`)
  string,         // a character constant (`literal`)
  name,           // a name, letters folded to capitals (`text`)
  system_name,    // ⎕IO, ⎕PP, ...: `text` is the whole name with its quad
  quad,           // ⎕ alone: evaluated input or output
  quote_quad,     // ⍞: character input or output
  function,       // a primitive function symbol, / \ ⌿ ⍀ included (`glyph`)
  dot,            // . of the inner and outer products
  jot,            // ∘ of the outer product
  assign,         // ←
  branch,         // →
  left_paren,     // (
  right_paren,    // )
  left_bracket,   // [
  right_bracket,  // ]
  semicolon,      // ;
  colon,          // : after a label
  del,            // ∇
};

struct Token {
  TokenKind kind = TokenKind::name;
  std::size_t column = 0;  // the first character, counted from 0 in the line
  std::size_t end = 0;     // one past the last character
  char32_t glyph = 0;
  std::string text;
  Value literal;
};

// The primitive function symbols of the glyph table (interp/apl/glyphs.h), in any of their
// spellings (− ⋆ ∣ ∼ ∈ ^ are - * | ~ ∊ ∧).
bool is_primitive_glyph(char32_t c);
// Characters of names: letters, ∆ ⍙ _ and, after the first, digits.
bool is_name_start(char32_t c);
bool is_name_char(char32_t c);

// The tokens of one line, up to a comment. SYNTAX ERROR (with its column) for a character that
// is no APL symbol, an unterminated character constant or a malformed number.
std::vector<Token> tokenize(std::u32string_view line);

// The line without its comment (a ⍝ outside quotes and what follows it).
std::u32string_view strip_comment(std::u32string_view line);

}  // namespace igds::apl
