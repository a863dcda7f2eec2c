// The structure of an APL statement. APL reads right to left: `A f B g C` is `A f (B g C)`; a
// name is a function or a variable by what it is when the statement runs (APL\360 User's
// Manual, chapter 1), so the parser asks a classifier about each name.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "interp/apl/lexer.h"
#include "interp/apl/value.h"

namespace igds::apl {

// What a name is when the statement runs: a variable (with a value or not yet: `undefined`), or
// a function of no, one or two arguments.
enum class NameClass { variable, undefined, niladic, monadic, dyadic };
using Classifier = std::function<NameClass(const std::string& name)>;

struct Node;
using NodePtr = std::unique_ptr<Node>;

struct FunctionNode {
  enum class Kind {
    primitive,  // `glyph`
    defined,    // a defined or native function: `name`
    reduce,     // `glyph`/ or `glyph`⌿ (`op` is / or ⌿)
    scan,       // `glyph`\ or `glyph`⍀ (`op` is \ or ⍀)
    outer,      // ∘.`glyph`
    inner,      // `glyph`.`op`
    system,     // ⎕EX ⎕NC ⎕FX ⎕CR: `name`
  };
  Kind kind = Kind::primitive;
  char32_t glyph = 0;
  char32_t op = 0;
  std::string name;
  NodePtr axis;  // [k] after the function, when given
  std::size_t column = 0;
};

struct Node {
  enum class Kind {
    constant,         // `value`
    variable,         // `name`
    niladic,          // a niladic function's call: `name`
    system_variable,  // `name` (⎕IO, ⎕PP, ...)
    quad,             // ⎕: evaluated input
    quote_quad,       // ⍞: character input
    monadic,          // `function` `right`
    dyadic,           // `left` `function` `right`
    index,            // `left`[`indices`]
    assign,           // `name` ← `right` (name may be ⎕, ⍞ or a system variable)
    index_assign,     // `name`[`indices`] ← `right`
  };
  Kind kind = Kind::constant;
  std::size_t column = 0;
  Value value;
  std::string name;
  std::unique_ptr<FunctionNode> function;
  NodePtr left, right;
  std::vector<NodePtr> indices;  // an elided index is null
  bool parenthesized = false;    // (X←3) shows its value, X←3 does not
};

struct Statement {
  std::string label;    // `L:` in a defined function's line
  bool branch = false;  // →expr; a bare → has no expr
  NodePtr expr;         // null for an empty statement (a comment line)
};

// The statement of the tokens. SYNTAX ERROR with the column of the offending token (VALUE ERROR
// when it stands beside a name that has no value, as `FOO 3` with FOO undefined: APL\360 reads
// the name before it finds the statement malformed); DEPTH ERROR when parentheses and functions
// nest deeper than max_depth.
Statement parse(const std::vector<Token>& tokens, const Classifier& classify, bool allow_label,
                int max_depth);

}  // namespace igds::apl
