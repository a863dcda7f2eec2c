#include "workspace/exchange/cad_read.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>

#include <fmt/format.h>

#include "workspace/numbers/fortran.h"

namespace igds {

namespace {

[[noreturn]] void fail(std::string reason) {
  throw CadReadError(reason);
}

// A real as IGES and STEP write it, blanks around it allowed: a FORTRAN real (an optional sign,
// digits with or without a point, an exponent written E or D in either case), finite.
std::optional<double> parse_real(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return fortran::read_real(s);
}

std::optional<long long> parse_whole(std::string_view s) {
  const auto v = parse_real(s);
  if (!v || std::floor(*v) != *v || std::abs(*v) > 1e15) return std::nullopt;
  return static_cast<long long>(*v);
}

// The checks every surface gets, whichever file it came from: degrees, counts, knots
// non-decreasing with no knot more often than degree + 1 inside, weights positive, the
// parameter range within the knots' valid span.
void check_surface(CadSurface& s) {
  auto check_direction = [](const char* d, int degree, std::size_t count,
                            const std::vector<double>& knots, double& first, double& last) {
    if (degree < 1 || degree > 25) fail(fmt::format("DEGREE {} IN {} (1 TO 25)", degree, d));
    if (count < std::size_t(degree) + 1)
      fail(fmt::format("{} CONTROLS IN {} FOR DEGREE {}", count, d, degree));
    if (knots.size() != count + std::size_t(degree) + 1)
      fail(fmt::format("{} KNOTS IN {}, NOT {}", knots.size(), d, count + std::size_t(degree) + 1));
    for (std::size_t k = 1; k < knots.size(); ++k)
      if (!(knots[k] >= knots[k - 1])) fail(fmt::format("THE KNOTS IN {} DECREASE", d));
    const double low = knots[std::size_t(degree)], high = knots[count];
    if (!(high > low)) fail(fmt::format("THE KNOTS IN {} SPAN NOTHING", d));
    if (!(first < last)) {
      first = low;
      last = high;
    }
    first = std::max(first, low);
    last = std::min(last, high);
    if (!(first < last)) fail(fmt::format("THE PARAMETER RANGE IN {} IS OUTSIDE THE KNOTS", d));
  };
  check_direction("U", s.degree_u, s.count_u, s.knots_u, s.u0, s.u1);
  check_direction("V", s.degree_v, s.count_v, s.knots_v, s.v0, s.v1);
  for (const Vec3& c : s.controls)
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
      fail("A CONTROL POINT IS NOT FINITE");
  if (!s.weights.empty()) {
    for (double w : s.weights)
      if (!(w > 0) || !std::isfinite(w)) fail("A WEIGHT IS NOT POSITIVE");
    if (std::all_of(s.weights.begin(), s.weights.end(), [](double w) { return w == 1; }))
      s.weights.clear();
  }
}

// Controls count_u x count_v, checked against the text that holds them (IGES: the entity's
// parameters; STEP: the file) before anything is allocated: every control takes at least
// `least` bytes of it.
void check_counts(std::size_t count_u, std::size_t count_v, std::size_t file_bytes,
                  std::size_t least) {
  if (count_u == 0 || count_v == 0 || count_u > cad_max_controls ||
      count_v > cad_max_controls / count_u)
    fail(fmt::format("{} X {} CONTROLS (AT MOST {} IN ALL)", count_u, count_v, cad_max_controls));
  if (count_u * count_v > file_bytes / least)
    fail(fmt::format("{} X {} CONTROLS CANNOT BE IN {} BYTES", count_u, count_v, file_bytes));
}

}  // namespace

// IGES: the D section's first entity 128, its parameters from the P section (free format, the
// delimiters of the G section).
CadSurface read_iges_surface(std::string_view text) {
  // The sections' data, by letter: the lines' first 72 columns (P: 64), in order.
  std::string g, d;
  std::vector<std::string_view> p;
  std::size_t line_number = 0;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    at = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty()) continue;
    if (line.size() < 73)
      fail(fmt::format("LINE {}: {} COLUMNS, AN IGES RECORD HAS 80", line_number, line.size()));
    const char section = line[72];
    if (section == 'G')
      g.append(line.substr(0, 72));
    else if (section == 'D')
      d.append(line.substr(0, 72)), d.push_back('\n');
    else if (section == 'P')
      p.push_back(line.substr(0, 64));
    else if (section != 'S' && section != 'T')
      fail(fmt::format("LINE {}: SECTION LETTER '{}' IS NOT S, G, D, P OR T", line_number,
                       std::isprint(static_cast<unsigned char>(section)) ? section : '?'));
  }
  if (g.empty() || d.empty() || p.empty()) fail("NOT AN IGES FILE (NO G, D OR P SECTION)");
  // The delimiters: G's first two parameters, `1H,` and `1H;` unless the file says otherwise.
  char delimiter = ',', end_mark = ';';
  std::size_t g_at = 0;
  auto g_delimiter = [&](char& out) {
    if (g.compare(g_at, 2, "1H") == 0 && g.size() > g_at + 3) {
      out = g[g_at + 2];
      g_at += 3;
    }
    if (g_at < g.size() && (g[g_at] == delimiter || g[g_at] == end_mark)) ++g_at;
  };
  g_delimiter(delimiter);
  g_delimiter(end_mark);
  if (delimiter == end_mark || delimiter == ' ' || end_mark == ' ')
    fail("THE G SECTION'S DELIMITERS ARE NOT TWO DIFFERENT CHARACTERS");

  // The first directory entry of type 128 (two lines of nine 8-column fields).
  std::size_t first = 0, lines = 0;
  const std::size_t entries = std::count(d.begin(), d.end(), '\n') / 2;
  for (std::size_t e = 0; e < entries; ++e) {
    const std::string_view one(&d[(2 * e) * 73], 72), two(&d[(2 * e + 1) * 73], 72);
    const auto type = parse_whole(one.substr(0, 8));
    if (!type) fail(fmt::format("DIRECTORY ENTRY {}: NO ENTITY TYPE", e + 1));
    if (*type != 128) continue;
    const auto pointer = parse_whole(one.substr(8, 8)), count = parse_whole(two.substr(24, 8));
    if (!pointer || !count || *pointer < 1 || *count < 1 || std::size_t(*pointer) > p.size() ||
        std::size_t(*count) > p.size() - std::size_t(*pointer) + 1)
      fail(fmt::format("DIRECTORY ENTRY {}: ITS PARAMETER LINES ARE NOT IN THE FILE", e + 1));
    first = std::size_t(*pointer);
    lines = std::size_t(*count);
    break;
  }
  if (lines == 0) fail("NO B-SPLINE SURFACE (ENTITY 128) IN THE FILE");

  // The parameters, up to the end mark.
  std::string data;
  for (std::size_t k = first; k < first + lines; ++k) data.append(p[k - 1]);
  std::vector<std::string_view> params;
  const std::string_view all(data);
  for (std::size_t at = 0;;) {
    const std::size_t next = all.find_first_of(std::string{delimiter, end_mark}, at);
    if (next == std::string_view::npos) fail("ENTITY 128'S PARAMETERS DO NOT END");
    params.push_back(all.substr(at, next - at));
    at = next + 1;
    if (all[next] == end_mark) break;
  }
  std::size_t next = 0;
  auto whole = [&](const char* what) {
    if (next >= params.size()) fail(fmt::format("ENTITY 128 ENDS BEFORE {}", what));
    const auto v = parse_whole(params[next++]);
    if (!v) fail(fmt::format("ENTITY 128: {} IS NOT A WHOLE NUMBER", what));
    return *v;
  };
  auto real = [&](const char* what) {
    if (next >= params.size()) fail(fmt::format("ENTITY 128 ENDS BEFORE {}", what));
    const auto v = parse_real(params[next++]);
    if (!v) fail(fmt::format("ENTITY 128: {} IS NOT A NUMBER", what));
    return *v;
  };
  if (whole("ITS TYPE") != 128) fail("ENTITY 128'S PARAMETERS ARE OF ANOTHER ENTITY");
  const long long k1 = whole("K1"), k2 = whole("K2"), m1 = whole("M1"), m2 = whole("M2");
  if (k1 < 0 || k2 < 0 || m1 < 1 || m2 < 1 || m1 > 25 || m2 > 25)
    fail(fmt::format("ENTITY 128: K1 {} K2 {} M1 {} M2 {}", k1, k2, m1, m2));
  CadSurface s;
  s.degree_u = int(m1);
  s.degree_v = int(m2);
  if (k1 + 1 > (long long)cad_max_controls || k2 + 1 > (long long)cad_max_controls)
    fail(fmt::format("ENTITY 128: {} X {} CONTROLS", k1 + 1, k2 + 1));
  s.count_u = std::size_t(k1 + 1);
  s.count_v = std::size_t(k2 + 1);
  // Each control takes four parameters (weight, x, y, z), each at least two bytes.
  check_counts(s.count_u, s.count_v, data.size(), 8);
  const std::size_t controls = s.count_u * s.count_v;
  const std::size_t needed =
      10 + (s.count_u + s.count_v + std::size_t(m1 + m2) + 2) + 4 * controls + 4;
  if (params.size() < needed)
    fail(fmt::format("ENTITY 128 HAS {} PARAMETERS, NOT {}", params.size(), needed));
  for (int k = 0; k < 5; ++k) whole("PROP");
  const bool polynomial = parse_whole(params[7]) == 1;  // PROP3
  for (std::size_t k = 0; k < s.count_u + std::size_t(m1) + 1; ++k)
    s.knots_u.push_back(real("A KNOT"));
  for (std::size_t k = 0; k < s.count_v + std::size_t(m2) + 1; ++k)
    s.knots_v.push_back(real("A KNOT"));
  s.weights.resize(controls);
  for (double& w : s.weights) w = real("A WEIGHT");
  if (polynomial) s.weights.clear();
  s.controls.resize(controls);
  for (Vec3& c : s.controls) {
    c.x = real("A CONTROL");
    c.y = real("A CONTROL");
    c.z = real("A CONTROL");
  }
  s.u0 = real("U0");
  s.u1 = real("U1");
  s.v0 = real("V0");
  s.v1 = real("V1");
  check_surface(s);
  return s;
}

namespace {

// A STEP parameter: a number, a reference, a string, an enumeration, $ or *, a list, or a typed
// value (NAME(value)).
struct StepValue {
  enum Kind { number, reference, string, enumeration, unset, list, typed } kind = unset;
  double value = 0;
  std::size_t id = 0;
  std::string_view text;  // string, enumeration, the type of a typed value
  std::vector<StepValue> items;
};

// Reads the parameters of one instance, from just after its '(' to the matching ')'. Nesting is
// bounded (`depth`), so a forged file cannot exhaust the stack.
class StepParser {
 public:
  explicit StepParser(std::string_view text) : text_(text) {}
  std::vector<StepValue> list() {
    std::vector<StepValue> items;
    skip_blanks();
    if (peek() == ')') {
      ++at_;
      return items;
    }
    for (;;) {
      items.push_back(value());
      skip_blanks();
      const char c = take();
      if (c == ')') return items;
      if (c != ',') fail(fmt::format("STEP: '{}' WHERE ',' OR ')' WAS DUE", printable(c)));
    }
  }
  std::size_t at() const { return at_; }

 private:
  StepValue value() {
    skip_blanks();
    StepValue v;
    const char c = peek();
    if (c == '(') {
      ++at_;
      if (++depth_ > 16) fail("STEP: LISTS NESTED TOO DEEPLY");
      v.kind = StepValue::list;
      v.items = list();
      --depth_;
    } else if (c == '#') {
      ++at_;
      const std::size_t start = at_;
      while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_]))) ++at_;
      std::uint64_t id = 0;
      const auto [end, ec] = std::from_chars(text_.data() + start, text_.data() + at_, id);
      if (ec != std::errc() || start == at_) fail("STEP: A REFERENCE WITHOUT A NUMBER");
      v.kind = StepValue::reference;
      v.id = std::size_t(id);
    } else if (c == '\'') {
      ++at_;
      const std::size_t start = at_;
      for (;;) {
        if (at_ >= text_.size()) fail("STEP: A STRING DOES NOT END");
        if (text_[at_] == '\'') {
          if (at_ + 1 < text_.size() && text_[at_ + 1] == '\'') {
            at_ += 2;
            continue;
          }
          break;
        }
        ++at_;
      }
      v.kind = StepValue::string;
      v.text = text_.substr(start, at_ - start);
      ++at_;
    } else if (c == '.') {
      ++at_;
      const std::size_t start = at_;
      while (at_ < text_.size() && text_[at_] != '.') ++at_;
      if (at_ >= text_.size()) fail("STEP: AN ENUMERATION DOES NOT END");
      v.kind = StepValue::enumeration;
      v.text = text_.substr(start, at_ - start);
      ++at_;
    } else if (c == '$' || c == '*') {
      ++at_;
    } else if (std::isalpha(static_cast<unsigned char>(c))) {
      const std::size_t start = at_;
      while (at_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_'))
        ++at_;
      v.kind = StepValue::typed;
      v.text = text_.substr(start, at_ - start);
      skip_blanks();
      if (take() != '(') fail("STEP: A TYPED VALUE WITHOUT '('");
      if (++depth_ > 16) fail("STEP: LISTS NESTED TOO DEEPLY");
      v.items = list();
      --depth_;
    } else {
      const std::size_t start = at_;
      while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) ||
                                    text_[at_] == '.' || text_[at_] == '+' || text_[at_] == '-'))
        ++at_;
      const auto number = parse_real(text_.substr(start, at_ - start));
      if (!number) fail(fmt::format("STEP: '{}' IS NOT A NUMBER", printable(c)));
      v.kind = StepValue::number;
      v.value = *number;
    }
    return v;
  }
  static char printable(char c) { return std::isprint(static_cast<unsigned char>(c)) ? c : '?'; }
  void skip_blanks() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  char peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }
  char take() {
    if (at_ >= text_.size()) fail("STEP: AN INSTANCE DOES NOT END");
    return text_[at_++];
  }
  std::string_view text_;
  std::size_t at_ = 0;
  int depth_ = 0;
};

// An instance's records: (NAME, parameters) once for a simple instance, once per part of a
// complex one.
struct StepRecord {
  std::string_view name;
  std::vector<StepValue> parameters;
};

std::vector<StepRecord> parse_instance(std::string_view body) {
  std::vector<StepRecord> records;
  auto record = [&](std::string_view rest, std::size_t& used) {
    std::size_t at = 0;
    while (at < rest.size() && std::isspace(static_cast<unsigned char>(rest[at]))) ++at;
    const std::size_t start = at;
    while (at < rest.size() &&
           (std::isalnum(static_cast<unsigned char>(rest[at])) || rest[at] == '_'))
      ++at;
    const std::string_view name = rest.substr(start, at - start);
    while (at < rest.size() && std::isspace(static_cast<unsigned char>(rest[at]))) ++at;
    if (name.empty() || at >= rest.size() || rest[at] != '(')
      fail("STEP: AN INSTANCE WITHOUT A NAME");
    StepParser p(rest.substr(at + 1));
    records.push_back({name, p.list()});
    used = at + 1 + p.at();
  };
  std::size_t at = 0;
  while (at < body.size() && std::isspace(static_cast<unsigned char>(body[at]))) ++at;
  if (at < body.size() && body[at] == '(') {
    // A complex instance: (A(...) B(...) ...).
    ++at;
    for (;;) {
      while (at < body.size() && std::isspace(static_cast<unsigned char>(body[at]))) ++at;
      if (at >= body.size()) fail("STEP: A COMPLEX INSTANCE DOES NOT END");
      if (body[at] == ')') break;
      if (records.size() >= 32) fail("STEP: A COMPLEX INSTANCE OF TOO MANY PARTS");
      std::size_t used = 0;
      record(body.substr(at), used);
      at += used;
    }
  } else {
    std::size_t used = 0;
    record(body.substr(at), used);
  }
  return records;
}

const StepValue& parameter(const StepRecord& r, std::size_t k, StepValue::Kind kind,
                           const char* what) {
  if (k >= r.parameters.size() || r.parameters[k].kind != kind)
    fail(fmt::format("STEP: {} OF {} IS MISSING OR OF THE WRONG KIND", what, r.name));
  return r.parameters[k];
}

std::vector<double> step_numbers(const StepValue& list, const char* what) {
  std::vector<double> out;
  out.reserve(list.items.size());
  for (const StepValue& v : list.items) {
    if (v.kind != StepValue::number) fail(fmt::format("STEP: {} ARE NOT NUMBERS", what));
    out.push_back(v.value);
  }
  return out;
}

// Knots written out from distinct values and their multiplicities.
std::vector<double> expand_knots(const std::vector<double>& multiplicities,
                                 const std::vector<double>& values, std::size_t most) {
  if (multiplicities.size() != values.size())
    fail("STEP: AS MANY KNOT MULTIPLICITIES AS KNOTS ARE DUE");
  std::vector<double> knots;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double m = multiplicities[k];
    if (!(m >= 1) || m != std::floor(m) || m > double(most - knots.size()))
      fail("STEP: A KNOT MULTIPLICITY IS NOT POSSIBLE");
    knots.insert(knots.end(), std::size_t(m), values[k]);
  }
  return knots;
}

}  // namespace

CadSurface read_step_surface(std::string_view text) {
  const std::size_t data = text.find("DATA;");
  if (text.substr(0, 13) != "ISO-10303-21;" || data == std::string_view::npos)
    fail("NOT A STEP FILE (ISO-10303-21; AND DATA; ARE DUE)");
  // Every instance #n= ... ; by its number (strings may hold ';', so they are skipped whole).
  std::unordered_map<std::size_t, std::string_view> instances;
  std::string_view surface_body;
  for (std::size_t at = data + 5; at < text.size();) {
    const std::size_t hash = text.find_first_not_of(" \t\r\n", at);
    if (hash == std::string_view::npos) break;
    if (text.compare(hash, 7, "ENDSEC;") == 0) break;
    if (text[hash] != '#') fail("STEP: AN INSTANCE DOES NOT START WITH #");
    std::size_t id = 0, p = hash + 1;
    const auto [end, ec] = std::from_chars(text.data() + p, text.data() + text.size(), id);
    if (ec != std::errc()) fail("STEP: AN INSTANCE WITHOUT A NUMBER");
    p = std::size_t(end - text.data());
    p = text.find_first_not_of(" \t\r\n", p);
    if (p == std::string_view::npos || text[p] != '=') fail("STEP: AN INSTANCE WITHOUT =");
    const std::size_t body = p + 1;
    bool quoted = false;
    for (p = body; p < text.size(); ++p) {
      if (text[p] == '\'') quoted = !quoted;
      if (!quoted && text[p] == ';') break;
    }
    if (p >= text.size()) fail(fmt::format("STEP: INSTANCE #{} DOES NOT END", id));
    const std::string_view whole = text.substr(body, p - body);
    if (!instances.emplace(id, whole).second) fail(fmt::format("STEP: #{} IS DEFINED TWICE", id));
    if (surface_body.empty() && whole.find("B_SPLINE_SURFACE_WITH_KNOTS") != std::string_view::npos)
      surface_body = whole;
    at = p + 1;
  }
  if (surface_body.empty()) fail("NO B-SPLINE SURFACE (B_SPLINE_SURFACE_WITH_KNOTS) IN THE FILE");

  const std::vector<StepRecord> records = parse_instance(surface_body);
  const StepRecord *simple = nullptr, *base = nullptr, *knots = nullptr, *rational = nullptr;
  for (const StepRecord& r : records) {
    if (r.name == "B_SPLINE_SURFACE_WITH_KNOTS") (records.size() == 1 ? simple : knots) = &r;
    if (r.name == "B_SPLINE_SURFACE") base = &r;
    if (r.name == "RATIONAL_B_SPLINE_SURFACE") rational = &r;
  }
  // A simple instance: name, degrees, points, form, closed, closed, self-intersecting, then the
  // knots' multiplicities and values and their kind; a complex one splits them in its parts.
  std::size_t b = 0;
  if (simple) {
    base = simple;
    knots = simple;
    b = 1;  // the name
  } else if (!base || !knots) {
    fail("STEP: A B-SPLINE SURFACE WITHOUT ITS B_SPLINE_SURFACE PART");
  }
  CadSurface s;
  const double du = parameter(*base, b, StepValue::number, "THE U DEGREE").value;
  const double dv = parameter(*base, b + 1, StepValue::number, "THE V DEGREE").value;
  if (!(du >= 1 && du <= 25 && dv >= 1 && dv <= 25) || du != std::floor(du) || dv != std::floor(dv))
    fail(fmt::format("STEP: DEGREES {} AND {} (1 TO 25)", du, dv));
  s.degree_u = int(du);
  s.degree_v = int(dv);
  const StepValue& points = parameter(*base, b + 2, StepValue::list, "THE CONTROL POINTS");
  s.count_u = points.items.size();
  s.count_v = s.count_u > 0 ? points.items[0].items.size() : 0;
  check_counts(s.count_u, s.count_v, text.size(), 2);
  s.controls.resize(s.count_u * s.count_v);
  for (std::size_t a = 0; a < s.count_u; ++a) {
    const StepValue& row = points.items[a];
    if (row.kind != StepValue::list || row.items.size() != s.count_v)
      fail("STEP: THE CONTROL POINTS ARE NOT A RECTANGLE");
    for (std::size_t c = 0; c < s.count_v; ++c) {
      if (row.items[c].kind != StepValue::reference)
        fail("STEP: A CONTROL POINT IS NOT A REFERENCE");
      const auto found = instances.find(row.items[c].id);
      if (found == instances.end())
        fail(fmt::format("STEP: CONTROL POINT #{} IS NOT IN THE FILE", row.items[c].id));
      const std::vector<StepRecord> point = parse_instance(found->second);
      if (point.size() != 1 || point[0].name != "CARTESIAN_POINT")
        fail(fmt::format("STEP: #{} IS NOT A CARTESIAN_POINT", row.items[c].id));
      const std::vector<double> xyz =
          step_numbers(parameter(point[0], 1, StepValue::list, "THE COORDINATES"), "COORDINATES");
      if (xyz.size() != 3) fail(fmt::format("STEP: #{} IS NOT A POINT IN SPACE", row.items[c].id));
      s.controls[c * s.count_u + a] = {xyz[0], xyz[1], xyz[2]};
    }
  }
  const std::size_t k = simple ? b + 7 : 0;
  s.knots_u = expand_knots(
      step_numbers(parameter(*knots, k, StepValue::list, "THE U MULTIPLICITIES"), "MULTIPLICITIES"),
      step_numbers(parameter(*knots, k + 2, StepValue::list, "THE U KNOTS"), "KNOTS"),
      s.count_u + std::size_t(s.degree_u) + 1);
  s.knots_v =
      expand_knots(step_numbers(parameter(*knots, k + 1, StepValue::list, "THE V MULTIPLICITIES"),
                                "MULTIPLICITIES"),
                   step_numbers(parameter(*knots, k + 3, StepValue::list, "THE V KNOTS"), "KNOTS"),
                   s.count_v + std::size_t(s.degree_v) + 1);
  if (rational) {
    const StepValue& weights = parameter(*rational, 0, StepValue::list, "THE WEIGHTS");
    if (weights.items.size() != s.count_u) fail("STEP: THE WEIGHTS ARE NOT THE POINTS' RECTANGLE");
    s.weights.resize(s.controls.size());
    for (std::size_t a = 0; a < s.count_u; ++a) {
      const std::vector<double> row = step_numbers(weights.items[a], "WEIGHTS");
      if (row.size() != s.count_v) fail("STEP: THE WEIGHTS ARE NOT THE POINTS' RECTANGLE");
      for (std::size_t c = 0; c < s.count_v; ++c) s.weights[c * s.count_u + a] = row[c];
    }
  }
  check_surface(s);
  return s;
}

namespace {

// The basis functions of degree p that are not zero at t in span `span`, and their first
// derivatives (The NURBS Book, A2.2 and A2.3, first derivatives only).
void basis(const std::vector<double>& knots, int p, std::size_t span, double t, double* n,
           double* dn) {
  double left[26], right[26], ndu[26][26];
  ndu[0][0] = 1;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - knots[span + 1 - std::size_t(j)];
    right[j] = knots[span + std::size_t(j)] - t;
    double saved = 0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) n[j] = ndu[j][p];
  for (int r = 0; r <= p; ++r) {
    // First derivative: p (N_{r,p-1} / (u_{i+p} - u_i) - N_{r+1,p-1} / (u_{i+p+1} - u_{i+1})).
    double d = 0;
    if (r >= 1) d += ndu[r - 1][p - 1] / ndu[p][r - 1];
    if (r <= p - 1) d -= ndu[r][p - 1] / ndu[p][r];
    dn[r] = p * d;
  }
}

// The span [knots[k], knots[k+1]) holding t, k in [p, count - 1].
std::size_t find_span(const std::vector<double>& knots, int p, std::size_t count, double t) {
  if (t >= knots[count]) {
    std::size_t k = count - 1;
    while (k > std::size_t(p) && knots[k] == knots[count]) --k;
    return k;
  }
  const auto it = std::upper_bound(knots.begin() + p, knots.begin() + std::ptrdiff_t(count), t);
  return std::size_t(it - knots.begin()) - 1;
}

}  // namespace

SurfacePoint evaluate(const CadSurface& s, double u, double v) {
  u = std::clamp(u, s.u0, s.u1);
  v = std::clamp(v, s.v0, s.v1);
  const int p = s.degree_u, q = s.degree_v;
  const std::size_t su = find_span(s.knots_u, p, s.count_u, u);
  const std::size_t sv = find_span(s.knots_v, q, s.count_v, v);
  double nu[26], dnu[26], nv[26], dnv[26];
  basis(s.knots_u, p, su, u, nu, dnu);
  basis(s.knots_v, q, sv, v, nv, dnv);
  // Homogeneous sums: S = A / w, S_u = (A_u - w_u S) / w.
  Vec3 a, au, av;
  double w = 0, wu = 0, wv = 0;
  for (int l = 0; l <= q; ++l) {
    const std::size_t row = (sv - std::size_t(q) + std::size_t(l)) * s.count_u;
    for (int k = 0; k <= p; ++k) {
      const std::size_t index = row + su - std::size_t(p) + std::size_t(k);
      const double weight = s.weights.empty() ? 1 : s.weights[index];
      const Vec3 c = weight * s.controls[index];
      a = a + (nu[k] * nv[l]) * c;
      au = au + (dnu[k] * nv[l]) * c;
      av = av + (nu[k] * dnv[l]) * c;
      w += nu[k] * nv[l] * weight;
      wu += dnu[k] * nv[l] * weight;
      wv += nu[k] * dnv[l] * weight;
    }
  }
  const Vec3 point = (1 / w) * a;
  return {point, (1 / w) * (au - wu * point), (1 / w) * (av - wv * point)};
}

}  // namespace igds
