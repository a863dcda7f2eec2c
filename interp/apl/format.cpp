#include "interp/apl/format.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interp/apl/elements.h"
#include "interp/apl/text.h"

namespace igds::apl {

namespace {

// The significant digits (trailing zeros removed) and the decimal exponent of |x| rounded to
// `digits` significant digits: 1234.5 with 3 gives "123" and 3.
struct Scientific {
  std::string digits;
  int exponent = 0;
};

Scientific scientific(double ax, int digits) {
  std::string s = fmt::format("{:.{}e}", ax, digits - 1);
  auto e = s.find('e');
  Scientific r;
  for (std::size_t i = 0; i < e; ++i)
    if (s[i] != '.') r.digits.push_back(s[i]);
  r.exponent = std::stoi(s.substr(e + 1));
  while (r.digits.size() > 1 && r.digits.back() == '0') r.digits.pop_back();
  return r;
}

std::u32string widen(const std::string& ascii) {
  std::u32string out;
  for (char c : ascii) out.push_back(c == '-' ? U'¯' : static_cast<char32_t>(c));
  return out;
}

// The scaled form of a number: mantissa, E, exponent, the mantissa with at least `fraction`
// digits after its point.
std::string scaled(bool negative, const Scientific& s, std::size_t fraction) {
  std::string out = negative ? "-" : "";
  out += s.digits[0];
  std::string rest = s.digits.substr(1);
  if (rest.size() < fraction) rest.append(fraction - rest.size(), '0');
  if (!rest.empty()) out += "." + rest;
  out += fmt::format("E{}", s.exponent);
  return out;
}

bool needs_scaled(const Scientific& s, int pp) {
  return s.exponent < -6 || s.exponent >= pp;
}

std::string fixed(bool negative, const Scientific& s) {
  std::string integer, fraction;
  if (s.exponent >= 0) {
    const auto n = static_cast<std::size_t>(s.exponent) + 1;
    integer = s.digits.substr(0, std::min(n, s.digits.size()));
    if (integer.size() < n) integer.append(n - integer.size(), '0');
    if (s.digits.size() > n) fraction = s.digits.substr(n);
  } else {
    integer = "0";
    fraction = std::string(static_cast<std::size_t>(-s.exponent - 1), '0') + s.digits;
  }
  std::string out = negative ? "-" : "";
  out += integer;
  if (!fraction.empty()) out += "." + fraction;
  return out;
}

// One column of a numeric matrix, formatted together: every number in scaled form when one
// needs it (E's aligned, mantissas padded with zeros), otherwise decimal points aligned.
std::vector<std::u32string> format_column(const double* x, std::size_t count, std::size_t step,
                                          int pp) {
  std::vector<Scientific> parts(count);
  std::vector<bool> negative(count);
  bool any_scaled = false;
  for (std::size_t i = 0; i < count; ++i) {
    const double v = x[i * step];
    negative[i] = v < 0;
    if (v == 0) {
      parts[i] = {"0", 0};
      continue;
    }
    parts[i] = scientific(std::fabs(v), pp);
    any_scaled = any_scaled || needs_scaled(parts[i], pp);
  }
  std::vector<std::u32string> texts(count);
  std::vector<std::size_t> cut(count);
  std::size_t left = 0, right = 0, fraction = 0;
  if (any_scaled)
    for (auto& p : parts) fraction = std::max(fraction, p.digits.size() - 1);
  for (std::size_t i = 0; i < count; ++i) {
    texts[i] = widen(any_scaled ? scaled(negative[i], parts[i], fraction)
                                : fixed(negative[i] && x[i * step] != 0, parts[i]));
    auto at = texts[i].find_first_of(any_scaled ? U"E" : U".");
    cut[i] = at == std::u32string::npos ? texts[i].size() : at;
    left = std::max(left, cut[i]);
    right = std::max(right, texts[i].size() - cut[i]);
  }
  for (std::size_t i = 0; i < count; ++i) {
    std::u32string padded(left - cut[i], U' ');
    padded += texts[i];
    padded.append(left + right - padded.size(), U' ');
    texts[i] = std::move(padded);
  }
  return texts;
}

// The character matrix (rows × width) of a numeric array of rank ≥ 2 seen as rows × columns.
Value format_matrix(Context& ctx, const Value& b, Shape shape) {
  const std::size_t cols = b.shape().back(), rows = cols == 0 ? 0 : b.size() / cols;
  std::vector<std::vector<std::u32string>> columns(cols);
  std::size_t width = 0;
  for (std::size_t c = 0; c < cols && rows > 0; ++c) {
    columns[c] = format_column(b.numbers().data() + c, rows, cols, ctx.pp);
    width += columns[c][0].size() + (c > 0);
  }
  shape.back() = width;
  Value r = ctx.new_characters(std::move(shape));
  char32_t* out = r.mutable_characters().data();
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t c = 0; c < cols; ++c) {
      if (c > 0) *out++ = U' ';
      out = std::copy(columns[c][i].begin(), columns[c][i].end(), out);
    }
  }
  return r;
}

std::vector<std::string> lines_of(const Value& chars) {
  std::vector<std::string> lines;
  auto c = chars.characters();
  if (chars.rank() <= 1) {
    lines.push_back(encode_utf8(std::u32string_view(c.data(), c.size())));
    return lines;
  }
  const Shape& s = chars.shape();
  const std::size_t width = s.back(), rows_per = s[s.size() - 2];
  const std::size_t all_rows = product(s, 0, s.size() - 1);
  if (all_rows == 0) return lines;
  for (std::size_t r = 0; r < all_rows; ++r) {
    if (r > 0 && rows_per > 0 && r % rows_per == 0) {
      // One blank line per outer axis that moves on between this matrix and the last.
      const std::size_t m = r / rows_per;
      std::size_t blanks = 0, period = 1;
      for (std::size_t axis = s.size() - 2; axis-- > 0;) {
        if (m % period == 0) ++blanks;
        period *= s[axis];
        if (m % period != 0) break;
      }
      lines.insert(lines.end(), blanks, "");
    }
    lines.push_back(encode_utf8(std::u32string_view(c.data() + r * width, width)));
  }
  return lines;
}

}  // namespace

std::string format_number(double x, int pp) {
  if (x == 0) return "0";
  Scientific s = scientific(std::fabs(x), pp);
  return encode_utf8(widen(needs_scaled(s, pp) ? scaled(x < 0, s, 0) : fixed(x < 0, s)));
}

Value format(Context& ctx, const Value& b) {
  if (b.is_character()) {
    ctx.charge(b.size());
    return b;
  }
  ctx.charge(b.size() * 16);
  if (b.rank() <= 1) {
    std::u32string text;
    auto x = b.numbers();
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (i > 0) text.push_back(U' ');
      text += decode_utf8(format_number(x[i], ctx.pp));
    }
    ctx.checked_count({text.size()});
    return Value::text(text);
  }
  return format_matrix(ctx, b, b.shape());
}

Value format_by_specification(Context& ctx, const Value& a, const Value& b) {
  if (b.is_character()) domain_error();
  const auto spec = integer_list(a);
  const std::size_t cols = b.rank() == 0 ? 1 : b.shape().back();
  std::vector<std::pair<std::int64_t, std::int64_t>> fields(cols);
  for (std::size_t c = 0; c < cols; ++c) {
    if (spec.size() == 1) {
      fields[c] = {0, spec[0]};
    } else if (spec.size() == 2) {
      fields[c] = {spec[0], spec[1]};
    } else if (spec.size() == 2 * cols) {
      fields[c] = {spec[2 * c], spec[2 * c + 1]};
    } else {
      length_error();
    }
    if (fields[c].first < 0 || fields[c].first > 1000 || std::abs(fields[c].second) > 30)
      domain_error();
  }
  ctx.charge(b.size() * 16);
  const std::size_t rows = cols == 0 ? 0 : b.size() / cols;
  auto x = b.numbers();
  std::vector<std::vector<std::string>> texts(cols, std::vector<std::string>(rows));
  std::vector<std::size_t> widths(cols);
  for (std::size_t c = 0; c < cols; ++c) {
    auto [w, p] = fields[c];
    std::size_t longest = 0;
    for (std::size_t i = 0; i < rows; ++i) {
      const double v = x[i * cols + c];
      std::string t;
      if (p >= 0) {
        t = fmt::format("{:.{}f}", std::fabs(v), p);
        if (v < 0 && t.find_first_of("123456789") != std::string::npos) t = "-" + t;
      } else {
        Scientific s = scientific(std::fabs(v), static_cast<int>(-p));
        if (v == 0) s = {"0", 0};
        t = scaled(v < 0, s, static_cast<std::size_t>(-p - 1));
      }
      longest = std::max(longest, t.size());
      texts[c][i] = std::move(t);
    }
    widths[c] = w > 0 ? static_cast<std::size_t>(w) : longest + 1;
  }
  std::size_t width = 0;
  for (auto w : widths) width += w;
  Shape shape = b.rank() == 0 ? Shape{} : b.shape();
  if (shape.empty()) shape.push_back(0);
  shape.back() = width;
  Value r = ctx.new_characters(std::move(shape));
  char32_t* out = r.mutable_characters().data();
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t c = 0; c < cols; ++c) {
      const std::u32string t = widen(texts[c][i]);
      if (t.size() > widths[c]) {
        out = std::fill_n(out, widths[c], U'*');
      } else {
        out = std::fill_n(out, widths[c] - t.size(), U' ');
        out = std::copy(t.begin(), t.end(), out);
      }
    }
  }
  return r;
}

namespace {

// Lines longer than ⎕PW continued on lines indented six blanks (APL\360): numbers are never cut,
// a numeric display breaking only at a column of blanks common to all its lines, so that its
// columns stay aligned; characters break at the width.
std::vector<std::string> folded(const std::vector<std::string>& lines, std::size_t width,
                                bool numeric) {
  std::vector<std::u32string> rows;
  std::size_t longest = 0;
  for (const auto& l : lines) {
    rows.push_back(decode_utf8(l));
    longest = std::max(longest, rows.back().size());
  }
  if (longest <= width) return lines;
  std::vector<bool> blank(longest, true);
  if (numeric)
    for (const auto& r : rows)
      for (std::size_t c = 0; c < r.size(); ++c) blank[c] = blank[c] && r[c] == U' ';
  // The pieces [start, end) of every line, the same for all.
  constexpr std::size_t indent = 6;
  std::vector<std::pair<std::size_t, std::size_t>> pieces;
  for (std::size_t start = 0; start < longest;) {
    const std::size_t room = pieces.empty() ? width : width - indent;
    std::size_t end = std::min(longest, start + room);
    std::size_t next = end;
    if (numeric && end < longest) {
      std::size_t b = end;
      while (b > start && !blank[b]) --b;
      if (b > start) {
        end = b;
        next = b + 1;
      }
    }
    pieces.emplace_back(start, end);
    start = next;
  }
  std::vector<std::string> out;
  for (const auto& r : rows) {
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      const auto [from, to] = pieces[p];
      std::u32string piece = from < r.size() ? r.substr(from, to - from) : std::u32string();
      if (numeric) piece.erase(piece.find_last_not_of(U' ') + 1);
      if (p > 0 && piece.empty()) continue;
      out.push_back(encode_utf8((p > 0 ? std::u32string(indent, U' ') : std::u32string()) + piece));
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> display(Context& ctx, const Value& v) {
  if (v.rank() >= 2 && v.empty()) return {};
  std::vector<std::string> lines = lines_of(format(ctx, v));
  if (v.is_numeric())
    for (auto& line : lines) line.erase(line.find_last_not_of(' ') + 1);
  return folded(lines, static_cast<std::size_t>(std::max(ctx.pw, 30)), v.is_numeric());
}

}  // namespace igds::apl
