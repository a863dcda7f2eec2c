#include "interp/apl/code.h"

#include <array>
#include <utility>

#include "interp/apl/error.h"

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

 private:
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
          emit(Op::monadic, f.column, f.glyph, 0, axis);
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

  void dyadic(const Node& n, bool needed) {
    const FunctionNode& f = *n.function;
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
    c.expression(*statement.expr, true);
    c.emit(Op::branch, statement.expr->column);
    return code;
  }
  if (!statement.expr) {
    c.emit(Op::end, 0);
    return code;
  }
  const Node& e = *statement.expr;
  c.expression(e, false);
  std::uint8_t flags = shy(e) ? 0 : shows;
  if (!e.parenthesized && e.kind == Node::Kind::monadic &&
      e.function->kind == FunctionNode::Kind::primitive && e.function->glyph == U'⍎')
    flags |= shy_execute;
  c.emit(Op::end, e.column, 0, 0, flags);
  return code;
}

}  // namespace igds::apl
