#include "interp/apl/parser.h"

#include <string_view>

#include "interp/apl/code.h"
#include "interp/apl/error.h"
#include "interp/apl/glyphs.h"

namespace igds::apl {

namespace {

bool is_scalar_dyadic(char32_t g) {
  return has_role(g, Role::scalar_dyadic);
}

bool is_operator_glyph(char32_t g) {
  return has_role(g, Role::slash_operator);
}

bool is_variable_class(NameClass c) {
  return c == NameClass::variable || c == NameClass::undefined;
}

// ⎕EX ⎕NC ⎕FX ⎕CR: the system names that are functions.
bool is_system_function_token(const Token& t) {
  SystemName s;
  return t.kind == TokenKind::system_name && system_name(t.text, s) && is_system_function(s);
}

class Parser {
 public:
  Parser(const std::vector<Token>& tokens, const Classifier& classify, int max_depth)
      : tokens_(tokens), classify_(classify), max_depth_(max_depth) {}

  Statement statement(bool allow_label) {
    Statement s;
    if (allow_label && tokens_.size() >= 2 && tokens_[0].kind == TokenKind::name &&
        tokens_[1].kind == TokenKind::colon) {
      s.label = tokens_[0].text;
      pos_ = 2;
    }
    if (at_end()) return s;
    if (peek().kind == TokenKind::branch) {
      s.branch = true;
      ++pos_;
      if (at_end()) return s;
    }
    s.expr = expression();
    if (!at_end()) fail(peek().column);
    return s;
  }

 private:
  struct Deeper {
    explicit Deeper(Parser& p) : p_(p) {
      if (++p_.depth_ > p_.max_depth_) {
        Error e(ErrorKind::depth);
        if (!p_.at_end()) e.set_column(p_.peek().column);
        throw e;
      }
    }
    ~Deeper() { --p_.depth_; }
    Parser& p_;
  };

  [[noreturn]] void fail(std::size_t column) const {
    Error e(ErrorKind::syntax);
    e.set_column(column);
    throw e;
  }
  [[noreturn]] void fail_here() const {
    fail(at_end() ? (tokens_.empty() ? 0 : tokens_.back().end) : peek().column);
  }

  // An operand (from token `first`) followed by something that is not a function: SYNTAX ERROR,
  // or VALUE ERROR at a name without a value beside it (the right one first, as APL reads).
  [[noreturn]] void juxtaposed(std::size_t first) const {
    auto undefined = [&](std::size_t at) {
      return at < tokens_.size() && tokens_[at].kind == TokenKind::name &&
             name_class(tokens_[at]) == NameClass::undefined;
    };
    if (undefined(pos_) || (pos_ == first + 1 && undefined(first))) {
      Error e(ErrorKind::value);
      e.set_column(tokens_[undefined(pos_) ? pos_ : first].column);
      throw e;
    }
    fail(peek().column);
  }

  bool at_end() const { return pos_ >= tokens_.size(); }
  const Token& peek(std::size_t ahead = 0) const { return tokens_[pos_ + ahead]; }
  bool peek_is(std::size_t ahead, TokenKind kind) const {
    return pos_ + ahead < tokens_.size() && tokens_[pos_ + ahead].kind == kind;
  }
  bool at_expression_end() const {
    if (at_end()) return true;
    auto k = peek().kind;
    return k == TokenKind::right_paren || k == TokenKind::right_bracket ||
           k == TokenKind::semicolon;
  }
  NameClass name_class(const Token& t) const { return classify_(t.text); }

  bool starts_function() const {
    if (at_end()) return false;
    const Token& t = peek();
    if (t.kind == TokenKind::function) return true;
    if (t.kind == TokenKind::jot) return peek_is(1, TokenKind::dot);
    if (is_system_function_token(t)) return true;
    if (t.kind == TokenKind::name) {
      auto c = name_class(t);
      return c == NameClass::monadic || c == NameClass::dyadic;
    }
    return false;
  }

  NodePtr make(Node::Kind kind, std::size_t column) {
    auto n = std::make_unique<Node>();
    n->kind = kind;
    n->column = column;
    return n;
  }

  NodePtr expression() {
    Deeper deeper(*this);
    if (at_expression_end()) fail_here();
    const Token& t = peek();
    const bool assignable = t.kind == TokenKind::name || t.kind == TokenKind::system_name ||
                            t.kind == TokenKind::quad || t.kind == TokenKind::quote_quad;
    if (assignable && peek_is(1, TokenKind::assign)) {
      if (t.kind == TokenKind::name && !is_variable_class(name_class(t))) fail(t.column);
      if (is_system_function_token(t)) fail(t.column);
      auto n = make(Node::Kind::assign, t.column);
      n->name = t.kind == TokenKind::quad ? "⎕" : t.kind == TokenKind::quote_quad ? "⍞" : t.text;
      pos_ += 2;
      n->right = expression();
      return n;
    }
    if (t.kind == TokenKind::name && is_variable_class(name_class(t)) &&
        peek_is(1, TokenKind::left_bracket)) {
      std::size_t close = matching_bracket(pos_ + 1);
      if (close + 1 < tokens_.size() && tokens_[close + 1].kind == TokenKind::assign) {
        auto n = make(Node::Kind::index_assign, t.column);
        n->name = t.text;
        ++pos_;
        n->indices = index_list();
        ++pos_;  // ←
        n->right = expression();
        return n;
      }
    }
    if (starts_function()) {
      auto f = function(true);
      if (at_expression_end()) fail(f->column);
      auto n = make(Node::Kind::monadic, f->column);
      n->function = std::move(f);
      n->right = expression();
      return n;
    }
    const std::size_t first = pos_;
    auto left = operand();
    if (at_expression_end()) return left;
    if (!starts_function()) juxtaposed(first);
    auto f = function(false);
    if (at_expression_end()) fail(f->column);
    auto n = make(Node::Kind::dyadic, f->column);
    n->function = std::move(f);
    n->left = std::move(left);
    n->right = expression();
    return n;
  }

  // The token that closes the bracket at `open`, or the end when it is not closed.
  std::size_t matching_bracket(std::size_t open) const {
    int level = 0;
    for (std::size_t i = open; i < tokens_.size(); ++i) {
      auto k = tokens_[i].kind;
      if (k == TokenKind::left_bracket || k == TokenKind::left_paren) ++level;
      if (k == TokenKind::right_bracket || k == TokenKind::right_paren) {
        if (--level == 0) return i;
      }
    }
    return tokens_.size();
  }

  std::unique_ptr<FunctionNode> function(bool monadic) {
    const Token& t = peek();
    auto f = std::make_unique<FunctionNode>();
    f->column = t.column;
    if (t.kind == TokenKind::jot) {
      pos_ += 2;  // ∘.
      if (at_end() || peek().kind != TokenKind::function || !is_scalar_dyadic(peek().glyph))
        fail_here();
      f->kind = FunctionNode::Kind::outer;
      f->glyph = peek().glyph;
      ++pos_;
      if (monadic) fail(f->column);
      return f;
    }
    if (t.kind == TokenKind::system_name) {
      f->kind = FunctionNode::Kind::system;
      f->name = t.text;
      ++pos_;
      if (!monadic) fail(t.column);
      return f;
    }
    if (t.kind == TokenKind::name) {
      f->kind = FunctionNode::Kind::defined;
      f->name = t.text;
      auto c = name_class(t);
      if ((monadic && c == NameClass::dyadic) || (!monadic && c == NameClass::monadic))
        fail(t.column);
      ++pos_;
      if (peek_is(0, TokenKind::left_bracket)) fail_here();
      return f;
    }
    f->glyph = t.glyph;
    ++pos_;
    if (peek_is(0, TokenKind::dot) && peek_is(1, TokenKind::function)) {
      if (!is_scalar_dyadic(f->glyph) || !is_scalar_dyadic(peek(1).glyph)) fail(peek(1).column);
      f->kind = FunctionNode::Kind::inner;
      f->op = peek(1).glyph;
      pos_ += 2;
      if (monadic) fail(f->column);
      return f;
    }
    if (is_scalar_dyadic(f->glyph) && peek_is(0, TokenKind::function) &&
        is_operator_glyph(peek().glyph)) {
      f->op = peek().glyph;
      f->kind =
          (f->op == U'/' || f->op == U'⌿') ? FunctionNode::Kind::reduce : FunctionNode::Kind::scan;
      ++pos_;
      if (!monadic) fail(f->column);
    }
    if (peek_is(0, TokenKind::left_bracket)) {
      ++pos_;
      if (peek_is(0, TokenKind::right_bracket)) fail_here();
      f->axis = expression();
      if (!peek_is(0, TokenKind::right_bracket)) fail_here();
      ++pos_;
    }
    return f;
  }

  NodePtr operand() {
    const Token& t = peek();
    NodePtr n;
    switch (t.kind) {
      case TokenKind::number:
      case TokenKind::string:
        n = make(Node::Kind::constant, t.column);
        n->value = t.literal;
        ++pos_;
        break;
      case TokenKind::name:
        if (name_class(t) == NameClass::niladic) {
          n = make(Node::Kind::niladic, t.column);
        } else if (is_variable_class(name_class(t))) {
          n = make(Node::Kind::variable, t.column);
        } else {
          fail(t.column);
        }
        n->name = t.text;
        ++pos_;
        break;
      case TokenKind::system_name:
        n = make(Node::Kind::system_variable, t.column);
        n->name = t.text;
        ++pos_;
        break;
      case TokenKind::quad:
        n = make(Node::Kind::quad, t.column);
        ++pos_;
        break;
      case TokenKind::quote_quad:
        n = make(Node::Kind::quote_quad, t.column);
        ++pos_;
        break;
      case TokenKind::left_paren: {
        Deeper deeper(*this);
        ++pos_;
        n = expression();
        n->parenthesized = true;
        if (!peek_is(0, TokenKind::right_paren)) fail_here();
        ++pos_;
        break;
      }
      default:
        fail(t.column);
    }
    while (peek_is(0, TokenKind::left_bracket)) {
      auto index = make(Node::Kind::index, peek().column);
      index->left = std::move(n);
      index->indices = index_list();
      n = std::move(index);
    }
    return n;
  }

  // [I;J;...] at the current token; an empty position is an elided index (all of that axis).
  std::vector<NodePtr> index_list() {
    ++pos_;  // [
    std::vector<NodePtr> indices;
    while (true) {
      if (peek_is(0, TokenKind::semicolon)) {
        indices.push_back(nullptr);
        ++pos_;
        continue;
      }
      if (peek_is(0, TokenKind::right_bracket)) {
        indices.push_back(nullptr);
        ++pos_;
        return indices;
      }
      indices.push_back(expression());
      if (peek_is(0, TokenKind::semicolon)) {
        ++pos_;
        continue;
      }
      if (peek_is(0, TokenKind::right_bracket)) {
        ++pos_;
        return indices;
      }
      fail_here();
    }
  }

  const std::vector<Token>& tokens_;
  const Classifier& classify_;
  int max_depth_;
  int depth_ = 0;
  std::size_t pos_ = 0;
};

}  // namespace

Statement parse(const std::vector<Token>& tokens, const Classifier& classify, bool allow_label,
                int max_depth) {
  return Parser(tokens, classify, max_depth).statement(allow_label);
}

}  // namespace igds::apl
