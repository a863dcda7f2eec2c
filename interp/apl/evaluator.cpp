#include "interp/apl/evaluator.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <new>
#include <stdexcept>

#include "interp/apl/editor.h"
#include "interp/apl/format.h"
#include "interp/apl/glyphs.h"
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

// The work a statement of a function costs besides its primitives (finding its code, its
// names), in elements: a loop of small statements is stopped by the budget as soon as a loop
// over large arrays would be, and looks for Ctrl-C every few thousand statements.
constexpr std::uint64_t statement_work = 64;

NameClass class_of_valence(int valence) {
  return valence == 0 ? NameClass::niladic : valence == 1 ? NameClass::monadic : NameClass::dyadic;
}

std::size_t characters_in(std::string_view utf8) {
  return decode_utf8(utf8).size();
}

std::uint64_t milliseconds_now() {
  using namespace std::chrono;
  return static_cast<std::uint64_t>(
      duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count());
}

Error with_column(ErrorKind kind, std::size_t column) {
  Error e(kind);
  e.set_column(column);
  return e;
}

// A name as ⎕NC and ⎕EX take it: one row of a character argument, blanks around it dropped.
std::vector<std::string> names_of(const Value& b) {
  if (b.rank() > 2) rank_error();
  if (!b.is_character()) {
    if (b.empty()) return {};
    domain_error();
  }
  const std::size_t width = b.rank() == 0 ? 1 : b.shape().back();
  const std::size_t rows = b.rank() == 2 ? b.shape()[0] : 1;
  std::vector<std::string> out;
  auto c = b.characters();
  for (std::size_t r = 0; r < rows; ++r) {
    std::u32string_view row(c.data() + r * width, width);
    std::u32string name(trim(row));
    for (auto& ch : name)
      if (ch >= U'a' && ch <= U'z') ch = ch - U'a' + U'A';
    out.push_back(encode_utf8(name));
  }
  return out;
}

bool valid_name(std::string_view name) {
  const std::u32string u = decode_utf8(name);
  if (u.empty() || !is_name_start(u[0])) return false;
  return std::all_of(u.begin(), u.end(), is_name_char);
}

}  // namespace

Evaluator::Evaluator(Host& h) : host(h), started_(milliseconds_now()) {}

// --- symbols and names -----------------------------------------------------------------------

std::uint32_t Evaluator::symbol(const std::string& name) {
  if (auto it = ids_.find(name); it != ids_.end()) return it->second;
  const auto id = static_cast<std::uint32_t>(symbols_.size());
  Symbol s;
  s.name = name;
  s.owned = host.owns(name);
  symbols_.push_back(std::move(s));
  ids_.emplace(name, id);
  return id;
}

const Evaluator::Symbol* Evaluator::find_symbol(const std::string& name) const {
  auto it = ids_.find(name);
  return it == ids_.end() ? nullptr : &symbols_[it->second];
}

std::optional<Value>* Evaluator::local_slot(std::uint32_t id) {
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f) {
    if (f->kind != Frame::Kind::function) continue;
    const auto& ids = f->function->slot_symbols;
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (ids[i] == id) return &f->slots[i];
  }
  return nullptr;
}

const std::optional<Value>* Evaluator::local_slot(std::uint32_t id) const {
  return const_cast<Evaluator*>(this)->local_slot(id);
}

Value Evaluator::load(std::uint32_t id) const {
  if (const auto* s = local_slot(id)) {
    if (!*s) throw Error(ErrorKind::value);
    return **s;
  }
  const Symbol& sym = symbols_[id];
  if (sym.owned) {
    auto v = host.get(sym.name);
    if (!v) throw Error(ErrorKind::value);
    return std::move(*v);
  }
  if (!sym.value) throw Error(ErrorKind::value);
  return *sym.value;
}

void Evaluator::store(std::uint32_t id, Value v) {
  if (auto* s = local_slot(id)) {
    *s = std::move(v);
    return;
  }
  Symbol& sym = symbols_[id];
  if (sym.function || sym.native) syntax_error();
  if (sym.owned) {
    // The host's name takes the value at once, or refuses it (APL\360: what a statement assigned
    // before it failed stays assigned).
    host.check(sym.name, v);
    host.set(sym.name, v);
    return;
  }
  sym.value = std::move(v);
  changed(sym);
}

void Evaluator::index_store(std::uint32_t id, const Instr& in) {
  const Code& code = *frames_.back().code;
  const std::vector<bool>& given = code.index_lists[in.b];
  std::vector<std::optional<Value>> indices(in.count);
  for (std::size_t i = 0; i < in.count; ++i)
    if (given[i]) indices[i] = pop();
  const Value& v = stack_.back();
  if (in.op == Op::index_assign_local) {
    auto& slot = frames_.back().slots[id];
    if (!slot) throw Error(ErrorKind::value);
    index_assign(ctx, *slot, indices, v);
    return;
  }
  if (auto* s = local_slot(id)) {
    if (!*s) throw Error(ErrorKind::value);
    index_assign(ctx, **s, indices, v);
    return;
  }
  Symbol& sym = symbols_[id];
  if (sym.function || sym.native) syntax_error();
  if (sym.owned) {
    auto target = host.get(sym.name);
    if (!target) throw Error(ErrorKind::value);
    index_assign(ctx, *target, indices, v);
    host.check(sym.name, *target);
    host.set(sym.name, *target);
    return;
  }
  if (!sym.value) throw Error(ErrorKind::value);
  index_assign(ctx, *sym.value, indices, v);
  changed(sym);
}

NameClass Evaluator::static_class(const std::string& name) const {
  const Symbol* s = find_symbol(name);
  if (s && s->function) return class_of_valence(s->function->header.valence());
  if (s && s->native) return class_of_valence(s->native->valence);
  if (s && s->value) return NameClass::variable;
  if (host.owns(name)) return host.get(name) ? NameClass::variable : NameClass::undefined;
  return NameClass::undefined;
}

NameClass Evaluator::classify(const std::string& name) const {
  if (const Symbol* s = find_symbol(name)) {
    const auto id = static_cast<std::uint32_t>(s - symbols_.data());
    if (const auto* slot = local_slot(id))
      return *slot ? NameClass::variable : NameClass::undefined;
  }
  return static_class(name);
}

std::optional<Value> Evaluator::lookup(const std::string& name) const {
  if (const Symbol* s = find_symbol(name)) {
    try {
      return load(static_cast<std::uint32_t>(s - symbols_.data()));
    } catch (const Error&) {
      return std::nullopt;
    }
  }
  if (host.owns(name)) return host.get(name);
  return std::nullopt;
}

void Evaluator::set_variable(const std::string& name, Value value) {
  store(symbol(name), std::move(value));
}

bool Evaluator::is_global_variable(const std::string& name) const {
  const Symbol* s = find_symbol(name);
  return s && s->value;
}

bool Evaluator::is_variable(const std::string& name) const {
  return host.owns(name) || is_global_variable(name);
}

std::vector<std::pair<std::string, Value>> Evaluator::globals() const {
  std::vector<std::pair<std::string, Value>> out;
  for (const auto& s : symbols_)
    if (s.value) out.emplace_back(s.name, *s.value);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

std::vector<std::pair<std::string, std::optional<Value>>> Evaluator::globals_changed(
    std::uint64_t version) const {
  std::vector<std::pair<std::string, std::optional<Value>>> out;
  for (const auto& s : symbols_)
    if (s.changed > version) out.emplace_back(s.name, s.value);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

std::vector<std::string> Evaluator::function_names(bool natives) const {
  std::vector<std::string> out;
  for (const auto& s : symbols_)
    if (natives ? s.native.has_value() : s.function != nullptr) out.push_back(s.name);
  std::sort(out.begin(), out.end());
  return out;
}

std::shared_ptr<const DefinedFunction> Evaluator::function(const std::string& name) const {
  const Symbol* s = find_symbol(name);
  return s ? s->function : nullptr;
}

const NativeEntry* Evaluator::native(const std::string& name) const {
  const Symbol* s = find_symbol(name);
  return s && s->native ? &*s->native : nullptr;
}

void Evaluator::definitions_changed() {
  ++generation_;
  shadowing_ = 0;
  for (auto& f : frames_) {
    if (f.kind != Frame::Kind::function) continue;
    f.shadows =
        std::any_of(f.function->slot_symbols.begin(), f.function->slot_symbols.end(),
                    [&](std::uint32_t id) { return symbols_[id].function || symbols_[id].native; });
    shadowing_ += f.shadows;
  }
}

void Evaluator::define(DefinedFunction f) {
  const std::string name = f.header.name;
  // APL\360: a pendent function (waiting for a function it called) cannot be changed; a suspended
  // one can, when its header stays, and resumes with its new lines.
  for (const auto& frame : frames_) {
    if (frame.kind != Frame::Kind::function || frame.function->header.name != name) continue;
    if (!frame.suspended || frame.function->header_text != f.header_text)
      throw Error(ErrorKind::defn);
  }
  for (const auto& slot : f.slots) f.slot_symbols.push_back(symbol(slot));
  auto defined = std::make_shared<const DefinedFunction>(std::move(f));
  Symbol& sym = symbols_[symbol(name)];
  sym.function = defined;
  sym.native.reset();
  for (auto& frame : frames_) {
    if (frame.kind != Frame::Kind::function || frame.function->header.name != name) continue;
    frame.function = defined;
    frame.slots.resize(defined->first_label);
    for (std::size_t i = defined->first_label; i < defined->slots.size(); ++i)
      frame.slots.emplace_back(
          Value::number(static_cast<double>(defined->labels.at(defined->slots[i]))));
  }
  definitions_changed();
}

void Evaluator::define_native(const std::string& name, NativeEntry entry) {
  Symbol& sym = symbols_[symbol(name)];
  sym.native = std::move(entry);
  sym.function.reset();
  definitions_changed();
}

bool Evaluator::erase(const std::string& name) {
  auto it = ids_.find(name);
  if (it == ids_.end()) return false;
  Symbol& sym = symbols_[it->second];
  if (sym.function) {
    sym.function.reset();
    definitions_changed();
    return true;
  }
  if (sym.value) {
    sym.value.reset();
    changed(sym);
    return true;
  }
  return false;
}

void Evaluator::clear() {
  clear_state_indicator();
  for (auto& s : symbols_) {
    if (s.value) changed(s);
    s.value.reset();
    s.function.reset();
  }
  ctx.io = 1;
  ctx.pp = 10;
  ctx.ct = 1e-13;
  ctx.rl = 16807;
  ctx.pw = 80;
  definitions_changed();
}

// --- the state indicator ---------------------------------------------------------------------

std::vector<std::string> Evaluator::state_indicator() const {
  std::vector<std::string> lines;
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f)
    if (f->kind == Frame::Kind::function)
      lines.push_back(
          fmt::format("{}[{}]{}", f->function->header.name, f->line, f->suspended ? " *" : ""));
  return lines;
}

void Evaluator::clear_state_indicator() {
  while (!frames_.empty()) pop_frame();
}

bool Evaluator::pendent(const std::string& name) const {
  return std::any_of(frames_.begin(), frames_.end(), [&](const Frame& f) {
    return f.kind == Frame::Kind::function && !f.suspended && f.function->header.name == name;
  });
}

void Evaluator::push_frame(Frame f) {
  // A line typed at the prompt always runs, so that → can clear a state indicator that is full.
  if (f.kind != Frame::Kind::immediate &&
      frames_.size() >= static_cast<std::size_t>(ctx.limits.max_depth))
    throw Error(ErrorKind::depth);
  f.base = stack_.size();
  if (f.kind == Frame::Kind::function) {
    for (std::uint32_t id : f.function->slot_symbols)
      f.shadows = f.shadows || symbols_[id].function || symbols_[id].native;
    shadowing_ += f.shadows;
  }
  frames_.push_back(std::move(f));
}

void Evaluator::pop_frame() {
  Frame& f = frames_.back();
  restore_system(f);
  shadowing_ -= f.shadows;
  stack_.erase(stack_.begin() + static_cast<std::ptrdiff_t>(f.base), stack_.end());
  frames_.pop_back();
}

void Evaluator::restore_system(const Frame& f) {
  for (const auto& [name, x] : f.saved) {
    switch (name) {
      case SystemName::io:
        ctx.io = static_cast<int>(x);
        break;
      case SystemName::pp:
        ctx.pp = static_cast<int>(x);
        break;
      case SystemName::ct:
        ctx.ct = x;
        break;
      case SystemName::rl:
        ctx.rl = static_cast<std::uint32_t>(x);
        break;
      case SystemName::pw:
        ctx.pw = static_cast<int>(x);
        break;
      default:
        break;
    }
  }
}

// --- output ----------------------------------------------------------------------------------

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

void Evaluator::show(const Value& v) {
  for (const auto& line : display(ctx, v)) {
    ctx.charge(line.size());  // a long listing can be stopped
    print(line);
  }
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

// --- running ---------------------------------------------------------------------------------

Value Evaluator::pop() {
  Value v = std::move(stack_.back());
  stack_.pop_back();
  return v;
}

std::shared_ptr<const Code> Evaluator::compile_text(std::u32string_view text, bool& nothing) {
  const Classifier classify = [this](const std::string& name) { return this->classify(name); };
  const Statement statement = parse(tokenize(text), classify, false, ctx.limits.max_depth);
  nothing = !statement.expr && !statement.branch;
  const Resolver resolve = [this](const std::string& name) {
    return NameRef{false, false, symbol(name)};
  };
  auto code = std::make_shared<Code>(compile(statement, resolve));
  return code;
}

const Code* Evaluator::function_line(Frame& f) {
  const DefinedFunction& fn = *f.function;
  const std::size_t i = f.line - 1;
  if (fn.line_errors[i]) throw Error(*fn.line_errors[i]);
  // A line is compiled once for the definitions it was compiled with; while a running function's
  // local hides a function's name the names' classes depend on the calls, and lines are compiled
  // each time.
  if (shadowing_ == 0 && fn.compiled_for == generation_ && fn.compiled[i])
    return fn.compiled[i].get();
  const bool cache = shadowing_ == 0;
  const Classifier classify = [&](const std::string& name) {
    if (fn.slot_of(name) >= 0) return NameClass::variable;
    return cache ? static_class(name) : this->classify(name);
  };
  const Statement statement = parse(fn.tokens[i], classify, true, ctx.limits.max_depth);
  const Resolver resolve = [&](const std::string& name) {
    const int slot = fn.slot_of(name);
    if (slot >= 0)
      return NameRef{true, static_cast<std::size_t>(slot) >= fn.first_label,
                     static_cast<std::uint32_t>(slot)};
    return NameRef{false, false, symbol(name)};
  };
  auto code = std::make_shared<const Code>(compile(statement, resolve));
  if (!cache) {
    f.owned = std::move(code);
    return f.owned.get();
  }
  if (fn.compiled_for != generation_) {
    for (auto& c : fn.compiled)
      if (c) fn.retired.push_back(std::move(c));
    fn.compiled_for = generation_;
  }
  fn.compiled[i] = std::move(code);
  return fn.compiled[i].get();
}

void Evaluator::run_line(std::string_view line) {
  ctx.start_line();
  Frame f;
  f.kind = Frame::Kind::immediate;
  f.text = std::string(line);
  try {
    try {
      bool nothing = false;
      f.owned = compile_text(decode_utf8(line), nothing);
      f.code = f.owned.get();
      push_frame(std::move(f));
    } catch (const std::bad_alloc&) {
      throw Error(ErrorKind::ws_full);
    } catch (const std::length_error&) {
      throw Error(ErrorKind::ws_full);
    }
  } catch (const Error& e) {
    report(e, line);
    return;
  }
  run();
  flush();
}

void Evaluator::run() {
  while (!frames_.empty() && !frames_.back().suspended) {
    try {
      try {
        step();
      } catch (const std::bad_alloc&) {
        throw Error(ErrorKind::ws_full);
      } catch (const std::length_error&) {
        throw Error(ErrorKind::ws_full);
      }
    } catch (Error& e) {
      fail(std::move(e));
    } catch (const Escape& e) {
      escape(e.at_prompt);
    }
  }
}

namespace {

[[noreturn, gnu::noinline]] void unset_local(const Operand& o) {
  throw with_column(ErrorKind::value, o.column);
}

}  // namespace

[[gnu::always_inline]] inline const Value& Evaluator::argument(const Frame& f,
                                                               const Operand& o) const {
  if (o.from == Operand::local) {
    const auto& slot = f.slots[o.index];
    if (!slot) [[unlikely]]
      unset_local(o);
    return *slot;
  }
  if (o.from == Operand::constant) return f.code->constants[o.index];
  return f.scratch;
}

void Evaluator::start_statement(Frame& f) {
  const DefinedFunction& fn = *f.function;
  if (f.line < 1 || f.line > fn.lines.size()) {
    return_from_function();
    return;
  }
  f.pc = 0;
  ctx.charge(statement_work);
  // The line compiled already for these definitions: the loops' case.
  if (shadowing_ == 0 && fn.compiled_for == generation_) {
    if (const Code* code = fn.compiled[f.line - 1].get()) {
      f.code = code;
      return;
    }
  }
  f.code = function_line(f);
}

// Runs the top frame until the frames change (a call, a return, a line typed that ends): a
// function's statements one after the other.
void Evaluator::step() {
  Frame* f = &frames_.back();
next_statement:
  if (!f->code) {
    // The next line of a function, compiled already for these definitions (the loops' case),
    // or as start_statement finds it.
    const DefinedFunction& fn = *f->function;
    const Code* known = nullptr;
    if (f->line >= 1 && f->line <= fn.lines.size() && shadowing_ == 0 &&
        fn.compiled_for == generation_ && ctx.work + statement_work < ctx.next_poll)
      known = fn.compiled[f->line - 1].get();
    if (known) {
      ctx.work += statement_work;
      f->pc = 0;
      f->code = known;
    } else {
      const std::size_t depth = frames_.size();
      start_statement(*f);
      if (frames_.size() != depth) return;
    }
  }
  const Code& code = *f->code;
  for (;;) {
    const Instr& in = code.instrs[f->pc++];
    switch (in.op) {
      case Op::constant:
        stack_.push_back(code.constants[in.a]);
        break;
      case Op::local: {
        const auto& slot = f->slots[in.a];
        if (!slot) throw Error(ErrorKind::value);
        stack_.push_back(*slot);
        break;
      }
      case Op::name:
        stack_.push_back(load(in.a));
        break;
      case Op::niladic:
        call(in.a, in, 0);
        return;
      case Op::system_variable:
        stack_.push_back(system_variable(static_cast<SystemName>(in.a)));
        break;
      case Op::quad_input:
        quad_input(in);
        return;
      case Op::quote_input: {
        ctx.charge(1);
        const std::string prompt = encode_utf8(pending_);
        pending_.clear();
        std::optional<std::string> line = host.read_line(prompt);
        if (!line) throw Error(ErrorKind::interrupt);
        stack_.push_back(Value::text(*line));
        break;
      }
      case Op::monadic: {
        std::optional<Value> axis;
        if (in.flags & has_axis) axis = pop();
        Value b = pop();
        const auto glyph = static_cast<char32_t>(in.a);
        if (axis && !has_role(glyph, Role::axis_monadic)) syntax_error();
        if (in.flags & scalar) {
          stack_.push_back(scalar_monadic(ctx, glyph, std::move(b)));
          break;
        }
        const Value* k = axis ? &*axis : nullptr;
        switch (glyph) {
          case U'⍴':
            stack_.push_back(shape_of(ctx, b));
            break;
          case U',':
            stack_.push_back(ravel(ctx, b, k));
            break;
          case U'⍳':
            stack_.push_back(iota(ctx, b));
            break;
          case U'⌽':
            stack_.push_back(reverse(ctx, b, k, false));
            break;
          case U'⊖':
            stack_.push_back(reverse(ctx, b, k, true));
            break;
          case U'⍉':
            stack_.push_back(transpose(ctx, b));
            break;
          case U'⍋':
            stack_.push_back(grade(ctx, b, true));
            break;
          case U'⍒':
            stack_.push_back(grade(ctx, b, false));
            break;
          case U'⌹':
            stack_.push_back(matrix_inverse(ctx, b));
            break;
          case U'⍕':
            stack_.push_back(format(ctx, b));
            break;
          default:
            syntax_error();
        }
        break;
      }
      case Op::dyadic: {
        // The arguments: from the stack, or read here from a slot or a constant (right first).
        const Value* right = in.right.from == Operand::stack ? nullptr : &argument(*f, in.right);
        const Value* left = in.left.from == Operand::stack ? nullptr : &argument(*f, in.left);
        if (!right) right = &stack_[stack_.size() - (left ? 1 : 2)];
        if (!left) left = &stack_.back();
        const std::size_t on_stack =
            (in.left.from == Operand::stack) + (in.right.from == Operand::stack);
        if ((in.flags & scalar) && left->is_one_number() && right->is_one_number() &&
            left->rank() == 0 && right->rank() == 0) {
          // Two numbers, the loops' case: no array made.
          const double r = in.loops->one(ctx, left->one_number(), right->one_number());
          if (in.result.from == Operand::scratch) {
            if (f->scratch.is_one_number() && f->scratch.rank() == 0)
              f->scratch.set_one_number(r);
            else
              f->scratch = Value(r);
            for (std::size_t k = 0; k < on_stack; ++k) stack_.pop_back();
            break;
          }
          if (in.result.from == Operand::local) {
            auto& slot = f->slots[in.result.index];
            if (slot && slot->is_one_number() && slot->rank() == 0)
              slot->set_one_number(r);
            else
              slot.emplace(r);
            for (std::size_t k = 0; k < on_stack; ++k) stack_.pop_back();
          } else if (on_stack == 0) {
            stack_.emplace_back(r);
            break;
          } else {
            if (on_stack == 2) stack_.pop_back();
            stack_.back().set_one_number(r);
            break;
          }
        } else {
          Value r = dyadic_primitive(
              in, in.left.from == Operand::stack ? pop() : *left,
              in.right.from == Operand::stack ? std::nullopt : std::optional(*right));
          if (in.result.from == Operand::scratch) {
            f->scratch = std::move(r);
            break;
          }
          if (in.result.from != Operand::local) {
            stack_.push_back(std::move(r));
            break;
          }
          f->slots[in.result.index] = std::move(r);
        }
        // Z←A f B: the statement ends with the assignment.
        if (f->kind != Frame::Kind::function) {
          end_statement(in);
          return;
        }
        ++f->line;
        f->code = nullptr;
        goto next_statement;
      }
      case Op::execute:
        execute_text(in);
        return;
      case Op::reduce:
      case Op::scan: {
        std::optional<Value> axis;
        if (in.flags & has_axis) axis = pop();
        Value b = pop();
        const bool first = (in.flags & first_axis) != 0;
        const Value* k = axis ? &*axis : nullptr;
        const auto glyph = static_cast<char32_t>(in.a);
        stack_.push_back(in.op == Op::reduce ? reduce(ctx, glyph, b, k, first)
                                             : scan(ctx, glyph, b, k, first));
        break;
      }
      case Op::outer: {
        Value a = pop();
        Value b = pop();
        stack_.push_back(outer_product(ctx, static_cast<char32_t>(in.a), a, b));
        break;
      }
      case Op::inner: {
        Value a = pop();
        Value b = pop();
        stack_.push_back(
            inner_product(ctx, static_cast<char32_t>(in.a), static_cast<char32_t>(in.b), a, b));
        break;
      }
      case Op::call_monadic:
        call(in.a, in, 1);
        return;
      case Op::call_dyadic:
        call(in.a, in, 2);
        return;
      case Op::system_function: {
        Value b = pop();
        stack_.push_back(system_function(static_cast<SystemName>(in.a), b));
        break;
      }
      case Op::index: {
        const std::vector<bool>& given = code.index_lists[in.a];
        Value b = pop();
        std::vector<std::optional<Value>> indices(in.count);
        for (std::size_t i = 0; i < in.count; ++i)
          if (given[i]) indices[i] = pop();
        ctx.charge(1);
        stack_.push_back(index(ctx, b, indices));
        break;
      }
      case Op::assign_local: {
        auto& slot = f->slots[in.a];
        const Value& v = stack_.back();
        if (slot && slot->is_one_number() && v.is_one_number() && slot->rank() == 0 &&
            v.rank() == 0)
          slot->set_one_number(v.one_number());  // a loop's counter: no value made
        else
          slot = v;
        if (!(in.flags & ends)) break;
        if (f->kind != Frame::Kind::function) {
          end_statement(in);
          return;
        }
        stack_.pop_back();
        ++f->line;
        f->code = nullptr;
        goto next_statement;
      }
      case Op::assign_name:
        store(in.a, stack_.back());
        break;
      case Op::assign_system:
        set_system_variable(static_cast<SystemName>(in.a), stack_.back());
        break;
      case Op::assign_quad:
        show(stack_.back());
        break;
      case Op::assign_quote:
        quote_output(stack_.back());
        break;
      case Op::index_assign_local:
      case Op::index_assign_name:
        index_store(in.a, in);
        break;
      case Op::branch:
        branch(*f, pop());
        if (f->kind != Frame::Kind::function) return;
        goto next_statement;
      case Op::branch_compress: {
        const Value* right = in.right.from == Operand::stack ? nullptr : &argument(*f, in.right);
        const Value* left = in.left.from == Operand::stack ? nullptr : &argument(*f, in.left);
        if (in.left.from == Operand::scratch) left = &f->scratch;
        if (!right) right = &stack_[stack_.size() - (left ? 1 : 2)];
        if (!left) left = &stack_.back();
        // →A/B with A a whole number of copies of the line number B, in a function: B, or the
        // next line for none; the loops' case, no array made.
        const double copies = left->one_number(), to = right->one_number();
        if (f->kind == Frame::Kind::function && left->is_one_number() && right->is_one_number() &&
            (copies == 0 || copies == 1) && to == std::floor(to)) {
          const auto n = static_cast<double>(f->function->lines.size());
          f->line = copies == 0          ? f->line + 1
                    : to >= 1 && to <= n ? static_cast<std::size_t>(to)
                                         : 0;
          f->code = nullptr;
          while (stack_.size() > f->base) stack_.pop_back();
          goto next_statement;
        }
        Value a = in.left.from == Operand::stack ? pop() : *left;  // A is above B
        Value b = in.right.from == Operand::stack ? pop() : *right;
        branch(*f, replicate(ctx, a, b, nullptr, false));
        if (f->kind != Frame::Kind::function) return;
        goto next_statement;
      }
      case Op::naked_branch:
        throw Escape{f->kind == Frame::Kind::immediate};
      case Op::end:
        if (f->kind != Frame::Kind::function) {
          end_statement(in);
          return;
        }
        if (stack_.size() > f->base) {
          const bool shy = (in.flags & shows) == 0 || ((in.flags & shy_execute) && f->executed_shy);
          if (!shy) show(stack_.back());
          while (stack_.size() > f->base) stack_.pop_back();
        }
        ++f->line;
        f->code = nullptr;
        goto next_statement;
    }
  }
}

Value Evaluator::dyadic_primitive(const Instr& in, Value a, std::optional<Value> right) {
  std::optional<Value> axis;
  if (in.flags & has_axis) axis = pop();
  Value b = right ? std::move(*right) : pop();
  const auto glyph = static_cast<char32_t>(in.a);
  if (axis && !has_role(glyph, Role::axis_dyadic)) syntax_error();
  if (in.flags & scalar) return scalar_dyadic(ctx, glyph, std::move(a), std::move(b));
  const Value* k = axis ? &*axis : nullptr;
  switch (glyph) {
    case U'⍴':
      return reshape(ctx, a, b);
    case U',':
      return catenate(ctx, a, b, k);
    case U'⍳':
      return index_of(ctx, a, b);
    case U'↑':
      return take(ctx, a, b, k);
    case U'↓':
      return drop(ctx, a, b, k);
    case U'⌽':
      return rotate(ctx, a, b, k, false);
    case U'⊖':
      return rotate(ctx, a, b, k, true);
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
      return replicate(ctx, a, b, k, false);
    case U'⌿':
      return replicate(ctx, a, b, k, true);
    case U'\\':
      return expand(ctx, a, b, k, false);
    case U'⍀':
      return expand(ctx, a, b, k, true);
    case U'⍕':
      return format_by_specification(ctx, a, b);
    default:
      syntax_error();
  }
}

void Evaluator::end_statement(const Instr& in) {
  Frame& f = frames_.back();
  const bool has_value = stack_.size() > f.base;
  const bool shy = (in.flags & shows) == 0 || ((in.flags & shy_execute) && f.executed_shy);
  switch (f.kind) {
    case Frame::Kind::immediate:
      if (has_value && !shy) show(stack_.back());
      pop_frame();
      return;
    case Frame::Kind::function:
      if (has_value && !shy) show(stack_.back());
      ++f.line;
      f.code = nullptr;
      stack_.erase(stack_.begin() + static_cast<std::ptrdiff_t>(f.base), stack_.end());
      return;
    case Frame::Kind::execute: {
      std::optional<Value> v;
      if (has_value) v = pop();
      const bool needed = f.needs_value;
      const std::uint32_t column = f.call_column;
      pop_frame();
      frames_.back().executed_shy = shy;
      if (v)
        stack_.push_back(std::move(*v));
      else if (needed)
        throw with_column(ErrorKind::value, column);
      return;
    }
    case Frame::Kind::quad: {
      if (!has_value) {
        pop_frame();  // a statement without a value: ⎕ asks again
        return;
      }
      Value v = pop();
      pop_frame();
      ++frames_.back().pc;
      stack_.push_back(std::move(v));
      return;
    }
  }
}

void Evaluator::branch(Frame& f, const Value& target) {
  if (target.empty()) {  // no branch: the next statement
    if (f.kind == Frame::Kind::function) {
      ++f.line;
      f.code = nullptr;
      while (stack_.size() > f.base) stack_.pop_back();
    } else {
      pop_frame();
    }
    return;
  }
  if (target.is_character() || !near_integer(target.numbers()[0])) throw Error(ErrorKind::domain);
  const double t = std::round(target.numbers()[0]);
  if (f.kind == Frame::Kind::function) {
    // →N goes to line N; a number that is no line of the function leaves it (→0).
    const auto n = static_cast<double>(f.function->lines.size());
    f.line = t >= 1 && t <= n ? static_cast<std::size_t>(t) : 0;
    f.code = nullptr;
    while (stack_.size() > f.base) stack_.pop_back();
    return;
  }
  // Typed at the prompt: →N resumes the function suspended last at its line N (APL\360), and
  // does nothing when none is suspended.
  pop_frame();
  if (frames_.empty()) return;
  Frame& s = frames_.back();
  if (s.kind != Frame::Kind::function || !s.suspended) return;
  const auto n = static_cast<double>(s.function->lines.size());
  s.suspended = false;
  s.line = t >= 1 && t <= n ? static_cast<std::size_t>(t) : 0;
  s.code = nullptr;
  ctx.start_line();
}

void Evaluator::return_from_function() {
  Frame& f = frames_.back();
  std::optional<Value> result;
  if (!f.function->header.result.empty()) result = std::move(f.slots[0]);
  const bool needed = f.needs_value;
  const std::uint32_t column = f.call_column;
  pop_frame();
  if (result)
    stack_.push_back(std::move(*result));
  else if (needed)
    throw with_column(ErrorKind::value, column);
}

void Evaluator::call(std::uint32_t id, const Instr& in, int valence) {
  const Symbol& sym = symbols_[id];
  if (sym.function) {
    std::shared_ptr<const DefinedFunction> fn = sym.function;
    const Header& h = fn->header;
    if (h.valence() != valence) syntax_error();
    Frame frame;
    frame.kind = Frame::Kind::function;
    frame.needs_value = (in.flags & needs_value) != 0;
    frame.call_column = in.column;
    frame.line = 1;
    frame.slots.resize(fn->slots.size());
    std::size_t k = h.result.empty() ? 0 : 1;
    if (valence == 2) {
      frame.slots[k++] = pop();  // A is on top of B
      frame.slots[k++] = pop();
    } else if (valence == 1) {
      frame.slots[k++] = pop();
    }
    for (std::size_t i = fn->first_label; i < fn->slots.size(); ++i)
      frame.slots[i] = Value::number(static_cast<double>(fn->labels.at(fn->slots[i])));
    for (const auto& local : h.locals) {
      SystemName s;
      if (system_name(local, s)) frame.saved.emplace_back(s, system_variable(s).numbers()[0]);
    }
    frame.function = std::move(fn);
    push_frame(std::move(frame));
    return;
  }
  if (!sym.native) throw Error(ErrorKind::value);
  const NativeEntry native = *sym.native;  // the table may change while it runs
  if (native.valence != valence) syntax_error();
  std::optional<Value> a, b;
  if (valence == 2) a = pop();
  if (valence >= 1) b = pop();
  call_native(native, in, a ? &*a : nullptr, b ? &*b : nullptr);
}

void Evaluator::call_native(const NativeEntry& native, const Instr& in, const Value* left,
                            const Value* right) {
  ctx.charge(1);
  std::optional<Value> r;
  try {
    r = native.function(left, right);
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error(ErrorKind::ws_full);
  } catch (const std::exception& e) {
    throw Error(ErrorKind::domain, e.what());
  }
  push_result(std::move(r), in);
}

void Evaluator::push_result(std::optional<Value> v, const Instr& in) {
  if (v)
    stack_.push_back(std::move(*v));
  else if (in.flags & needs_value)
    throw Error(ErrorKind::value);
}

void Evaluator::execute_text(const Instr& in) {
  // ⍎B (APL.SV "execute"): the statement of the characters B, its result if it has one; an error
  // in it is reported at the ⍎.
  Value text = pop();
  if (text.rank() > 1) rank_error();
  if (text.is_numeric() && !text.empty()) domain_error();
  ctx.charge(text.size() + 1);
  std::shared_ptr<const Code> code;
  bool nothing = false;
  try {
    auto c = text.characters();
    code = compile_text(std::u32string_view(c.data(), c.size()), nothing);
  } catch (const Error& e) {
    throw Error(e.kind(), e.what());
  }
  if (code->branch) syntax_error();
  if (nothing) {
    frames_.back().executed_shy = true;
    if (in.flags & needs_value) throw Error(ErrorKind::value);
    return;
  }
  Frame frame;
  frame.kind = Frame::Kind::execute;
  frame.needs_value = (in.flags & needs_value) != 0;
  frame.call_column = in.column;
  frame.text = text.utf8();
  frame.owned = std::move(code);
  frame.code = frame.owned.get();
  push_frame(std::move(frame));
}

void Evaluator::quad_input(const Instr&) {
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
    if (typed == U"→") throw Escape{false};
    std::shared_ptr<const Code> code;
    try {
      bool nothing = false;
      code = compile_text(text, nothing);
      if (nothing) continue;
      if (code->branch) syntax_error();
    } catch (const Error& e) {
      report(e, *line);
      continue;
    }
    if (frames_.size() >= static_cast<std::size_t>(ctx.limits.max_depth))
      throw Error(ErrorKind::depth);
    --frames_.back().pc;  // asked again unless the line gives a value
    Frame frame;
    frame.kind = Frame::Kind::quad;
    frame.text = *line;
    frame.owned = std::move(code);
    frame.code = frame.owned.get();
    push_frame(std::move(frame));
    return;
  }
}

void Evaluator::quote_output(const Value& v) {
  std::vector<std::string> lines = display(ctx, v);
  if (lines.empty()) return;
  lines[0] = encode_utf8(pending_) + lines[0];
  pending_.clear();
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) host.print(lines[i]);
  pending_ = decode_utf8(lines.back());
}

void Evaluator::fail(Error e) {
  while (!frames_.empty()) {
    Frame& f = frames_.back();
    if (!e.has_column() && f.code && f.pc > 0) e.set_column(f.code->instrs[f.pc - 1].column);
    switch (f.kind) {
      case Frame::Kind::immediate:
        report(e, f.text);
        pop_frame();
        return;
      case Frame::Kind::function: {
        // The function is suspended at the line: reported with its name and line number.
        if (!e.located()) {
          const std::string prefix = fmt::format("{}[{}] ", f.function->header.name, f.line);
          const std::size_t line = f.line >= 1 ? f.line - 1 : 0;
          const std::string text =
              line < f.function->lines.size() ? f.function->lines[line] : std::string();
          e.locate(prefix + text, characters_in(prefix) + (e.has_column() ? e.column() : 0));
        }
        report(e, {});
        f.suspended = true;
        f.code = nullptr;
        stack_.erase(stack_.begin() + static_cast<std::ptrdiff_t>(f.base), stack_.end());
        return;
      }
      case Frame::Kind::execute:
        // Reported at the ⍎ of the statement that ran it.
        pop_frame();
        e = Error(e.kind(), e.what());
        continue;
      case Frame::Kind::quad:
        if (e.kind() == ErrorKind::interrupt) {
          pop_frame();
          ++frames_.back().pc;
          e = Error(e.kind(), e.what());
          continue;
        }
        report(e, f.text);
        pop_frame();  // ⎕ asks again
        return;
    }
  }
}

void Evaluator::escape(bool at_prompt) {
  // → alone abandons the line typed at the prompt and every frame it started; typed at the
  // prompt itself, it abandons the suspension the prompt stood at (APL\360).
  auto pop_group = [this] {
    while (!frames_.empty()) {
      const bool typed = frames_.back().kind == Frame::Kind::immediate;
      pop_frame();
      if (typed) return;
    }
  };
  pop_group();
  if (at_prompt) pop_group();
}

// --- system variables and functions ----------------------------------------------------------

Value Evaluator::system_variable(SystemName s) const {
  switch (s) {
    case SystemName::io:
      return Value::number(ctx.io);
    case SystemName::pp:
      return Value::number(ctx.pp);
    case SystemName::ct:
      return Value::number(ctx.ct);
    case SystemName::rl:
      return Value::number(ctx.rl);
    case SystemName::pw:
      return Value::number(ctx.pw);
    case SystemName::lc: {  // the lines of the functions on the stack, the latest first
      Numbers lines;
      for (auto f = frames_.rbegin(); f != frames_.rend(); ++f)
        if (f->kind == Frame::Kind::function) lines.push_back(static_cast<double>(f->line));
      const std::size_t n = lines.size();  // before the move: arguments have no order
      return Value::of_numbers({n}, std::move(lines));
    }
    case SystemName::ts: {  // year month day hour minute second millisecond, local time
      using namespace std::chrono;
      const auto now = system_clock::now();
      const std::time_t t = system_clock::to_time_t(now);
      std::tm tm{};
      localtime_r(&t, &tm);
      const auto ms = duration_cast<milliseconds>(now.time_since_epoch()).count() % 1000;
      return Value::vector({static_cast<double>(tm.tm_year + 1900),
                            static_cast<double>(tm.tm_mon + 1), static_cast<double>(tm.tm_mday),
                            static_cast<double>(tm.tm_hour), static_cast<double>(tm.tm_min),
                            static_cast<double>(tm.tm_sec), static_cast<double>(ms)});
    }
    case SystemName::ai: {  // user number, computer time, connected time, keying time (ms)
      const double cpu = static_cast<double>(std::clock()) * 1000.0 / CLOCKS_PER_SEC;
      const double connected = static_cast<double>(milliseconds_now() - started_);
      return Value::vector({1000, std::round(cpu), connected, 0});
    }
    case SystemName::av: {  // the printable ASCII characters, then the APL glyphs of the table
      std::u32string av;
      for (char32_t c = 32; c < 127; ++c) av.push_back(c);
      for (const Glyph& g : glyph_table())
        if (g.glyph >= 0x80) av.push_back(g.glyph);
      return Value::text(std::u32string_view(av));
    }
    default:
      syntax_error();
  }
}

void Evaluator::set_system_variable(SystemName s, const Value& v) {
  if (s != SystemName::io && s != SystemName::pp && s != SystemName::ct && s != SystemName::rl &&
      s != SystemName::pw)
    syntax_error();
  if (v.is_character() || v.size() != 1) domain_error();
  const double x = v.numbers()[0];
  if (s == SystemName::ct) {
    if (!(x >= 0 && x <= 1e-9)) domain_error();
    ctx.ct = x;
    return;
  }
  const std::int64_t i = integer_of(x);
  switch (s) {
    case SystemName::io:
      if (i != 0 && i != 1) domain_error();
      ctx.io = static_cast<int>(i);
      return;
    case SystemName::pp:
      if (i < 1 || i > 17) domain_error();
      ctx.pp = static_cast<int>(i);
      return;
    case SystemName::pw:
      if (i < 30 || i > 254) domain_error();
      ctx.pw = static_cast<int>(i);
      return;
    default:
      if (i < 1 || i > 2147483646) domain_error();
      ctx.rl = static_cast<std::uint32_t>(i);
      return;
  }
}

Value Evaluator::system_function(SystemName s, const Value& b) {
  ctx.charge(b.size() + 1);
  switch (s) {
    case SystemName::nc:
    case SystemName::ex: {
      // ⎕NC (APL.SV name classification): 0 free, 1 label, 2 variable, 3 function, 4 not a
      // name. ⎕EX (expunge): the name erased, 1 when it is free afterwards.
      const std::vector<std::string> names = names_of(b);
      Numbers out;
      for (const auto& name : names) {
        double r = 0;
        SystemName quad;
        if (system_name(name, quad)) {
          r = s == SystemName::nc ? (is_system_function(quad) ? 3 : 2) : 0;
        } else if (!valid_name(name)) {
          r = s == SystemName::nc ? 4 : 0;
        } else {
          const std::uint32_t id = symbol(name);
          Symbol& sym = symbols_[id];
          std::optional<Value>* slot = local_slot(id);
          bool label = false;
          for (auto f = frames_.rbegin(); slot && f != frames_.rend(); ++f) {
            if (f->kind != Frame::Kind::function) continue;
            const int k = f->function->slot_of(name);
            if (k < 0) continue;
            label = static_cast<std::size_t>(k) >= f->function->first_label;
            break;
          }
          if (s == SystemName::nc) {
            if (slot)
              r = label ? 1 : *slot ? 2 : 0;
            else if (sym.function || sym.native)
              r = 3;
            else if (sym.value || (sym.owned && host.get(name)))
              r = 2;
          } else {
            if (slot && !label) {
              slot->reset();
              r = 1;
            } else if (!slot && sym.function) {
              sym.function.reset();
              definitions_changed();
              r = 1;
            } else if (!slot && !sym.owned && !sym.native) {
              sym.value.reset();
              changed(sym);
              r = 1;
            }
          }
        }
        out.push_back(r);
      }
      if (b.rank() <= 1) return Value::number(out.empty() ? 0 : out[0]);
      const std::size_t n = out.size();
      return Value::of_numbers({n}, std::move(out));
    }
    case SystemName::cr: {
      // ⎕CR: a defined function as a character matrix, its header then its lines; an empty
      // matrix for any other name.
      const std::vector<std::string> names = names_of(b);
      if (names.size() != 1) length_error();
      const auto fn = function(names[0]);
      if (!fn) return Value::blanks({0, 0});
      std::vector<std::u32string> rows;
      std::size_t width = 0;
      for (const auto& line : fn->source()) {
        rows.push_back(decode_utf8(line));
        width = std::max(width, rows.back().size());
      }
      Value r = ctx.new_characters({rows.size(), width});
      auto out = r.mutable_characters();
      std::fill(out.begin(), out.end(), U' ');
      for (std::size_t i = 0; i < rows.size(); ++i)
        std::copy(rows[i].begin(), rows[i].end(), out.begin() + i * width);
      return r;
    }
    case SystemName::fx: {
      // ⎕FX: the function of a character matrix (header, then lines) defined; its name, or the
      // index of the header row when it cannot be defined (APL.SV).
      if (b.rank() > 2) rank_error();
      if (!b.is_character()) domain_error();
      const std::size_t width = b.rank() == 0 ? 1 : b.shape().back();
      const std::size_t rows = b.rank() == 2 ? b.shape()[0] : 1;
      std::vector<std::string> source;
      auto c = b.characters();
      for (std::size_t r = 0; r < rows; ++r) {
        std::u32string_view row(c.data() + r * width, width);
        while (!row.empty() && row.back() == U' ') row.remove_suffix(1);
        source.push_back(encode_utf8(row));
      }
      try {
        DefinedFunction f = make_function(source);
        const std::string name = f.header.name;
        const Symbol* sym = find_symbol(name);
        if (host.owns(name) || (sym && (sym->native || sym->value))) throw Error(ErrorKind::defn);
        define(std::move(f));
        return Value::text(name);
      } catch (const Error&) {
        return Value::number(ctx.io);
      }
    }
    default:
      syntax_error();
  }
}

}  // namespace igds::apl
