#include "workspace/exchange/iges.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/interrupt.h"
#include "workspace/kernels/memory.h"
#include "workspace/kernels/parallel.h"
#include "workspace/numbers/decimal.h"
#include "workspace/numbers/fortran.h"

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
  fortran::put_i_whole(out, std::int64_t(sequence), 7);
  out.push_back('\n');
}

// A Hollerith string (nHtext) of printable characters; an empty one is the parameter left out
// (IGES 5.3, 2.2.3: its default), never `0H`.
std::string hollerith(std::string_view text) {
  if (text.empty()) return {};
  std::string s;
  for (char c : text.substr(0, 60)) s.push_back(c >= 0x20 && c < 0x7F ? c : '?');
  return fmt::format("{}H{}", s.size(), s);
}

// Every record is 80 columns and a newline: the S and G sections' 72 data columns, or the P
// section's 64 and its pointer back to the directory (8 columns), then the section letter and
// the sequence number.
constexpr std::size_t record = 81;
// The texts of numbers made ahead are kept in slots of 32 bytes (format_real's most), half a
// million at a time (enough for threads_for to share their making between the cores).
constexpr std::size_t slot = 32;
constexpr std::size_t numbers_at_once = std::size_t{1} << 19;

// Free-format parameters packed into records of `width` data columns, never splitting a
// parameter: the global section (72 columns) and each entity's parameter lines (64 columns, then
// the pointer back to its directory entry). Each record is made where it belongs, in the
// TextOut's room.
class Records {
 public:
  // Records into `out`, numbered from `first_sequence`.
  Records(TextOut& out, char section, std::size_t width, std::size_t first_sequence)
      : out_(&out),
        section_(section),
        width_(width),
        sequence_(first_sequence),
        first_(first_sequence) {}

  // Starts an entity's parameters (P section): records end with its DE pointer.
  void begin(std::size_t de) {
    fortran::put_i_whole(de_, std::int64_t(de), 7);
    first_ = sequence_;
  }
  // A parameter and its delimiter (at most 71 characters together).
  void token(const char* text, std::size_t length, char delimiter) {
    if (used_ > 0 && used_ + length + 1 > width_) finish();
    if (used_ == 0) line_ = out_->room(record + slot);
    std::memcpy(line_ + used_, text, length);
    line_[used_ + length] = delimiter;
    used_ += length + 1;
  }
  void token(std::string_view text, char delimiter = ',') {
    token(text.data(), text.size(), delimiter);
  }
  // The same for a text that starts a slot of `slot` readable bytes, copied whole (a record's
  // room has that much to spare: the bytes after the parameter are written again later).
  void slot_token(std::string_view text, char delimiter = ',') {
    if (used_ > 0 && used_ + text.size() + 1 > width_) finish();
    if (used_ == 0) line_ = out_->room(record + slot);
    used_ = put_slot(line_, used_, text, delimiter);
  }
  // Parameters text(0) .. text(count - 1), each a text that starts a slot (as slot_token's) and
  // followed by a comma: the same records as slot_token would make one by one. Where a record
  // begins depends only on the lengths, so those places are found first; then the current
  // record is completed here, the records wholly of the run are made by put_each (each knows its
  // parameters and its sequence number), and the last one is left open here.
  template <class Text>
  void slot_tokens(std::size_t count, const Text& text) {
    starts_.clear();
    for (std::size_t k = 0, used = used_; k < count; ++k) {
      const std::size_t length = text(k).size() + 1;
      if (used > 0 && used + length > width_) {
        starts_.push_back(k);
        used = 0;
      }
      used += length;
    }
    const std::size_t whole = starts_.empty() ? 0 : starts_.size() - 1;
    std::size_t k = 0;
    if (!starts_.empty()) {
      for (; k < starts_[0]; ++k) slot_token(text(k));
      finish();
      if (whole > 0 && sequence_ + whole - 1 > max_sequence) too_many_lines(max_sequence + 1);
      put_each(*out_, whole, record + slot, [&](char* line, std::size_t r) {
        std::size_t used = 0;
        for (std::size_t j = starts_[r]; j < starts_[r + 1]; ++j)
          used = put_slot(line, used, text(j), ',');
        return end_line(line, used, sequence_ + r);
      });
      sequence_ += whole;
      k = starts_[whole];
    }
    for (; k < count; ++k) slot_token(text(k));
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
    out_->commit(end_line(line_, used_, sequence_++));
    used_ = 0;
    return sequence_ - first_;
  }
  std::size_t next_sequence() const { return sequence_; }
  std::size_t first() const { return first_; }

 private:
  // A slot's text and `delimiter` at column `used` of `line`; returns the columns used.
  static std::size_t put_slot(char* line, std::size_t used, std::string_view text, char delimiter) {
    std::memcpy(line + used, text.data(), slot);
    line[used + text.size()] = delimiter;
    return used + text.size() + 1;
  }
  // The end of record `sequence` whose data fill `used` columns of `line`: blanks, the DE
  // pointer (P section), the section letter and the sequence number; returns where it ends.
  char* end_line(char* line, std::size_t used, std::size_t sequence) const {
    std::memset(line + used, ' ', width_ - used);
    char* w = line + width_;
    if (section_ == 'P') {
      *w++ = ' ';
      w = std::copy_n(de_, 7, w);
    }
    *w++ = section_;
    w = fortran::put_i_whole(w, std::int64_t(sequence), 7);
    *w++ = '\n';
    return w;
  }
  TextOut* out_;
  char section_;
  std::size_t width_, used_ = 0, sequence_, first_;
  char de_[7] = {};  // the DE pointer's columns (P section)
  char* line_ = nullptr;
  std::vector<std::size_t> starts_;  // slot_tokens: where the records begin
};

struct Entity {
  int type = 0;
  std::size_t parameters = 0;  // first P line
  std::size_t lines = 0;       // P lines
  std::string_view label;
  int subscript = 0;
  int form = 0;
  bool dependent = false;  // physically dependent on another entity (a part of the shell)
};

// Puts into `p` the parameters of entities [0, count), the next ones of the file after `list`,
// and adds them to `list`: entity k's written by write(p, k), which returns its type, label and
// subscript; block by block (`block` entities, prepare(first, last) called first). A Ctrl-C
// waiting stops it between blocks.
template <class Prepare, class Write>
void put_entities(Records& p, std::vector<Entity>& list, std::size_t count, std::size_t block,
                  const Prepare& prepare, const Write& write) {
  block = std::max<std::size_t>(block, 1);
  for (std::size_t first = 0; first < count; first += block) {
    check_interrupt();
    const std::size_t last = std::min(count, first + block);
    prepare(first, last);
    for (std::size_t k = first; k < last; ++k) {
      p.begin(2 * list.size() + 1);
      Entity e = write(p, k);
      e.lines = p.finish();
      e.parameters = p.first();
      list.push_back(e);
    }
  }
}

// One directory entry at w: two records of nine 8-column fields (IGES 5.3, 2.2.4.4); where it
// ends (at most directory_most bytes).
constexpr std::size_t directory_most = 512;
char* directory_entry(char* w, const Entity& e, std::size_t sequence) {
  auto end_record = [&](std::size_t n) {
    if (n > max_sequence) too_many_lines(n);
    *w++ = 'D';
    w = fortran::put_i_whole(w, std::int64_t(n), 7);
    *w++ = '\n';
  };
  w = fortran::put_i_whole(w, e.type, 8);
  w = fortran::put_i_whole(w, std::int64_t(e.parameters), 8);
  // Structure, font, level, view, matrix, label.
  for (int k = 0; k < 6; ++k) w = fortran::put_i_whole(w, 0, 8);
  // Status: visible, independent (or physically dependent), geometry, hierarchy global.
  w = std::copy_n(e.dependent ? "00010000" : "00000000", 8, w);
  end_record(sequence);
  w = fortran::put_i_whole(w, e.type, 8);
  w = fortran::put_i_whole(w, 0, 8);  // line weight
  w = fortran::put_i_whole(w, 0, 8);  // colour
  w = fortran::put_i_whole(w, std::int64_t(e.lines), 8);
  w = fortran::put_i_whole(w, e.form, 8);
  w = std::fill_n(w, 16, ' ');  // reserved
  w = std::fill_n(w, 8 - std::min<std::size_t>(8, e.label.size()), ' ');
  w = std::copy_n(e.label.data(), std::min<std::size_t>(8, e.label.size()), w);
  w = fortran::put_i_whole(w, e.subscript, 8);
  end_record(sequence + 1);
  return w;
}

// Knots of Bézier spans of degree 3 on [first, last], one per unit: `first` four times, each
// inner integer three times (the pieces join with C0 only, as the surface does), `last` four
// times.
void knots(Records& p, const IntegerReals& reals, std::size_t first, std::size_t last) {
  for (int k = 0; k < 4; ++k) p.slot_token(reals[first]);
  for (std::size_t s = first + 1; s < last; ++s)
    for (int k = 0; k < 3; ++k) p.slot_token(reals[s]);
  for (int k = 0; k < 4; ++k) p.slot_token(reals[last]);
}

// Numbers' texts made ahead, as Records::real writes them, each at the start of a slot of `slot`
// bytes (for Records::slot_tokens).
class RealTexts {
 public:
  // Room for n texts, left unwritten: each is written by make (or copy) before it is read.
  void resize(std::size_t n) {
    if (text_.capacity() < n * slot) reserve_large(text_, n * slot);
    text_.resize(n * slot);
    length_.resize(n);
  }
  void make(std::size_t k, double v) {
    length_[k] = static_cast<std::uint8_t>(format_real(&text_[k * slot], v));
  }
  // Texts [from, from + n) copied to [to, to + n).
  void copy(std::size_t from, std::size_t to, std::size_t n) {
    std::memmove(&text_[to * slot], &text_[from * slot], n * slot);
    std::memmove(&length_[to], &length_[from], n);
  }
  // Texts k, k + 1, ... as Records::slot_tokens reads them.
  struct From {
    const char* text;
    const std::uint8_t* length;
    std::string_view operator()(std::size_t j) const { return {text + j * slot, length[j]}; }
  };
  From from(std::size_t k) const { return {text_.data() + k * slot, length_.data() + k}; }

 private:
  std::vector<char, UnwrittenAllocator<char>> text_;
  std::vector<std::uint8_t> length_;
};

// The weight of every control, 1 (polynomial), as the text of a slot.
constexpr char one_slot[slot] = "1.";
constexpr std::string_view one(one_slot, 2);

// The texts of a block of curves' numbers, made on all cores before the curves are written: each
// curve's knots as they are written (a knot formatted once, copied for its multiplicity), then its
// controls' coordinates.
class CurveTexts {
 public:
  // The texts of curves [first, last), curve(k) the k-th.
  template <class Curve>
  void make(std::size_t first, std::size_t last, const Curve& curve) {
    first_curve_ = first;
    first_.assign(1, 0);
    for (std::size_t k = first; k < last; ++k)
      first_.push_back(first_.back() + knot_count(curve(k)) + 3 * curve(k).controls.size());
    texts_.resize(first_.back());
    parallel_for(last - first, threads_for(first_.back()), [&](std::size_t from, std::size_t to) {
      for (std::size_t b = from; b < to; ++b) {
        const CubicBspline& c = curve(first + b);
        std::size_t k = first_[b];
        for (std::size_t i = 0; i < c.knots.size(); ++i) {
          texts_.make(k, c.knots[i]);
          for (int m = 1; m < c.multiplicities[i]; ++m) texts_.copy(k, k + std::size_t(m), 1);
          k += std::size_t(c.multiplicities[i]);
        }
        for (Vec3 v : c.controls) {
          texts_.make(k++, v.x);
          texts_.make(k++, v.y);
          texts_.make(k++, v.z);
        }
      }
    });
  }
  // Texts j, j + 1, ... of curve k (j = 0 its first knot).
  RealTexts::From from(std::size_t k, std::size_t j) const {
    return texts_.from(first_[k - first_curve_] + j);
  }
  std::string_view at(std::size_t k, std::size_t j) const { return from(k, j)(0); }
  // The knots of c as they are written, each as many times as its multiplicity.
  static std::size_t knot_count(const CubicBspline& c) {
    std::size_t n = 0;
    for (int m : c.multiplicities) n += std::size_t(m);
    return n;
  }

 private:
  RealTexts texts_;
  std::size_t first_curve_ = 0;
  std::vector<std::size_t> first_;  // each curve's first text
};

// Entity 126 of a curve or stringer (surface_curves.h: C2 in the running chord length): curve k
// of `texts`, c.
void write_curve(Records& p, const CubicBspline& c, const CurveTexts& texts, std::size_t k) {
  const bool closed = c.controls.front() == c.controls.back();
  p.integer(126);
  p.integer(std::int64_t(c.controls.size()) - 1);  // K: upper index of the controls
  p.integer(3);                                    // M: degree
  p.integer(0);                                    // PROP1: not declared planar
  p.integer(closed ? 1 : 0);                       // PROP2: closed
  p.integer(1);                                    // PROP3: polynomial
  p.integer(0);                                    // PROP4: not periodic
  const std::size_t knots = CurveTexts::knot_count(c), n = c.controls.size();
  p.slot_tokens(knots, texts.from(k, 0));
  p.slot_tokens(n, [](std::size_t) { return one; });  // weights
  p.slot_tokens(3 * n, texts.from(k, knots));
  p.slot_token(texts.at(k, 0));          // V(0)
  p.slot_token(texts.at(k, knots - 1));  // V(1)
  p.token("0.", 2, ',');                 // normal (PROP1 = 0: not used)
  p.token("0.", 2, ',');
  p.token("0.", 2, ';');
}

// The texts of the net's numbers, a window of the net's rows at a time (half a million numbers,
// made on all cores): the bulk of a file, and a control shared by neighbouring patches is
// formatted once.
class NetTexts {
 public:
  explicit NetTexts(const BezierNet& net)
      : net_(net), window_(std::max<std::size_t>(1, numbers_at_once / (net.cols * 3))) {}
  // Makes rows [first, last] ready (and some after them); rows already made are kept. Returns
  // the end of the rows ready from `first`.
  std::size_t rows(std::size_t first, std::size_t last) {
    if (first >= lo_ && last < hi_) return hi_;
    const std::size_t row = net_.cols * 3;
    const std::size_t lo = first, hi = std::min(net_.rows, std::max(last + 1, first + window_));
    // Rows [first, hi_) are made: moved to the front, the others made after them.
    const std::size_t kept = first >= lo_ && first < hi_ ? hi_ - first : 0;
    if (kept > 0) texts_.copy((first - lo_) * row, 0, kept * row);
    texts_.resize((hi - lo) * row);
    lo_ = lo;
    hi_ = hi;
    const std::size_t made = kept * row, n = (hi - lo) * row - made;
    const double* v = &net_.xyz[lo * row + made];
    parallel_for(n, threads_for(n), [&](std::size_t from, std::size_t to) {
      for (std::size_t k = from; k < to; ++k) texts_.make(made + k, v[k]);
    });
    return hi_;
  }
  // Numbers k, k + 1, ... (3 per control, x y z) of row `row`, made ready by rows(), and on into
  // the rows after it.
  RealTexts::From from(std::size_t row, std::size_t k) const {
    return texts_.from((row - lo_) * net_.cols * 3 + k);
  }
  std::size_t cols() const { return net_.cols; }

 private:
  const BezierNet& net_;
  const std::size_t window_;  // rows
  std::size_t lo_ = 0, hi_ = 0;
  RealTexts texts_;
};

// Entity 128 of the net's rows [row0, row0 + rows) and columns [col0, col0 + cols): the whole
// surface, or one patch, on the parameters [u0, u1] x [v0, v1]; the net's numbers from `texts`
// (made ready here, unless they are), the knots and parameters from `reals`.
void write_surface(Records& p, NetTexts& texts, const IntegerReals& reals, std::size_t row0,
                   std::size_t rows, std::size_t col0, std::size_t cols) {
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
  knots(p, reals, u0, u1);
  knots(p, reals, v0, v1);
  p.slot_tokens(rows * cols, [](std::size_t) { return one; });  // weights
  // Controls with the first index (u) varying fastest: along the net's rows. Rows of the net's
  // whole width follow each other in `texts`: all those made are one run.
  for (std::size_t r = row0; r < row0 + rows;) {
    const std::size_t ready = texts.rows(r, std::min(r + 3, row0 + rows - 1));
    const std::size_t end = cols == texts.cols() ? std::min(ready, row0 + rows) : r + 1;
    p.slot_tokens((end - r) * cols * 3, texts.from(r, 3 * col0));
    r = end;
  }
  p.slot_token(reals[u0]);
  p.slot_token(reals[u1]);
  p.slot_token(reals[v0]);
  p.slot_token(reals[v1], ';');
}

// Unit flag and name (IGES 5.3, G14 and G15); none has no flag of its own: 3, "see the name".
struct IgesUnit {
  int flag;
  std::string_view name;
};
IgesUnit iges_unit(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::mm:
      return {2, "2HMM"};
    case LengthUnit::cm:
      return {10, "2HCM"};
    case LengthUnit::m:
      return {6, "1HM"};
    case LengthUnit::inch:
      return {1, "2HIN"};
    case LengthUnit::foot:
      return {4, "2HFT"};
    case LengthUnit::none:
      break;
  }
  return {3, "4HNONE"};
}

std::string_view unit_words(LengthUnit unit) {
  constexpr std::string_view words[] = {"millimetres", "centimetres", "metres",
                                        "inches",      "feet",        "none declared"};
  return words[static_cast<int>(unit)];
}

// `text` in records of 72 columns broken between words (a word longer than a record is cut).
void start_records(std::string& records, std::string_view text, std::size_t& lines) {
  while (!text.empty()) {
    std::size_t take = std::min<std::size_t>(text.size(), 72);
    if (take < text.size()) {
      const std::size_t blank = text.substr(0, 73).rfind(' ');
      if (blank != std::string_view::npos && blank > 0) take = blank;
    }
    records.append(text.substr(0, take));
    records.append(72 - take, ' ');
    end_record(records, 'S', ++lines);
    text.remove_prefix(take);
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  }
}

// The shell of the patches (EXPORT's FACES), after the patches (entities 0 .. F-1 of `list`):
// each edge's curve (entity 126, the border's Bézier controls), the vertex list (502), the edge
// list (504), a loop (508) and a face (510) per patch, the open shell (514 form 2). Entities of
// the shell are physically dependent; the shell is the one a reader starts from.
void put_shell(Records& p, std::vector<Entity>& list, const BezierNet& net, const PatchShell& shell,
               const IntegerReals& reals, std::size_t block_bytes) {
  const std::size_t faces = list.size(), ns = (net.cols - 1) / 3 + 1, nc = (net.rows - 1) / 3 + 1;
  const std::size_t edges = shell.along_count() + shell.across_count();
  auto de = [](std::size_t entity) { return std::int64_t(2 * entity + 1); };
  const std::size_t first_edge = faces, vertices = first_edge + edges, edge_list = vertices + 1,
                    first_loop = edge_list + 1, first_face = first_loop + faces;
  // Edge k: along curve i from node j, or along stringer j from node i.
  struct Side {
    bool along;
    std::size_t i, j;
  };
  auto side_of = [&](std::size_t k) {
    return k < shell.along_count()
               ? Side{true, k / (ns - 1), k % (ns - 1)}
               : Side{false, (k - shell.along_count()) / ns, (k - shell.along_count()) % ns};
  };
  put_entities(
      p, list, edges, block_bytes / (20 * record), [](std::size_t, std::size_t) {},
      [&](Records& q, std::size_t k) {
        const Side e = side_of(k);
        const std::size_t from = e.along ? e.j : e.i;
        q.integer(126);
        q.integer(3);  // K: four controls
        q.integer(3);  // M: cubic
        q.integer(0);  // PROP1..4: not declared planar, open, polynomial, not periodic
        q.integer(0);
        q.integer(1);
        q.integer(0);
        for (int m = 0; m < 8; ++m) q.slot_token(reals[m < 4 ? from : from + 1]);
        for (int m = 0; m < 4; ++m) q.token("1.", 2, ',');
        for (int c = 0; c < 4; ++c)
          for (int x = 0; x < 3; ++x)
            q.real(net.xyz[3 * shell.control_index(e.along, e.i, e.j, c) + std::size_t(x)]);
        q.slot_token(reals[from]);
        q.slot_token(reals[from + 1]);
        q.token("0.", 2, ',');
        q.token("0.", 2, ',');
        q.token("0.", 2, ';');
        return Entity{.type = 126, .label = "EDGE", .subscript = int(k + 1), .dependent = true};
      });
  // The vertices: every node of the grid (a pole's nodes stand for one vertex, the others stay
  // unused in the list).
  put_entities(
      p, list, 1, 1, [](std::size_t, std::size_t) {},
      [&](Records& q, std::size_t) {
        q.integer(502);
        q.integer(std::int64_t(nc * ns));
        for (std::size_t n = 0; n < nc * ns; ++n)
          for (int x = 0; x < 3; ++x)
            q.real(net.xyz[3 * ((3 * (n / ns)) * net.cols + 3 * (n % ns)) + std::size_t(x)],
                   n + 1 == nc * ns && x == 2 ? ';' : ',');
        return Entity{.type = 502, .label = "VERTICES", .form = 1, .dependent = true};
      });
  put_entities(
      p, list, 1, 1, [](std::size_t, std::size_t) {},
      [&](Records& q, std::size_t) {
        q.integer(504);
        q.integer(std::int64_t(edges));
        for (std::size_t k = 0; k < edges; ++k) {
          const Side e = side_of(k);
          q.integer(de(first_edge + k));
          q.integer(de(vertices));
          q.integer(std::int64_t(shell.vertex(e.i, e.j)) + 1);
          q.integer(de(vertices));
          q.integer(
              std::int64_t(e.along ? shell.vertex(e.i, e.j + 1) : shell.vertex(e.i + 1, e.j)) + 1,
              k + 1 == edges ? ';' : ',');
        }
        return Entity{.type = 504, .label = "EDGES", .form = 1, .dependent = true};
      });
  // Patch (i, j)'s loop: along its first curve and up its last stringer as the edges run, back
  // along its last curve and down its first stringer against them: counterclockwise in (u, v),
  // and each inner edge used once each way.
  put_entities(
      p, list, faces, block_bytes / (4 * record), [](std::size_t, std::size_t) {},
      [&](Records& q, std::size_t k) {
        const std::size_t i = k / (ns - 1), j = k % (ns - 1);
        const Side sides[4] = {{true, i, j}, {false, i, j + 1}, {true, i + 1, j}, {false, i, j}};
        std::size_t kept = 0;
        for (const Side& e : sides) kept += !shell.degenerate(e.along, e.i, e.j);
        q.integer(508);
        q.integer(std::int64_t(kept));
        std::size_t written = 0;
        for (int n = 0; n < 4; ++n) {
          const Side& e = sides[n];
          if (shell.degenerate(e.along, e.i, e.j)) continue;
          q.integer(0);  // an edge
          q.integer(de(edge_list));
          q.integer(std::int64_t(shell.edge(e.along, e.i, e.j)) + 1);
          q.integer(n < 2 ? 1 : 0);                     // as the edge runs, or against it
          q.integer(0, ++written == kept ? ';' : ',');  // no curve in parameter space
        }
        return Entity{
            .type = 508, .label = "LOOP", .subscript = int(k + 1), .form = 1, .dependent = true};
      });
  put_entities(
      p, list, faces, block_bytes / record, [](std::size_t, std::size_t) {},
      [&](Records& q, std::size_t k) {
        q.integer(510);
        q.integer(de(k));  // the patch
        q.integer(1);      // one loop, the outer one
        q.integer(1);
        q.integer(de(first_loop + k), ';');
        return Entity{
            .type = 510, .label = "FACE", .subscript = int(k + 1), .form = 1, .dependent = true};
      });
  put_entities(
      p, list, 1, 1, [](std::size_t, std::size_t) {},
      [&](Records& q, std::size_t) {
        q.integer(514);
        q.integer(std::int64_t(faces));
        for (std::size_t k = 0; k < faces; ++k) {
          q.integer(de(first_face + k));
          q.integer(1, k + 1 == faces ? ';' : ',');  // the face's normal is the surface's
        }
        return Entity{.type = 514, .label = "SHELL", .form = 2};
      });
}

}  // namespace

double cad_resolution(double largest) {
  return std::max(largest, 1.0) * 1e-12;
}

void write_iges(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                TextOut& out, SurfaceForm form) {
  const BezierNet net = surface_net(input, patches);
  const std::size_t nc = std::size_t(input.nocur), ns = std::size_t(input.nostr);
  if (!std::isfinite(net.largest)) throw DataError(DataError::Problem::patch_not_finite);
  const double largest = net.largest;

  // Start section.
  std::size_t s_lines = 0;
  const std::string start = fmt::format(
      "IGDS surface {}: {} (entity 128), exact, and its input curves and stringers (entity "
      "126) in the group CURVES (entity 402). Units: {}.",
      header.name,
      form == SurfaceForm::one ? "one bicubic B-spline surface"
                               : "its bicubic patches as the faces of one shell (entity 514)",
      unit_words(header.unit));
  std::string records;
  start_records(records, start, s_lines);
  out.put(records);

  // Global section (IGES 5.3, 2.2.4.3).
  Records g(out, 'G', 72, 1);
  const std::string date = hollerith(iges_date(header.date));
  g.token("1H,");
  g.token("1H;");
  g.token(hollerith(header.name));         // 3 product identification (sender)
  g.token(hollerith(header.file_name));    // 4 file name
  g.token(hollerith("IGDS"));              // 5 native system
  g.token(hollerith("IGDS EXPORT IGES"));  // 6 preprocessor version
  g.integer(32);                           // 7 bits of an integer
  g.integer(38);                           // 8 single precision: largest power of ten
  g.integer(6);                            // 9 ... and significant digits
  g.integer(308);                          // 10 double precision: largest power of ten
  g.integer(15);                           // 11 ... and significant digits
  g.token(hollerith(header.name));         // 12 product identification (receiver)
  g.token("1.");                           // 13 model space scale
  const IgesUnit unit = iges_unit(header.unit);
  g.integer(unit.flag);                     // 14 units flag
  g.token(unit.name);                       // 15 units name
  g.integer(1);                             // 16 line weight gradations
  g.token("1.");                            // 17 width of the heaviest line
  g.token(date);                            // 18 date of this file
  g.real(cad_resolution(largest));          // 19 resolution
  g.real(largest > 0 ? largest : 1.0);      // 20 largest coordinate
  g.token(hollerith(header.author));        // 21 author
  g.token(hollerith(header.organization));  // 22 organization
  g.integer(11);                            // 23 IGES 5.3
  g.integer(0);                             // 24 no drafting standard
  g.token(date, ';');                       // 25 date of the model
  const std::size_t g_lines = g.finish();

  // A curve or stringer whose input points all coincide (a pole) is a point: left out.
  const std::vector<std::optional<CubicBspline>> splines = input_bsplines(net);
  std::vector<std::size_t> curves;  // the indices of splines kept
  for (std::size_t k = 0; k < nc + ns; ++k)
    if (splines[k]) curves.push_back(k);
  const std::size_t patch_count = form == SurfaceForm::one ? 1 : (nc - 1) * (ns - 1);
  // FACES: the patches, the edges' curves, the vertex list, the edge list, a loop and a face per
  // patch, and the shell.
  const std::optional<PatchShell> shell =
      form == SurfaceForm::one ? std::nullopt
                               : std::optional<PatchShell>(std::in_place, net, nc, ns);
  const std::size_t edge_count = shell ? shell->along_count() + shell->across_count() : 0;
  const std::size_t shell_entities = shell ? edge_count + 2 + 2 * patch_count + 1 : 0;
  const std::size_t entities = patch_count + shell_entities + curves.size() + 1;

  // Directory section: 2 records of 81 characters per entity, written once the parameters are.
  const std::uint64_t d_at = out.offset();
  const std::size_t d_lines = 2 * entities;
  out.skip(record * d_lines);

  // Parameter section, a few megabytes of text at a time.
  constexpr std::size_t block_bytes = std::size_t{8} << 20;
  std::vector<Entity> list;
  list.reserve(entities);
  Records p(out, 'P', 64, 1);
  NetTexts texts(net);
  const IntegerReals reals(std::max(nc, ns));
  if (form == SurfaceForm::one) {
    p.begin(1);
    write_surface(p, texts, reals, 0, net.rows, 0, net.cols);
    const std::size_t lines = p.finish();
    list.push_back({128, p.first(), lines, "SURFACE", 0});
  } else {
    // A patch's 94 parameters, two or more to a record (none is longer than 25 characters).
    const std::size_t patch_most = (94 / 2) * record;
    put_entities(
        p, list, patch_count, block_bytes / patch_most,
        [&](std::size_t first, std::size_t last) {
          texts.rows(3 * (first / (ns - 1)), 3 * ((last - 1) / (ns - 1)) + 3);
        },
        [&](Records& q, std::size_t k) {
          const std::size_t i = k / (ns - 1), j = k % (ns - 1);
          write_surface(q, texts, reals, 3 * i, 4, 3 * j, 4);
          return Entity{.type = 128, .label = "PATCH", .subscript = int(k + 1), .dependent = true};
        });
    put_shell(p, list, net, *shell, reals, block_bytes);
  }
  // The curves' numbers are made ahead, half a million at a time.
  CurveTexts curve_texts;
  auto curve = [&](std::size_t k) -> const CubicBspline& { return *splines[curves[k]]; };
  put_entities(
      p, list, curves.size(), curves.empty() ? 1 : numbers_at_once / (4 * curve(0).controls.size()),
      [&](std::size_t first, std::size_t last) { curve_texts.make(first, last, curve); },
      [&](Records& q, std::size_t k) {
        const std::size_t index = curves[k];
        write_curve(q, curve(k), curve_texts, k);
        const bool curve = index < nc;
        return Entity{.type = 126,
                      .label = curve ? "CURVE" : "STRINGER",
                      .subscript = int(curve ? index + 1 : index - nc + 1)};
      });
  // The group of the curves: 402 form 7, unordered, without back pointers.
  const std::size_t first_curve = patch_count + shell_entities;
  p.begin(2 * list.size() + 1);
  p.integer(402);
  p.integer(std::int64_t(curves.size()), curves.empty() ? ';' : ',');
  for (std::size_t k = 0; k < curves.size(); ++k)
    p.integer(std::int64_t(2 * (first_curve + k) + 1), k + 1 < curves.size() ? ',' : ';');
  const std::size_t group_lines = p.finish();
  list.push_back({402, p.first(), group_lines, "CURVES", 0, 7});
  const std::size_t p_lines = p.next_sequence() - 1;

  const std::uint64_t end = out.offset();
  out.seek(d_at);
  put_each(out, list.size(), directory_most,
           [&](char* w, std::size_t e) { return directory_entry(w, list[e], 2 * e + 1); });
  out.seek(end);

  // Terminate section.
  records.clear();
  const std::size_t counts[4] = {s_lines, g_lines, d_lines, p_lines};
  const char letters[4] = {'S', 'G', 'D', 'P'};
  for (int k = 0; k < 4; ++k) {
    records.push_back(letters[k]);
    fortran::put_i_whole(records, std::int64_t(counts[k]), 7);
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
