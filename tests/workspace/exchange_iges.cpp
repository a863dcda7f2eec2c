// IGES and STEP files of a surface (workspace/exchange/iges.h, step.h), taken apart by the test:
// fixed 80-column records, sections, pointers and counts, Hollerith strings, every number read
// back to the same double; STEP references and the product structure; the golden files.
#include "workspace/exchange/iges.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "tests/workspace/exchange_support.h"
#include "workspace/exchange/step.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/data_error.h"
#include "workspace/numbers/decimal.h"

namespace igds::test::exchange {

namespace {

const CadHeader header{"HULL", "HULL.IGS", {1987, 9, 22, 9, 55, 50}, "A. DESIGNER", "CNUCE PISA"};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The free-format parameters of a section's data: integers, reals and Hollerith strings
// (nHtext), separated by ',' and ended by ';'; blanks outside strings do not count (records are
// padded with them).
std::vector<std::string> parameters(const std::string& data) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < data.size()) {
    while (i < data.size() && data[i] == ' ') ++i;
    std::size_t j = i;
    while (j < data.size() && std::isdigit(static_cast<unsigned char>(data[j]))) ++j;
    if (j > i && j < data.size() && data[j] == 'H') {
      const std::size_t n = std::stoul(data.substr(i, j - i));
      out.push_back(data.substr(j + 1, n));
      i = j + 1 + n;
    } else {
      j = data.find_first_of(",;", i);
      std::string token = data.substr(i, j - i);
      token.erase(token.find_last_not_of(' ') + 1);
      out.push_back(token);
      i = j;
    }
    REQUIRE(i < data.size());
    const char delimiter = data[i++];
    if (delimiter == ';') break;
    REQUIRE(delimiter == ',');
  }
  return out;
}

double real(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  REQUIRE(end == s.c_str() + s.size());
  return v;
}

struct Entity {
  int type = 0, form = 0, subscript = 0;
  std::string label, status;
  std::vector<std::string> parameters;
};

// Takes an IGES file apart, checking its records, sections and pointers on the way.
std::vector<Entity> read_iges(const std::string& text, std::vector<std::string>* global = nullptr) {
  const std::vector<std::string> lines = lines_of(text);
  std::map<char, std::vector<std::string>> sections;
  const std::string order = "SGDPT";
  std::size_t section = 0;
  for (const auto& line : lines) {
    REQUIRE(line.size() == 80);
    const char letter = line[72];
    REQUIRE(order.find(letter) != std::string::npos);
    REQUIRE(order.find(letter) >= section);  // sections in order
    section = order.find(letter);
    auto& list = sections[letter];
    list.push_back(line);
    REQUIRE(std::stoul(line.substr(73)) == list.size());  // sequence numbers from 1
  }
  REQUIRE(sections['T'].size() == 1);
  const std::string& t = sections['T'][0];
  for (std::size_t k = 0; k < 4; ++k) {
    CHECK(t[8 * k] == order[k]);
    CHECK(std::stoul(t.substr(8 * k + 1, 7)) == sections[order[k]].size());
  }
  std::string g;
  for (const auto& line : sections['G']) g += line.substr(0, 72);
  if (global) *global = parameters(g);

  const auto& d = sections['D'];
  const auto& p = sections['P'];
  REQUIRE(d.size() % 2 == 0);
  std::vector<Entity> out;
  std::size_t next_p = 1;
  for (std::size_t k = 0; k < d.size(); k += 2) {
    auto field = [&](std::size_t line, std::size_t n) { return d[line].substr(8 * (n - 1), 8); };
    Entity e;
    e.type = std::stoi(field(k, 1));
    CHECK(std::stoi(field(k + 1, 1)) == e.type);
    const std::size_t first = std::stoul(field(k, 2)), count = std::stoul(field(k + 1, 4));
    e.status = field(k, 9);
    CHECK((e.status == "00000000" || e.status == "00010000"));  // independent or dependent
    e.form = std::stoi(field(k + 1, 5));
    e.label = field(k + 1, 8);
    e.label.erase(0, e.label.find_first_not_of(' '));
    e.subscript = std::stoi(field(k + 1, 9));
    // The parameter lines follow each other and point back at this entry.
    CHECK(first == next_p);
    next_p = first + count;
    std::string data;
    for (std::size_t q = first; q < first + count; ++q) {
      REQUIRE(q <= p.size());
      const std::string& line = p[q - 1];
      CHECK(std::stoul(line.substr(65, 7)) == k + 1);
      CHECK(line[64] == ' ');
      data += line.substr(0, 64);
    }
    e.parameters = parameters(data);
    REQUIRE(!e.parameters.empty());
    CHECK(std::stoi(e.parameters[0]) == e.type);
    out.push_back(std::move(e));
  }
  CHECK(next_p == p.size() + 1);
  return out;
}

// Knots expanded as written: `first` four times, inner integers three times, `last` four times.
std::vector<double> bezier_knots(double first, double last) {
  std::vector<double> k(4, first);
  for (double s = first + 1; s < last; ++s) k.insert(k.end(), 3, s);
  k.insert(k.end(), 4, last);
  return k;
}

// Calls each(e, parameters) for every entity e (from 0, in the directory's order) of a file whose
// P section is checked to be as one thread packs it: the parameters (numbers, never Hollerith
// strings here), each with its delimiter, as many to a record of 64 columns as fit, a record
// begun by a parameter that does not fit in the one before, an entity's last record ended by
// its ';', then the DE pointer and the sequence number (IGES 5.3, 2.2.4.5); and each directory
// entry pointing at its parameters' records. Views into `text`, few assertions: for files of
// many megabytes. Returns the number of entities.
template <class Each>
std::size_t packed_parameters(std::string_view text, const Each& each) {
  std::vector<std::string_view> d, p;
  for (std::size_t at = 0; at + 81 <= text.size(); at += 81) {
    const std::string_view line = text.substr(at, 80);
    if (line[72] == 'D') d.push_back(line);
    if (line[72] == 'P') p.push_back(line);
  }
  std::vector<std::string_view> parameters;
  std::vector<std::size_t> first;  // each entity's first P record
  std::string data;                // the record being packed
  std::string_view de;
  std::size_t packed = 0, same = 0;
  auto end_record = [&] {
    data.resize(64, ' ');
    ++packed;
    same += packed <= p.size() && p[packed - 1] == fmt::format("{} {}P{:7}", data, de, packed);
    data.clear();
  };
  for (const std::string_view line : p) {
    de = line.substr(65, 7);
    if (parameters.empty()) first.push_back(packed + 1);
    for (std::size_t i = 0; i < 64 && line[i] != ' ';) {
      std::size_t end = i;
      while (end < 64 && line[end] != ',' && line[end] != ';') ++end;
      if (end == 64) break;  // not a parameter: the records packed differ
      const std::string_view token = line.substr(i, end + 1 - i);
      if (!data.empty() && data.size() + token.size() > 64) end_record();
      data += token;
      parameters.push_back(token.substr(0, token.size() - 1));
      i = end + 1;
      if (token.back() == ';') {
        end_record();
        each(first.size() - 1, parameters);
        parameters.clear();
      }
    }
  }
  CHECK(packed == p.size());
  CHECK(same == p.size());
  REQUIRE(d.size() == 2 * first.size());
  first.push_back(p.size() + 1);
  std::size_t pointing = 0;
  for (std::size_t e = 0; e + 1 < first.size(); ++e) {
    auto field = [&](std::size_t line, std::size_t n) {
      return std::stoul(std::string(d[line].substr(8 * (n - 1), 8)));
    };
    pointing += field(2 * e, 2) == first[e] && field(2 * e + 1, 4) == first[e + 1] - first[e] &&
                std::stoul(std::string(p[first[e] - 1].substr(65, 7))) == 2 * e + 1;
  }
  CHECK(pointing + 1 == first.size());
  return first.size() - 1;
}

}  // namespace

TEST_CASE("IGES: records, sections, pointers and the global section") {
  const TestSurface t = golden_surface();
  std::vector<std::string> g;
  const std::vector<Entity> entities =
      read_iges(write_iges(t.input, t.surface.patches, header, SurfaceForm::patches), &g);
  REQUIRE(g.size() == 25);
  CHECK(g[0] == ",");
  CHECK(g[1] == ";");
  CHECK(g[2] == "HULL");
  CHECK(g[3] == "HULL.IGS");
  CHECK(g[13] == "2");  // millimetres
  CHECK(g[14] == "MM");
  CHECK(g[17] == "19870922.095550");
  double largest = 0;
  for (double v : surface_net(t.input, t.surface.patches).xyz)
    largest = std::max(largest, std::abs(v));
  CHECK(real(g[18]) == largest * 1e-12);
  CHECK(real(g[19]) == largest);
  CHECK(g[20] == "A. DESIGNER");
  CHECK(g[21] == "CNUCE PISA");
  CHECK(g[22] == "11");  // IGES 5.3
  // 12 patches; the shell: 31 edges, the vertex and edge lists, 12 loops, 12 faces, the shell;
  // 5 curves, 4 stringers, the group of the curves.
  constexpr std::size_t shell = 31 + 2 + 12 + 12 + 1, curves = 12 + shell;
  REQUIRE(entities.size() == 12 + shell + 5 + 4 + 1);
  for (std::size_t k = 0; k < 12; ++k) {
    CHECK(entities[k].type == 128);
    CHECK(entities[k].label == "PATCH");
    CHECK(entities[k].subscript == int(k + 1));
    CHECK(entities[k].status == "00010000");
  }
  CHECK(entities[curves].label == "CURVE");
  CHECK(entities[curves].status == "00000000");
  CHECK(entities[curves + 4].subscript == 5);
  CHECK(entities[curves + 5].label == "STRINGER");
  const Entity& group = entities[curves + 9];
  CHECK(group.type == 402);
  CHECK(group.form == 7);
  CHECK(group.label == "CURVES");
  REQUIRE(group.parameters.size() == 2 + 9);
  CHECK(group.parameters[1] == "9");
  for (std::size_t k = 0; k < 9; ++k)
    CHECK(std::stoul(group.parameters[2 + k]) == 2 * (curves + k) + 1);
}

TEST_CASE(
    "IGES: no author nor organization is a parameter left out, the start section whole "
    "words, the unit as asked") {
  const TestSurface t = golden_surface();
  CadHeader anonymous = header;
  anonymous.author.clear();
  anonymous.organization.clear();
  anonymous.name = "HULL0001";
  const struct {
    LengthUnit unit;
    const char *flag, *name, *words;
  } units[] = {{LengthUnit::mm, "2", "MM", "Units: millimetres."},
               {LengthUnit::cm, "10", "CM", "Units: centimetres."},
               {LengthUnit::m, "6", "M", "Units: metres."},
               {LengthUnit::inch, "1", "IN", "Units: inches."},
               {LengthUnit::foot, "4", "FT", "Units: feet."},
               {LengthUnit::none, "3", "NONE", "Units: none declared."}};
  for (const auto& u : units) {
    anonymous.unit = u.unit;
    const std::string text = write_iges(t.input, t.surface.patches, anonymous);
    std::vector<std::string> g;
    const std::vector<Entity> entities = read_iges(text, &g);
    REQUIRE(g.size() == 25);
    CHECK(g[13] == u.flag);
    CHECK(g[14] == u.name);
    CHECK(g[20].empty());
    CHECK(g[21].empty());
    CHECK(text.find(",,11,0,") != std::string::npos);  // G21, G22 null, as IGES 5.3 allows
    CHECK(text.find("0H") == std::string::npos);
    // The start section: its records joined by blanks are the sentence, no word cut.
    std::string start;
    for (const std::string& line : lines_of(text)) {
      if (line[72] != 'S') break;
      std::string data = line.substr(0, 72);
      data.erase(data.find_last_not_of(' ') + 1);
      CHECK(data.front() != ' ');
      start += (start.empty() ? "" : " ") + data;
    }
    CHECK(start ==
          std::string("IGDS surface HULL0001: one bicubic B-spline surface (entity 128), exact, "
                      "and its input curves and stringers (entity 126) in the group CURVES "
                      "(entity 402). ") +
              u.words);
    CHECK(entities.size() == 1 + 9 + 1);
  }
}

TEST_CASE("IGES: each patch is its Bézier net, every number read back to the same double") {
  const TestSurface t = golden_surface();
  const BezierNet net = surface_net(t.input, t.surface.patches);
  const std::vector<Entity> entities =
      read_iges(write_iges(t.input, t.surface.patches, header, SurfaceForm::patches));
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      const auto& p = entities[i * 3 + j].parameters;
      // 128, K1 K2 M1 M2, PROP1..5, 8 + 8 knots, 16 weights, 48 coordinates, U0 U1 V0 V1.
      REQUIRE(p.size() == 1 + 4 + 5 + 16 + 16 + 48 + 4);
      CHECK(p[1] == "3");
      CHECK(p[2] == "3");
      CHECK(p[7] == "1");  // PROP3: polynomial
      for (int k = 0; k < 8; ++k) {
        CHECK(real(p[10 + std::size_t(k)]) == (k < 4 ? double(j) : double(j + 1)));
        CHECK(real(p[18 + std::size_t(k)]) == (k < 4 ? double(i) : double(i + 1)));
      }
      for (std::size_t b = 0; b < 4; ++b)
        for (std::size_t a = 0; a < 4; ++a)
          for (std::size_t c = 0; c < 3; ++c)
            CHECK(real(p[42 + 3 * (4 * b + a) + c]) ==
                  net.xyz[3 * ((3 * i + b) * net.cols + 3 * j + a) + c]);
      CHECK(real(p[90]) == double(j));
      CHECK(real(p[93]) == double(i + 1));
    }
  }
  // Curve 2: the B-spline of surface_curves.h, knots and controls exactly.
  const auto c = input_curve_bspline(net, 1);
  REQUIRE(c);
  const auto& p = entities[12 + 31 + 2 + 12 + 12 + 1 + 1].parameters;  // after the shell
  const std::size_t n = c->controls.size();
  REQUIRE(p.size() == 7 + (n + 4) + n + 3 * n + 2 + 3);
  CHECK(std::stoul(p[1]) == n - 1);
  std::vector<double> knots;
  for (std::size_t k = 0; k < c->knots.size(); ++k)
    knots.insert(knots.end(), std::size_t(c->multiplicities[k]), c->knots[k]);
  for (std::size_t k = 0; k < knots.size(); ++k) CHECK(real(p[7 + k]) == knots[k]);
  for (std::size_t k = 0; k < n; ++k) {
    CHECK(real(p[7 + n + 4 + n + 3 * k]) == c->controls[k].x);
    CHECK(real(p[7 + n + 4 + n + 3 * k + 2]) == c->controls[k].z);
  }
}

TEST_CASE("IGES: one surface with inner knots of multiplicity 3, the default") {
  const TestSurface t = golden_surface();
  const BezierNet net = surface_net(t.input, t.surface.patches);
  const std::vector<Entity> entities = read_iges(write_iges(t.input, t.surface.patches, header));
  REQUIRE(entities.size() == 1 + 5 + 4 + 1);
  CHECK(entities[0].label == "SURFACE");
  const auto& p = entities[0].parameters;
  REQUIRE(p.size() == 10 + 14 + 17 + 130 + 3 * 130 + 4);
  CHECK(p[1] == "9");
  CHECK(p[2] == "12");
  const std::vector<double> u = bezier_knots(0, 3), v = bezier_knots(0, 4);
  for (std::size_t k = 0; k < u.size(); ++k) CHECK(real(p[10 + k]) == u[k]);
  for (std::size_t k = 0; k < v.size(); ++k) CHECK(real(p[24 + k]) == v[k]);
  for (std::size_t k = 0; k < net.xyz.size(); ++k) CHECK(real(p[41 + 130 + k]) == net.xyz[k]);
}

TEST_CASE("IGES: a surface made on all cores, packed as one thread packs it, in both forms") {
  // 190 x 190 points: a net of 568 rows, its numbers made about 300 rows at a time (more than a
  // quarter of a million numbers: on all cores), each run of them packed into some 150,000
  // records (on all cores, a block at a time), the curves' 290,000 numbers made at once.
  const TestSurface t = test_surface(190, 190, 0, 0);
  const BezierNet net = surface_net(t.input, t.surface.patches);
  REQUIRE(net.rows == 568);
  auto text = [](double v) {
    char buffer[32];
    return std::string(buffer, format_real(buffer, v));
  };
  // Curve or stringer k's knots and controls: how many are right.
  auto curve_right = [&](std::size_t k, const std::vector<std::string_view>& p) {
    const auto c = k < 190 ? input_curve_bspline(net, k) : input_stringer_bspline(net, k - 190);
    const std::size_t n = c->controls.size();
    std::size_t right = 0;
    if (p.size() != 7 + (n + 4) + n + 3 * n + 2 + 3) return right;
    std::size_t at = 7;
    for (std::size_t i = 0; i < c->knots.size(); ++i)
      for (int m = 0; m < c->multiplicities[i]; ++m) right += p[at++] == text(c->knots[i]);
    at += n;
    for (Vec3 v : c->controls) {
      right += p[at++] == text(v.x);
      right += p[at++] == text(v.y);
      right += p[at++] == text(v.z);
    }
    return right;
  };
  const std::size_t curve_numbers = 2 * 190 * (196 + 3 * 192);  // 192 controls, 196 knots each

  {
    const std::string file = write_iges(t.input, t.surface.patches, header, SurfaceForm::one);
    const std::size_t controls = net.rows * net.cols, knots = net.cols + 4;
    std::size_t right = 0, curves_right = 0;
    const std::size_t entities =
        packed_parameters(file, [&](std::size_t e, const std::vector<std::string_view>& p) {
          if (e == 0 && p.size() == 10 + 2 * knots + controls + 3 * controls + 4) {
            for (std::size_t k = 0; k < net.xyz.size(); ++k)
              right += p[10 + 2 * knots + controls + k] == text(net.xyz[k]);
          } else if (e >= 1 && e <= 2 * 190) {
            curves_right += curve_right(e - 1, p);
          }
        });
    CHECK(entities == 1 + 2 * 190 + 1);
    CHECK(right == net.xyz.size());
    CHECK(curves_right == curve_numbers);
  }
  {
    const std::string file = write_iges(t.input, t.surface.patches, header, SurfaceForm::patches);
    // After the patches, the shell: 190 x 189 edges each way, the two lists, 189 x 189 loops and
    // faces, the shell; then the curves.
    const std::size_t patches = 189 * 189, curves = patches + 2 * 190 * 189 + 2 + 2 * patches + 1;
    std::size_t right = 0, curves_right = 0;
    const std::size_t entities =
        packed_parameters(file, [&](std::size_t e, const std::vector<std::string_view>& p) {
          if (e < patches && p.size() == 1 + 4 + 5 + 16 + 16 + 48 + 4) {
            const std::size_t i = e / 189, j = e % 189;
            for (std::size_t b = 0; b < 4; ++b)
              for (std::size_t a = 0; a < 4; ++a)
                for (std::size_t c = 0; c < 3; ++c)
                  right += p[42 + 3 * (4 * b + a) + c] ==
                           text(net.xyz[3 * ((3 * i + b) * net.cols + 3 * j + a) + c]);
          } else if (e >= curves && e < curves + 2 * 190) {
            curves_right += curve_right(e - curves, p);
          }
        });
    CHECK(entities == curves + 2 * 190 + 1);
    CHECK(right == patches * 48);
    CHECK(curves_right == curve_numbers);
  }
}

TEST_CASE("IGES: a curve that is a point is left out and the directory says so") {
  TestSurface t = test_surface(4, 5, 0, 0);
  for (int j = 0; j < 5; ++j) std::fill_n(t.inppn.data() + 3 * j, 3, 1.0);
  t.surface = interpolate(t.input);
  const std::vector<Entity> entities =
      read_iges(write_iges(t.input, t.surface.patches, header, SurfaceForm::patches));
  // The shell: 4 x 4 + 3 x 5 edges, the lists, 12 loops and faces, the shell; the pole's four
  // edges left out of their loops.
  constexpr std::size_t shell = 31 + 2 + 12 + 12 + 1;
  REQUIRE(entities.size() == 12 + shell + 3 + 5 + 1);
  CHECK(entities[12 + 31 + 2].parameters[1] == "3");      // patch 1's loop: three edges
  CHECK(entities[12 + 31 + 2 + 4].parameters[1] == "4");  // patch 5's, the next row's: four
  CHECK(entities[12 + shell].label == "CURVE");
  CHECK(entities[12 + shell].subscript == 2);
  CHECK(entities[12 + shell + 8].parameters[1] == "8");
}

TEST_CASE("IGES and STEP refuse a surface that is not finite or of the wrong shape") {
  TestSurface t = golden_surface();
  Array patches = t.surface.patches;
  patches.ravel[100] = NAN;
  CHECK_THROWS_AS(write_iges(t.input, patches, header), DataError);
  CHECK_THROWS_AS(write_step(t.input, patches, header), DataError);
  patches = Array({3, 3, 3, 4, 4});
  CHECK_THROWS_AS(write_iges(t.input, patches, header), DataError);
}

TEST_CASE("STEP: every reference defined once, numbers exact, one part") {
  const TestSurface t = golden_surface();
  const BezierNet net = surface_net(t.input, t.surface.patches);
  for (SurfaceForm form : {SurfaceForm::patches, SurfaceForm::one}) {
    const std::string text = write_step(t.input, t.surface.patches, header, form);
    CHECK(text.rfind("ISO-10303-21;\nHEADER;\n", 0) == 0);
    CHECK(text.find("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));") !=
          std::string::npos);
    CHECK(text.size() - text.rfind("ENDSEC;\nEND-ISO-10303-21;\n") == 26);
    // Instances #1..#n in order; every reference names one of them.
    const std::string data = text.substr(text.find("DATA;\n"));
    std::map<std::size_t, std::string> instances;
    const std::regex instance(R"(\n#(\d+)=([A-Z_0-9(]+))");
    for (auto it = std::sregex_iterator(data.begin(), data.end(), instance);
         it != std::sregex_iterator(); ++it)
      instances[std::stoul((*it)[1])] = (*it)[2];
    REQUIRE(!instances.empty());
    CHECK(instances.begin()->first == 1);
    CHECK(instances.rbegin()->first == instances.size());
    std::set<std::size_t> referenced;
    const std::regex reference(R"([(,\s]#(\d+))");
    for (auto it = std::sregex_iterator(data.begin(), data.end(), reference);
         it != std::sregex_iterator(); ++it)
      referenced.insert(std::stoul((*it)[1]));
    for (std::size_t id : referenced) CHECK(instances.count(id) == 1);
    std::size_t surfaces = 0, curves = 0, points = 0;
    for (const auto& [id, type] : instances) {
      surfaces += type == "B_SPLINE_SURFACE_WITH_KNOTS(";
      curves += type == "B_SPLINE_CURVE_WITH_KNOTS(";
      points += type == "CARTESIAN_POINT(";
    }
    CHECK(surfaces == (form == SurfaceForm::one ? 1 : 12));
    // FACES: a curve for each of the 31 edges besides the 9 input curves, and the shell.
    std::size_t faces = 0, edge_curves = 0, shells = 0;
    for (const auto& [id, type] : instances) {
      faces += type == "ADVANCED_FACE(";
      edge_curves += type == "EDGE_CURVE(";
      shells += type == "OPEN_SHELL(";
    }
    const bool one = form == SurfaceForm::one;
    CHECK(curves == (one ? 9 : 9 + 31));
    CHECK(faces == (one ? 0 : 12));
    CHECK(edge_curves == (one ? 0 : 31));
    CHECK(shells == (one ? 0 : 1));
    CHECK(std::count_if(instances.begin(), instances.end(),
                        [](const auto& i) { return i.second == "GEOMETRIC_CURVE_SET("; }) == 1);
    CHECK(text.find("GEOMETRIC_CURVE_SET('input curves',(") != std::string::npos);
    CHECK(instances.count(1));
    // The net's points come first, in order, each number the same double.
    const std::regex point(R"(CARTESIAN_POINT\('',\(([^,]+),([^,]+),([^)]+)\)\);)");
    std::size_t k = 0;
    for (auto it = std::sregex_iterator(data.begin(), data.end(), point);
         it != std::sregex_iterator() && k < net.rows * net.cols; ++it, ++k)
      for (int c = 0; c < 3; ++c)
        CHECK(real((*it)[std::size_t(c) + 1]) == net.xyz[3 * k + std::size_t(c)]);
    CHECK(k == net.rows * net.cols);
    CHECK(points > net.rows * net.cols);
    CHECK(text.find("GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION('HULL'") !=
          std::string::npos);
    CHECK(text.find("SI_UNIT(.MILLI.,.METRE.)") != std::string::npos);
  }
  // The length unit as asked; none: no length unit, nor an uncertainty, which would need one.
  const struct {
    LengthUnit unit;
    const char* text;
  } units[] = {{LengthUnit::mm, "(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));"},
               {LengthUnit::cm, "(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.CENTI.,.METRE.));"},
               {LengthUnit::m, "(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.METRE.));"},
               {LengthUnit::inch, "(CONVERSION_BASED_UNIT('INCH',#"},
               {LengthUnit::foot, "(CONVERSION_BASED_UNIT('FOOT',#"},
               {LengthUnit::none, "GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT(())"}};
  for (const auto& u : units) {
    CadHeader h = header;
    h.unit = u.unit;
    const std::string text = write_step(t.input, t.surface.patches, h);
    CHECK(text.find(u.text) != std::string::npos);
    CHECK((text.find("LENGTH_UNIT()") != std::string::npos) == (u.unit != LengthUnit::none));
  }
  CHECK(write_step(t.input, t.surface.patches, header).find("LENGTH_MEASURE(6.03E-11)") !=
        std::string::npos);
  // Apostrophes and backslashes are doubled in STEP strings.
  CadHeader odd = header;
  odd.name = "O'NEIL\\1";
  CHECK(write_step(t.input, t.surface.patches, odd).find("PRODUCT('O''NEIL\\\\1'") !=
        std::string::npos);
}

TEST_CASE("STEP: a surface large enough to be made on the cores, its references and curves") {
  // 447 x 447 references in the surface and 300 curves of 152 controls: each far more text than
  // put_each (text_out.h) makes on one thread. Their text, made here one after the other.
  const TestSurface t = test_surface(150, 150, 0, 0);
  const BezierNet net = surface_net(t.input, t.surface.patches);
  const std::string text = write_step(t.input, t.surface.patches, header);
  auto ref = [](std::size_t id) { return "#" + std::to_string(id); };
  auto real_text = [](double v) {
    char buffer[32];
    return std::string(buffer, format_real(buffer, v));
  };
  const std::size_t first_point =
      std::stoul(text.substr(text.find("\n#", text.find("REPRESENTATION_CONTEXT")) + 2));
  std::size_t id = first_point + net.rows * net.cols;
  std::string expected = ref(id++) + "=B_SPLINE_SURFACE_WITH_KNOTS('SURFACE',3,3,(";
  for (std::size_t c = 0; c < net.cols; ++c) {
    expected += c > 0 ? ",\n  (" : "(";
    for (std::size_t r = 0; r < net.rows; ++r)
      expected += (r > 0 ? "," : "") + ref(first_point + r * net.cols + c);
    expected += ')';
  }
  expected += "),.UNSPECIFIED.,.F.,.F.,.F.,";
  std::string multiplicities = "(4", knots = "(0.";
  for (int k = 1; k < 149; ++k) multiplicities += ",3", knots += "," + real_text(k);
  multiplicities += ",4)", knots += ",149.)";
  expected += multiplicities + ',' + multiplicities + ',' + knots + ',' + knots;
  expected += ",.UNSPECIFIED.);\n";
  for (std::size_t k = 0; k < 300; ++k) {
    const auto c = k < 150 ? input_curve_bspline(net, k) : input_stringer_bspline(net, k - 150);
    REQUIRE(c);
    REQUIRE(c->controls.size() == 152);
    const std::size_t first = id;
    for (Vec3 v : c->controls)
      expected += ref(id++) + "=CARTESIAN_POINT('',(" + real_text(v.x) + ',' + real_text(v.y) +
                  ',' + real_text(v.z) + "));\n";
    expected +=
        ref(id++) + "=B_SPLINE_CURVE_WITH_KNOTS('" +
        (k < 150 ? "CURVE " + std::to_string(k + 1) : "STRINGER " + std::to_string(k - 150 + 1)) +
        "',3,(";
    for (std::size_t p = first; p < first + 152; ++p)
      expected += (p == first ? "" : (p - first) % 8 == 0 ? ",\n  " : ",") + ref(p);
    expected += "),.UNSPECIFIED.,.F.,.F.,(";
    for (std::size_t m = 0; m < c->knots.size(); ++m)
      expected += (m > 0 ? "," : "") + std::to_string(c->multiplicities[m]);
    expected += "),(";
    for (std::size_t m = 0; m < c->knots.size(); ++m)
      expected += (m > 0 ? "," : "") + real_text(c->knots[m]);
    expected += "),.UNSPECIFIED.);\n";
  }
  const std::size_t at = text.find(ref(first_point + net.rows * net.cols) + "=");
  REQUIRE(at != std::string::npos);
  CHECK(text.compare(at, expected.size(), expected) == 0);
  const std::string origin = ref(id) + "=CARTESIAN_POINT('',(0.,0.,0.));\n";
  CHECK(text.compare(at + expected.size(), origin.size(), origin) == 0);
}

TEST_CASE("golden: the IGES and STEP files of a small surface") {
  const TestSurface t = golden_surface();
  check_golden("surface_5x4.igs", write_iges(t.input, t.surface.patches, header));
  CadHeader step = header;
  step.file_name = "HULL.STP";
  check_golden("surface_5x4.stp", write_step(t.input, t.surface.patches, step));
}

}  // namespace igds::test::exchange
