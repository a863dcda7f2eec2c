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

bool small_number(const std::string& word, int& n) {
  if (word.empty() || word.size() > 3 ||
      !std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  n = std::stoi(word);
  return true;
}

}  // namespace

class AplSession::Impl {
 public:
  explicit Impl(Host& host) : eval(host) {}

  Next execute(std::string_view line);
  void open_editor(std::string_view rest);
  void editor_line(std::string_view line);
  bool close_editor();
  Next system_command(std::string_view line);
  // Names in lines of at most ⎕PW characters, starting with `first` (a heading) when given.
  void list_names(std::vector<std::string> names, std::string_view from,
                  std::string_view first = {});
  void check_definable(const std::string& name, const std::string& original) const;
  void setting(const std::vector<std::string>& words, int& value, int low, int high);

  Evaluator eval;
  std::unique_ptr<Editor> editor;
  std::string edited;  // the name of the function being edited (empty for a new one)
};

AplSession::Next AplSession::Impl::execute(std::string_view line) {
  eval.requested = Next::stay;
  if (editor) {
    editor_line(line);
    return eval.requested;
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
  if (name != original && (eval.function(name) || eval.native(name))) throw Error(ErrorKind::defn);
  if (eval.native(name) || eval.is_variable(name)) throw Error(ErrorKind::defn);
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
      if (auto f = eval.function(name)) {
        if (eval.pendent(name)) throw Error(ErrorKind::defn);
        source = f->source();
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
  if (!step.close || !close_editor()) return;
  // ∇ at the start of a line: the definition closed, the line is read at the six-blank prompt.
  if (step.reopen) execute(line);
}

bool AplSession::Impl::close_editor() {
  try {
    DefinedFunction f = make_function(editor->source());
    const std::string name = f.header.name;
    check_definable(name, edited);
    eval.define(std::move(f));
    editor.reset();
    edited.clear();
    return true;
  } catch (const Error& e) {
    eval.print(e.what());  // the definition stays open, to be mended
    return false;
  }
}

void AplSession::Impl::list_names(std::vector<std::string> names, std::string_view from,
                                  std::string_view first) {
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  const std::size_t width = static_cast<std::size_t>(eval.ctx.pw);
  const std::string prefix = first.empty() ? std::string() : std::string(first) + " ";
  const std::string indent(decode_utf8(prefix).size(), ' ');
  std::string line = prefix;
  std::size_t on_line = 0;
  for (const auto& n : names) {
    if (!from.empty() && n < from) continue;
    if (on_line > 0 && decode_utf8(line).size() + 1 + decode_utf8(n).size() > width) {
      eval.print(line);
      line = indent;
      on_line = 0;
    }
    if (on_line > 0) line += ' ';
    line += n;
    ++on_line;
  }
  if (on_line > 0) eval.print(line);
}

void AplSession::Impl::setting(const std::vector<std::string>& words, int& value, int low,
                               int high) {
  if (words.size() == 1) {
    eval.print("IS " + std::to_string(value));
    return;
  }
  int n = -1;
  if (words.size() != 2 || !small_number(words[1], n) || n < low || n > high) {
    eval.print("INCORRECT COMMAND");
    return;
  }
  eval.print("WAS " + std::to_string(value));
  value = n;
}

AplSession::Next AplSession::Impl::system_command(std::string_view line) {
  // The system commands of APL\360 (User's Manual, chapter 6) that a session in igds has, and
  // APL2's )SIC.
  std::vector<std::string> words = words_of(line.substr(1));
  const std::string command = words.empty() ? "" : folded(words[0]);
  const std::string argument = words.size() > 1 ? words[1] : "";
  auto print_all = [this](const std::vector<std::string>& lines) {
    for (const auto& l : lines) eval.print(l);
  };
  if (command == "OFF") return Next::off;
  if (command == "VARS" || command == "FNS") {
    // The session's own names, then the host's under its heading.
    const bool vars = command == "VARS";
    std::vector<std::string> own, host;
    if (vars) {
      for (const auto& [name, v] : eval.globals()) own.push_back(name);
      host = eval.host.variable_names();
    } else {
      own = eval.function_names(false);
      host = eval.function_names(true);
    }
    const std::string from = folded(argument);
    list_names(own, from);
    const std::string heading = eval.host.heading();
    list_names(host, from, heading.empty() ? "" : heading + ":");
    return Next::stay;
  }
  if (command == "ERASE" && words.size() > 1) {
    std::string kept;
    for (std::size_t i = 1; i < words.size(); ++i) {
      const std::string name = folded(words[i]);
      if (!eval.erase(name)) kept += " " + name;
    }
    if (!kept.empty()) eval.print("NOT ERASED:" + kept);
    return Next::stay;
  }
  if (command == "DIGITS") {
    setting(words, eval.ctx.pp, 1, 17);
    return Next::stay;
  }
  if (command == "ORIGIN") {
    setting(words, eval.ctx.io, 0, 1);
    return Next::stay;
  }
  if (command == "WIDTH") {
    setting(words, eval.ctx.pw, 30, 254);
    return Next::stay;
  }
  if (command == "SI" && words.size() == 1) {
    print_all(eval.state_indicator());
    return Next::stay;
  }
  if (command == "SIC" && words.size() == 1) {
    eval.clear_state_indicator();
    return Next::stay;
  }
  if (command == "SAVE" && words.size() <= 2) {
    print_all(eval.host.save_workspace(argument));
    return Next::stay;
  }
  if (command == "LOAD" && words.size() == 2) {
    print_all(eval.host.load_workspace(argument));
    return Next::stay;
  }
  if (command == "COPY" && words.size() >= 2) {
    std::vector<std::string> names;
    for (std::size_t i = 2; i < words.size(); ++i) names.push_back(folded(words[i]));
    print_all(eval.host.copy_workspace(argument, names));
    return Next::stay;
  }
  if (command == "CLEAR" && words.size() == 1) {
    eval.clear();
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
  impl_->eval.define_native(name, NativeEntry{valence, std::move(function), std::move(help)});
}

std::string AplSession::function_help(std::string_view name) const {
  const NativeEntry* n = impl_->eval.native(folded(name));
  return n ? n->help : std::string();
}

std::vector<std::string> AplSession::function_names() const {
  std::vector<std::string> names = impl_->eval.function_names(false);
  for (auto& n : impl_->eval.function_names(true)) names.push_back(std::move(n));
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::vector<std::string>> AplSession::defined_functions() const {
  std::vector<std::vector<std::string>> all;
  for (const auto& name : impl_->eval.function_names(false))
    all.push_back(impl_->eval.function(name)->source());
  return all;
}

void AplSession::define_function(const std::vector<std::string>& source) {
  DefinedFunction f = make_function(source);
  const std::string name = f.header.name;
  impl_->check_definable(name, name);
  impl_->eval.define(std::move(f));
}

std::string AplSession::function_name(const std::vector<std::string>& source) {
  return make_function(source).header.name;
}

std::vector<std::pair<std::string, Value>> AplSession::variables() const {
  return impl_->eval.globals();
}

std::uint64_t AplSession::variables_version() const {
  return impl_->eval.global_changes();
}

std::vector<std::pair<std::string, std::optional<Value>>> AplSession::variables_changed(
    std::uint64_t version) const {
  return impl_->eval.globals_changed(version);
}

std::optional<Value> AplSession::variable(std::string_view name) const {
  return impl_->eval.lookup(folded(name));
}

void AplSession::assign(std::string_view name, Value value) {
  if (!is_name(name)) throw Error(ErrorKind::syntax);
  impl_->eval.set_variable(folded(name), std::move(value));
}

bool AplSession::erase(std::string_view name) {
  return impl_->eval.erase(folded(name));
}

void AplSession::clear() {
  impl_->eval.clear();
}

std::vector<std::string> AplSession::state_indicator() const {
  return impl_->eval.state_indicator();
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

int AplSession::print_width() const {
  return impl_->eval.ctx.pw;
}

void AplSession::set_print_width(int width) {
  if (width < 30 || width > 254) throw Error(ErrorKind::domain);
  impl_->eval.ctx.pw = width;
}

void AplSession::request(Next next) {
  impl_->eval.requested = next;
}

void AplSession::set_limits(const Limits& limits) {
  impl_->eval.ctx.limits = limits;
}

const Limits& AplSession::limits() const {
  return impl_->eval.ctx.limits;
}

}  // namespace igds::apl
