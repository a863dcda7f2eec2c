#include "workspace/exchange/iges.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/large_array.h"
#include "workspace/kernels/parallel.h"

namespace igds {

namespace {

// Sequence numbers have 7 digits (IGES 5.3, 2.2.3).
constexpr std::size_t max_sequence = 9'999'999;

[[noreturn]] void too_many_lines(std::size_t lines) {
  DataError e(DataError::Problem::too_many_points);
  e.count = double(lines);
  e.limit = double(max_sequence);
  throw e;
}

// Columns 73-80 of a record: the section letter and the sequence number.
void end_record(std::string& out, char section, std::size_t sequence) {
  if (sequence > max_sequence) too_many_lines(sequence);
  out.push_back(section);
  put_integer(out, std::int64_t(sequence), 7);
  out.push_back('\n');
}

// A Hollerith string (nHtext) of printable characters.
std::string hollerith(std::string_view text) {
  std::string s;
  for (char c : text.substr(0, 60)) s.push_back(c >= 0x20 && c < 0x7F ? c : '?');
  return fmt::format("{}H{}", s.size(), s);
}

// Free-format parameters packed into records of `width` data columns, never splitting a
// parameter: the global section (72 columns) and each entity's parameter lines (64 columns, then
// the pointer back to its directory entry). Each record is made in a buffer and appended whole.
class Records {
 public:
  Records(TextOut& out, char section, std::size_t width, std::size_t first_sequence)
      : out_(out),
        section_(section),
        width_(width),
        sequence_(first_sequence),
        first_(first_sequence) {}

  // Starts an entity's parameters (P section): records end with its DE pointer.
  void begin(std::size_t de) {
    de_ = de;
    first_ = sequence_;
  }
  // A parameter and its delimiter (at most 71 characters together).
  void token(const char* text, std::size_t length, char delimiter) {
    if (used_ > 0 && used_ + length + 1 > width_) finish();
    for (std::size_t k = 0; k < length; ++k) line_[used_ + k] = text[k];
    line_[used_ + length] = delimiter;
    used_ += length + 1;
  }
  void token(std::string_view text, char delimiter = ',') {
    token(text.data(), text.size(), delimiter);
  }
  void integer(std::int64_t v, char delimiter = ',') {
    char buffer[24];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
    token(buffer, std::size_t(end - buffer), delimiter);
  }
  void real(double v, char delimiter = ',') {
    char buffer[32];
    token(buffer, format_real(buffer, v), delimiter);
  }
  // Ends the current record; returns the number of records of the entity (P section).
  std::size_t finish() {
    if (used_ == 0) return sequence_ - first_;
    if (sequence_ > max_sequence) too_many_lines(sequence_);
    for (std::size_t k = used_; k < width_; ++k) line_[k] = ' ';
    std::size_t at = width_;
    if (section_ == 'P') {
      line_[at++] = ' ';
      at = right_justified(at, de_, 7);
    }
    line_[at++] = section_;
    at = right_justified(at, sequence_++, 7);
    line_[at++] = '\n';
    out_.put(std::string_view(line_, at));
    used_ = 0;
    return sequence_ - first_;
  }
  std::size_t next_sequence() const { return sequence_; }
  std::size_t first() const { return first_; }

 private:
  std::size_t right_justified(std::size_t at, std::size_t value, std::size_t width) {
    for (std::size_t k = width; k-- > 0; value /= 10)
      line_[at + k] = value > 0 || k == width - 1 ? char('0' + value % 10) : ' ';
    return at + width;
  }
  TextOut& out_;
  char section_;
  std::size_t width_, used_ = 0, sequence_, de_ = 0, first_;
  char line_[96];
};

struct Entity {
  int type = 0;
  std::size_t parameters = 0;  // first P line
  std::size_t lines = 0;       // P lines
  std::string label;
  int subscript = 0;
};

// One directory entry: two records of nine 8-column fields (IGES 5.3, 2.2.4.4).
void directory_entry(TextOut& out, const Entity& e, std::size_t sequence) {
  std::string records;
  put_integer(records, e.type, 8);
  put_integer(records, std::int64_t(e.parameters), 8);
  for (int k = 0; k < 6; ++k)
    put_integer(records, 0, 8);  // structure, font, level, view, matrix, label
  records += "00000000";         // status: visible, independent, geometry, hierarchy global
  end_record(records, 'D', sequence);
  put_integer(records, e.type, 8);
  put_integer(records, 0, 8);  // line weight
  put_integer(records, 0, 8);  // colour
  put_integer(records, std::int64_t(e.lines), 8);
  put_integer(records, 0, 8);  // form
  records.append(16, ' ');     // reserved
  records.append(8 - std::min<std::size_t>(8, e.label.size()), ' ');
  records.append(e.label, 0, 8);
  put_integer(records, e.subscript, 8);
  end_record(records, 'D', sequence + 1);
  out.put(records);
}

// Knots of Bézier spans of degree 3 on [first, last], one per unit: `first` four times, each
// inner integer three times (the pieces join with C0 only, as the surface does), `last` four
// times.
void knots(Records& p, std::size_t first, std::size_t last) {
  for (int k = 0; k < 4; ++k) p.real(double(first));
  for (std::size_t s = first + 1; s < last; ++s)
    for (int k = 0; k < 3; ++k) p.real(double(s));
  for (int k = 0; k < 4; ++k) p.real(double(last));
}

// Entity 126 of a curve or stringer (surface_curves.h: C2 in the running chord length).
void write_curve(Records& p, const CubicBspline& c) {
  const bool closed = c.controls.front() == c.controls.back();
  p.integer(126);
  p.integer(std::int64_t(c.controls.size()) - 1);  // K: upper index of the controls
  p.integer(3);                                    // M: degree
  p.integer(0);                                    // PROP1: not declared planar
  p.integer(closed ? 1 : 0);                       // PROP2: closed
  p.integer(1);                                    // PROP3: polynomial
  p.integer(0);                                    // PROP4: not periodic
  for (std::size_t k = 0; k < c.knots.size(); ++k)
    for (int m = 0; m < c.multiplicities[k]; ++m) p.real(c.knots[k]);
  for (std::size_t k = 0; k < c.controls.size(); ++k) p.token("1.", 2, ',');  // weights
  for (Vec3 v : c.controls) {
    p.real(v.x);
    p.real(v.y);
    p.real(v.z);
  }
  p.real(c.knots.front());  // V(0)
  p.real(c.knots.back());   // V(1)
  p.token("0.", 2, ',');    // normal (PROP1 = 0: not used)
  p.token("0.", 2, ',');
  p.token("0.", 2, ';');
}

// The texts of the net's numbers as Records::real writes them, a window of the net's rows at a
// time, made on two threads: the bulk of a file, and a control shared by neighbouring patches is
// formatted once.
class NetTexts {
 public:
  explicit NetTexts(const BezierNet& net) : net_(net) {}
  // Makes rows [first, last] ready (and some after them).
  void rows(std::size_t first, std::size_t last) {
    if (first >= lo_ && last < hi_) return;
    lo_ = first;
    hi_ = std::min(net_.rows, std::max(last + 1, first + window));
    const std::size_t n = (hi_ - lo_) * net_.cols * 3;
    text_.resize(n * slot);
    length_.resize(n);
    const double* v = &net_.xyz[3 * lo_ * net_.cols];
    const unsigned threads = n >= 4096 ? std::min(2u, threads_for(std::size_t{1} << 20)) : 1;
    parallel_for(n, threads, [&](std::size_t from, std::size_t to) {
      for (std::size_t k = from; k < to; ++k)
        length_[k] = static_cast<std::uint8_t>(format_real(&text_[k * slot], v[k]));
    });
  }
  // Number `k` (3 per control, x y z) of row `row`, made ready by rows().
  std::string_view at(std::size_t row, std::size_t k) const {
    const std::size_t i = (row - lo_) * net_.cols * 3 + k;
    return {&text_[i * slot], length_[i]};
  }

 private:
  static constexpr std::size_t slot = 32;    // format_real's most
  static constexpr std::size_t window = 25;  // rows: eight rows of patches
  const BezierNet& net_;
  std::size_t lo_ = 0, hi_ = 0;
  std::vector<char> text_;
  std::vector<std::uint8_t> length_;
};

// Entity 128 of the net's rows [row0, row0 + rows) and columns [col0, col0 + cols): the whole
// surface, or one patch, on the parameters [u0, u1] x [v0, v1]; the net's numbers from `texts`.
void write_surface(Records& p, NetTexts& texts, std::size_t row0, std::size_t rows,
                   std::size_t col0, std::size_t cols) {
  const std::size_t u0 = col0 / 3, u1 = u0 + (cols - 1) / 3, v0 = row0 / 3,
                    v1 = v0 + (rows - 1) / 3;
  p.integer(128);
  p.integer(std::int64_t(cols) - 1);  // K1: upper index along u
  p.integer(std::int64_t(rows) - 1);  // K2: along v
  p.integer(3);                       // M1, M2: bicubic
  p.integer(3);
  p.integer(0);  // PROP1, PROP2: not declared closed
  p.integer(0);
  p.integer(1);  // PROP3: polynomial
  p.integer(0);  // PROP4, PROP5: not periodic
  p.integer(0);
  knots(p, u0, u1);
  knots(p, v0, v1);
  for (std::size_t k = 0; k < rows * cols; ++k) p.token("1.", 2, ',');
  // Controls with the first index (u) varying fastest: along the net's rows.
  for (std::size_t r = row0; r < row0 + rows; ++r) {
    texts.rows(r, std::min(r + 3, row0 + rows - 1));
    for (std::size_t k = 3 * col0; k < 3 * (col0 + cols); ++k) p.token(texts.at(r, k));
  }
  p.real(double(u0));
  p.real(double(u1));
  p.real(double(v0));
  p.real(double(v1), ';');
}

}  // namespace

void write_iges(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                TextOut& out, SurfaceForm form) {
  const BezierNet net = surface_net(input, patches);
  const std::size_t nc = std::size_t(input.nocur), ns = std::size_t(input.nostr);
  double largest = 0;
  for (double v : net.xyz) largest = std::max(largest, std::abs(v));
  for (double v : net.xyz)
    if (!std::isfinite(v)) throw DataError(DataError::Problem::patch_not_finite);

  // Start section.
  std::size_t s_lines = 0;
  const std::string start = fmt::format(
      "IGDS surface {}: {} (entity 128), exact, and its input curves and stringers (entity "
      "126). Units mm.",
      header.name,
      form == SurfaceForm::one ? "one bicubic B-spline surface" : "its bicubic patches");
  std::string records;
  for (std::size_t at = 0; at < start.size(); at += 72) {
    const std::string_view piece = std::string_view(start).substr(at, 72);
    records.append(piece);
    records.append(72 - piece.size(), ' ');
    end_record(records, 'S', ++s_lines);
  }
  out.put(records);

  // Global section (IGES 5.3, 2.2.4.3).
  Records g(out, 'G', 72, 1);
  const std::string date = hollerith(iges_date(header.date));
  g.token("1H,");
  g.token("1H;");
  g.token(hollerith(header.name));          // 3 product identification (sender)
  g.token(hollerith(header.file_name));     // 4 file name
  g.token(hollerith("IGDS"));               // 5 native system
  g.token(hollerith("IGDS EXPORT IGES"));   // 6 preprocessor version
  g.integer(32);                            // 7 bits of an integer
  g.integer(38);                            // 8 single precision: largest power of ten
  g.integer(6);                             // 9 ... and significant digits
  g.integer(308);                           // 10 double precision: largest power of ten
  g.integer(15);                            // 11 ... and significant digits
  g.token(hollerith(header.name));          // 12 product identification (receiver)
  g.token("1.");                            // 13 model space scale
  g.integer(2);                             // 14 units: millimetres
  g.token("2HMM");                          // 15 units name
  g.integer(1);                             // 16 line weight gradations
  g.token("1.");                            // 17 width of the heaviest line
  g.token(date);                            // 18 date of this file
  g.real(std::max(largest, 1.0) * 1e-9);    // 19 resolution
  g.real(largest > 0 ? largest : 1.0);      // 20 largest coordinate
  g.token(hollerith(header.author));        // 21 author
  g.token(hollerith(header.organization));  // 22 organization
  g.integer(11);                            // 23 IGES 5.3
  g.integer(0);                             // 24 no drafting standard
  g.token(date, ';');                       // 25 date of the model
  const std::size_t g_lines = g.finish();

  // A curve or stringer whose input points all coincide (a pole) is a point: left out.
  std::vector<std::pair<std::size_t, CubicBspline>> curves, stringers;
  for (std::size_t i = 0; i < nc; ++i)
    if (auto c = input_curve_bspline(net, i)) curves.emplace_back(i + 1, std::move(*c));
  for (std::size_t j = 0; j < ns; ++j)
    if (auto c = input_stringer_bspline(net, j)) stringers.emplace_back(j + 1, std::move(*c));
  const std::size_t entities =
      (form == SurfaceForm::one ? 1 : (nc - 1) * (ns - 1)) + curves.size() + stringers.size();

  // Directory section: 2 records of 81 characters per entity, written once the parameters are.
  const std::uint64_t d_at = out.offset();
  const std::size_t d_lines = 2 * entities;
  out.skip(81 * d_lines);

  // Parameter section.
  std::vector<Entity> list;
  list.reserve(entities);
  Records p(out, 'P', 64, 1);
  auto entity = [&](int type, const char* label, std::size_t subscript, auto&& write) {
    p.begin(2 * list.size() + 1);
    write();
    const std::size_t lines = p.finish();
    list.push_back({type, p.first(), lines, label, int(subscript)});
  };
  NetTexts texts(net);
  if (form == SurfaceForm::one) {
    entity(128, "SURFACE", 0, [&] { write_surface(p, texts, 0, net.rows, 0, net.cols); });
  } else {
    for (std::size_t i = 0; i + 1 < nc; ++i)
      for (std::size_t j = 0; j + 1 < ns; ++j)
        entity(128, "PATCH", i * (ns - 1) + j + 1,
               [&] { write_surface(p, texts, 3 * i, 4, 3 * j, 4); });
  }
  for (const auto& c : curves) entity(126, "CURVE", c.first, [&] { write_curve(p, c.second); });
  for (const auto& c : stringers)
    entity(126, "STRINGER", c.first, [&] { write_curve(p, c.second); });
  const std::size_t p_lines = p.next_sequence() - 1;

  const std::uint64_t end = out.offset();
  out.seek(d_at);
  for (std::size_t e = 0; e < list.size(); ++e) directory_entry(out, list[e], 2 * e + 1);
  out.seek(end);

  // Terminate section.
  records.clear();
  const std::size_t counts[4] = {s_lines, g_lines, d_lines, p_lines};
  const char letters[4] = {'S', 'G', 'D', 'P'};
  for (int k = 0; k < 4; ++k) {
    records.push_back(letters[k]);
    put_integer(records, std::int64_t(counts[k]), 7);
  }
  records.append(40, ' ');
  end_record(records, 'T', 1);
  out.put(records);
}

std::string write_iges(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                       SurfaceForm form) {
  StringOut out;
  write_iges(input, patches, header, out, form);
  return out.take_text();
}

}  // namespace igds
