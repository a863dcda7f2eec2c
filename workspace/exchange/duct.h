// DUCT 4.4 picture files (docs/exchange.md, "DUCT 4.4 picture files"): read into a DuctPicture
// (duct_read.cpp), turned into a drawing in space (duct_drawing.cpp), laid out from any drawing
// (duct_layout.cpp) and written (duct_write.cpp). The reader is total: whatever the bytes, it
// returns a picture whose counts all agree or throws DuctError naming the line and what is wrong,
// in time and memory proportional to the file.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/drawing/drawing.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/vec3.h"
#include "workspace/text_out.h"

namespace igds {

// The most pixels, and the most instructions, a picture may hold: counts above are refused before
// anything is allocated for them.
inline constexpr std::size_t duct_max_pixels = 4'000'000;
// The largest picture file read (DISPLAY PICTURE): that many pixels and as many instructions in
// their fields, with TU parameters (88 bytes for the two lines), and room for texts.
inline constexpr std::size_t duct_max_file_bytes = 400u << 20;

// The parts of an instruction code (docs/exchange.md, "The file"), each with its value in the code.
enum class DuctArc : std::uint16_t { line = 0, conic = 512, bezier = 1024 };  // IARC
enum class DuctMark : std::uint16_t {                                         // IMARK
  none = 0,
  cross = 64,  // X
  plus = 128,  // +
  square = 192,
  diamond = 256,
};
enum class DuctPen : std::uint8_t {  // IUPDN
  move = 0,                          // invisible move to the first pixel, visible thereafter
  invisible = 8,                     // all moves invisible
  visible = 16,                      // all moves visible, the first one too
  continued = 24,                    // all visible, from the previous instruction's last pixel
};
enum class DuctDash : std::uint8_t { solid = 0, dashed = 1, chain = 2 };  // IDASH

struct DuctInstruction {
  int colour = 1;  // ICOL / 2048; 0 in pictures without colours
  DuctArc arc = DuctArc::line;
  DuctMark mark = DuctMark::none;
  bool mark_all = false;  // JMARK = 32: every pixel (span ends of arcs), else the first only
  DuctPen pen = DuctPen::move;
  DuctDash dash = DuctDash::solid;
  std::size_t pixels = 0;  // NPIX
  // ICOL + IARC + IMARK + JMARK + IUPDN + IDASH.
  std::int64_t code() const;
  friend bool operator==(const DuctInstruction&, const DuctInstruction&) = default;
};

// The instruction a code stands for (with no pixels), or nullopt when the code does not
// decompose: negative, above 2^31 - 1, IDASH above 2, IARC 1536, IMARK above 256.
std::optional<DuctInstruction> decompose_duct_code(std::int64_t code);

struct DuctText {
  std::size_t pixel = 1;  // J1: the pixel it is written at, 1-based
  int colour = 1;         // J3
  int units = 1;          // J4: 2 height in model units, 1 on paper, 0 a dimension's format
  double angle = 0;       // S1: degrees on the paper
  double height = 3;      // S2: on the paper, mm
  std::string text;       // J2 characters, at most 80
  friend bool operator==(const DuctText&, const DuctText&) = default;
};

struct DuctDimension {
  std::array<std::int64_t, 11> k{};  // K1..K11 (K2 K3 K5 K6 K7 are pixel numbers or 0)
  double t = 0;                      // T1
  friend bool operator==(const DuctDimension&, const DuctDimension&) = default;
};

struct DuctPicture {
  // Line 1 (file name and date), then every line down to the one holding only '*'.
  std::vector<std::string> header;
  std::array<std::int64_t, 10> counters{};  // I1..I10
  std::array<double, 7> reals{};            // R1..R7: x, y, z min and max; projection height
  std::vector<DuctInstruction> instructions;
  std::vector<double> xyz;  // x y z of every pixel, in file order
  std::vector<double> tu;   // T U of every pixel when I1 has its TU part, else empty
  std::vector<DuctText> texts;
  std::vector<DuctDimension> dimensions;

  std::size_t pixel_count() const { return xyz.size() / 3; }
  bool has_tu() const { return counters[0] % 2 == 1; }
  bool has_texts() const { return counters[0] / 2 % 2 == 1; }
  friend bool operator==(const DuctPicture&, const DuctPicture&) = default;
};

// What is wrong with a picture file, and where: typed fields, with an English account in what()
// and the words of a report in reason().
struct DuctError : std::exception {
  enum class Problem {
    no_star,              // no line holding only '*' ends the header
    truncated,            // the file ends where `expected` more lines were due
    not_a_number,         // `found` is not the number the format wants there
    too_many_numbers,     // a line holds more numbers than its format (`expected`)
    version,              // I1 = `got` is not 4..7 (a picture of DUCT 4.3 or later)
    counter,              // counter I`which` = `got` is out of its range
    too_large,            // `got` instructions or pixels, more than the `expected` limit
    code,                 // instruction code `got` does not decompose
    no_pixels,            // an instruction with `got` pixels (at least 1)
    arc_pixels,           // an arc instruction with `got` pixels: not 2n+1 (conic) or 3n+1
                          // (Bézier), or 2n, 3n after IUPDN 24
    nothing_to_continue,  // IUPDN 24 on the first instruction
    pixel_sum,            // I5 = `expected` pixels but the instructions have `got` (so far)
    instruction_count,    // I4 = `expected` instructions, but the line holds a pixel
    only_lines,           // I6 = -2 (only straight lines) but an instruction has arcs
    text_counts,          // `got` texts or dimensions (below 0)
    text_pixel,           // text or dimension at pixel `got`; the picture has `expected`
    text_length,          // a text of `got` characters (0..80)
    trailing,             // something after the end of the picture
  };
  Problem problem;
  std::size_t line = 0;  // 1-based; for truncated the line after the last
  std::string found;
  std::int64_t got = 0, expected = 0;
  int which = 0;

  DuctError(Problem p, std::size_t l) : problem(p), line(l) {}
  const char* what() const noexcept override;
  // "LINE 12: CONIC ARC OF 4 PIXELS (2N+1 OR 2N AFTER IUPDN 24)", for a report.
  std::string reason() const;

 private:
  mutable std::string text_;
};

// Reads a picture (docs/exchange.md, "Reading"): fields as FORTRAN list-directed readers take
// them (blanks or commas between numbers, a record continued on the next line when it is short,
// blank lines skipped) or packed in their fixed columns. Throws DuctError.
DuctPicture read_duct(std::string_view text);

// The size of DUCT's marks in a drawing (device units, half side: an input point's square).
inline constexpr double duct_mark_size = 3;

// The picture as a drawing in space, in instruction order, then its texts:
// - straight lines: a polyline; conic arcs: a rational quadratic chain (conic_spans); Bézier
//   spans: a cubic chain. Each instruction's items have Style{colour (1 if 0), dash} and
//   Identity{Role::line, instruction number}.
// - IUPDN 0 draws from its first pixel; 8 draws nothing but marks; 16 first draws a straight
//   line from the previous instruction's last pixel; 24 starts the curve at that pixel (it is the
//   instruction's first pixel: marks on the first pixel go there).
// - Marks: the first pixel, or with JMARK every pixel (for arcs the span ends), size
//   duct_mark_size, X cross, plus, square, diamond.
// - Texts at their pixels, pen J3 (1 if 0), Identity{Role::label, text number, pixel}; size 1.
//   The drawing has no text angle or paper height: S1 and S2 stay in the DuctPicture.
// - Dimensions are not drawn (their format text is, being a text).
// The picture must be one read_duct accepts (or made by duct_picture); throws
// std::invalid_argument when its pixel counts do not add up.
Drawing3 duct_drawing(const DuctPicture& picture);

// A conic span as rational quadratic Bézier spans (docs/exchange.md, "Conic arcs"): with b the
// bulge factor 2|(M - P0) x (P1 - P0)| / |P1 - P0|^2 and f = 1 + s b^2, the weight of the middle
// control is w = (2 - f)/f and the control C = (2M - fQ)/(2 - f), Q = (P0 + P1)/2, so that the
// curve passes through M at t = 1/2. For f >= 2 (w <= 0: an arc beyond a half ellipse) the same
// curve is given as two spans split at M, controls M -/+ f(P1 - P0)/4, inner weights 1/f, all
// positive. For f <= 0 (the wrong half of the hyperbola), a chord of zero length or numbers that
// overflow: the two lines P0 M and M P1, as straight quadratic spans.
struct ConicSpans {
  int spans = 1;                    // 1 or 2
  std::array<Vec3, 5> controls{};   // 2 spans + 1 controls
  std::array<double, 5> weights{};  // one per control
  bool lines = false;               // the two-lines fallback
};
ConicSpans conic_spans(Vec3 p0, Vec3 m, Vec3 p1, double shape);

// The inverse: the mid point M and the shape factor s of the rational quadratic span P0, C, P1
// with positive weights w0, w1, w2 (s = 0 when M lies on the chord).
struct ConicShape {
  Vec3 mid;
  double shape = 0;
};
ConicShape conic_shape(Vec3 p0, Vec3 c, Vec3 p1, double w0, double w1, double w2);

// What the writer puts in the header and the counters besides the drawing.
struct DuctHeader {
  std::string name;   // line 1: "IGDS PICTURE FILE <name> <date>"
  std::string date;   // e.g. duct_date() of workspace/exchange/dates.h
  std::string title;  // line 2 (title and units); empty: no line 2
};
struct DuctView {
  int axis = 3;                    // I2: axis of projection 1, 2, 3 = X, Y, Z
  double height = 0;               // R7: projection height
  int dimensions = 3;              // I7: 3 a picture in space, 2 in the plane
  std::array<int, 3> projected{};  // I8..I10: non-zero for a projected picture
};

// A drawing as a picture, in item order: a polyline is a straight-line instruction (closed: its
// first point again at the end); a polynomial cubic a Bézier-span instruction; a rational
// quadratic a conic-arc instruction (conic_shape; T carries s, so I1 gets its TU part); a
// rational cubic (only a perspective makes them) straight lines within 1e-5 of the drawing's
// largest extent (workspace/drawing/flatten.h); consecutive marks of one style and shape one
// invisible instruction (IUPDN 8) marking every pixel (a dot as a plus, a circle as a diamond);
// consecutive texts one invisible instruction of their pixels, each text at its pixel, colour the
// pen, on paper at 0 degrees, 3 mm high, at most 80 characters (control characters as '?'). Pens
// below 1 are colour 1; dotted is dashed. Counters: I1 = 4 (+2 texts, +1 TU), I2 = view.axis, I3 =
// -1, I4, I5, I6 = -2 when all instructions are straight lines, I7..I10 from `view`; R1..R6 the box
// of the curves a reader draws from the written pixels (not of their control points), rounded
// outwards to values F10.4's columns hold exactly (docs/exchange.md, "Limits"); R7 = view.height.
// An empty drawing gives one invisible pixel at the origin (a picture always has an instruction).
// Throws DataError (point_not_finite, `number` the item, 1-based) for a point that is not finite.
DuctPicture duct_picture(const Drawing3& drawing, const DuctHeader& header,
                         const DuctView& view = {});
// The picture of an image (a drawing in the plane): its points at z = 0, I7 = 2, I2 = 3 (seen
// along z), I8 = the IGDS projection code of DESIM[2] (1..4).
DuctPicture duct_picture(const Drawing2& drawing, const DuctHeader& header, Projection projection);

// The picture in the fixed formats of the file (docs/exchange.md, "The file"): header lines, " *",
// (1X,10I6), (1X,7F10.4), (1X,I11,1X,I6) per instruction, (3(1X,E14.7)) or
// (3(1X,E14.7),2(1X,F10.4)) per pixel, then texts and dimensions when I1 says so. Lines end in LF.
// Reals stay in their columns at any magnitude, in a form Fw.d reads (fortran::put_f_input). A
// record whose fields touch is written as FORTRAN writes it; when an integer does not fit its
// field, every value of that record follows a blank (list-directed readers read both); a text's
// numbers are brought into their fields so that its string stays in column 51. Whatever read_duct
// returns, this writes a text it reads back.
std::string write_duct(const DuctPicture& picture);
// The same into `out`, made while it is written (a picture may be hundreds of megabytes).
void write_duct(const DuctPicture& picture, TextOut& out);
// write_duct(duct_picture(drawing, header, ...)) into `out`, byte for byte, without the picture
// being kept: once the counts, limits and instructions are laid out and written, its pixels are
// written straight from the drawing's points, on every core. Throws DataError as duct_picture
// does, before writing anything. Returns duct_counts_fit of what it wrote.
bool write_duct(const Drawing3& drawing, const DuctHeader& header, const DuctView& view,
                TextOut& out);
bool write_duct(const Drawing2& drawing, const DuctHeader& header, Projection projection,
                TextOut& out);
// Whether every count of `p` fits its I6 field (the counters I1..I10, each instruction's NPIX,
// the numbers of texts and dimensions), so that DUCT's own fixed formats read the file: a picture
// of a million pixels or more does not (I5), and its counters record is written free-form.
bool duct_counts_fit(const DuctPicture& p);

}  // namespace igds
