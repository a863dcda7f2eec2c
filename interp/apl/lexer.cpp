#include "interp/apl/lexer.h"

#include <cmath>
#include <string_view>

#include "interp/apl/error.h"
#include "interp/apl/glyphs.h"
#include "interp/apl/text.h"
#include "workspace/numbers/typed.h"

namespace igds::apl {

namespace {

bool is_digit(char32_t c) {
  return c >= U'0' && c <= U'9';
}

[[noreturn]] void syntax_at(std::size_t column) {
  Error e(ErrorKind::syntax);
  e.set_column(column);
  throw e;
}

// Whether a number starts at i: a digit, a high minus, or a point followed by a digit.
bool number_starts(std::u32string_view line, std::size_t i) {
  if (i >= line.size()) return false;
  char32_t c = line[i];
  if (is_digit(c) || c == U'¯') return true;
  return c == U'.' && i + 1 < line.size() && is_digit(line[i + 1]);
}

// One number at i (APL\360 User's Manual: `¯3.5`, `1E¯3`, `.5`, `1.5E3`); i moves past it. A
// number beyond the largest double is a DOMAIN ERROR; one below the smallest is zero.
double number_at(std::u32string_view line, std::size_t& i) {
  const std::size_t start = i;
  const ScannedNumber n = igds::scan_number(line.substr(i), NumberSigns::apl);
  if (n.length == 0) syntax_at(start);
  i += n.length;
  // A number runs into nothing: `1.2.3`, `3A`, `2E` and `1¯2` are malformed.
  if (i < line.size() && (is_name_char(line[i]) || line[i] == U'.' || line[i] == U'¯'))
    syntax_at(start);
  if (std::isinf(n.value)) {
    Error e(ErrorKind::domain);
    e.set_column(start);
    throw e;
  }
  return n.value;
}

Token simple(TokenKind kind, std::size_t column, char32_t glyph = 0) {
  Token t;
  t.kind = kind;
  t.column = column;
  t.glyph = glyph;
  return t;
}

}  // namespace

bool is_primitive_glyph(char32_t c) {
  return has_role(
      c, Role::scalar_monadic | Role::scalar_dyadic | Role::mixed_monadic | Role::mixed_dyadic);
}

bool is_name_start(char32_t c) {
  return (c >= U'A' && c <= U'Z') || (c >= U'a' && c <= U'z') || c == U'_' ||
         (c >= 0x80 && has_role(c, Role::name_character));
}

bool is_name_char(char32_t c) {
  return is_name_start(c) || is_digit(c);
}

std::u32string_view strip_comment(std::u32string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == U'\'') quoted = !quoted;
    if (line[i] == U'⍝' && !quoted) return line.substr(0, i);
  }
  return line;
}

std::vector<Token> tokenize(std::u32string_view line) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    if (!tokens.empty() && tokens.back().end == 0) tokens.back().end = i;
    const char32_t c = line[i];
    const std::size_t column = i;
    if (c == U' ' || c == U'\t' || c == U'\r') {  // \r: a line from a file with CR LF ends
      ++i;
    } else if (c == U'⍝') {
      break;
    } else if (number_starts(line, i)) {
      Numbers values;
      while (true) {
        values.push_back(number_at(line, i));
        std::size_t j = i;
        while (j < line.size() && (line[j] == U' ' || line[j] == U'\t')) ++j;
        if (!number_starts(line, j)) break;
        i = j;
      }
      Token t = simple(TokenKind::number, column);
      const std::size_t n = values.size();  // before the move: arguments have no order
      t.literal = n == 1 ? Value::number(values[0]) : Value::of_numbers({n}, std::move(values));
      tokens.push_back(std::move(t));
    } else if (c == U'\'') {
      std::u32string text;
      ++i;
      while (true) {
        if (i >= line.size()) syntax_at(column);
        if (line[i] == U'\'') {
          if (i + 1 < line.size() && line[i + 1] == U'\'') {
            text.push_back(U'\'');
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        text.push_back(line[i++]);
      }
      Token t = simple(TokenKind::string, column);
      t.literal = text.size() == 1 ? Value::character(text[0]) : Value::text(text);
      tokens.push_back(std::move(t));
    } else if (is_name_start(c)) {
      Token t = simple(TokenKind::name, column);
      while (i < line.size() && is_name_char(line[i])) {
        char32_t n = line[i++];
        if (n >= U'a' && n <= U'z') n = n - U'a' + U'A';
        append_utf8(t.text, n);
      }
      tokens.push_back(std::move(t));
    } else if (c == U'⎕') {
      ++i;
      if (i < line.size() && is_name_start(line[i])) {
        Token t = simple(TokenKind::system_name, column);
        t.text = "⎕";
        while (i < line.size() && is_name_char(line[i])) {
          char32_t n = line[i++];
          if (n >= U'a' && n <= U'z') n = n - U'a' + U'A';
          if (n >= 0x80) syntax_at(column);
          t.text.push_back(static_cast<char>(n));
        }
        tokens.push_back(std::move(t));
      } else {
        tokens.push_back(simple(TokenKind::quad, column));
      }
    } else {
      ++i;
      switch (c) {
        case U'⍞':
          tokens.push_back(simple(TokenKind::quote_quad, column));
          break;
        case U'←':
          tokens.push_back(simple(TokenKind::assign, column));
          break;
        case U'→':
          tokens.push_back(simple(TokenKind::branch, column));
          break;
        case U'(':
          tokens.push_back(simple(TokenKind::left_paren, column));
          break;
        case U')':
          tokens.push_back(simple(TokenKind::right_paren, column));
          break;
        case U'[':
          tokens.push_back(simple(TokenKind::left_bracket, column));
          break;
        case U']':
          tokens.push_back(simple(TokenKind::right_bracket, column));
          break;
        case U';':
          tokens.push_back(simple(TokenKind::semicolon, column));
          break;
        case U':':
          tokens.push_back(simple(TokenKind::colon, column));
          break;
        case U'.':
          tokens.push_back(simple(TokenKind::dot, column));
          break;
        case U'∘':
          tokens.push_back(simple(TokenKind::jot, column));
          break;
        case U'∇':
          tokens.push_back(simple(TokenKind::del, column));
          break;
        default:
          if (!is_primitive_glyph(c)) syntax_at(column);
          tokens.push_back(simple(TokenKind::function, column, canonical_glyph(c)));
      }
    }
  }
  if (!tokens.empty() && tokens.back().end == 0) tokens.back().end = i;
  return tokens;
}

}  // namespace igds::apl
