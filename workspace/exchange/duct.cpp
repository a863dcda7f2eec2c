#include "workspace/exchange/duct.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "workspace/drawing/project.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/large_array.h"
#include "workspace/numbers/fortran.h"

namespace igds {

// ---------------------------------------------------------------------------------------------
// Instruction codes (duct.md, "Instruction code").

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

bool blank(char c) {
  return c == ' ' || c == '\t';
}

bool blank_line(std::string_view line) {
  return std::all_of(line.begin(), line.end(), blank);
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
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

// The formats of duct.md.
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

// ---------------------------------------------------------------------------------------------
// Conic arcs (duct.md, "Curves"; docs/exchange.md derives the weights).

ConicSpans conic_spans(Vec3 p0, Vec3 m, Vec3 p1, double shape) {
  ConicSpans out;
  const Vec3 chord = p1 - p0;
  const double c2 = dot(chord, chord);
  const double b = 2 * norm(cross(m - p0, chord)) / c2;
  const double f = 1 + shape * b * b;
  auto finite = [](Vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (c2 > 0 && std::isfinite(c2) && std::isfinite(f) && f > 0) {
    if (f < 2) {
      // One span: the rational quadratic of the seed's equation (1) in Bernstein form.
      const double w = (2 - f) / f;
      const Vec3 q = 0.5 * (p0 + p1);
      const Vec3 control = (1 / (2 - f)) * (2 * m - f * q);
      if (finite(control) && std::isfinite(w) && w > 0) {
        out.spans = 1;
        out.controls = {p0, control, p1, {}, {}};
        out.weights = {1, w, 1, 0, 0};
        return out;
      }
    }
    // Two spans split at M (de Casteljau at t = 1/2 in homogeneous coordinates): controls
    // M -/+ f(P1 - P0)/4, weights 1/f at the three inner controls.
    const Vec3 half = (f / 4) * chord;
    const double w = 1 / f;
    if (finite(half) && w > 0) {
      out.spans = 2;
      out.controls = {p0, m - half, m, m + half, p1};
      out.weights = {1, w, w, w, 1};
      return out;
    }
  }
  out.spans = 2;
  out.lines = true;
  out.controls = {p0, 0.5 * (p0 + m), m, 0.5 * (m + p1), p1};
  out.weights = {1, 1, 1, 1, 1};
  return out;
}

ConicShape conic_shape(Vec3 p0, Vec3 c, Vec3 p1, double w0, double w1, double w2) {
  // In standard form (end weights 1) the middle weight is w1/sqrt(w0 w2); M is the point at
  // t = 1/2 and f = 2/(1 + w) (the inverse of conic_spans).
  const double w = w1 / std::sqrt(w0 * w2);
  ConicShape out;
  // M = (Q + wC)/(1 + w) with Q the chord's middle, in a form that cannot overflow.
  out.mid = (1 / (1 + w)) * (0.5 * p0 + 0.5 * p1) + (w / (1 + w)) * c;
  const Vec3 chord = p1 - p0;
  const double c2 = dot(chord, chord);
  const double b = c2 > 0 ? 2 * norm(cross(out.mid - p0, chord)) / c2 : 0;
  const double f = 2 / (1 + w);
  out.shape = b > 0 && std::isfinite(b) ? (f - 1) / (b * b) : 0;
  if (!std::isfinite(out.shape)) out.shape = 0;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Picture to drawing.

namespace {

MarkShape mark_shape(DuctMark m) {
  switch (m) {
    case DuctMark::cross:
      return MarkShape::cross;
    case DuctMark::plus:
      return MarkShape::plus;
    case DuctMark::diamond:
      return MarkShape::diamond;
    case DuctMark::square:
    case DuctMark::none:
      break;
  }
  return MarkShape::square;
}

Dash dash_of(DuctDash d) {
  switch (d) {
    case DuctDash::dashed:
      return Dash::dashed;
    case DuctDash::chain:
      return Dash::chain;
    case DuctDash::solid:
      break;
  }
  return Dash::solid;
}

}  // namespace

Drawing3 duct_drawing(const DuctPicture& picture) {
  std::size_t total = 0;
  for (const auto& in : picture.instructions) total += in.pixels;
  if (total * 3 != picture.xyz.size() || (!picture.tu.empty() && picture.tu.size() != 2 * total))
    throw std::invalid_argument("DUCT picture: the pixels do not add up");
  for (const auto& t : picture.texts)
    if (t.pixel < 1 || t.pixel > total)
      throw std::invalid_argument("DUCT picture: a text at no pixel");

  Drawing3 d;
  auto pixel = [&](std::size_t k) { return Vec3::load(&picture.xyz[3 * k]); };
  std::vector<double> curve, chain, weights;
  std::size_t next = 0;  // the first pixel of the instruction
  bool have_last = false;
  Vec3 last;
  for (std::size_t n = 0; n < picture.instructions.size(); ++n) {
    const DuctInstruction& in = picture.instructions[n];
    const Style style{.pen = in.colour < 1 ? 1 : in.colour, .dash = dash_of(in.dash)};
    const Identity id{Role::line, int(n + 1)};
    const bool continued = in.pen == DuctPen::continued && have_last;
    if (in.pen == DuctPen::continued && !have_last)
      throw std::invalid_argument("DUCT picture: IUPDN 24 with no previous pixel");
    // The instruction's curve: its pixels, after the previous last pixel for IUPDN 24.
    curve.clear();
    if (continued) curve.insert(curve.end(), {last.x, last.y, last.z});
    curve.insert(curve.end(), picture.xyz.begin() + std::ptrdiff_t(3 * next),
                 picture.xyz.begin() + std::ptrdiff_t(3 * (next + in.pixels)));
    const std::size_t count = curve.size() / 3;
    const Vec3View points(curve.data(), count);
    const bool join = in.pen == DuctPen::visible && have_last;
    const bool drawn = in.pen != DuctPen::invisible;

    switch (in.arc) {
      case DuctArc::line:
        if (drawn) {
          if (join) {
            std::vector<double> joined = {last.x, last.y, last.z};
            joined.insert(joined.end(), curve.begin(), curve.end());
            d.add_polyline(Vec3View(joined.data(), count + 1), style, id);
          } else if (count >= 2) {
            d.add_polyline(points, style, id);
          }
        }
        break;
      case DuctArc::bezier:
        if (drawn) {
          if (join) {
            const double line[6] = {last.x, last.y, last.z, curve[0], curve[1], curve[2]};
            d.add_polyline(Vec3View(line, 2), style, id);
          }
          if (count >= 4) d.add_curve(3, points, {}, style, id);
        }
        break;
      case DuctArc::conic:
        if (drawn) {
          if (join) {
            const double line[6] = {last.x, last.y, last.z, curve[0], curve[1], curve[2]};
            d.add_polyline(Vec3View(line, 2), style, id);
          }
          if (count >= 3) {
            chain.clear();
            weights.clear();
            chain.insert(chain.end(), curve.begin(), curve.begin() + 3);
            weights.push_back(1);
            for (std::size_t k = 1; k + 1 < count; k += 2) {
              // The mid point's T is its shape factor; without TU parameters, 1.
              const std::size_t file_pixel = next + k - (continued ? 1 : 0);
              const double s = picture.tu.empty() ? 1.0 : picture.tu[2 * file_pixel];
              const ConicSpans spans = conic_spans(points[k - 1], points[k], points[k + 1], s);
              for (int c = 1; c <= 2 * spans.spans; ++c) {
                const Vec3 v = spans.controls[std::size_t(c)];
                chain.insert(chain.end(), {v.x, v.y, v.z});
                weights.push_back(spans.weights[std::size_t(c)]);
              }
            }
            d.add_curve(2, Vec3View(chain.data(), chain.size() / 3), weights, style, id);
          }
        }
        break;
    }

    if (in.mark != DuctMark::none) {
      const std::size_t step = in.arc == DuctArc::conic ? 2 : in.arc == DuctArc::bezier ? 3 : 1;
      for (std::size_t k = 0; k < count; k += step) {
        d.add_mark(points[k], mark_shape(in.mark), duct_mark_size, style, id);
        if (!in.mark_all) break;
      }
    }
    last = points[count - 1];
    have_last = true;
    next += in.pixels;
  }

  for (std::size_t t = 0; t < picture.texts.size(); ++t) {
    const DuctText& text = picture.texts[t];
    d.add_text(pixel(text.pixel - 1), text.text, 1, Style{.pen = text.colour < 1 ? 1 : text.colour},
               Identity{Role::label, int(t + 1), int(text.pixel)});
  }
  return d;
}

// ---------------------------------------------------------------------------------------------
// Drawing to picture.

namespace {

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The tight box of what is drawn: points, and the extremes of each curve span where its
// derivative vanishes.
struct BoxBuilder {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  void add(Vec3 p) {
    if (!finite(p)) return;  // an extreme evaluated inside a span of huge numbers
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  bool empty() const { return lo.x > hi.x; }
};

// The roots in (0, 1) of a t^2 + b t + c.
int unit_roots(double a, double b, double c, double roots[2]) {
  int n = 0;
  auto keep = [&](double t) {
    if (t > 0 && t < 1) roots[n++] = t;
  };
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (scale == 0) return 0;
  if (std::abs(a) <= 1e-12 * scale) {
    if (b != 0) keep(-c / b);
    return n;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  keep(q / a);
  if (q != 0) keep(c / q);
  return n;
}

double coordinate(Vec3 v, int k) {
  return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

Vec3 cubic_point(const Vec3 c[4], double t) {
  const double s = 1 - t;
  return (s * s * s) * c[0] + (3 * s * s * t) * c[1] + (3 * s * t * t) * c[2] + (t * t * t) * c[3];
}

void add_cubic_span(BoxBuilder& box, const Vec3 c[4]) {
  box.add(c[0]);
  box.add(c[3]);
  for (int k = 0; k < 3; ++k) {
    const double x0 = coordinate(c[0], k), x1 = coordinate(c[1], k), x2 = coordinate(c[2], k),
                 x3 = coordinate(c[3], k);
    // The derivative's Bernstein coefficients 3(x1-x0), 3(x2-x1), 3(x3-x2) in the power basis.
    const double a = -x0 + 3 * x1 - 3 * x2 + x3, b = 2 * (x0 - 2 * x1 + x2), cc = x1 - x0;
    double roots[2];
    const int n = unit_roots(a, b, cc, roots);
    for (int r = 0; r < n; ++r) box.add(cubic_point(c, roots[r]));
  }
}

Vec3 quadratic_point(const Vec3 c[3], const double w[3], double t) {
  const double s = 1 - t;
  const double b0 = s * s * w[0], b1 = 2 * s * t * w[1], b2 = t * t * w[2];
  return (1 / (b0 + b1 + b2)) * (b0 * c[0] + b1 * c[1] + b2 * c[2]);
}

void add_quadratic_span(BoxBuilder& box, const Vec3 c[3], const double w[3]) {
  box.add(c[0]);
  box.add(c[2]);
  // x = N/D with N and D quadratics; N'D - ND' is a quadratic (its cubic terms cancel).
  const double d0 = w[0], d1 = 2 * (w[1] - w[0]), d2 = w[0] - 2 * w[1] + w[2];
  for (int k = 0; k < 3; ++k) {
    const double y0 = w[0] * coordinate(c[0], k), y1 = w[1] * coordinate(c[1], k),
                 y2 = w[2] * coordinate(c[2], k);
    const double n0 = y0, n1 = 2 * (y1 - y0), n2 = y0 - 2 * y1 + y2;
    double roots[2];
    const int n = unit_roots(n2 * d1 - n1 * d2, 2 * (n2 * d0 - n0 * d2), n1 * d0 - n0 * d1, roots);
    for (int r = 0; r < n; ++r) box.add(quadratic_point(c, w, roots[r]));
  }
}

// A rational cubic span flattened: homogeneous de Casteljau halving until the inner controls lie
// within `tolerance` of the chord (the span lies in their hull, the weights being positive).
void flatten_rational_cubic(const std::array<double, 16>& h, double tolerance, int depth,
                            std::vector<Vec3>& out) {
  auto point = [&](int k) {
    return Vec3{h[4 * k] / h[4 * k + 3], h[4 * k + 1] / h[4 * k + 3], h[4 * k + 2] / h[4 * k + 3]};
  };
  const Vec3 a = point(0), b = point(3);
  const Vec3 chord = b - a;
  const double length = norm(chord);
  double deviation = 0;
  for (int k = 1; k <= 2; ++k) {
    const Vec3 v = point(k) - a;
    deviation = std::max(deviation, length > 0 ? norm(cross(v, chord)) / length : norm(v));
  }
  if (deviation <= tolerance || depth >= 16) {
    out.push_back(b);
    return;
  }
  std::array<double, 16> left, right;
  for (int i = 0; i < 4; ++i) {
    const double p0 = h[i], p1 = h[4 + i], p2 = h[8 + i], p3 = h[12 + i];
    const double q0 = (p0 + p1) / 2, q1 = (p1 + p2) / 2, q2 = (p2 + p3) / 2;
    const double r0 = (q0 + q1) / 2, r1 = (q1 + q2) / 2, s = (r0 + r1) / 2;
    left[i] = p0, left[4 + i] = q0, left[8 + i] = r0, left[12 + i] = s;
    right[i] = s, right[4 + i] = r1, right[8 + i] = q2, right[12 + i] = p3;
  }
  flatten_rational_cubic(left, tolerance, depth + 1, out);
  flatten_rational_cubic(right, tolerance, depth + 1, out);
}

DuctMark duct_mark(MarkShape shape) {
  switch (shape) {
    case MarkShape::cross:
      return DuctMark::cross;
    case MarkShape::square:
      return DuctMark::square;
    case MarkShape::diamond:
    case MarkShape::circle:
      return DuctMark::diamond;
    case MarkShape::plus:
    case MarkShape::dot:
      break;
  }
  return DuctMark::plus;
}

DuctDash duct_dash(Dash dash) {
  switch (dash) {
    case Dash::solid:
      return DuctDash::solid;
    case Dash::chain:
      return DuctDash::chain;
    case Dash::dashed:
    case Dash::dotted:
      break;
  }
  return DuctDash::dashed;
}

// Printable ASCII for a line of the file: control and other bytes become '?'.
std::string printable(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (!(c >= 0x20 && c < 0x7F)) c = '?';
  return out;
}

// R1..R6 rounded outwards to F10.4's 4 decimals, so the limits hold the whole picture.
double outwards(double v, bool up) {
  if (!(std::abs(v) < 1e11)) return v;
  const double scaled = v * 1e4;
  // A value already on the grid of 1e-4 (to the rounding of the product) stays where it is.
  const double slack = 1e-12 * std::abs(scaled);
  return (up ? std::ceil(scaled - slack) : std::floor(scaled + slack)) / 1e4;
}

// The largest extent of every point of a drawing (0 when it has none).
template <class P>
double extent_of(const Drawing<P>& drawing) {
  const Box3 all = bounding_box(drawing);
  return all.lo.x <= all.hi.x
             ? std::max({all.hi.x - all.lo.x, all.hi.y - all.lo.y, all.hi.z - all.lo.z})
             : 0.0;
}

// The picture of a drawing (a drawing in the plane at z = 0) as duct_picture makes it, but its
// pixels handed to `pixels` in file order rather than kept (xyz and tu are left empty):
// pixels.shape(s) gives the shape factor T of the pixel that follows (a conic arc's mid pixel),
// pixels.pixel(v) each pixel. Throws DataError before handing on any pixel of an item that is not
// finite.
template <class P, class Pixels>
DuctPicture lay_out(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view,
                    Pixels& pixels) {
  using Kind = typename Drawing<P>::Kind;
  DuctPicture p;
  std::string first = printable(fmt::format("IGDS PICTURE FILE {} {}", header.name, header.date));
  p.header.push_back(first);
  if (!header.title.empty()) {
    std::string title = printable(header.title);
    if (trimmed(title) == "*") title = "(*)";
    p.header.push_back(title);
  }

  p.instructions.reserve(drawing.size());

  BoxBuilder box;
  std::size_t count = 0;  // pixels so far
  bool shapes = false;    // a conic arc's shape factor was given
  bool all_lines = true;
  // Runs of marks (or texts) of one style and shape share an invisible instruction.
  enum class Run { none, marks, texts } run = Run::none;
  Style run_style;
  MarkShape run_shape = MarkShape::square;

  auto add_pixel = [&](Vec3 v) { pixels.pixel(v), ++count; };
  auto bound = [&](Vec3 v) {
    if constexpr (Pixels::lays_out) box.add(v);
  };
  auto start = [&](const Style& style, DuctArc arc, DuctMark mark, DuctPen pen) {
    DuctInstruction in;
    in.colour = std::clamp(style.pen, 1, 999999);
    in.arc = arc;
    in.mark = mark;
    in.pen = pen;
    in.dash = duct_dash(style.dash);
    p.instructions.push_back(in);
    return &p.instructions.back();
  };

  std::optional<double> extent;  // of the whole drawing, for the first rational cubic
  std::vector<Vec3> flat, points;
  const auto items = drawing.items();
  for (std::size_t n = 0; n < items.size(); ++n) {
    const auto& item = items[n];
    points.clear();
    for (P point : drawing.points(item)) points.push_back(in_space(point));
    const auto w = drawing.weights(item);
    if constexpr (Pixels::lays_out) {
      const bool bad =
          std::any_of(points.begin(), points.end(), [](Vec3 v) { return !finite(v); }) ||
          std::any_of(w.begin(), w.end(), [](double x) { return !(std::isfinite(x) && x > 0); });
      if (bad) {
        DataError e(DataError::Problem::point_not_finite);
        e.number = n + 1;
        throw e;
      }
    }
    if (item.kind != Kind::mark && item.kind != Kind::text) run = Run::none;
    switch (item.kind) {
      case Kind::polyline: {
        if (points.empty()) break;
        DuctInstruction* in = start(item.style, DuctArc::line, DuctMark::none, DuctPen::move);
        for (Vec3 v : points) {
          add_pixel(v);
          bound(v);
        }
        if (item.closed) add_pixel(points[0]);
        in->pixels = points.size() + (item.closed ? 1 : 0);
        break;
      }
      case Kind::curve: {
        const bool rational =
            !w.empty() && std::any_of(w.begin(), w.end(), [&](double x) { return x != w[0]; });
        if (item.degree == 3 && !rational) {
          DuctInstruction* in = start(item.style, DuctArc::bezier, DuctMark::none, DuctPen::move);
          all_lines = false;
          for (Vec3 v : points) add_pixel(v);
          for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
            const Vec3 c[4] = {points[k], points[k + 1], points[k + 2], points[k + 3]};
            if constexpr (Pixels::lays_out) add_cubic_span(box, c);
          }
          in->pixels = points.size();
        } else if (item.degree == 3) {
          // A rational cubic has no DUCT form: straight lines close to it.
          flat.assign(1, points[0]);
          for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
            std::array<double, 16> h;
            for (int i = 0; i < 4; ++i) {
              const Vec3 v = points[k + std::size_t(i)];
              const double wi = w[k + std::size_t(i)];
              h[4 * std::size_t(i)] = v.x * wi, h[4 * std::size_t(i) + 1] = v.y * wi;
              h[4 * std::size_t(i) + 2] = v.z * wi, h[4 * std::size_t(i) + 3] = wi;
            }
            if (!extent) extent = extent_of(drawing);
            flatten_rational_cubic(h, 1e-5 * *extent, 0, flat);
          }
          DuctInstruction* in = start(item.style, DuctArc::line, DuctMark::none, DuctPen::move);
          for (Vec3 v : flat) {
            add_pixel(v);
            bound(v);
          }
          in->pixels = flat.size();
        } else {
          DuctInstruction* in = start(item.style, DuctArc::conic, DuctMark::none, DuctPen::move);
          all_lines = false;
          add_pixel(points[0]);
          for (std::size_t k = 0; k + 2 < points.size(); k += 2) {
            const double ws[3] = {w.empty() ? 1 : w[k], w.empty() ? 1 : w[k + 1],
                                  w.empty() ? 1 : w[k + 2]};
            const ConicShape cs =
                conic_shape(points[k], points[k + 1], points[k + 2], ws[0], ws[1], ws[2]);
            pixels.shape(cs.shape);
            shapes = true;
            add_pixel(cs.mid);
            add_pixel(points[k + 2]);
            const Vec3 c[3] = {points[k], points[k + 1], points[k + 2]};
            if constexpr (Pixels::lays_out) add_quadratic_span(box, c, ws);
          }
          in->pixels = points.size();
        }
        break;
      }
      case Kind::mark: {
        const Vec3 v = points[0];
        bound(v);
        if (run == Run::marks && item.style == run_style && item.shape == run_shape) {
          p.instructions.back().pixels += 1;
          p.instructions.back().mark_all = true;
        } else {
          start(item.style, DuctArc::line, duct_mark(item.shape), DuctPen::invisible)->pixels = 1;
          run = Run::marks;
          run_style = item.style;
          run_shape = item.shape;
        }
        add_pixel(v);
        break;
      }
      case Kind::text: {
        const Vec3 v = points[0];
        bound(v);
        if (run == Run::texts) {
          p.instructions.back().pixels += 1;
        } else {
          start(item.style, DuctArc::line, DuctMark::none, DuctPen::invisible)->pixels = 1;
          run = Run::texts;
        }
        add_pixel(v);
        DuctText text;
        text.pixel = count;
        text.colour = std::clamp(item.style.pen, 1, 999);
        text.units = 1;
        text.angle = 0;
        text.height = 3;
        text.text = printable(drawing.text(item).substr(0, 80));
        p.texts.push_back(std::move(text));
        break;
      }
    }
  }
  if (p.instructions.empty()) {
    start(Style{}, DuctArc::line, DuctMark::none, DuctPen::invisible)->pixels = 1;
    add_pixel({0, 0, 0});
  }
  auto& c = p.counters;
  c[0] = 4 + (p.texts.empty() ? 0 : 2) + (shapes ? 1 : 0);
  c[1] = view.axis;
  c[2] = -1;
  c[3] = std::int64_t(p.instructions.size());
  c[4] = std::int64_t(count);
  c[5] = all_lines ? -2 : 0;
  c[6] = view.dimensions;
  c[7] = view.projected[0];
  c[8] = view.projected[1];
  c[9] = view.projected[2];
  if (!box.empty()) {
    p.reals = {outwards(box.lo.x, false),
               outwards(box.hi.x, true),
               outwards(box.lo.y, false),
               outwards(box.hi.y, true),
               outwards(box.lo.z, false),
               outwards(box.hi.z, true),
               view.height};
  } else {
    p.reals = {0, 0, 0, 0, 0, 0, view.height};
  }
  return p;
}

// The pixels of a picture kept in it.
struct KeptPixels {
  static constexpr bool lays_out = true;
  DuctPicture& p;
  std::vector<std::pair<std::size_t, double>> shapes;  // pixel, shape factor
  void shape(double s) { shapes.emplace_back(p.pixel_count(), s); }
  void pixel(Vec3 v) { p.xyz.insert(p.xyz.end(), {v.x, v.y, v.z}); }
};

template <class P>
DuctPicture kept(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view) {
  DuctPicture p;
  // Room for every pixel at once: a picture of millions of them is not copied as it grows.
  std::size_t pixels = 0;
  for (const auto& item : drawing.items()) pixels += item.count + (item.closed ? 1 : 0);
  p.xyz.reserve(3 * pixels);
  KeptPixels out{p, {}};
  DuctPicture laid = lay_out(drawing, header, view, out);
  laid.xyz = std::move(p.xyz);
  if (laid.has_tu()) {
    laid.tu.assign(2 * laid.pixel_count(), 0.0);
    for (const auto& [pixel, s] : out.shapes) laid.tu[2 * pixel] = s;
  }
  return laid;
}

// What an image's picture says of its view.
DuctView image_view(Projection projection) {
  DuctView view;
  view.axis = 3;
  view.dimensions = 2;
  view.projected = {static_cast<int>(projection), 0, 0};
  return view;
}

}  // namespace

DuctPicture duct_picture(const Drawing3& drawing, const DuctHeader& header, const DuctView& view) {
  return kept(drawing, header, view);
}

DuctPicture duct_picture(const Drawing2& drawing, const DuctHeader& header, Projection projection) {
  return kept(drawing, header, image_view(projection));
}

// ---------------------------------------------------------------------------------------------
// Writing.

namespace {

// A record of fields with no blank between them ((1X,10I6), (1X,7F10.4), ...): as FORTRAN
// writes it when every value fits its field, so that fixed columns read it; when one does not,
// every value after a blank, so that list-directed readers read it (columns being lost anyway).
class WrittenRecord {
 public:
  void integer(std::int64_t v, int width) {
    fields_.push_back({{}, width});
    fortran::put_i_whole(fields_.back().text, v, 1);
  }
  void fixed(double v, int width, int decimals) {
    fields_.push_back({{}, width});
    fortran::put_f_whole(fields_.back().text, v, 1, decimals);
  }
  void write(std::string& out) const {
    bool fits = true;
    for (const auto& f : fields_) fits = fits && trimmed(f.text).size() <= std::size_t(f.width);
    out += ' ';  // 1X
    for (const auto& f : fields_) {
      const std::string_view text = trimmed(f.text);
      if (fits)
        out.append(std::size_t(f.width) - text.size(), ' ');
      else
        out += ' ';
      out += text;
    }
  }

 private:
  struct Field {
    std::string text;
    int width;
  };
  std::vector<Field> fields_;
};

}  // namespace

namespace {

// The header lines, counters, reals and instructions of a picture.
void write_head(const DuctPicture& p, TextOut& out) {
  // The records besides the pixels are few: made in a string, then put.
  std::string head;
  for (const auto& line : p.header) {
    head += line;
    head += '\n';
  }
  head += " *\n";
  WrittenRecord counters, reals;
  for (std::int64_t v : p.counters) counters.integer(v, 6);
  for (double v : p.reals) reals.fixed(v, 10, 4);
  counters.write(head);
  head += '\n';
  reals.write(head);
  head += '\n';
  out.put(head);
  // Instructions and pixels have a blank before every field.
  for (const auto& in : p.instructions) {
    char* w = out.room(2 * 22 + 1);
    *w++ = ' ';
    w = fortran::put_i_whole(w, in.code(), 11);
    *w++ = ' ';
    w = fortran::put_i_whole(w, std::int64_t(in.pixels), 6);
    *w++ = '\n';
    out.commit(w);
  }
}

// A pixel line, the bulk of a picture, at w: (3(1X,E14.7)), then 2(1X,F10.4) with T U when `tu`.
// Where it ends.
constexpr std::size_t pixel_line_most = 3 * 15 + 2 * 27 + 1;
char* pixel_line(char* w, const double xyz[3], const double* tu) {
  for (int i = 0; i < 3; ++i) {
    *w++ = ' ';
    w = fortran::put_e_whole(w, xyz[i], 14, 7);
  }
  if (tu) {
    for (int i = 0; i < 2; ++i) {
      *w++ = ' ';
      w = fortran::put_f_whole(w, tu[i], 10, 4);
    }
  }
  *w++ = '\n';
  return w;
}

// The texts and dimensions after the pixels, when I1 says so.
void write_tail(const DuctPicture& p, TextOut& out) {
  if (!p.has_texts()) return;
  std::string tail;
  WrittenRecord counts;
  counts.integer(std::int64_t(p.texts.size()), 6);
  counts.integer(std::int64_t(p.dimensions.size()), 6);
  counts.write(tail);
  tail += '\n';
  for (const auto& t : p.texts) {
    // The string starts in column 51 whatever the numbers: values its fields cannot hold (DUCT
    // could not have written them) are brought into them.
    WrittenRecord numbers;
    numbers.integer(std::int64_t(t.pixel), 8);
    numbers.integer(std::int64_t(t.text.size()), 3);
    numbers.integer(std::clamp(t.colour, -99, 999), 3);
    numbers.integer(std::clamp(t.units, -9, 99), 2);
    numbers.fixed(std::isfinite(t.angle) ? std::fmod(t.angle, 360.0) : 0.0, 8, 3);
    numbers.fixed(std::isfinite(t.height) ? std::clamp(t.height, -999.999, 9999.999) : 0.0, 8, 3);
    numbers.write(tail);
    tail.append(17, ' ');
    tail.append(t.text, 0, 30);
    if (t.text.size() > 30) {
      tail += "\n ";
      tail.append(t.text, 30);
    }
    tail += '\n';
    if (tail.size() > TextOut::max_room) out.put(tail), tail.clear();
  }
  for (const auto& d : p.dimensions) {
    static constexpr int widths[11] = {2, 8, 8, 2, 8, 8, 8, 3, 3, 3, 2};
    WrittenRecord dimension;
    for (int k = 0; k < 11; ++k) dimension.integer(d.k[std::size_t(k)], widths[k]);
    dimension.fixed(d.t, 8, 3);
    dimension.write(tail);
    tail += '\n';
    if (tail.size() > TextOut::max_room) out.put(tail), tail.clear();
  }
  out.put(tail);
}

// The pixels of a picture written as they come, with T U when the picture has them: gathered in
// blocks, each block's lines made on two threads.
class WrittenPixels {
 public:
  static constexpr bool lays_out = false;  // the picture was laid out before
  WrittenPixels(TextOut& out, bool tu) : out_(out), tu_(tu) { block_.reserve(block); }
  void shape(double s) { t_ = s; }
  void pixel(Vec3 v) {
    block_.push_back({v.x, v.y, v.z, t_});
    t_ = 0;
    if (block_.size() == block) flush();
  }
  void flush() {
    put_each(out_, block_.size(), pixel_line_most, threads_for(4 * block_.size()), aside_,
             [&](char* w, std::size_t k) {
               const double tu[2] = {block_[k][3], 0};
               return pixel_line(w, block_[k].data(), tu_ ? tu : nullptr);
             });
    block_.clear();
  }

 private:
  static constexpr std::size_t block = std::size_t{1} << 16;
  TextOut& out_;
  bool tu_;
  double t_ = 0;                              // the shape factor of the next pixel
  std::vector<std::array<double, 4>> block_;  // x y z T
  Aside aside_;
};

// Pixels not wanted: the picture's layout alone.
struct NoPixels {
  static constexpr bool lays_out = true;
  void shape(double) {}
  void pixel(Vec3) {}
};

// A drawing's picture written without being kept: laid out once for the counts, limits and
// instructions that come first, then walked again for its pixels.
template <class P>
void write_picture(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view,
                   TextOut& out) {
  NoPixels none;
  const DuctPicture p = lay_out(drawing, header, view, none);
  write_head(p, out);
  WrittenPixels pixels(out, p.has_tu());
  lay_out(drawing, header, view, pixels);
  pixels.flush();
  write_tail(p, out);
}

}  // namespace

void write_duct(const DuctPicture& p, TextOut& out) {
  write_head(p, out);
  const bool tu = !p.tu.empty();
  Aside aside;
  put_each(out, p.pixel_count(), pixel_line_most, threads_for(3 * p.pixel_count()), aside,
           [&](char* w, std::size_t k) {
             return pixel_line(w, &p.xyz[3 * k], tu ? &p.tu[2 * k] : nullptr);
           });
  write_tail(p, out);
}

void write_duct(const Drawing3& drawing, const DuctHeader& header, const DuctView& view,
                TextOut& out) {
  write_picture(drawing, header, view, out);
}

void write_duct(const Drawing2& drawing, const DuctHeader& header, Projection projection,
                TextOut& out) {
  write_picture(drawing, header, image_view(projection), out);
}

std::string write_duct(const DuctPicture& picture) {
  StringOut out;
  write_duct(picture, out);
  return out.take_text();
}

}  // namespace igds
