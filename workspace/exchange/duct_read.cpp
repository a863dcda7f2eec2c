// Reading a DUCT picture file (docs/exchange.md, "Reading"): the text to a DuctPicture, or a
// DuctError naming the line and what is wrong; and what an instruction code stands for.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "workspace/exchange/duct_parts.h"
#include "workspace/numbers/fortran.h"

namespace igds {

// ---------------------------------------------------------------------------------------------
// Instruction codes (docs/exchange.md, "The file").

std::int64_t DuctInstruction::code() const {
  return std::int64_t(2048) * colour + static_cast<int>(arc) + static_cast<int>(mark) +
         (mark_all ? 32 : 0) + static_cast<int>(pen) + static_cast<int>(dash);
}

std::optional<DuctInstruction> decompose_duct_code(std::int64_t code) {
  if (code < 0 || code > 2147483647) return std::nullopt;
  DuctInstruction in;
  in.colour = static_cast<int>(code / 2048);
  const int rest = static_cast<int>(code % 2048);
  const int dash = rest % 8, arc = rest / 512, mark = rest / 64 % 8;
  if (dash > 2 || arc > 2 || mark > 4) return std::nullopt;
  in.dash = static_cast<DuctDash>(dash);
  in.pen = static_cast<DuctPen>(rest % 32 - dash);
  in.mark_all = rest / 32 % 2 == 1;
  in.mark = static_cast<DuctMark>(64 * mark);
  in.arc = static_cast<DuctArc>(512 * arc);
  return in;
}

// ---------------------------------------------------------------------------------------------
// Errors.

namespace {

std::string problem_text(const DuctError& e, bool report) {
  using P = DuctError::Problem;
  auto up = [&](std::string s) {
    if (report)
      for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  };
  switch (e.problem) {
    case P::no_star:
      return up("no line holding only '*' ends the header");
    case P::truncated:
      return up(fmt::format("the file ends where {} more lines were due", e.expected));
    case P::not_a_number:
      return up(fmt::format("'{}' is not {}", e.found, e.which == 1 ? "an integer" : "a number"));
    case P::too_many_numbers:
      return up(fmt::format("more numbers than the {} of the format", e.expected));
    case P::version:
      return up(fmt::format("I1 = {} is not 4 to 7 (a picture of DUCT 4.3 or later)", e.got));
    case P::counter:
      return up(fmt::format("I{} = {} is out of range", e.which, e.got));
    case P::too_large:
      return up(fmt::format("{} {}, more than {}", e.got, e.found, e.expected));
    case P::code:
      return up(fmt::format("instruction code {} does not decompose", e.got));
    case P::no_pixels:
      return up(fmt::format("an instruction of {} pixels", e.got));
    case P::arc_pixels:
      return up(fmt::format(
          "{} of {} pixels ({})", e.found, e.got,
          e.found == "conic arc" ? "2n+1, or 2n after IUPDN 24" : "3n+1, or 3n after IUPDN 24"));
    case P::nothing_to_continue:
      return up("IUPDN 24 on the first instruction: no pixel to continue from");
    case P::pixel_sum:
      return up(fmt::format("I5 = {} pixels but the instructions have {}", e.expected, e.got));
    case P::instruction_count:
      return up(fmt::format("I4 = {} instructions but this line holds a pixel", e.expected));
    case P::only_lines:
      return up("I6 = -2 (only straight lines) but this instruction has arcs");
    case P::text_pixel:
      return up(fmt::format("pixel {} of a picture of {}", e.got, e.expected));
    case P::text_counts:
      return up(fmt::format("{} texts or dimensions", e.got));
    case P::text_length:
      return up(fmt::format("a text of {} characters (0 to 80)", e.got));
    case P::trailing:
      return up("more after the end of the picture");
  }
  return "damaged";
}

}  // namespace

const char* DuctError::what() const noexcept {
  try {
    text_ = fmt::format("DUCT picture, line {}: {}", line, problem_text(*this, false));
  } catch (...) {
    return "DUCT picture damaged";
  }
  return text_.c_str();
}

std::string DuctError::reason() const {
  return fmt::format("LINE {}: {}", line, problem_text(*this, true));
}

// ---------------------------------------------------------------------------------------------
// Reading.

namespace {

// The lines of a file, one at a time, with their numbers; '\r' before '\n' is dropped.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {
    total_ = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    if (!text.empty() && text.back() != '\n') ++total_;
  }
  bool at_end() const { return number_ >= total_; }
  std::size_t remaining() const { return total_ - number_; }
  std::size_t total() const { return total_; }
  std::size_t number() const { return number_; }  // of the line last returned
  std::string_view next() {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0, number_ = 0, total_ = 0;
};

using duct::trimmed;

bool blank(char c) {
  return c == ' ' || c == '\t';
}

bool blank_line(std::string_view line) {
  return std::all_of(line.begin(), line.end(), blank);
}

// A token as an error shows it: printable, at most 24 characters.
std::string shown(std::string_view token) {
  std::string out;
  for (char c : token.substr(0, 24)) out.push_back(c >= 0x20 && c < 0x7F ? c : '?');
  if (token.size() > 24) out += "...";
  return out;
}

// One field of a FORTRAN format: `skip` columns (nX), then `width` columns.
struct Field {
  int skip = 0, width = 0;
  bool integer = true;
};

// The formats of the file's records.
constexpr Field I6{0, 6, true}, F10{0, 10, false};
const std::vector<Field> counters_format = [] {
  std::vector<Field> f(10, I6);
  f[0].skip = 1;
  return f;
}();
const std::vector<Field> reals_format = [] {
  std::vector<Field> f(7, F10);
  f[0].skip = 1;
  return f;
}();
const std::vector<Field> instruction_format = {{1, 11, true}, {1, 6, true}};
const std::vector<Field> pixel_format = {{1, 14, false}, {1, 14, false}, {1, 14, false}};
const std::vector<Field> pixel_tu_format = {
    {1, 14, false}, {1, 14, false}, {1, 14, false}, {1, 10, false}, {1, 10, false}};
const std::vector<Field> text_counts_format = {{1, 6, true}, {0, 6, true}};
const std::vector<Field> text_format = {{1, 8, true}, {0, 3, true},  {0, 3, true},
                                        {0, 2, true}, {0, 8, false}, {0, 8, false}};
const std::vector<Field> dimension_format = {
    {1, 2, true}, {0, 8, true}, {0, 8, true}, {0, 2, true}, {0, 8, true}, {0, 8, true},
    {0, 8, true}, {0, 3, true}, {0, 3, true}, {0, 3, true}, {0, 2, true}, {0, 8, false}};

// The values of one READ: integers and reals in the order of the format.
struct Record {
  double real[12];
  std::int64_t integer[12];
  std::size_t line = 0;  // where it began
};

[[noreturn]] void not_a_number(std::size_t line, std::string_view token, bool integer) {
  DuctError e(DuctError::Problem::not_a_number, line);
  e.found = shown(token);
  e.which = integer ? 1 : 0;
  throw e;
}

void parse_into(Record& r, std::size_t k, const Field& f, std::string_view token,
                std::size_t line) {
  if (f.integer) {
    const auto v = fortran::read_integer(token);
    if (!v) not_a_number(line, token, true);
    r.integer[k] = *v;
    r.real[k] = double(*v);
  } else {
    const auto v = fortran::read_real(token);
    if (!v) not_a_number(line, token, false);
    r.real[k] = *v;
    r.integer[k] = 0;
  }
}

// The line read in the format's fixed columns, when every field holds one clean number and
// nothing lies outside them (fields may then touch: -12345-12345).
bool read_fixed(std::string_view line, const std::vector<Field>& format, Record& r) {
  std::size_t col = 0;
  for (std::size_t k = 0; k < format.size(); ++k) {
    const Field& f = format[k];
    const std::size_t skip_end = std::min(line.size(), col + std::size_t(f.skip));
    if (!blank_line(line.substr(std::min(col, line.size()), skip_end - std::min(col, line.size()))))
      return false;
    col += std::size_t(f.skip);
    if (col >= line.size()) return false;
    const std::string_view field = trimmed(line.substr(col, std::size_t(f.width)));
    col += std::size_t(f.width);
    if (field.empty()) return false;
    for (char c : field)
      if (blank(c) || c == ',') return false;
    if (f.integer) {
      const auto v = fortran::read_integer(field);
      if (!v) return false;
      r.integer[k] = *v;
      r.real[k] = double(*v);
    } else {
      const auto v = fortran::read_real(field);
      if (!v) return false;
      r.real[k] = *v;
    }
  }
  return col >= line.size() || blank_line(line.substr(col));
}

// One READ of `format.size()` values starting on the next line, as list-directed input takes it
// (separated values, continued on the following lines while too few) or in fixed columns.
Record read_record(Lines& lines, const std::vector<Field>& format) {
  Record r;
  const std::size_t want = format.size();
  if (lines.at_end()) {
    DuctError e(DuctError::Problem::truncated, lines.total() + 1);
    e.expected = 1;
    throw e;
  }
  std::string_view line = lines.next();
  r.line = lines.number();
  std::string_view tokens[16];
  std::size_t n = fortran::split_values(line, tokens, 16);
  if (n > want) {  // (fixed fields hold no blanks: as many values at most)
    DuctError e(DuctError::Problem::too_many_numbers, lines.number());
    e.expected = std::int64_t(want);
    throw e;
  }
  if (n < want && n > 0 && read_fixed(line, format, r)) return r;
  std::size_t have = 0;
  while (true) {
    for (std::size_t k = 0; k < n; ++k)
      parse_into(r, have + k, format[have + k], tokens[k], lines.number());
    have += n;
    if (have == want) return r;
    if (lines.at_end()) {
      DuctError e(DuctError::Problem::truncated, lines.total() + 1);
      e.expected = 1;
      throw e;
    }
    line = lines.next();
    n = fortran::split_values(line, tokens, 16);
    if (have + n > want) {
      DuctError e(DuctError::Problem::too_many_numbers, lines.number());
      e.expected = std::int64_t(want);
      throw e;
    }
  }
}

[[noreturn]] void counter_error(std::size_t line, int which, std::int64_t got) {
  DuctError e(DuctError::Problem::counter, line);
  e.which = which;
  e.got = got;
  throw e;
}

void check_count(std::size_t line, int which, std::int64_t got, const char* what) {
  if (got < 0) counter_error(line, which, got);
  if (got > std::int64_t(duct_max_pixels)) {
    DuctError e(DuctError::Problem::too_large, line);
    e.got = got;
    e.expected = std::int64_t(duct_max_pixels);
    e.found = what;
    throw e;
  }
}

void require_lines(const Lines& lines, std::int64_t needed) {
  if (std::int64_t(lines.remaining()) < needed) {
    DuctError e(DuctError::Problem::truncated, lines.total() + 1);
    e.expected = needed - std::int64_t(lines.remaining());
    throw e;
  }
}

// An instruction line that holds a pixel instead: three or five numbers, not all integers.
bool looks_like_pixel(std::string_view line) {
  std::string_view tokens[6];
  const std::size_t n = fortran::split_values(line, tokens, 6);
  if (n != 3 && n != 5) return false;
  bool fraction = false;
  for (std::size_t k = 0; k < n; ++k) {
    if (!fortran::read_real(tokens[k])) return false;
    fraction = fraction || !fortran::read_integer(tokens[k]);
  }
  return fraction;
}

// The next line without consuming it (a copy of the cursor).
std::string_view peek_line(const Lines& lines) {
  Lines copy = lines;
  return copy.at_end() ? std::string_view{} : copy.next();
}

int small_int(std::int64_t v) {
  return static_cast<int>(std::clamp<std::int64_t>(v, -1000000000, 1000000000));
}

// Up to `count` characters of `line` from column `from` (0-based), blanks where it is short.
std::string characters(std::string_view line, std::size_t from, std::size_t count) {
  std::string s(count, ' ');
  if (from < line.size()) {
    const std::size_t n = std::min(count, line.size() - from);
    std::copy_n(line.begin() + std::ptrdiff_t(from), n, s.begin());
  }
  return s;
}

}  // namespace

DuctPicture read_duct(std::string_view text) {
  DuctPicture p;
  Lines lines(text);
  using P = DuctError::Problem;

  // Header: everything down to the line holding only '*'.
  bool star = false;
  while (!lines.at_end()) {
    const std::string_view line = lines.next();
    if (trimmed(line) == "*") {
      star = true;
      break;
    }
    p.header.emplace_back(line);
  }
  if (!star) throw DuctError(P::no_star, lines.total() + 1);

  // Counters.
  const Record ci = read_record(lines, counters_format);
  for (int k = 0; k < 10; ++k) p.counters[k] = ci.integer[k];
  const auto& c = p.counters;
  if (c[0] < 4 || c[0] > 7) {
    DuctError e(P::version, ci.line);
    e.got = c[0];
    throw e;
  }
  if (c[1] < 0 || c[1] > 3) counter_error(ci.line, 2, c[1]);
  if (c[3] < 1) counter_error(ci.line, 4, c[3]);
  check_count(ci.line, 4, c[3], "instructions");
  check_count(ci.line, 5, c[4], "pixels");
  if (c[6] != 0 && c[6] != 2 && c[6] != 3) counter_error(ci.line, 7, c[6]);
  const Record cr = read_record(lines, reals_format);
  for (int k = 0; k < 7; ++k) p.reals[k] = cr.real[k];

  // Every instruction and every pixel takes a line at least: a file too short for its counts is
  // refused before anything is allocated for them.
  const std::int64_t instructions = c[3], pixels = c[4];
  require_lines(lines, instructions + pixels);

  p.instructions.reserve(std::size_t(instructions));
  std::int64_t sum = 0;
  for (std::int64_t n = 0; n < instructions; ++n) {
    if (looks_like_pixel(peek_line(lines))) {
      DuctError e(P::instruction_count, lines.number() + 1);
      e.expected = instructions;
      throw e;
    }
    const Record r = read_record(lines, instruction_format);
    auto in = decompose_duct_code(r.integer[0]);
    if (!in) {
      DuctError e(P::code, r.line);
      e.got = r.integer[0];
      throw e;
    }
    const std::int64_t npix = r.integer[1];
    if (npix < 1) {
      DuctError e(P::no_pixels, r.line);
      e.got = npix;
      throw e;
    }
    check_count(r.line, 5, npix, "pixels");
    const bool continued = in->pen == DuctPen::continued;
    if (continued && n == 0) throw DuctError(P::nothing_to_continue, r.line);
    if (in->arc != DuctArc::line && c[5] == -2) throw DuctError(P::only_lines, r.line);
    const bool bad_conic = in->arc == DuctArc::conic && (continued ? npix % 2 != 0 : npix % 2 != 1);
    const bool bad_bezier =
        in->arc == DuctArc::bezier && (continued ? npix % 3 != 0 : npix % 3 != 1);
    if (bad_conic || bad_bezier) {
      DuctError e(P::arc_pixels, r.line);
      e.got = npix;
      e.found = bad_conic ? "conic arc" : "Bezier spans";
      throw e;
    }
    sum += npix;
    if (sum > pixels) {
      DuctError e(P::pixel_sum, r.line);
      e.expected = pixels;
      e.got = sum;
      throw e;
    }
    in->pixels = std::size_t(npix);
    p.instructions.push_back(*in);
  }
  if (sum != pixels) {
    DuctError e(P::pixel_sum, ci.line);
    e.expected = pixels;
    e.got = sum;
    throw e;
  }

  const bool tu = p.has_tu();
  p.xyz.resize(3 * std::size_t(pixels));
  if (tu) p.tu.resize(2 * std::size_t(pixels));
  for (std::int64_t k = 0; k < pixels; ++k) {
    const Record r = read_record(lines, tu ? pixel_tu_format : pixel_format);
    std::copy_n(r.real, 3, &p.xyz[3 * std::size_t(k)]);
    if (tu) std::copy_n(r.real + 3, 2, &p.tu[2 * std::size_t(k)]);
  }

  if (p.has_texts()) {
    const Record r = read_record(lines, text_counts_format);
    for (int k = 0; k < 2; ++k) {
      if (r.integer[k] < 0) {
        DuctError e(P::text_counts, r.line);
        e.got = r.integer[k];
        throw e;
      }
      check_count(r.line, 0, r.integer[k], k == 0 ? "texts" : "dimensions");
    }
    require_lines(lines, r.integer[0] + r.integer[1]);
    p.texts.reserve(std::size_t(r.integer[0]));
    for (std::int64_t t = 0; t < r.integer[0]; ++t) {
      // (1X,I8,I3,I3,I2,2F8.3,17X,A): the numbers in columns 1..50, the string from column 51.
      if (lines.at_end()) throw DuctError(P::truncated, lines.total() + 1);
      const std::string_view line = lines.next();
      const std::size_t at = lines.number();
      Record n;
      const std::string_view numbers = line.substr(0, std::min<std::size_t>(line.size(), 50));
      if (!read_fixed(numbers, text_format, n)) {
        std::string_view tokens[8];
        const std::size_t count = fortran::split_values(numbers, tokens, 8);
        if (count > text_format.size()) {
          DuctError e(P::too_many_numbers, at);
          e.expected = std::int64_t(text_format.size());
          throw e;
        }
        if (count < text_format.size()) {
          DuctError e(P::not_a_number, at);
          e.found = shown(trimmed(numbers));
          throw e;
        }
        for (std::size_t k = 0; k < count; ++k) parse_into(n, k, text_format[k], tokens[k], at);
      }
      DuctText text;
      if (n.integer[0] < 1 || n.integer[0] > pixels) {
        DuctError e(P::text_pixel, at);
        e.got = n.integer[0];
        e.expected = pixels;
        throw e;
      }
      if (n.integer[1] < 0 || n.integer[1] > 80) {
        DuctError e(P::text_length, at);
        e.got = n.integer[1];
        throw e;
      }
      text.pixel = std::size_t(n.integer[0]);
      const std::size_t length = std::size_t(n.integer[1]);
      text.colour = small_int(n.integer[2]);
      text.units = small_int(n.integer[3]);
      text.angle = n.real[4];
      text.height = n.real[5];
      text.text = characters(line, 50, std::min<std::size_t>(length, 30));
      if (length > 30) {
        if (lines.at_end()) {
          DuctError e(P::truncated, lines.total() + 1);
          e.expected = 1;
          throw e;
        }
        text.text += characters(lines.next(), 1, length - 30);
      }
      p.texts.push_back(std::move(text));
    }
    p.dimensions.reserve(std::size_t(r.integer[1]));
    for (std::int64_t d = 0; d < r.integer[1]; ++d) {
      const Record n = read_record(lines, dimension_format);
      DuctDimension dim;
      std::copy_n(n.integer, 11, dim.k.begin());
      dim.t = n.real[11];
      for (int k : {1, 2, 4, 5, 6}) {
        if (dim.k[std::size_t(k)] < 0 || dim.k[std::size_t(k)] > pixels) {
          DuctError e(P::text_pixel, n.line);
          e.got = dim.k[std::size_t(k)];
          e.expected = pixels;
          throw e;
        }
      }
      p.dimensions.push_back(dim);
    }
  }

  while (!lines.at_end()) {
    if (!blank_line(lines.next())) throw DuctError(P::trailing, lines.number());
  }
  return p;
}

}  // namespace igds
