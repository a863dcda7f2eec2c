#include "interp/apl_args.h"

#include <cmath>

#include "commands/reports.h"
#include "interp/apl/array_bridge.h"
#include "interp/apl/error.h"
#include "interp/words.h"

namespace igds::apl_args {

using apl::Error;
using apl::ErrorKind;

void refuse(const DataError& e) {
  throw Error(ErrorKind::domain, worded(e).what());
}

std::vector<double> number_list(Args v) {
  if (!v || v->is_character()) throw Error(ErrorKind::domain);
  if (v->rank() > 1) throw Error(ErrorKind::rank);
  auto x = v->numbers();
  return {x.begin(), x.end()};
}

std::vector<double> numbers_of(Args v, std::size_t count) {
  std::vector<double> x = number_list(v);
  if (x.size() != count) throw Error(ErrorKind::length);
  return x;
}

int whole_of(Args v, int low, int high) {
  const double x = numbers_of(v, 1)[0];
  if (!(x >= low && x <= high) || std::floor(x) != x) throw Error(ErrorKind::domain);
  return static_cast<int>(x);
}

std::string text_of(Args v) {
  if (!v) throw Error(ErrorKind::value);
  if (v->is_numeric() && !v->empty()) throw Error(ErrorKind::domain);
  if (v->is_numeric()) return {};
  return v->utf8();
}

std::vector<std::string> words_of(Args v) {
  if (!v || v->empty()) return {};
  if (!v->is_character() || v->rank() > 1) throw Error(ErrorKind::domain);
  return split_words(v->utf8());
}

Array points_of(Args v, std::size_t last) {
  if (!v || v->is_character()) throw Error(ErrorKind::domain);
  if (v->rank() == 0 || v->shape().back() != last) throw Error(ErrorKind::length);
  return apl::to_array(*v);
}

Array matrix_of(Args v, std::size_t columns) {
  if (!v || v->is_character()) throw Error(ErrorKind::domain);
  if (v->rank() > 2) throw Error(ErrorKind::rank);
  Array a = apl::to_array(*v);
  if (v->rank() < 2) {
    if (a.size() != columns) throw Error(ErrorKind::length);
    a.shape = {1, columns};
  }
  if (a.shape[1] != columns) throw Error(ErrorKind::length);
  return a;
}

Array desim_array(const Description& d) {
  Array a;
  a.shape = {5};
  a.ravel = {static_cast<double>(d.what), static_cast<double>(static_cast<int>(d.projection)),
             d.parameters[0], d.parameters[1], d.parameters[2]};
  return a;
}

Description description_of(std::span<const double> v) {
  Description d;
  d.what = static_cast<int>(v[0]);
  d.projection = static_cast<Projection>(static_cast<int>(v[1]));
  d.parameters = {v[2], v[3], v[4]};
  return d;
}

}  // namespace igds::apl_args
