#include "workspace/exchange/step.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <vector>

#include "workspace/exchange/dates.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/data_error.h"
#include "workspace/numbers/decimal.h"

namespace igds {

namespace {

// Entity instances of the exchange structure (ISO 10303-21), numbered in order, made in a string
// that is handed on to `text` whenever it holds more than 64 KB (or kept, with no `text`).
class Instances {
 public:
  Instances(std::string& out, TextOut* text) : out_(out), text_(text) {}
  // Starts instance #n = and returns n.
  std::size_t begin() {
    if (text_ && out_.size() >= (std::size_t{1} << 16)) flush();
    const std::size_t id = next_++;
    ref(id);
    out_ += '=';
    return id;
  }
  std::size_t next() const { return next_; }
  // The next `n` numbers are taken by instances written elsewhere.
  void skip(std::size_t n) { next_ += n; }
  void ref(std::size_t id) {
    char buffer[24];
    out_ += '#';
    out_.append(buffer,
                std::size_t(std::to_chars(buffer, buffer + sizeof buffer, id).ptr - buffer));
  }
  void real(double v) {
    char buffer[32];
    out_.append(buffer, format_real(buffer, v));
  }
  // A string: printable ASCII, apostrophes and backslashes doubled.
  void string(std::string_view s) {
    out_ += '\'';
    for (char c : s) {
      if (!(c >= 0x20 && c < 0x7F)) c = '?';
      if (c == '\'' || c == '\\') out_ += c;
      out_ += c;
    }
    out_ += '\'';
  }
  std::string& out() { return out_; }
  // Hands what is made on to `text`.
  void flush() {
    text_->put(out_);
    out_.clear();
  }

 private:
  std::string& out_;
  TextOut* text_;
  std::size_t next_ = 1;
};

// Instance #id = CARTESIAN_POINT('',(x,y,z)); at w, as Instances writes it; where it ends.
constexpr std::size_t point_line_most = 24 + 21 + 3 * 32 + 5;
char* point_line(char* w, std::size_t id, const double xyz[3]) {
  constexpr std::string_view head = "=CARTESIAN_POINT('',(";
  *w++ = '#';
  w = std::to_chars(w, w + 24, id).ptr;
  w = std::copy(head.begin(), head.end(), w);
  for (int i = 0; i < 3; ++i) {
    w += format_real(w, xyz[i]);
    *w++ = i < 2 ? ',' : ')';
  }
  *w++ = ')';
  *w++ = ';';
  *w++ = '\n';
  return w;
}

char* put_ref(char* w, std::size_t id) {
  *w++ = '#';
  return std::to_chars(w, w + 24, id).ptr;
}
char* put_text(char* w, std::string_view text) {
  return std::copy(text.begin(), text.end(), w);
}

// Instance #id = B_SPLINE_SURFACE_WITH_KNOTS('name',...) of the net's rows [row0, row0 + rows)
// and columns [col0, col0 + cols), the control point of row r and column c being instance
// first_point + r * net_cols + c, listed by u (columns) outside, v (rows) inside; the knots from
// `reals`. Made in three parts: the head, the references, the rest.
struct SurfaceOf {
  std::size_t row0, rows, col0, cols;
};
constexpr std::string_view surface_head_text = "=B_SPLINE_SURFACE_WITH_KNOTS('";
std::size_t surface_head_most(std::string_view name) {
  return 24 + surface_head_text.size() + name.size() + 8;
}
char* surface_head(char* w, std::size_t id, std::string_view name) {
  w = put_ref(w, id);
  w = put_text(w, surface_head_text);
  w = put_text(w, name);
  return put_text(w, "',3,3,(");
}
// References [r0, r1) of column c (counted from col0): the column's opening before its first, its
// closing after its last.
constexpr std::size_t surface_reference_most = 5 + 1 + 21;
char* surface_references(char* w, const SurfaceOf& f, std::size_t c, std::size_t r0, std::size_t r1,
                         std::size_t first_point, std::size_t net_cols) {
  for (std::size_t r = r0; r < r1; ++r) {
    if (r > 0)
      *w++ = ',';
    else
      w = put_text(w, c > 0 ? ",\n  (" : "(");
    w = put_ref(w, first_point + (f.row0 + r) * net_cols + f.col0 + c);
  }
  if (r1 == f.rows) *w++ = ')';
  return w;
}
std::size_t surface_tail_most(const SurfaceOf& f) {
  const std::size_t knots = std::max(f.rows, f.cols) / 3 + 1;
  return 64 + 4 * 34 * knots;
}
char* surface_tail(char* w, const SurfaceOf& f, const IntegerReals& reals) {
  w = put_text(w, "),.UNSPECIFIED.,.F.,.F.,.F.,");
  const std::size_t u0 = f.col0 / 3, u1 = u0 + (f.cols - 1) / 3, v0 = f.row0 / 3,
                    v1 = v0 + (f.rows - 1) / 3;
  // Knot multiplicities (4, 3, ..., 3, 4) or values of Bézier spans on [first, last], one a unit.
  auto knots = [&](std::size_t first, std::size_t last, bool multiplicities) {
    *w++ = '(';
    for (std::size_t k = first; k <= last; ++k) {
      if (k > first) *w++ = ',';
      if (multiplicities)
        *w++ = k == first || k == last ? '4' : '3';
      else
        w = put_text(w, reals[k]);
    }
    *w++ = ')';
  };
  knots(u0, u1, true);
  *w++ = ',';
  knots(v0, v1, true);
  *w++ = ',';
  knots(u0, u1, false);
  *w++ = ',';
  knots(v0, v1, false);
  return put_text(w, ",.UNSPECIFIED.);\n");
}
// The whole instance at w, in at most surface_most bytes.
std::size_t surface_most(std::string_view name, const SurfaceOf& f) {
  return surface_head_most(name) + f.rows * f.cols * surface_reference_most + surface_tail_most(f);
}
char* surface_line(char* w, std::size_t id, std::string_view name, const SurfaceOf& f,
                   std::size_t first_point, std::size_t net_cols, const IntegerReals& reals) {
  w = surface_head(w, id, name);
  for (std::size_t c = 0; c < f.cols; ++c)
    w = surface_references(w, f, c, 0, f.rows, first_point, net_cols);
  return surface_tail(w, f, reals);
}

// A list of `count` references, id(k) the k-th, eight to a line.
template <class Id>
void references(Instances& s, std::size_t count, const Id& id) {
  s.out() += '(';
  for (std::size_t k = 0; k < count; ++k) {
    if (k > 0) s.out() += k % 8 == 0 ? ",\n  " : ",";
    s.ref(id(k));
  }
  s.out() += ')';
}

// The input curves' and stringers' instances as the items of one put_each, curve after curve:
// a curve's control points (CARTESIAN_POINT, an item each), then its B_SPLINE_CURVE_WITH_KNOTS in
// pieces of a bounded size: the head, its references eight at a time (a line of the file each),
// its multiplicities eight at a time, its knots four at a time.
class CurveItems {
 public:
  // A curve: its spline, its name (CURVE or STRINGER, and its number from 1), the instance of its
  // first control point (the curve's own follows its control points).
  struct Curve {
    const CubicBspline* spline;
    bool stringer;
    std::size_t number, first_id;
  };
  explicit CurveItems(std::vector<Curve> curves) : curves_(std::move(curves)) {
    first_item_.reserve(curves_.size() + 1);
    std::size_t items = 0;
    for (const Curve& c : curves_) {
      first_item_.push_back(items);
      const std::size_t n = c.spline->controls.size(), k = c.spline->knots.size();
      items +=
          n + 1 + groups(n, references_per) + groups(k, multiplicities_per) + groups(k, knots_per);
    }
    first_item_.push_back(items);
  }
  std::size_t count() const { return first_item_.back(); }
  static constexpr std::size_t references_per = 8, multiplicities_per = 8, knots_per = 4;
  static constexpr std::string_view tail_text = "),.UNSPECIFIED.);\n";
  // The most bytes of an item: the largest of a point, the head, eight references and what
  // follows them, eight multiplicities, four knots and the end.
  static constexpr std::size_t most =
      std::max({point_line_most, std::size_t{24 + 40 + 40}, 4 + references_per * 22 + 25,
                multiplicities_per * 12 + 3, knots_per * 33 + tail_text.size()});
  // Item k at w; returns where it ends.
  char* item(char* w, std::size_t k) const {
    const std::size_t q = std::size_t(std::upper_bound(first_item_.begin(), first_item_.end(), k) -
                                      first_item_.begin() - 1);
    const Curve& c = curves_[q];
    const CubicBspline& b = *c.spline;
    const std::size_t n = b.controls.size(), knots = b.knots.size();
    std::size_t e = k - first_item_[q];
    if (e < n) {
      const Vec3 v = b.controls[e];
      const double xyz[3] = {v.x, v.y, v.z};
      return point_line(w, c.first_id + e, xyz);
    }
    e -= n;
    if (e == 0) {
      w = put_ref(w, c.first_id + n);
      w = put_text(w, c.stringer ? "=B_SPLINE_CURVE_WITH_KNOTS('STRINGER "
                                 : "=B_SPLINE_CURVE_WITH_KNOTS('CURVE ");
      w = std::to_chars(w, w + 24, c.number).ptr;
      return put_text(w, "',3,(");
    }
    e -= 1;
    if (e < groups(n, references_per)) {
      const std::size_t first = e * references_per, last = std::min(n, first + references_per);
      for (std::size_t t = first; t < last; ++t) {
        if (t > 0) w = put_text(w, t % 8 == 0 ? ",\n  " : ",");
        w = put_ref(w, c.first_id + t);
      }
      if (last < n) return w;
      w = put_text(w, "),.UNSPECIFIED.,");
      w = put_text(w, b.controls.front() == b.controls.back() ? ".T." : ".F.");
      return put_text(w, ",.F.,(");
    }
    e -= groups(n, references_per);
    if (e < groups(knots, multiplicities_per)) {
      const std::size_t first = e * multiplicities_per,
                        last = std::min(knots, first + multiplicities_per);
      for (std::size_t t = first; t < last; ++t) {
        if (t > 0) *w++ = ',';
        w = std::to_chars(w, w + 12, b.multiplicities[t]).ptr;
      }
      return last < knots ? w : put_text(w, "),(");
    }
    e -= groups(knots, multiplicities_per);
    const std::size_t first = e * knots_per, last = std::min(knots, first + knots_per);
    for (std::size_t t = first; t < last; ++t) {
      if (t > 0) *w++ = ',';
      w += format_real(w, b.knots[t]);
    }
    return last < knots ? w : put_text(w, tail_text);
  }

 private:
  static std::size_t groups(std::size_t n, std::size_t per) { return (n + per - 1) / per; }
  std::vector<Curve> curves_;
  std::vector<std::size_t> first_item_;  // of each curve, and the count after the last
};

}  // namespace

void write_step(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                TextOut& text, SurfaceForm form) {
  const BezierNet net = surface_net(input, patches);
  const std::size_t nc = std::size_t(input.nocur), ns = std::size_t(input.nostr);
  if (!std::isfinite(net.largest)) throw DataError(DataError::Problem::patch_not_finite);

  std::string out;
  out.reserve(std::size_t{1} << 17);
  Instances s(out, &text);
  out += "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((";
  s.string("IGDS surface " + header.name);
  out += "),'2;1');\nFILE_NAME(";
  s.string(header.file_name);
  out += ',';
  s.string(iso_date(header.date));
  out += ",(";
  s.string(header.author);
  out += "),(";
  s.string(header.organization);
  out += "),'IGDS','IGDS EXPORT STEP','');\n";
  out += "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n";

  // The product: a part of one shape (AP214's smallest product structure).
  const std::size_t application = s.begin();
  out += "APPLICATION_CONTEXT('automotive design');\n";
  s.begin();
  out += "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,";
  s.ref(application);
  out += ");\n";
  const std::size_t product_context = s.begin();
  out += "PRODUCT_CONTEXT('',";
  s.ref(application);
  out += ",'mechanical');\n";
  const std::size_t product = s.begin();
  out += "PRODUCT(";
  s.string(header.name);
  out += ',';
  s.string(header.name);
  out += ",'',(";
  s.ref(product_context);
  out += "));\n";
  s.begin();
  out += "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(";
  s.ref(product);
  out += "));\n";
  const std::size_t formation = s.begin();
  out += "PRODUCT_DEFINITION_FORMATION('','',";
  s.ref(product);
  out += ");\n";
  const std::size_t definition_context = s.begin();
  out += "PRODUCT_DEFINITION_CONTEXT('part definition',";
  s.ref(application);
  out += ",'design');\n";
  const std::size_t definition = s.begin();
  out += "PRODUCT_DEFINITION('design','',";
  s.ref(formation);
  out += ',';
  s.ref(definition_context);
  out += ");\n";
  const std::size_t shape = s.begin();
  out += "PRODUCT_DEFINITION_SHAPE('','',";
  s.ref(definition);
  out += ");\n";

  // The length unit (none: the context has none, nor a length uncertainty, which needs one),
  // the angles' units, the uncertainty, the geometric context.
  std::size_t length_unit = 0;
  auto si_length = [&](std::string_view prefix) {
    const std::size_t id = s.begin();
    out += "(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(";
    out += prefix;
    out += ",.METRE.));\n";
    return id;
  };
  // A unit defined by its length in millimetres (ISO 10303-41 conversion_based_unit).
  auto converted = [&](std::string_view name, std::string_view millimetres) {
    const std::size_t mm = si_length(".MILLI.");
    const std::size_t measure = s.begin();
    out += "LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(";
    out += millimetres;
    out += "),";
    s.ref(mm);
    out += ");\n";
    const std::size_t dimensions = s.begin();
    out += "DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n";
    const std::size_t id = s.begin();
    out += "(CONVERSION_BASED_UNIT(";
    s.string(name);
    out += ',';
    s.ref(measure);
    out += ")LENGTH_UNIT()NAMED_UNIT(";
    s.ref(dimensions);
    out += "));\n";
    return id;
  };
  switch (header.unit) {
    case LengthUnit::mm:
      length_unit = si_length(".MILLI.");
      break;
    case LengthUnit::cm:
      length_unit = si_length(".CENTI.");
      break;
    case LengthUnit::m:
      length_unit = si_length("$");
      break;
    case LengthUnit::inch:
      length_unit = converted("INCH", "25.4");
      break;
    case LengthUnit::foot:
      length_unit = converted("FOOT", "304.8");
      break;
    case LengthUnit::none:
      break;
  }
  const std::size_t radian = s.begin();
  out += "(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n";
  const std::size_t steradian = s.begin();
  out += "(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT());\n";
  std::size_t uncertainty = 0;
  if (length_unit != 0) {
    uncertainty = s.begin();
    out += "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(";
    s.real(cad_resolution(net.largest));
    out += "),";
    s.ref(length_unit);
    out += ",'distance_accuracy_value','');\n";
  }
  const std::size_t context = s.begin();
  out += "(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((";
  if (uncertainty != 0) s.ref(uncertainty);
  out += "))GLOBAL_UNIT_ASSIGNED_CONTEXT((";
  if (length_unit != 0) {
    s.ref(length_unit);
    out += ',';
  }
  s.ref(radian);
  out += ',';
  s.ref(steradian);
  out += "))REPRESENTATION_CONTEXT('',''));\n";

  // The net's control points, row by row: the bulk of the file (text_out.h's put_each).
  const std::size_t first_point = s.next(), points = net.rows * net.cols;
  s.flush();
  put_each(text, points, point_line_most,
           [&](char* w, std::size_t k) { return point_line(w, first_point + k, &net.xyz[3 * k]); });
  s.skip(points);

  std::size_t surface = 0, first_face = 0, faces = 0;  // the one surface, or the faces
  const IntegerReals reals(std::max(nc, ns));
  if (form == SurfaceForm::one) {
    // One instance of millions of references, made like the points, eight references an item.
    const SurfaceOf whole{0, net.rows, 0, net.cols};
    surface = s.next();
    s.skip(1);
    std::size_t size = out.size();
    out.resize(size + surface_head_most("SURFACE"));
    out.resize(std::size_t(surface_head(out.data() + size, surface, "SURFACE") - out.data()));
    s.flush();
    const std::size_t per_column = (net.rows + 7) / 8;
    put_each(text, net.cols * per_column, 8 * surface_reference_most, [&](char* w, std::size_t k) {
      const std::size_t c = k / per_column, r = 8 * (k % per_column);
      return surface_references(w, whole, c, r, std::min(net.rows, r + 8), first_point, net.cols);
    });
    size = out.size();
    out.resize(size + surface_tail_most(whole));
    out.resize(std::size_t(surface_tail(out.data() + size, whole, reals) - out.data()));
  } else {
    // One instance per patch, made like the points.
    const std::size_t first_patch = s.next(), count = (nc - 1) * (ns - 1);
    const std::size_t most = surface_most("PATCH 18446744073709551615", {0, 4, 0, 4});
    s.flush();
    put_each(text, count, most, [&](char* w, std::size_t k) {
      char name[32] = "PATCH ";
      const std::size_t length =
          std::size_t(std::to_chars(name + 6, name + sizeof name, k + 1).ptr - name);
      return surface_line(w, first_patch + k, std::string_view(name, length),
                          {3 * (k / (ns - 1)), 4, 3 * (k % (ns - 1)), 4}, first_point, net.cols,
                          reals);
    });
    s.skip(count);

    // The shell: vertices, edges (a curve and an EDGE_CURVE each, along the curves then along
    // the stringers), faces (four ORIENTED_EDGEs, a loop, a bound, the face each), made like
    // the points.
    const PatchShell shell(net, nc, ns);
    const std::size_t first_vertex = s.next();
    s.flush();
    put_each(text, nc * ns, 64, [&](char* w, std::size_t k) {
      w = put_ref(w, first_vertex + k);
      w = put_text(w, "=VERTEX_POINT('',");
      w = put_ref(w, first_point + (3 * (k / ns)) * net.cols + 3 * (k % ns));
      return put_text(w, ");\n");
    });
    s.skip(nc * ns);
    const std::size_t first_edge = s.next(), edges = shell.along_count() + shell.across_count();
    auto edge_id = [&](bool along, std::size_t i, std::size_t j) {
      return first_edge + 2 * shell.edge(along, i, j) + 1;
    };
    put_each(text, edges, 256 + 4 * 34, [&](char* w, std::size_t k) {
      const bool along = k < shell.along_count();
      const std::size_t e = along ? k : k - shell.along_count();
      const std::size_t i = along ? e / (ns - 1) : e / ns, j = along ? e % (ns - 1) : e % ns;
      const std::size_t curve = first_edge + 2 * k;
      w = put_ref(w, curve);
      w = put_text(w, "=B_SPLINE_CURVE_WITH_KNOTS('',3,(");
      for (int c = 0; c < 4; ++c) {
        if (c > 0) *w++ = ',';
        w = put_ref(w, first_point + shell.control_index(along, i, j, c));
      }
      w = put_text(w, "),.UNSPECIFIED.,.F.,.F.,(4,4),(");
      const std::size_t from = along ? j : i;
      w = put_text(w, reals[from]);
      *w++ = ',';
      w = put_text(w, reals[from + 1]);
      w = put_text(w, "),.UNSPECIFIED.);\n");
      w = put_ref(w, curve + 1);
      w = put_text(w, "=EDGE_CURVE('',");
      w = put_ref(w, first_vertex + shell.vertex(i, j));
      *w++ = ',';
      w = put_ref(w, first_vertex + (along ? shell.vertex(i, j + 1) : shell.vertex(i + 1, j)));
      *w++ = ',';
      w = put_ref(w, curve);
      return put_text(w, ",.T.);\n");
    });
    s.skip(2 * edges);
    // Patch (i, j): along its first curve (forward), up its last stringer (forward), back along
    // its last curve and down its first stringer (reversed): counterclockwise in (u, v), so the
    // face's normal is the surface's, and each inner edge is used once each way.
    first_face = s.next();
    faces = count;
    put_each(text, count, 7 * 96 + 64, [&](char* w, std::size_t k) {
      const std::size_t i = k / (ns - 1), j = k % (ns - 1), id = first_face + 7 * k;
      const struct {
        bool along;
        std::size_t i, j;
        bool forward;
      } sides[4] = {{true, i, j, true},
                    {false, i, j + 1, true},
                    {true, i + 1, j, false},
                    {false, i, j, false}};
      std::size_t used[4], n = 0;
      for (int side = 0; side < 4; ++side) {
        const auto& e = sides[side];
        w = put_ref(w, id + std::size_t(side));
        w = put_text(w, "=ORIENTED_EDGE('',*,*,");
        w = put_ref(w, edge_id(e.along, e.i, e.j));
        w = put_text(w, e.forward ? ",.T.);\n" : ",.F.);\n");
        if (!shell.degenerate(e.along, e.i, e.j)) used[n++] = id + std::size_t(side);
      }
      w = put_ref(w, id + 4);
      w = put_text(w, "=EDGE_LOOP('',(");
      for (std::size_t m = 0; m < n; ++m) {
        if (m > 0) *w++ = ',';
        w = put_ref(w, used[m]);
      }
      w = put_text(w, "));\n");
      w = put_ref(w, id + 5);
      w = put_text(w, "=FACE_OUTER_BOUND('',");
      w = put_ref(w, id + 4);
      w = put_text(w, ",.T.);\n");
      w = put_ref(w, id + 6);
      w = put_text(w, "=ADVANCED_FACE('PATCH ");
      w = std::to_chars(w, w + 24, k + 1).ptr;
      w = put_text(w, "',(");
      w = put_ref(w, id + 5);
      w = put_text(w, "),");
      w = put_ref(w, first_patch + k);
      return put_text(w, ",.T.);\n");
    });
    s.skip(7 * count);
  }

  // The curves and stringers: their instances numbered ahead (the list of items needs their
  // numbers first), then made in order.
  const std::vector<std::optional<CubicBspline>> splines = input_bsplines(net);
  std::vector<CurveItems::Curve> curves;
  std::vector<std::size_t> curve_items;
  for (std::size_t k = 0; k < nc + ns; ++k) {
    if (!splines[k]) continue;
    curves.push_back({&*splines[k], k >= nc, k < nc ? k + 1 : k - nc + 1, s.next()});
    s.skip(splines[k]->controls.size());
    curve_items.push_back(s.next());
    s.skip(1);
  }
  s.flush();
  const CurveItems made(std::move(curves));
  put_each(text, made.count(), CurveItems::most,
           [&](char* w, std::size_t k) { return made.item(w, k); });

  const std::size_t origin = s.begin();
  out += "CARTESIAN_POINT('',(0.,0.,0.));\n";
  const std::size_t z = s.begin();
  out += "DIRECTION('',(0.,0.,1.));\n";
  const std::size_t x = s.begin();
  out += "DIRECTION('',(1.,0.,0.));\n";
  const std::size_t placement = s.begin();
  out += "AXIS2_PLACEMENT_3D('',";
  s.ref(origin);
  out += ',';
  s.ref(z);
  out += ',';
  s.ref(x);
  out += ");\n";
  // A representation of `parts` (and the placement) for the product's shape.
  auto representation = [&](std::string_view type, const std::vector<std::size_t>& parts) {
    const std::size_t id = s.begin();
    out += type;
    out += '(';
    s.string(header.name);
    out += ",(";
    for (std::size_t part : parts) {
      s.ref(part);
      out += ',';
    }
    s.ref(placement);
    out += "),";
    s.ref(context);
    out += ");\n";
    s.begin();
    out += "SHAPE_DEFINITION_REPRESENTATION(";
    s.ref(shape);
    out += ',';
    s.ref(id);
    out += ");\n";
  };
  if (faces == 0) {
    const std::size_t set = s.begin();
    out += "GEOMETRIC_SET('surface',";
    references(s, 1, [&](std::size_t) { return surface; });
    out += ");\n";
    representation("GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION", {set});
  } else {
    const std::size_t shell = s.begin();
    out += "OPEN_SHELL('surface',";
    references(s, faces, [&](std::size_t k) { return first_face + 7 * k + 6; });
    out += ");\n";
    const std::size_t model = s.begin();
    out += "SHELL_BASED_SURFACE_MODEL('surface',(";
    s.ref(shell);
    out += "));\n";
    representation("MANIFOLD_SURFACE_SHAPE_REPRESENTATION", {model});
  }
  // The input curves apart, named, so that a CAD system keeps them as a group of their own.
  if (!curve_items.empty()) {
    const std::size_t curve_set = s.begin();
    out += "GEOMETRIC_CURVE_SET('input curves',";
    references(s, curve_items.size(), [&](std::size_t k) { return curve_items[k]; });
    out += ");\n";
    representation("GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION", {curve_set});
  }
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  s.flush();
}

std::string write_step(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                       SurfaceForm form) {
  StringOut out;
  write_step(input, patches, header, out, form);
  return out.take_text();
}

}  // namespace igds
