// A DUCT picture as text, in the fixed formats of the file (docs/exchange.md, "Writing"): a
// picture kept, or a drawing's picture written as it is laid out.
#include <algorithm>
#include <cmath>

#include "workspace/exchange/duct_parts.h"
#include "workspace/numbers/fortran.h"

namespace igds {

namespace {

using duct::trimmed;

// A record of fields with no blank between them ((1X,10I6), (1X,7F10.4), ...): in the fixed
// columns when every value fits its field (reals always do); when an integer does not, every
// value after a blank, so that list-directed readers read it (columns being lost anyway).
class WrittenRecord {
 public:
  void integer(std::int64_t v, int width) {
    fields_.push_back({{}, width});
    fortran::put_i_whole(fields_.back().text, v, 1);
  }
  // A real in its Fw.d columns whatever its magnitude (a point anywhere, an exponent: what Fw.d
  // reads), in the free form only when not finite.
  void fixed(double v, int width, int decimals) {
    fields_.push_back({std::string(std::size_t(width), ' '), width});
    if (!fortran::put_f_input(fields_.back().text.data(), v, width, decimals)) {
      fields_.back().text.clear();
      fortran::put_f_whole(fields_.back().text, v, 1, decimals);
    }
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
// Where it ends; at most pixel_line_most characters, xyz_line_most without T U.
constexpr std::size_t xyz_line_most = 3 * 15 + 1;
constexpr std::size_t pixel_line_most = xyz_line_most + 2 * 27;
char* pixel_line(char* w, const double xyz[3], const double* tu) {
  for (int i = 0; i < 3; ++i) {
    *w++ = ' ';
    w = fortran::put_e_whole(w, xyz[i], 14, 7);
  }
  if (tu) {
    for (int i = 0; i < 2; ++i) {
      *w++ = ' ';
      // (A shape factor is finite: conic_shape's, or read by read_duct.)
      if (fortran::put_f_input(w, tu[i], 10, 4))
        w += 10;
      else
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

// A drawing's picture written without being kept: its counts, limits and instructions, then its
// pixels straight from the drawing's points, lines made on every core (put_each) a group of
// pixels at a time, as many as a TextOut's room holds.
template <class P>
bool write_picture(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view,
                   TextOut& out) {
  const duct::Layout laid = duct::lay_out(drawing, header, view);
  const DuctPicture& p = laid.picture;
  write_head(p, out);
  const bool tu = p.has_tu();
  const std::size_t most = tu ? pixel_line_most : xyz_line_most;
  const std::size_t group = TextOut::max_room / most;
  const std::size_t count = laid.pixels.size();
  put_each(out, (count + group - 1) / group, group * most, [&](char* w, std::size_t k) {
    laid.pixels.each(k * group, std::min(count, (k + 1) * group),
                     [&](const double xyz[3], double shape) {
                       const double t[2] = {shape, 0};
                       w = pixel_line(w, xyz, tu ? t : nullptr);
                     });
    return w;
  });
  write_tail(p, out);
  return duct_counts_fit(p);
}

}  // namespace

bool duct_counts_fit(const DuctPicture& p) {
  auto fits = [](std::int64_t v) { return v >= -99999 && v <= 999999; };
  for (std::int64_t v : p.counters)
    if (!fits(v)) return false;
  for (const DuctInstruction& in : p.instructions)
    if (!fits(std::int64_t(in.pixels))) return false;
  return fits(std::int64_t(p.texts.size())) && fits(std::int64_t(p.dimensions.size()));
}

void write_duct(const DuctPicture& p, TextOut& out) {
  write_head(p, out);
  const bool tu = !p.tu.empty();
  put_each(out, p.pixel_count(), pixel_line_most, [&](char* w, std::size_t k) {
    return pixel_line(w, &p.xyz[3 * k], tu ? &p.tu[2 * k] : nullptr);
  });
  write_tail(p, out);
}

bool write_duct(const Drawing3& drawing, const DuctHeader& header, const DuctView& view,
                TextOut& out) {
  return write_picture(drawing, header, view, out);
}

bool write_duct(const Drawing2& drawing, const DuctHeader& header, Projection projection,
                TextOut& out) {
  return write_picture(drawing, header, duct::image_view(projection), out);
}

std::string write_duct(const DuctPicture& picture) {
  StringOut out;
  write_duct(picture, out);
  return out.take_text();
}

}  // namespace igds
