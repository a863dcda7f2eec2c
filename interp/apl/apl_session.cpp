#include "interp/apl/apl_session.h"

#include <algorithm>
#include <memory>

#include "interp/apl/editor.h"
#include "interp/apl/evaluator.h"
#include "interp/apl/function.h"
#include "interp/apl/lexer.h"
#include "interp/apl/text.h"

namespace igds::apl {

namespace {

std::string_view trim(std::string_view s) {
  auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> words_of(std::string_view s) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
    if (j > i) words.emplace_back(s.substr(i, j - i));
    i = j;
  }
  return words;
}

// Names as the tokenizer spells them: letters folded to capitals (ASCII only, whatever the
// locale: the bytes of ∆ and ⍙ stay as they are).
std::string folded(std::string_view s) {
  std::string out(s);
  for (auto& c : out)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return out;
}

bool is_name(std::string_view s) {
  std::u32string u = decode_utf8(s);
  if (u.empty() || !is_name_start(u[0])) return false;
  return std::all_of(u.begin(), u.end(), is_name_char);
}

}  // namespace

class AplSession::Impl {
 public:
  explicit Impl(Host& host) : eval(host) {}

  Next execute(std::string_view line);
  void open_editor(std::string_view rest);
  void editor_line(std::string_view line);
  void close_editor();
  Next system_command(std::string_view line);
  void list_names(std::vector<std::string> names, std::string_view from);
  void check_definable(const std::string& name, const std::string& original) const;

  Evaluator eval;
  std::unique_ptr<Editor> editor;
  std::string edited;  // the name of the function being edited (empty for a new one)
};

AplSession::Next AplSession::Impl::execute(std::string_view line) {
  eval.interrupted = false;
  eval.requested = Next::stay;
  if (editor) {
    editor_line(line);
    return Next::stay;
  }
  std::string_view typed = trim(line);
  if (typed.empty()) return Next::stay;
  if (typed.front() == ')') return system_command(typed);
  if (typed.starts_with("∇")) {
    open_editor(typed.substr(3));
    return Next::stay;
  }
  eval.run_line(line);
  return eval.requested;
}

void AplSession::Impl::check_definable(const std::string& name, const std::string& original) const {
  if (name != original && (eval.functions.count(name) || eval.natives.count(name)))
    throw Error(ErrorKind::defn);
  if (eval.natives.count(name) || eval.is_variable(name)) throw Error(ErrorKind::defn);
}

void AplSession::Impl::open_editor(std::string_view rest) {
  // The header runs to a bracket (an editor command) or a closing ∇.
  std::size_t cut = std::min(rest.find('['), rest.find("∇"));
  const std::string header(trim(rest.substr(0, cut)));
  const std::string_view tail =
      cut == std::string_view::npos ? std::string_view() : rest.substr(cut);
  try {
    std::vector<std::string> source;
    if (is_name(header)) {
      const std::string name = folded(header);
      if (auto it = eval.functions.find(name); it != eval.functions.end()) {
        source = it->second->source();
        edited = name;
      } else {
        check_definable(name, "");
        source = {header};
        edited.clear();
      }
    } else {
      const Header h = parse_header(header);
      check_definable(h.name, "");
      source = {header};
      edited.clear();
    }
    editor = std::make_unique<Editor>(source);
  } catch (const Error& e) {
    eval.print(e.what());
    return;
  }
  if (!tail.empty()) editor_line(tail);
}

void AplSession::Impl::editor_line(std::string_view line) {
  Editor::Step step = editor->line(line);
  for (const auto& out : step.output) eval.print(out);
  if (step.close) close_editor();
}

void AplSession::Impl::close_editor() {
  try {
    DefinedFunction f = make_function(editor->source());
    const std::string name = f.header.name;
    check_definable(name, edited);
    eval.functions[name] = std::make_shared<const DefinedFunction>(std::move(f));
    editor.reset();
    edited.clear();
  } catch (const Error& e) {
    eval.print(e.what());  // the definition stays open, to be mended
  }
}

void AplSession::Impl::list_names(std::vector<std::string> names, std::string_view from) {
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::string line;
  for (const auto& n : names) {
    if (!from.empty() && n < from) continue;
    if (!line.empty() && decode_utf8(line).size() + 1 + decode_utf8(n).size() > 80) {
      eval.print(line);
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += n;
  }
  if (!line.empty()) eval.print(line);
}

AplSession::Next AplSession::Impl::system_command(std::string_view line) {
  // The system commands of APL\360 (User's Manual, chapter 6) that a session in igds has.
  std::vector<std::string> words = words_of(line.substr(1));
  const std::string command = words.empty() ? "" : folded(words[0]);
  const std::string argument = words.size() > 1 ? words[1] : "";
  if (command == "OFF") return Next::off;
  if (command == "VARS" || command == "FNS") {
    std::vector<std::string> names;
    if (command == "VARS") {
      for (const auto& [name, v] : eval.globals) names.push_back(name);
      for (auto& name : eval.host.variable_names()) names.push_back(name);
    } else {
      for (const auto& [name, f] : eval.functions) names.push_back(name);
      for (const auto& [name, f] : eval.natives) names.push_back(name);
    }
    list_names(std::move(names), folded(argument));
    return Next::stay;
  }
  if (command == "ERASE" && words.size() > 1) {
    std::string kept;
    for (std::size_t i = 1; i < words.size(); ++i) {
      const std::string name = folded(words[i]);
      bool erased = eval.functions.erase(name) + eval.globals.erase(name) > 0;
      if (!erased) kept += " " + name;
    }
    if (!kept.empty()) eval.print("NOT ERASED:" + kept);
    return Next::stay;
  }
  if (command == "DIGITS" || command == "ORIGIN") {
    int& setting = command == "DIGITS" ? eval.ctx.pp : eval.ctx.io;
    const int low = command == "DIGITS" ? 1 : 0, high = command == "DIGITS" ? 17 : 1;
    if (words.size() == 1) {
      eval.print("IS " + std::to_string(setting));
      return Next::stay;
    }
    const bool digits =
        !argument.empty() && argument.size() <= 2 &&
        std::all_of(argument.begin(), argument.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int n = digits ? std::stoi(argument) : -1;
    if (words.size() != 2 || n < low || n > high) {
      eval.print("INCORRECT COMMAND");
      return Next::stay;
    }
    eval.print("WAS " + std::to_string(setting));
    setting = n;
    return Next::stay;
  }
  if (command == "SAVE") {
    eval.print(eval.host.save_workspace(argument));
    return Next::stay;
  }
  if (command == "LOAD" && words.size() == 2) {
    eval.print(eval.host.load_workspace(argument));
    return Next::stay;
  }
  if (command == "CLEAR" && words.size() == 1) {
    eval.globals.clear();
    eval.functions.clear();
    eval.ctx.io = 1;
    eval.ctx.pp = 10;
    eval.ctx.ct = 1e-13;
    eval.ctx.rl = 16807;
    eval.print("CLEAR WS");
    return Next::stay;
  }
  eval.print("INCORRECT COMMAND");
  return Next::stay;
}

AplSession::AplSession(Host& host) : impl_(std::make_unique<Impl>(host)) {
  define_native(
      "START", 0,
      [this](const Value*, const Value*) -> std::optional<Value> {
        request(Next::start);
        return std::nullopt;
      },
      "START: back to the IGDS conversation.");
}

AplSession::~AplSession() = default;

AplSession::Next AplSession::execute(std::string_view line) {
  return impl_->execute(line);
}

std::string AplSession::prompt() const {
  return impl_->editor ? impl_->editor->prompt() : std::string(6, ' ');
}

bool AplSession::defining() const {
  return impl_->editor != nullptr;
}

void AplSession::define_native(std::string name, int valence, Native function, std::string help) {
  if (!is_name(name) || valence < 0 || valence > 2) throw Error(ErrorKind::defn);
  name = folded(name);
  impl_->eval.functions.erase(name);
  impl_->eval.natives[name] = NativeEntry{valence, std::move(function), std::move(help)};
}

std::string AplSession::function_help(std::string_view name) const {
  auto it = impl_->eval.natives.find(folded(name));
  return it == impl_->eval.natives.end() ? std::string() : it->second.help;
}

std::vector<std::string> AplSession::function_names() const {
  std::vector<std::string> names;
  for (const auto& [name, f] : impl_->eval.functions) names.push_back(name);
  for (const auto& [name, f] : impl_->eval.natives) names.push_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::vector<std::string>> AplSession::defined_functions() const {
  std::vector<std::vector<std::string>> all;
  for (const auto& [name, f] : impl_->eval.functions) all.push_back(f->source());
  return all;
}

void AplSession::define_function(const std::vector<std::string>& source) {
  DefinedFunction f = make_function(source);
  const std::string name = f.header.name;
  impl_->check_definable(name, name);
  impl_->eval.functions[name] = std::make_shared<const DefinedFunction>(std::move(f));
}

std::vector<std::pair<std::string, Value>> AplSession::variables() const {
  return {impl_->eval.globals.begin(), impl_->eval.globals.end()};
}

std::optional<Value> AplSession::variable(std::string_view name) const {
  return impl_->eval.lookup(folded(name));
}

void AplSession::assign(std::string_view name, Value value) {
  if (!is_name(name)) throw Error(ErrorKind::syntax);
  impl_->eval.set_variable(folded(name), std::move(value));
}

bool AplSession::erase(std::string_view name) {
  const std::string n = folded(name);
  return impl_->eval.functions.erase(n) + impl_->eval.globals.erase(n) > 0;
}

void AplSession::clear() {
  impl_->eval.globals.clear();
  impl_->eval.functions.clear();
  impl_->eval.ctx.io = 1;
  impl_->eval.ctx.pp = 10;
}

int AplSession::index_origin() const {
  return impl_->eval.ctx.io;
}

void AplSession::set_index_origin(int origin) {
  if (origin != 0 && origin != 1) throw Error(ErrorKind::domain);
  impl_->eval.ctx.io = origin;
}

int AplSession::print_precision() const {
  return impl_->eval.ctx.pp;
}

void AplSession::set_print_precision(int digits) {
  if (digits < 1 || digits > 17) throw Error(ErrorKind::domain);
  impl_->eval.ctx.pp = digits;
}

void AplSession::request(Next next) {
  impl_->eval.requested = next;
}

void AplSession::interrupt() {
  impl_->eval.interrupted = true;
}

void AplSession::set_limits(const Limits& limits) {
  impl_->eval.ctx.limits = limits;
}

const Limits& AplSession::limits() const {
  return impl_->eval.ctx.limits;
}

}  // namespace igds::apl
