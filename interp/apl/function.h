// Defined functions (APL\360 User's Manual, chapter 5): a header `Z←A F B;L1;L2` naming the
// result, the arguments and the local names, and numbered lines, some with labels `L:`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interp/apl/error.h"
#include "interp/apl/lexer.h"

namespace igds::apl {

struct Code;

struct Header {
  std::string name, result, left, right;  // empty where there is none
  std::vector<std::string> locals;        // names and system variables (⎕IO ⎕PP ⎕CT ⎕RL)
  int valence() const { return right.empty() ? 0 : left.empty() ? 1 : 2; }
};

// The header's parts; DEFN ERROR when it is not of the form [Z←][A] F [B][;L]... with names
// all different.
Header parse_header(std::string_view text);

struct DefinedFunction {
  Header header;
  std::string header_text;
  std::vector<std::string> lines;                 // lines 1..n as typed
  std::vector<std::vector<Token>> tokens;         // each line's tokens
  std::vector<std::optional<Error>> line_errors;  // a line that cannot be read: its error
  std::map<std::string, std::size_t> labels;      // label → line number

  // The names a call gives a value of its own, in the order of its slots: the result, the
  // arguments, the local names (not the system variables), then the labels.
  std::vector<std::string> slots;
  std::size_t first_label = 0;  // the first label's slot
  // The slot of a name, or -1.
  int slot_of(std::string_view name) const;
  // The session's symbols of the slots' names (set by the session that defines the function).
  std::vector<std::uint32_t> slot_symbols;
  // The lines compiled, each the first time it runs, for the definitions of generation
  // `compiled_for` (a cache: the function itself never changes).
  mutable std::vector<std::shared_ptr<const Code>> compiled;
  mutable std::uint64_t compiled_for = 0;
  // Lines compiled for earlier definitions: a frame may still run one (by its address).
  mutable std::vector<std::shared_ptr<const Code>> retired;

  // The source: the header, then the lines (as ∇ would show them, without numbers).
  std::vector<std::string> source() const;
};

// A function from its source (header first, a leading ∇ allowed); DEFN ERROR for a bad header
// or a label that repeats a name of the header or another label.
DefinedFunction make_function(const std::vector<std::string>& source);

}  // namespace igds::apl
