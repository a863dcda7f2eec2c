#include "interp/apl/code.h"

#include <array>
#include <utility>

#include "interp/apl/error.h"
#include "interp/apl/glyphs.h"
#include "interp/apl/scalar.h"

namespace igds::apl {

namespace {

constexpr std::array<std::pair<std::string_view, SystemName>, 13> system_names{{
    {"⎕IO", SystemName::io},
    {"⎕PP", SystemName::pp},
    {"⎕CT", SystemName::ct},
    {"⎕RL", SystemName::rl},
    {"⎕PW", SystemName::pw},
    {"⎕LC", SystemName::lc},
    {"⎕TS", SystemName::ts},
    {"⎕AI", SystemName::ai},
    {"⎕AV", SystemName::av},
    {"⎕EX", SystemName::ex},
    {"⎕NC", SystemName::nc},
    {"⎕FX", SystemName::fx},
    {"⎕CR", SystemName::cr},
}};

[[noreturn]] void syntax_at(std::size_t column) {
  Error e(ErrorKind::syntax);
  e.set_column(column);
  throw e;
}

class Compiler {
 public:
  Compiler(Code& code, const Resolver& resolve) : code_(code), resolve_(resolve) {}

  void expression(const Node& n, bool needed) {
    switch (n.kind) {
      case Node::Kind::constant:
        code_.constants.push_back(n.value);
        emit(Op::constant, n.column, static_cast<std::uint32_t>(code_.constants.size() - 1));
        return;
      case Node::Kind::variable: {
        const NameRef r = resolve_(n.name);
        emit(r.local ? Op::local : Op::name, n.column, r.index);
        return;
      }
      case Node::Kind::niladic:
        emit(Op::niladic, n.column, symbol(n), 0, needed ? needs_value : 0);
        return;
      case Node::Kind::system_variable: {
        SystemName s;
        if (!system_name(n.name, s) || is_system_function(s)) syntax_at(n.column);
        emit(Op::system_variable, n.column, static_cast<std::uint32_t>(s));
        return;
      }
      case Node::Kind::quad:
        emit(Op::quad_input, n.column);
        return;
      case Node::Kind::quote_quad:
        emit(Op::quote_input, n.column);
        return;
      case Node::Kind::monadic:
        monadic(n, needed);
        return;
      case Node::Kind::dyadic:
        dyadic(n, needed);
        return;
      case Node::Kind::index: {
        std::vector<bool> given(n.indices.size());
        for (std::size_t i = n.indices.size(); i-- > 0;) {
          if (!n.indices[i]) continue;
          given[i] = true;
          expression(*n.indices[i], true);
        }
        expression(*n.left, true);
        code_.index_lists.push_back(std::move(given));
        emit(Op::index, n.column, static_cast<std::uint32_t>(code_.index_lists.size() - 1));
        code_.instrs.back().count = static_cast<std::uint16_t>(n.indices.size());
        return;
      }
      case Node::Kind::assign:
        expression(*n.right, true);
        assign(n);
        return;
      case Node::Kind::index_assign: {
        expression(*n.right, true);
        std::vector<bool> given(n.indices.size());
        for (std::size_t i = n.indices.size(); i-- > 0;) {
          if (!n.indices[i]) continue;
          given[i] = true;
          expression(*n.indices[i], true);
        }
        const NameRef r = resolve_(n.name);
        if (r.label) syntax_at(n.column);
        code_.index_lists.push_back(std::move(given));
        emit(r.local ? Op::index_assign_local : Op::index_assign_name, n.column, r.index,
             static_cast<std::uint32_t>(code_.index_lists.size() - 1));
        code_.instrs.back().count = static_cast<std::uint16_t>(n.indices.size());
        return;
      }
    }
    syntax_at(n.column);
  }

  void emit(Op op, std::size_t column, std::uint32_t a = 0, std::uint32_t b = 0,
            std::uint8_t flags = 0) {
    Instr i;
    i.op = op;
    i.a = a;
    i.b = b;
    i.flags = flags;
    i.column = static_cast<std::uint32_t>(column);
    code_.instrs.push_back(i);
  }

  std::uint32_t symbol(const Node& n) { return resolve_(n.name).index; }

  void monadic(const Node& n, bool needed) {
    const FunctionNode& f = *n.function;
    expression(*n.right, true);
    std::uint8_t axis = 0;
    if (f.axis) {
      expression(*f.axis, true);
      axis = has_axis;
    }
    switch (f.kind) {
      case FunctionNode::Kind::primitive:
        if (f.glyph == U'⍎') {
          if (axis) syntax_at(f.column);
          emit(Op::execute, f.column, 0, 0, needed ? needs_value : 0);
        } else {
          const bool scalar_fn = has_role(f.glyph, Role::scalar_monadic);
          emit(Op::monadic, f.column, f.glyph, 0,
               static_cast<std::uint8_t>(axis | (scalar_fn ? scalar : 0)));
        }
        return;
      case FunctionNode::Kind::defined:
        emit(Op::call_monadic, f.column, resolve_(f.name).index, 0, needed ? needs_value : 0);
        return;
      case FunctionNode::Kind::reduce:
      case FunctionNode::Kind::scan:
        emit(f.kind == FunctionNode::Kind::reduce ? Op::reduce : Op::scan, f.column, f.glyph, f.op,
             static_cast<std::uint8_t>(axis | ((f.op == U'⌿' || f.op == U'⍀') ? first_axis : 0)));
        return;
      case FunctionNode::Kind::system: {
        SystemName s;
        if (!system_name(f.name, s) || !is_system_function(s)) syntax_at(f.column);
        emit(Op::system_function, f.column, static_cast<std::uint32_t>(s));
        return;
      }
      case FunctionNode::Kind::outer:
      case FunctionNode::Kind::inner:
        break;
    }
    syntax_at(f.column);
  }

  // The arguments of a dyadic primitive (without axis) or of →A/B: read straight from a local
  // or a constant where that gives the same values as pushing them. The left argument is read
  // last in any case (APL reads right to left); the right one is read early only when nothing is
  // evaluated between, or when it cannot change (a constant, a label).
  std::pair<Operand, Operand> arguments(const Node& left, const Node& right) {
    const Operand l = operand(left), r = operand(right);
    const bool fixed_right =
        r.from == Operand::constant || (r.from == Operand::local && label(right));
    Operand rr = l.from != Operand::stack || fixed_right ? r : Operand{};
    if (rr.from == Operand::stack) expression(right, true);
    if (l.from == Operand::stack) expression(left, true);
    return {l, rr};
  }

  Operand operand(const Node& n) {
    Operand o;
    o.column = static_cast<std::uint32_t>(n.column);
    if (n.kind == Node::Kind::constant) {
      o.from = Operand::constant;
      code_.constants.push_back(n.value);
      o.index = static_cast<std::uint32_t>(code_.constants.size() - 1);
    } else if (n.kind == Node::Kind::variable) {
      const NameRef r = resolve_(n.name);
      if (r.local) {
        o.from = Operand::local;
        o.index = r.index;
      }
    }
    return o;
  }

  bool label(const Node& n) { return resolve_(n.name).label; }

  void dyadic(const Node& n, bool needed) {
    const FunctionNode& f = *n.function;
    if (f.kind == FunctionNode::Kind::primitive && !f.axis) {
      const auto [l, r] = arguments(*n.left, *n.right);
      emit(Op::dyadic, f.column, f.glyph);
      code_.instrs.back().left = l;
      code_.instrs.back().right = r;
      if (has_role(f.glyph, Role::scalar_dyadic)) {
        code_.instrs.back().flags |= scalar;
        code_.instrs.back().loops = &dyadic_loops(f.glyph);
      }
      return;
    }
    expression(*n.right, true);
    std::uint8_t axis = 0;
    if (f.axis) {
      expression(*f.axis, true);
      axis = has_axis;
    }
    expression(*n.left, true);
    switch (f.kind) {
      case FunctionNode::Kind::primitive:
        emit(Op::dyadic, f.column, f.glyph, 0, axis);
        if (has_role(f.glyph, Role::scalar_dyadic)) {
          code_.instrs.back().flags |= scalar;
          code_.instrs.back().loops = &dyadic_loops(f.glyph);
        }
        return;
      case FunctionNode::Kind::defined:
        emit(Op::call_dyadic, f.column, resolve_(f.name).index, 0, needed ? needs_value : 0);
        return;
      case FunctionNode::Kind::outer:
        emit(Op::outer, f.column, f.glyph);
        return;
      case FunctionNode::Kind::inner:
        emit(Op::inner, f.column, f.glyph, f.op);
        return;
      case FunctionNode::Kind::reduce:
      case FunctionNode::Kind::scan:
      case FunctionNode::Kind::system:
        break;
    }
    syntax_at(f.column);
  }

  void assign(const Node& n) {
    if (n.name == "⎕") {
      emit(Op::assign_quad, n.column);
    } else if (n.name == "⍞") {
      emit(Op::assign_quote, n.column);
    } else if (n.name.starts_with("⎕")) {
      SystemName s;
      if (!system_name(n.name, s) || is_system_function(s)) syntax_at(n.column);
      emit(Op::assign_system, n.column, static_cast<std::uint32_t>(s));
    } else {
      const NameRef r = resolve_(n.name);
      if (r.label) syntax_at(n.column);
      emit(r.local ? Op::assign_local : Op::assign_name, n.column, r.index);
    }
  }

  Code& code_;
  const Resolver& resolve_;
};

bool shy(const Node& n) {
  return !n.parenthesized && (n.kind == Node::Kind::assign || n.kind == Node::Kind::index_assign);
}

}  // namespace

bool system_name(const std::string& name, SystemName& out) {
  for (const auto& [text, s] : system_names) {
    if (text == name) {
      out = s;
      return true;
    }
  }
  return false;
}

bool is_system_function(SystemName s) {
  return s == SystemName::ex || s == SystemName::nc || s == SystemName::fx || s == SystemName::cr;
}

std::string system_name_text(SystemName s) {
  for (const auto& [text, name] : system_names)
    if (name == s) return std::string(text);
  return {};
}

Code compile(const Statement& statement, const Resolver& resolve) {
  Code code;
  Compiler c(code, resolve);
  if (statement.branch) {
    code.branch = true;
    if (!statement.expr) {
      c.emit(Op::naked_branch, 0);
      return code;
    }
    const Node& e = *statement.expr;
    // →A/B, the loops' idiom: the branch taken straight from A and B when they are numbers.
    if (e.kind == Node::Kind::dyadic && e.function->kind == FunctionNode::Kind::primitive &&
        e.function->glyph == U'/' && !e.function->axis) {
      const auto [l, r] = c.arguments(*e.left, *e.right);
      // →(I<N)/L: the comparison's result goes to the frame's scratch place, not the stack.
      // (→N/L, both operands where they are, has no instruction before it.)
      Instr* before = code.instrs.empty() ? nullptr : &code.instrs.back();
      const bool test = before && l.from == Operand::stack && r.from != Operand::stack &&
                        before->op == Op::dyadic && before->result.from == Operand::stack &&
                        !(before->flags & has_axis);
      if (test) before->result.from = Operand::scratch;
      c.emit(Op::branch_compress, e.column);
      code.instrs.back().left = l;
      code.instrs.back().right = r;
      if (test) code.instrs.back().left.from = Operand::scratch;
      return code;
    }
    c.expression(e, true);
    c.emit(Op::branch, e.column);
    return code;
  }
  if (!statement.expr) {
    c.emit(Op::end, 0);
    return code;
  }
  const Node& e = *statement.expr;
  c.expression(e, false);
  if (shy(e) && code.instrs.back().op == Op::assign_local) {
    // Z←A f B: the result straight into the slot.
    const std::size_t n = code.instrs.size();
    if (n >= 2 && code.instrs[n - 2].op == Op::dyadic && !(code.instrs[n - 2].flags & has_axis)) {
      Instr& f = code.instrs[n - 2];
      f.result.from = Operand::local;
      f.result.index = code.instrs.back().a;
      f.flags |= ends;
      code.instrs.pop_back();
      return code;
    }
    code.instrs.back().flags |= ends;
    return code;
  }
  std::uint8_t flags = shy(e) ? 0 : shows;
  if (!e.parenthesized && e.kind == Node::Kind::monadic &&
      e.function->kind == FunctionNode::Kind::primitive && e.function->glyph == U'⍎')
    flags |= shy_execute;
  c.emit(Op::end, e.column, 0, 0, flags);
  return code;
}

}  // namespace igds::apl
