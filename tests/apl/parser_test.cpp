// The structure of statements: right to left, functions known by the names' classes.
#include "interp/apl/parser.h"

#include <doctest/doctest.h>

#include "apl_support.h"
#include "interp/apl/error.h"

namespace igds::apl::test {

namespace {

// F is monadic, G dyadic, N niladic; other names are variables.
NameClass classes(const std::string& name) {
  if (name == "F") return NameClass::monadic;
  if (name == "G") return NameClass::dyadic;
  if (name == "N") return NameClass::niladic;
  return NameClass::variable;
}

Statement parsed(std::u32string_view line, bool label = false, int depth = 100) {
  return parse(tokenize(line), classes, label, depth);
}

std::pair<ErrorKind, std::size_t> failure(std::u32string_view line, int depth = 100) {
  try {
    parsed(line, false, depth);
  } catch (const Error& e) {
    return {e.kind(), e.has_column() ? e.column() : 999};
  }
  return {ErrorKind::interrupt, 999};
}

}  // namespace

TEST_CASE("right to left: A f B g C is A f (B g C)") {
  Statement s = parsed(U"2×3+4");
  REQUIRE(s.expr);
  CHECK(s.expr->kind == Node::Kind::dyadic);
  CHECK(s.expr->function->glyph == U'×');
  CHECK(s.expr->left->kind == Node::Kind::constant);
  CHECK(s.expr->right->kind == Node::Kind::dyadic);
  CHECK(s.expr->right->function->glyph == U'+');
  CHECK(first("2×3+4") == "14");
  CHECK(first("10-2-3") == "11");
  CHECK(first("(10-2)-3") == "5");
  CHECK(first("2×(3+4)") == "14");
}

TEST_CASE("operators and axes bind to the function on their left") {
  Statement s = parsed(U"+/[1]M");
  CHECK(s.expr->kind == Node::Kind::monadic);
  CHECK(s.expr->function->kind == FunctionNode::Kind::reduce);
  CHECK(s.expr->function->glyph == U'+');
  CHECK(s.expr->function->axis);
  Statement o = parsed(U"A∘.×B");
  CHECK(o.expr->function->kind == FunctionNode::Kind::outer);
  Statement i = parsed(U"A+.×B");
  CHECK(i.expr->function->kind == FunctionNode::Kind::inner);
  CHECK(i.expr->function->op == U'×');
  Statement c = parsed(U"1 0 1/A");  // after an array, / is compression
  CHECK(c.expr->kind == Node::Kind::dyadic);
  CHECK(c.expr->function->kind == FunctionNode::Kind::primitive);
  CHECK(c.expr->function->glyph == U'/');
}

TEST_CASE("assignment, indexing, and assignment inside an expression") {
  Statement s = parsed(U"A[1;]←5");
  CHECK(s.expr->kind == Node::Kind::index_assign);
  REQUIRE(s.expr->indices.size() == 2);
  CHECK(s.expr->indices[0]);
  CHECK(!s.expr->indices[1]);
  Statement g = parsed(U"⍋V←3 1 2");
  CHECK(g.expr->kind == Node::Kind::monadic);
  CHECK(g.expr->right->kind == Node::Kind::assign);
  Statement x = parsed(U"X[2][1]");
  CHECK(x.expr->kind == Node::Kind::index);
  CHECK(x.expr->left->kind == Node::Kind::index);
  Statement q = parsed(U"⎕←⎕IO");
  CHECK(q.expr->kind == Node::Kind::assign);
  CHECK(q.expr->name == "⎕");
  CHECK(q.expr->right->kind == Node::Kind::system_variable);
}

TEST_CASE("names by their class: niladic functions are arrays, valences are checked") {
  CHECK(parsed(U"N+1").expr->left->kind == Node::Kind::niladic);
  CHECK(parsed(U"F 1").expr->kind == Node::Kind::monadic);
  CHECK(parsed(U"1 G 2").expr->kind == Node::Kind::dyadic);
  CHECK(failure(U"1 F 2") == std::pair{ErrorKind::syntax, std::size_t{2}});
  CHECK(failure(U"G 2") == std::pair{ErrorKind::syntax, std::size_t{0}});
  CHECK(failure(U"F←3").first == ErrorKind::syntax);
  CHECK(failure(U"A+/B").first == ErrorKind::syntax);  // no dyadic reduction in APL\360
}

TEST_CASE("a primitive with the wrong number of arguments or an axis it has not") {
  CHECK(first("/1 2") == "SYNTAX ERROR");
  CHECK(first("∊1 2") == "SYNTAX ERROR");
  CHECK(first("<3") == "SYNTAX ERROR");
  CHECK(first("1⍎'2'") == "SYNTAX ERROR");
  CHECK(first("+[1]1 2") == "SYNTAX ERROR");
  CHECK(first("⍴[1]2 2⍴1") == "SYNTAX ERROR");
  CHECK(first("3⋆2") == "9");  // ⋆ is read as *
}

TEST_CASE("labels and branches in a function's lines") {
  Statement s = parsed(U"LOOP: →(I<3)/LOOP", true);
  CHECK(s.label == "LOOP");
  CHECK(s.branch);
  REQUIRE(s.expr);
  CHECK(s.expr->kind == Node::Kind::dyadic);
  Statement bare = parsed(U"→");
  CHECK(bare.branch);
  CHECK(!bare.expr);
  CHECK(!parsed(U"").expr);
  CHECK(failure(U"L: 1").first == ErrorKind::syntax);  // no labels in immediate execution
}

TEST_CASE("malformed statements: SYNTAX ERROR where the statement goes wrong") {
  CHECK(failure(U"2+") == std::pair{ErrorKind::syntax, std::size_t{1}});
  CHECK(failure(U"(1 2") == std::pair{ErrorKind::syntax, std::size_t{4}});
  CHECK(failure(U"1 2)") == std::pair{ErrorKind::syntax, std::size_t{3}});
  CHECK(failure(U"A B") == std::pair{ErrorKind::syntax, std::size_t{2}});
  CHECK(failure(U"(1)(2)").first == ErrorKind::syntax);
  CHECK(failure(U"∘.A").first == ErrorKind::syntax);
  CHECK(failure(U"+.⍴").first == ErrorKind::syntax);
  CHECK(failure(U"A[1").first == ErrorKind::syntax);
  CHECK(failure(U"←3").first == ErrorKind::syntax);
}

TEST_CASE("nesting deeper than the limit: DEPTH ERROR, not a crash") {
  std::u32string deep(5000, U'(');
  deep += U"1";
  deep.append(5000, U')');
  CHECK(failure(deep, 200).first == ErrorKind::depth);
  std::u32string chain;
  for (int i = 0; i < 5000; ++i) chain += U"1+";
  chain += U"1";
  CHECK(failure(chain, 200).first == ErrorKind::depth);
}

}  // namespace igds::apl::test
