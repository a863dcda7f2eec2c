// IMPORT IGES | STEP [name [nocur nostr]]: the B-spline surface of a CAD file becomes the current
// surface, sampled at NOCUR x NOSTR points with its border tangents (docs/exchange.md, "A CAD
// surface in").
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/entries.h"
#include "commands/surface.h"
#include "workspace/disk/disk.h"
#include "workspace/error.h"
#include "workspace/exchange/cad_read.h"

namespace igds {

namespace {

enum Option { iges, step };

constexpr Choice options[] = {
    {"IGES", iges, "[name [nocur nostr]]", "NAME.IGS: its first B-spline surface (entity 128)"},
    {"STEP", step, "[name [nocur nostr]]",
     "NAME.STP: its first B_SPLINE_SURFACE_WITH_KNOTS, rational or not"},
};
constexpr std::string_view types[] = {"IGS", "STP"};
constexpr std::string_view kept = "CURRENT SURFACE KEPT";

// The largest CAD file IMPORT reads: a surface of sixteen million controls and more.
constexpr std::size_t max_file_bytes = std::size_t{1} << 30;

const Prompt file_prompt{"FILE NAME?",
                         "A CAD file: 1 to 8 letters, digits or $ # @ + - _ (type IGS or STP); "
                         "NOCUR NOSTR may follow."};
const Prompt import_size_prompt{
    "NUMBER OF CURVES AND STRINGERS?",
    "NOCUR NOSTR, at least 2 each: points along v by points along u. An empty line takes the "
    "surface's own: as many as its distinct knots."};

// The distinct knots of a direction within its range (at most 1000): the input curves or
// stringers of a surface EXPORT wrote, so that it comes back with its own grid.
int own_count(const std::vector<double>& knots, double first, double last) {
  std::vector<double> inside;
  for (double k : knots)
    if (k >= first && k <= last && (inside.empty() || k != inside.back())) inside.push_back(k);
  return static_cast<int>(std::clamp<std::size_t>(inside.size(), 2, 1000));
}

GridSize ask_import_size(Context& ctx, GridSize own) {
  for (;;) {
    const bool on_the_line = ctx.pending_from_command_line();
    const auto words = ctx.ask_words(import_size_prompt);
    if (words.empty()) return own;
    try {
      const GridSize size = parse_grid_size(words);
      if (size.nocur < 2 || size.nostr < 2)
        throw EntryError("A SURFACE NEEDS AT LEAST 2 CURVES AND 2 STRINGERS");
      return size;
    } catch (const Error& e) {
      if (on_the_line) throw;
      ctx.report(e.what());
    }
  }
}

void run_import(Context& ctx, const Choice* option) {
  const auto code = static_cast<Option>(option->code);
  const std::string_view type = types[code];
  // The name, then whatever followed it on the line answers the grid's question.
  const std::string name = ask_for(ctx, file_prompt, [&](const std::vector<std::string>& w) {
    const auto n = cms_name(w[0]);
    if (!n) throw ParameterError(name_rule);
    ctx.unread(std::vector<std::string>(w.begin() + 1, w.end()));
    return *n;
  });
  const std::string text = read_user_file(ctx.disk(), name, type, max_file_bytes, kept);
  CadSurface cad;
  try {
    cad = code == iges ? read_iges_surface(text) : read_step_surface(text);
  } catch (const CadReadError& e) {
    throw Report(fmt::format("FILE REFUSED: {}.{} ({}); {}", name, type, e.what(), kept));
  }
  const GridSize size = ask_import_size(
      ctx, {own_count(cad.knots_v, cad.v0, cad.v1), own_count(cad.knots_u, cad.u0, cad.u1)});
  const int nocur = size.nocur, nostr = size.nostr;
  const Density density = ask_density(ctx, nocur, nostr);

  // Point (i, j) at u_j, v_i, the parameters evenly spaced; a border tangent is the surface's
  // derivative there over the chord of its end arc, per parameter step: IGDS's tangent per unit
  // of chord (docs/kernels.md), so that the end arc leaves as the surface does.
  const double hu = (cad.u1 - cad.u0) / (nostr - 1), hv = (cad.v1 - cad.v0) / (nocur - 1);
  auto u_of = [&](int j) { return j == nostr - 1 ? cad.u1 : cad.u0 + hu * j; };
  auto v_of = [&](int i) { return i == nocur - 1 ? cad.v1 : cad.v0 + hv * i; };
  Array inppn({std::size_t(nocur) * std::size_t(nostr), 3});
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j)
      evaluate(cad, u_of(j), v_of(i)).p.store(inppn.data() + 3 * (std::size_t(i) * nostr + j));
  auto point = [&](int i, int j) {
    return Vec3::load(inppn.data() + 3 * (std::size_t(i) * nostr + j));
  };
  Array inptg = zero_tangents(nocur, nostr);
  auto put = [&](int i, int j, bool along_curve, Vec3 derivative, double step, Vec3 neighbour) {
    const int row = tangent_row(i * nostr + j + 1, along_curve, nocur, nostr);
    const double chord = norm(neighbour - point(i, j));
    if (row < 0 || !(chord > 0)) return;
    (step / chord * derivative).store(inptg.data() + 4 * std::size_t(row));
  };
  for (int i = 0; i < nocur; ++i) {
    put(i, 0, true, evaluate(cad, cad.u0, v_of(i)).du, hu, point(i, 1));
    put(i, nostr - 1, true, evaluate(cad, cad.u1, v_of(i)).du, hu, point(i, nostr - 2));
  }
  for (int j = 0; j < nostr; ++j) {
    put(0, j, false, evaluate(cad, u_of(j), cad.v0).dv, hv, point(1, j));
    put(nocur - 1, j, false, evaluate(cad, u_of(j), cad.v1).dv, hv, point(nocur - 2, j));
  }
  Surface surface = interpolate_surface(
      ctx.workspace(), {nocur, nostr, density.intcu, density.intst, &inppn, &inptg});
  make_current(ctx.workspace(), nocur, nostr, density, std::move(inppn), std::move(inptg),
               std::move(surface));
  ctx.say(fmt::format("NOCUR {} NOSTR {} INTCU {} INTST {}", nocur, nostr, density.intcu,
                      density.intst));
}

constexpr const Prompt* questions[] = {&file_prompt, &import_size_prompt, &density_prompt};

}  // namespace

extern const Command import_command{
    .name = "IMPORT",
    .options = options,
    .follows = {},
    .option_prompt = {"IGES OR STEP?", "The kind of CAD file: IGES (NAME.IGS) or STEP (NAME.STP).",
                      options},
    .summary = "makes the B-spline surface of a CAD file (IGES, STEP) the current surface",
    .long_help =
        "IMPORT reads a B-spline surface from a CAD file on the disk and makes it the current "
        "surface, replacing the old one, so that IGDS can change it and EXPORT can send it "
        "back:\n"
        "\n"
        "  IMPORT IGES [name]  NAME.IGS: its first B-spline surface (entity 128)\n"
        "  IMPORT STEP [name]  NAME.STP: its first B_SPLINE_SURFACE_WITH_KNOTS, rational or not\n"
        "\n"
        "IGDS then asks NUMBER OF CURVES AND STRINGERS? (an empty line takes as many as the "
        "surface has distinct knots in each direction: a file EXPORT wrote comes back with its "
        "own grid) and INTERPOLATED CURVES AND STRINGERS?. The input points are the "
        "surface's at evenly spaced parameters, NOCUR along v by NOSTR along u; the border "
        "tangents are its exact derivatives there, per unit of chord as IGDS's tangents are. The "
        "surface is then interpolated as BUILD does, and UNDO gives the old one back.\n"
        "\n"
        "  FILE NOT FOUND       there is no NAME.IGS (NAME.STP) on the disk\n"
        "  FILE REFUSED: ...    the file is not what it should be, or holds no B-spline surface; "
        "the reason is given and the current surface is kept\n"
        "\n"
        "Example:\n"
        "  IMPORT IGES HULL\n"
        "  NUMBER OF CURVES AND STRINGERS?\n"
        "  INTERPOLATED CURVES AND STRINGERS? 3 3\n"
        "  NOCUR 6 NOSTR 5 INTCU 3 INTST 3",
    .questions = questions,
    .run = run_import,
};

}  // namespace igds
