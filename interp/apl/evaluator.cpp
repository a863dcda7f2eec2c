#include "interp/apl/evaluator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>

#include "interp/apl/format.h"
#include "interp/apl/lexer.h"
#include "interp/apl/mixed.h"
#include "interp/apl/operators.h"
#include "interp/apl/scalar.h"
#include "interp/apl/text.h"

namespace igds::apl {

namespace {

std::u32string_view trim(std::u32string_view s) {
  while (!s.empty() && (s.front() == U' ' || s.front() == U'\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == U' ' || s.back() == U'\t')) s.remove_suffix(1);
  return s;
}

bool is_system_name(const std::string& name) {
  return name.starts_with("⎕");
}

// The work a statement of a function costs besides its primitives (reading it, finding its
// names), in elements: a loop of small statements is stopped by the budget as soon as a loop
// over large arrays would be.
constexpr std::uint64_t statement_work = 64;

NameClass class_of_valence(int valence) {
  return valence == 0 ? NameClass::niladic : valence == 1 ? NameClass::monadic : NameClass::dyadic;
}

std::size_t characters_in(std::string_view utf8) {
  return decode_utf8(utf8).size();
}

// The primitives that take an axis [k] (APL\360: the structural ones, and the operators).
bool takes_axis(const FunctionNode& f, bool dyadic) {
  if (f.kind == FunctionNode::Kind::reduce || f.kind == FunctionNode::Kind::scan) return true;
  if (f.kind != FunctionNode::Kind::primitive) return false;
  std::u32string_view glyphs = dyadic ? U",⌽⊖↑↓/⌿\\⍀" : U",⌽⊖";
  return glyphs.find(f.glyph) != std::u32string_view::npos;
}

}  // namespace

// Counts nested evaluation (parentheses, function calls, ⍎): DEPTH ERROR beyond the limit.
class Evaluator::Deeper {
 public:
  explicit Deeper(Evaluator& e) : e_(e) {
    if (++e_.depth_ > e_.ctx.limits.max_depth) {
      --e_.depth_;
      throw Error(ErrorKind::depth);
    }
  }
  ~Deeper() { --e_.depth_; }
  Deeper(const Deeper&) = delete;
  Deeper& operator=(const Deeper&) = delete;

 private:
  Evaluator& e_;
};

// Pops a function's frame however the call ends, giving back the localized system variables.
class Evaluator::FrameGuard {
 public:
  explicit FrameGuard(Evaluator& e) : e_(e) {}
  ~FrameGuard() {
    for (auto& [name, old] : e_.frames_.back().saved_system) {
      const double x = old.numbers()[0];
      if (name == "⎕IO") e_.ctx.io = static_cast<int>(x);
      if (name == "⎕PP") e_.ctx.pp = static_cast<int>(x);
      if (name == "⎕CT") e_.ctx.ct = x;
      if (name == "⎕RL") e_.ctx.rl = static_cast<std::uint32_t>(x);
    }
    e_.frames_.pop_back();
  }
  FrameGuard(const FrameGuard&) = delete;
  FrameGuard& operator=(const FrameGuard&) = delete;

 private:
  Evaluator& e_;
};

std::optional<Value>* Evaluator::Frame::find(const std::string& name) {
  for (auto& [n, v] : locals)
    if (n == name) return &v;
  return nullptr;
}

const std::optional<Value>* Evaluator::Frame::find(const std::string& name) const {
  for (const auto& [n, v] : locals)
    if (n == name) return &v;
  return nullptr;
}

Evaluator::Evaluator(Host& h) : host(h) {
  ctx.interrupted = &interrupted;
  classifier_ = [this](const std::string& name) { return classify(name); };
}

NameClass Evaluator::classify(const std::string& name) const {
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f)
    if (f->find(name)) return NameClass::variable;
  if (auto it = functions.find(name); it != functions.end())
    return class_of_valence(it->second->header.valence());
  if (auto it = natives.find(name); it != natives.end())
    return class_of_valence(it->second.valence);
  return NameClass::variable;
}

bool Evaluator::is_variable(const std::string& name) const {
  if (host.owns(name) || globals.count(name)) return true;
  return std::any_of(staged_.begin(), staged_.end(),
                     [&](const auto& s) { return s.first == name; });
}

std::optional<Value> Evaluator::lookup(const std::string& name) const {
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f)
    if (auto* v = f->find(name)) return *v;
  for (auto s = staged_.rbegin(); s != staged_.rend(); ++s)
    if (s->first == name) return s->second;
  if (host.owns(name)) return host.get(name);
  if (auto it = globals.find(name); it != globals.end()) return it->second;
  return std::nullopt;
}

void Evaluator::set_variable(const std::string& name, Value value) {
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f) {
    if (auto* v = f->find(name)) {
      *v = std::move(value);
      return;
    }
  }
  if (functions.count(name) || natives.count(name)) syntax_error();
  const bool owned = host.owns(name);
  if (owned) host.check(name, value);
  if (!running_) {  // outside a statement (the host's own calls): made at once
    if (owned) {
      host.set(name, value);
    } else {
      globals[name] = std::move(value);
    }
    return;
  }
  for (auto& s : staged_) {
    if (s.first == name) {
      s.second = std::move(value);
      return;
    }
  }
  staged_.emplace_back(name, std::move(value));
}

Value& Evaluator::slot(const std::string& name) {
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f) {
    if (auto* v = f->find(name)) {
      if (!*v) throw Error(ErrorKind::value);
      return **v;
    }
  }
  if (functions.count(name) || natives.count(name)) syntax_error();
  for (auto& s : staged_)
    if (s.first == name) return s.second;
  std::optional<Value> v = lookup(name);
  if (!v) throw Error(ErrorKind::value);
  staged_.emplace_back(name, std::move(*v));
  return staged_.back().second;
}

void Evaluator::commit() {
  for (auto& [name, v] : staged_)
    if (host.owns(name)) host.set(name, v);
  for (auto& [name, v] : staged_)
    if (!host.owns(name)) globals[name] = std::move(v);
  staged_.clear();
}

void Evaluator::flush() {
  if (pending_.empty()) return;
  std::string line = encode_utf8(pending_);
  pending_.clear();
  host.print(line);
}

void Evaluator::print(std::string_view line) {
  flush();
  host.print(line);
}

void Evaluator::report(const Error& e, std::string_view typed) {
  flush();
  host.print(e.what());
  if (e.located()) {
    host.print(e.statement());
    host.print(std::string(e.caret(), ' ') + "^");
    return;
  }
  host.print(std::string("      ") + std::string(typed));
  host.print(std::string(6 + (e.has_column() ? e.column() : 0), ' ') + "^");
}

void Evaluator::run_line(std::string_view line) {
  const Context saved = ctx;
  ctx.work = 0;
  running_ = true;
  staged_.clear();
  execute_shy_ = false;
  auto fail = [&] {
    staged_.clear();
    ctx.io = saved.io;
    ctx.pp = saved.pp;
    ctx.ct = saved.ct;
    ctx.rl = saved.rl;
  };
  try {
    try {
      const std::u32string text = decode_utf8(line);
      const std::vector<Token> tokens = tokenize(text);
      const Statement statement = parse(tokens, classifier_, false, ctx.limits.max_depth);
      run_statement(statement);
      flush();
      commit();
    } catch (const std::bad_alloc&) {
      throw Error(ErrorKind::ws_full);
    } catch (const std::length_error&) {
      throw Error(ErrorKind::ws_full);
    }
  } catch (const Error& e) {
    fail();
    report(e, line);
  } catch (const Escape&) {
    fail();
    flush();
  }
  running_ = false;
  frames_.clear();
  staged_.clear();
  depth_ = 0;
}

Evaluator::Outcome Evaluator::run_statement(const Statement& statement) {
  Outcome out;
  if (statement.branch) {
    out.branch = true;
    if (!statement.expr) {
      out.naked = true;
      return out;
    }
    Value v = value_of(*statement.expr);
    if (v.empty()) return Outcome{};
    if (v.is_character() || !near_integer(v.numbers()[0])) {
      Error e(ErrorKind::domain);
      e.set_column(statement.expr->column);
      throw e;
    }
    out.target = std::round(v.numbers()[0]);
    return out;
  }
  if (!statement.expr) return out;
  execute_shy_ = false;
  std::optional<Value> r = eval(*statement.expr);
  if (r && !shy(*statement.expr))
    for (const auto& line : display(ctx, *r)) print(line);
  return out;
}

bool Evaluator::shy(const Node& node) const {
  if (node.parenthesized) return false;
  if (node.kind == Node::Kind::assign || node.kind == Node::Kind::index_assign) return true;
  return node.kind == Node::Kind::monadic && node.function->kind == FunctionNode::Kind::primitive &&
         node.function->glyph == U'⍎' && execute_shy_;
}

Value Evaluator::value_of(const Node& node) {
  std::optional<Value> v = eval(node);
  if (!v) {
    Error e(ErrorKind::value);
    e.set_column(node.column);
    throw e;
  }
  return std::move(*v);
}

std::optional<Value> Evaluator::eval(const Node& node) {
  Deeper deeper(*this);
  try {
    return eval_node(node);
  } catch (Error& e) {
    e.set_column(node.column);
    throw;
  }
}

std::optional<Value> Evaluator::eval_node(const Node& n) {
  switch (n.kind) {
    case Node::Kind::constant:
      return n.value;
    case Node::Kind::variable: {
      std::optional<Value> v = lookup(n.name);
      if (!v) throw Error(ErrorKind::value);
      return v;
    }
    case Node::Kind::niladic:
      return call(n.name, nullptr, nullptr);
    case Node::Kind::system_variable:
      return system_variable(n.name);
    case Node::Kind::quad:
      return quad_input();
    case Node::Kind::quote_quad:
      return quote_input();
    case Node::Kind::monadic: {
      Value b = value_of(*n.right);
      std::optional<Value> axis;
      if (n.function->axis) axis = value_of(*n.function->axis);
      return apply_monadic(*n.function, std::move(b), axis ? &*axis : nullptr);
    }
    case Node::Kind::dyadic: {
      Value b = value_of(*n.right);
      std::optional<Value> axis;
      if (n.function->axis) axis = value_of(*n.function->axis);
      Value a = value_of(*n.left);
      return apply_dyadic(*n.function, std::move(a), std::move(b), axis ? &*axis : nullptr);
    }
    case Node::Kind::index: {
      std::vector<std::optional<Value>> indices(n.indices.size());
      for (std::size_t i = n.indices.size(); i-- > 0;)
        if (n.indices[i]) indices[i] = value_of(*n.indices[i]);
      Value b = value_of(*n.left);
      ctx.charge(1);
      return index(ctx, b, indices);
    }
    case Node::Kind::assign: {
      Value v = value_of(*n.right);
      assign_to(n.name, v);
      return v;
    }
    case Node::Kind::index_assign: {
      Value v = value_of(*n.right);
      std::vector<std::optional<Value>> indices(n.indices.size());
      for (std::size_t i = n.indices.size(); i-- > 0;)
        if (n.indices[i]) indices[i] = value_of(*n.indices[i]);
      bool local = std::any_of(frames_.begin(), frames_.end(),
                               [&](const Frame& f) { return f.find(n.name) != nullptr; });
      Value& target = slot(n.name);
      index_assign(ctx, target, indices, v);
      if (!local && host.owns(n.name)) host.check(n.name, target);
      return v;
    }
  }
  syntax_error();
}

std::optional<Value> Evaluator::call(const std::string& name, const Value* left,
                                     const Value* right) {
  if (auto it = functions.find(name); it != functions.end()) {
    auto f = it->second;  // kept alive while it runs, whatever happens to the table
    const int valence = f->header.valence();
    if ((valence == 2) != (left != nullptr) || (valence >= 1) != (right != nullptr)) syntax_error();
    return call_defined(f, left, right);
  }
  auto it = natives.find(name);
  if (it == natives.end()) throw Error(ErrorKind::value);
  const NativeEntry native = it->second;
  if ((native.valence == 2) != (left != nullptr) || (native.valence >= 1) != (right != nullptr))
    syntax_error();
  ctx.charge(1);
  try {
    return native.function(left, right);
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error(ErrorKind::ws_full);
  } catch (const std::exception& e) {
    throw Error(ErrorKind::domain, e.what());
  }
}

std::optional<Value> Evaluator::call_defined(const std::shared_ptr<const DefinedFunction>& f,
                                             const Value* left, const Value* right) {
  Deeper deeper(*this);
  const Header& h = f->header;
  Frame frame;
  frame.function = f;
  if (!h.result.empty()) frame.locals.emplace_back(h.result, std::nullopt);
  if (left) frame.locals.emplace_back(h.left, *left);
  if (right) frame.locals.emplace_back(h.right, *right);
  for (const auto& local : h.locals) {
    if (is_system_name(local)) {
      frame.saved_system.emplace_back(local, system_variable(local));
    } else {
      frame.locals.emplace_back(local, std::nullopt);
    }
  }
  for (const auto& [label, line] : f->labels)
    frame.locals.emplace_back(label, Value::number(static_cast<double>(line)));
  frames_.push_back(std::move(frame));
  FrameGuard guard(*this);
  const std::size_t n = f->lines.size();
  std::size_t line = 1;
  while (line >= 1 && line <= n) {
    frames_.back().line = line;
    Outcome o;
    try {
      ctx.charge(statement_work);
      if (f->line_errors[line - 1]) throw Error(*f->line_errors[line - 1]);
      const Statement statement =
          parse(f->tokens[line - 1], classifier_, true, ctx.limits.max_depth);
      o = run_statement(statement);
    } catch (Error& e) {
      if (!e.located()) {
        const std::string prefix = fmt::format("{}[{}] ", h.name, line);
        e.locate(prefix + f->lines[line - 1],
                 characters_in(prefix) + (e.has_column() ? e.column() : 0));
      }
      throw;
    }
    if (o.naked) throw Escape{};
    if (!o.branch) {
      ++line;
    } else {
      // →N goes to line N; a number that is no line of the function leaves it (→0).
      line = o.target >= 1 && o.target <= static_cast<double>(n)
                 ? static_cast<std::size_t>(o.target)
                 : 0;
    }
  }
  if (h.result.empty()) return std::nullopt;
  return *frames_.back().find(h.result);
}

std::optional<Value> Evaluator::apply_monadic(const FunctionNode& f, Value b, const Value* axis) {
  if (axis && !takes_axis(f, false)) syntax_error();
  switch (f.kind) {
    case FunctionNode::Kind::defined:
      return call(f.name, nullptr, &b);
    case FunctionNode::Kind::reduce:
      return reduce(ctx, f.glyph, b, axis, f.op == U'⌿');
    case FunctionNode::Kind::scan:
      return scan(ctx, f.glyph, b, axis, f.op == U'⍀');
    case FunctionNode::Kind::outer:
    case FunctionNode::Kind::inner:
      syntax_error();
    case FunctionNode::Kind::primitive:
      break;
  }
  if (is_scalar_monadic(f.glyph)) return scalar_monadic(ctx, f.glyph, std::move(b));
  switch (f.glyph) {
    case U'⍴':
      return shape_of(ctx, b);
    case U',':
      return ravel(ctx, b, axis);
    case U'⍳':
      return iota(ctx, b);
    case U'⌽':
      return reverse(ctx, b, axis, false);
    case U'⊖':
      return reverse(ctx, b, axis, true);
    case U'⍉':
      return transpose(ctx, b);
    case U'⍋':
      return grade(ctx, b, true);
    case U'⍒':
      return grade(ctx, b, false);
    case U'⌹':
      return matrix_inverse(ctx, b);
    case U'⍕':
      return format(ctx, b);
    case U'⍎':
      return execute_text(b);
    default:
      syntax_error();
  }
}

std::optional<Value> Evaluator::apply_dyadic(const FunctionNode& f, Value a, Value b,
                                             const Value* axis) {
  if (axis && !takes_axis(f, true)) syntax_error();
  switch (f.kind) {
    case FunctionNode::Kind::defined:
      return call(f.name, &a, &b);
    case FunctionNode::Kind::outer:
      return outer_product(ctx, f.glyph, a, b);
    case FunctionNode::Kind::inner:
      return inner_product(ctx, f.glyph, f.op, a, b);
    case FunctionNode::Kind::reduce:
    case FunctionNode::Kind::scan:
      syntax_error();
    case FunctionNode::Kind::primitive:
      break;
  }
  if (is_scalar_dyadic(f.glyph)) return scalar_dyadic(ctx, f.glyph, std::move(a), std::move(b));
  switch (f.glyph) {
    case U'⍴':
      return reshape(ctx, a, b);
    case U',':
      return catenate(ctx, a, b, axis);
    case U'⍳':
      return index_of(ctx, a, b);
    case U'↑':
      return take(ctx, a, b, axis);
    case U'↓':
      return drop(ctx, a, b, axis);
    case U'⌽':
      return rotate(ctx, a, b, axis, false);
    case U'⊖':
      return rotate(ctx, a, b, axis, true);
    case U'⍉':
      return transpose(ctx, a, b);
    case U'∊':
      return member_of(ctx, a, b);
    case U'⍋':
      return grade(ctx, a, b, true);
    case U'⍒':
      return grade(ctx, a, b, false);
    case U'⊥':
      return decode(ctx, a, b);
    case U'⊤':
      return encode(ctx, a, b);
    case U'⌹':
      return matrix_divide(ctx, a, b);
    case U'?':
      return deal(ctx, a, b);
    case U'~':
      return without(ctx, a, b);
    case U'/':
      return replicate(ctx, a, b, axis, false);
    case U'⌿':
      return replicate(ctx, a, b, axis, true);
    case U'\\':
      return expand(ctx, a, b, axis, false);
    case U'⍀':
      return expand(ctx, a, b, axis, true);
    case U'⍕':
      return format_by_specification(ctx, a, b);
    default:
      syntax_error();
  }
}

std::optional<Value> Evaluator::execute_text(const Value& text) {
  // ⍎B (APL.SV "execute"): the statement of the characters B, its result if it has one.
  if (text.rank() > 1) rank_error();
  if (text.is_numeric() && !text.empty()) domain_error();
  Deeper deeper(*this);
  ctx.charge(text.size() + 1);
  try {
    auto c = text.characters();
    const std::vector<Token> tokens = tokenize(std::u32string_view(c.data(), c.size()));
    const Statement statement = parse(tokens, classifier_, false, ctx.limits.max_depth);
    if (statement.branch) syntax_error();
    if (!statement.expr) return std::nullopt;
    std::optional<Value> r = eval(*statement.expr);
    execute_shy_ = shy(*statement.expr);
    return r;
  } catch (const Error& e) {
    if (e.located()) throw;
    throw Error(e.kind(), e.what());  // reported at the ⍎ of the statement that ran it
  }
}

Value Evaluator::quad_input() {
  // ⎕ (APL\360 User's Manual, "evaluated input"): ⎕: is printed, the line typed is evaluated;
  // an error is reported and the input asked again; → abandons the statement.
  while (true) {
    print("⎕:");
    ctx.charge(1);
    std::optional<std::string> line = host.read_line("      ");
    if (!line) throw Error(ErrorKind::interrupt);
    const std::u32string text = decode_utf8(*line);
    const std::u32string_view typed = trim(text);
    if (typed.empty()) continue;
    if (typed == U"→") throw Escape{};
    const auto saved = staged_;
    try {
      const std::vector<Token> tokens = tokenize(text);
      const Statement statement = parse(tokens, classifier_, false, ctx.limits.max_depth);
      if (statement.branch) syntax_error();
      if (!statement.expr) continue;
      std::optional<Value> v = eval(*statement.expr);
      if (v) return std::move(*v);
    } catch (const Error& e) {
      if (e.kind() == ErrorKind::interrupt) throw;
      staged_ = saved;
      report(e, *line);
    }
  }
}

Value Evaluator::quote_input() {
  // ⍞: one line of characters; the prompt is what ⍞← left on the line.
  ctx.charge(1);
  const std::string prompt = encode_utf8(pending_);
  pending_.clear();
  std::optional<std::string> line = host.read_line(prompt);
  if (!line) throw Error(ErrorKind::interrupt);
  return Value::text(*line);
}

void Evaluator::quote_output(const Value& v) {
  std::vector<std::string> lines = display(ctx, v);
  if (lines.empty()) return;
  lines[0] = encode_utf8(pending_) + lines[0];
  pending_.clear();
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) host.print(lines[i]);
  pending_ = decode_utf8(lines.back());
}

void Evaluator::assign_to(const std::string& name, const Value& v) {
  if (name == "⎕") {
    for (const auto& line : display(ctx, v)) print(line);
  } else if (name == "⍞") {
    quote_output(v);
  } else if (is_system_name(name)) {
    set_system_variable(name, v);
  } else {
    set_variable(name, v);
  }
}

Value Evaluator::system_variable(const std::string& name) const {
  if (name == "⎕IO") return Value::number(ctx.io);
  if (name == "⎕PP") return Value::number(ctx.pp);
  if (name == "⎕CT") return Value::number(ctx.ct);
  if (name == "⎕RL") return Value::number(ctx.rl);
  if (name == "⎕LC") {  // the lines of the running functions, innermost first
    Numbers lines;
    for (auto f = frames_.rbegin(); f != frames_.rend(); ++f)
      lines.push_back(static_cast<double>(f->line));
    const std::size_t n = lines.size();  // before the move: arguments have no order
    return Value::of_numbers({n}, std::move(lines));
  }
  syntax_error();
}

void Evaluator::set_system_variable(const std::string& name, const Value& v) {
  if (name == "⎕LC" || (name != "⎕IO" && name != "⎕PP" && name != "⎕CT" && name != "⎕RL"))
    syntax_error();
  if (v.is_character() || v.size() != 1) domain_error();
  const double x = v.numbers()[0];
  if (name == "⎕CT") {
    if (!(x >= 0 && x <= 1e-9)) domain_error();
    ctx.ct = x;
    return;
  }
  const std::int64_t i = integer_of(x);
  if (name == "⎕IO") {
    if (i != 0 && i != 1) domain_error();
    ctx.io = static_cast<int>(i);
  } else if (name == "⎕PP") {
    if (i < 1 || i > 17) domain_error();
    ctx.pp = static_cast<int>(i);
  } else {
    if (i < 1 || i > 2147483646) domain_error();
    ctx.rl = static_cast<std::uint32_t>(i);
  }
}

}  // namespace igds::apl
