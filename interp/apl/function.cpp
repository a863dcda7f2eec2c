#include "interp/apl/function.h"

#include <algorithm>

#include "interp/apl/text.h"

namespace igds::apl {

namespace {

[[noreturn]] void defn_error() {
  throw Error(ErrorKind::defn);
}

bool localizable(const std::string& system_name) {
  return system_name == "⎕IO" || system_name == "⎕PP" || system_name == "⎕CT" ||
         system_name == "⎕RL";
}

std::string trimmed(std::string_view s) {
  auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

}  // namespace

Header parse_header(std::string_view text) {
  std::vector<Token> tokens;
  try {
    tokens = tokenize(decode_utf8(text));
  } catch (const Error&) {
    defn_error();
  }
  Header h;
  std::size_t i = 0;
  auto is = [&](std::size_t at, TokenKind kind) {
    return at < tokens.size() && tokens[at].kind == kind;
  };
  if (is(0, TokenKind::name) && is(1, TokenKind::assign)) {
    h.result = tokens[0].text;
    i = 2;
  }
  std::vector<std::string> names;
  while (is(i, TokenKind::name)) names.push_back(tokens[i++].text);
  switch (names.size()) {
    case 1:
      h.name = names[0];
      break;
    case 2:
      h.name = names[0];
      h.right = names[1];
      break;
    case 3:
      h.left = names[0];
      h.name = names[1];
      h.right = names[2];
      break;
    default:
      defn_error();
  }
  while (is(i, TokenKind::semicolon)) {
    ++i;
    if (is(i, TokenKind::name) || (is(i, TokenKind::system_name) && localizable(tokens[i].text))) {
      h.locals.push_back(tokens[i++].text);
    } else {
      defn_error();
    }
  }
  if (i != tokens.size()) defn_error();
  std::vector<std::string> all = h.locals;
  for (const auto* n : {&h.result, &h.left, &h.right})
    if (!n->empty()) all.push_back(*n);
  all.push_back(h.name);
  std::sort(all.begin(), all.end());
  if (std::adjacent_find(all.begin(), all.end()) != all.end()) defn_error();
  return h;
}

int DefinedFunction::slot_of(std::string_view name) const {
  for (std::size_t i = 0; i < slots.size(); ++i)
    if (slots[i] == name) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> DefinedFunction::source() const {
  std::vector<std::string> s{header_text};
  s.insert(s.end(), lines.begin(), lines.end());
  return s;
}

DefinedFunction make_function(const std::vector<std::string>& source) {
  if (source.empty()) defn_error();
  DefinedFunction f;
  std::string header = trimmed(source[0]);
  if (header.starts_with("∇")) header = trimmed(std::string_view(header).substr(3));
  f.header = parse_header(header);
  f.header_text = header;
  std::vector<std::string> names = f.header.locals;
  for (const auto* n : {&f.header.result, &f.header.left, &f.header.right, &f.header.name})
    if (!n->empty()) names.push_back(*n);
  for (std::size_t i = 1; i < source.size(); ++i) {
    f.lines.push_back(source[i]);
    std::vector<Token> tokens;
    std::optional<Error> error;
    try {
      tokens = tokenize(decode_utf8(source[i]));
    } catch (const Error& e) {
      error = e;
    }
    if (tokens.size() >= 2 && tokens[0].kind == TokenKind::name &&
        tokens[1].kind == TokenKind::colon) {
      const std::string& label = tokens[0].text;
      if (std::find(names.begin(), names.end(), label) != names.end()) defn_error();
      names.push_back(label);
      f.labels[label] = i;
    }
    f.tokens.push_back(std::move(tokens));
    f.line_errors.push_back(std::move(error));
  }
  for (const auto* n : {&f.header.result, &f.header.left, &f.header.right})
    if (!n->empty()) f.slots.push_back(*n);
  for (const auto& local : f.header.locals)
    if (!local.starts_with("⎕")) f.slots.push_back(local);
  f.first_label = f.slots.size();
  for (const auto& [label, line] : f.labels) f.slots.push_back(label);
  f.compiled.resize(f.lines.size());
  return f;
}

}  // namespace igds::apl
