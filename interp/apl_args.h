// The arguments of END APL's functions (interp/apl_env.h): APL values read as igds's numbers,
// points, words and names, with APL's reports when they are not.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "interp/apl/value.h"
#include "workspace/kernels/array.h"
#include "workspace/kernels/data_error.h"
#include "workspace/state.h"

namespace igds::apl_args {

using Args = const apl::Value*;

// A kernel's refusal as an APL report in igds's words (DOMAIN ERROR with them).
[[noreturn]] void refuse(const DataError& e);

// Exactly `count` numbers (a scalar or a vector): DOMAIN, RANK or LENGTH ERROR otherwise.
std::vector<double> numbers_of(Args v, std::size_t count);
// Any numbers of rank at most one.
std::vector<double> number_list(Args v);
// A whole number in [low, high].
int whole_of(Args v, int low, int high);
// The words of a character vector (an empty vector has none); DOMAIN ERROR for numbers.
std::vector<std::string> words_of(Args v);
// A character argument as text (its ravel); DOMAIN ERROR for numbers.
std::string text_of(Args v);
// Points: an array of any rank with `last` on its last axis.
Array points_of(Args v, std::size_t last);
// Rows of a matrix (or one vector) of `columns` numbers.
Array matrix_of(Args v, std::size_t columns);

// DESIM as the manual's 5-element vector, and back.
Array desim_array(const Description& d);
Description description_of(std::span<const double> v);

}  // namespace igds::apl_args
