// EXPORT SVG | TEK | HPGL | DUCT | IGES | STEP [name]: the current image, or the current surface
// exactly, in a file for other programs; IGES and STEP take FACES and a unit after the name.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <span>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/picture.h"
#include "commands/reports.h"
#include "devices/hpgl_plot.h"
#include "devices/svg.h"
#include "devices/tek_stream.h"
#include "workspace/disk/disk.h"
#include "workspace/error.h"
#include "workspace/exchange/duct.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/data_error.h"

namespace igds {

namespace {

enum Option { svg, tek, hpgl, duct, iges, step };

// The file types: the option's word for the pictures, the usual extensions for the exchange
// files (DUCTPIC as docs/exchange.md names DUCT pictures; IGS and STP as CAD systems expect).
constexpr std::string_view types[] = {"SVG", "TEK", "HPGL", "DUCTPIC", "IGS", "STP"};

// After the three of the pictures, so that no abbreviation of them changes.
constexpr Choice options[] = {
    {"SVG", svg, "[name]", "NAME.SVG, a picture any web browser shows"},
    {"TEK", tek, "[name]", "NAME.TEK, the bytes a Tektronix 4013 would receive"},
    {"HPGL", hpgl, "[name]", "NAME.HPGL, the plot PLOT would send"},
    {"DUCT", duct, "[name [IMAGE]]",
     "NAME.DUCTPIC, a DUCT 4.4 picture of the surface (name IMAGE: the image)"},
    {"IGES", iges, "[name [FACES] [M|MM|CM|INCH|FOOT|NONE]]",
     "NAME.IGS, the surface as one exact B-spline surface (IGES 5.3)"},
    {"STEP", step, "[name [FACES] [M|MM|CM|INCH|FOOT|NONE]]",
     "NAME.STP, the same in STEP (ISO 10303-21, AP214)"},
};

// The words after the name of an IGES or STEP file. M before MM, so that M is metres; FACES
// before FOOT, so that F is FACES.
enum CadWord { faces = 100 };
constexpr Choice cad_words[] = {
    {"FACES", faces},
    {"M", int(LengthUnit::m)},
    {"MM", int(LengthUnit::mm)},
    {"CM", int(LengthUnit::cm)},
    {"INCH", int(LengthUnit::inch)},
    {"FOOT", int(LengthUnit::foot)},
    {"NONE", int(LengthUnit::none)},
};

struct CadChoice {
  SurfaceForm form = SurfaceForm::one;
  LengthUnit unit = LengthUnit::mm;
};

// FACES and a unit, each at most once, from the words after the file's name.
CadChoice cad_choice(std::span<const std::string> words) {
  CadChoice choice;
  bool form_said = false, unit_said = false;
  for (const std::string& word : words) {
    const Choice* c = choose(cad_words, word);
    if (!c)
      throw ParameterError(fmt::format(
          "{}: FACES OR A UNIT (M, MM, CM, INCH, FOOT, NONE) MAY FOLLOW THE NAME", word));
    if (c->code == faces) {
      if (form_said) throw ParameterError("FACES TWICE");
      form_said = true;
      choice.form = SurfaceForm::patches;
    } else {
      if (unit_said) throw ParameterError("TWO UNITS");
      unit_said = true;
      choice.unit = static_cast<LengthUnit>(c->code);
    }
  }
  return choice;
}

const Prompt file_prompt{"FILE NAME?",
                         "1 to 8 letters, digits or $ # @ + - _; a file of that name is "
                         "replaced. After an IGES or STEP name: FACES, M MM CM INCH FOOT NONE."};

// EXPORT DUCT's name, and after it IMAGE for the current image as projected (docs/decisions.md).
constexpr Choice duct_words[] = {{"IMAGE", 1, "", "the current image as projected"}};
const Prompt duct_prompt{"FILE NAME?",
                         "A name for the file: 1 to 8 letters, digits or $ # @ + - _; after it "
                         "IMAGE for the current image as projected, not the surface."};

// The date the exchange files carry: now, local time; SOURCE_DATE_EPOCH (seconds since 1970,
// UTC), when set, as reproducible builds date their files (the golden tests use it).
Timestamp export_date() {
  std::time_t t = std::time(nullptr);
  bool utc = false;
  if (const char* fixed = std::getenv("SOURCE_DATE_EPOCH"); fixed && *fixed) {
    char* end = nullptr;
    const long long seconds = std::strtoll(fixed, &end, 10);
    if (*end == '\0' && seconds >= 0) {
      t = static_cast<std::time_t>(seconds);
      utc = true;
    }
  }
  std::tm tm{};
  if (utc ? gmtime_r(&t, &tm) == nullptr : localtime_r(&t, &tm) == nullptr) return {};
  return {tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec};
}

SurfaceInput input_of(const Workspace& ws) {
  return {ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg};
}

// EXPORT DUCT's name; `image` set by IMAGE after it.
std::string ask_duct_name(Context& ctx, bool& image) {
  return ask_for(ctx, duct_prompt, [&](const std::vector<std::string>& words) {
    auto name = words.empty() ? std::nullopt : cms_name(words[0]);
    if (!name) throw ParameterError(name_rule);
    if (words.size() > 2 || (words.size() == 2 && !choose(duct_words, words[1])))
      throw ParameterError("AFTER THE NAME ONLY IMAGE (THE CURRENT IMAGE AS PROJECTED)");
    image = words.size() == 2;
    return *name;
  });
}

// The DUCT writer refuses item n of a drawing (1-based) that is not finite: the report names what
// the item stands for, as the user knows it (a surface's curve, a tangent at a point).
template <class Drawing>
Report not_finite_in_picture(const Drawing& drawing, const DataError& e) {
  if (e.problem != DataError::Problem::point_not_finite || e.number == 0 ||
      e.number > drawing.size())
    return worded(e, "NO FILE WRITTEN");
  const Identity id = drawing.items()[e.number - 1].id;
  std::string what;
  switch (id.role) {
    case Role::curve:
      what = fmt::format("CURVE {}", id.index);
      break;
    case Role::stringer:
      what = fmt::format("STRINGER {}", id.index);
      break;
    case Role::tangent:
      what = fmt::format("THE TANGENT AT POINT {}", id.index);
      break;
    case Role::point:
      what = fmt::format("POINT {}", id.index);
      break;
    case Role::border:
      what = "THE BORDER";
      break;
    default:
      what = fmt::format("ITEM {} OF THE DRAWING", e.number);
      break;
  }
  return Report(reports::incorrect_entry,
                fmt::format("{} HAS A NUMBER THAT IS NOT FINITE IN THE DUCT PICTURE; NO FILE "
                            "WRITTEN",
                            what));
}

// EXPORT DUCT into `out`, written straight from the surface's curves or, with IMAGE, the image's
// drawing.
bool duct_file(const Workspace& ws, const std::string& name, bool image, TextOut& out) {
  const std::string date = duct_date(export_date());
  if (!image) {
    // PATCHES made for the curves are let go before the file is written.
    const Drawing3 drawing = [&] {
      Array made;
      return surface_curves(input_of(ws), patches_of(ws, made), ws.intpn);
    }();
    const std::string title =
        fmt::format("SURFACE {} X {}, INTCU {}, INTST {}", ws.nocur, ws.nostr, ws.intcu, ws.intst);
    try {
      return write_duct(drawing, {name, date, title}, {}, out);
    } catch (const DataError& e) {
      throw not_finite_in_picture(drawing, e);
    }
  }
  std::string title;
  for (const std::string& line : describe(ws.image->desim, 72))
    title += (title.empty() ? "" : " ") + line;
  const Picture picture = picture_of(ws.image);
  try {
    return write_duct(picture.drawing, {name, date, title}, ws.image->desim.projection, out);
  } catch (const DataError& e) {
    throw not_finite_in_picture(picture.drawing, e);
  }
}

// The patch (row by row from 1) whose Bézier controls are not finite (finite patches near the
// largest numbers), the first that holds the control; 0 when there is none.
std::size_t overflowing_patch(const Workspace& ws, const Array& patches) {
  const BezierNet net = surface_net(input_of(ws), patches);
  const std::size_t k = first_not_finite(net.xyz.data(), net.xyz.size());
  if (k == net.xyz.size()) return 0;
  const std::size_t row = k / 3 / net.cols, column = k / 3 % net.cols;
  const auto rows = static_cast<std::size_t>(ws.nocur) - 1;
  const auto columns = static_cast<std::size_t>(ws.nostr) - 1;
  const std::size_t i = std::min(row == 0 ? 0 : (row - 1) / 3, rows - 1);
  const std::size_t j = std::min(column == 0 ? 0 : (column - 1) / 3, columns - 1);
  return i * columns + j + 1;
}

// EXPORT IGES or STEP into `out`.
void cad_file(const Workspace& ws, const std::string& name, Option option, CadChoice choice,
              TextOut& out) {
  if (!ws.has_surface()) throw Report(reports::surface_not_found);
  const CadHeader header{
      name, fmt::format("{}.{}", name, types[option]), export_date(), "", "", choice.unit};
  Array made;
  const Array& patches = patches_of(ws, made);
  try {
    if (option == iges)
      write_iges(input_of(ws), patches, header, out, choice.form);
    else
      write_step(input_of(ws), patches, header, out, choice.form);
  } catch (const DataError& e) {
    // The writers say a patch's Bézier controls are not finite without saying which.
    if (e.problem != DataError::Problem::patch_not_finite) throw;
    if (const std::size_t patch = overflowing_patch(ws, patches))
      throw Report(reports::incorrect_entry,
                   fmt::format("PATCH {} HAS BEZIER CONTROLS THAT ARE NOT FINITE NUMBERS; NO FILE "
                               "WRITTEN",
                               patch));
    throw;
  }
}

void run_export(Context& ctx, const Choice* option) {
  const Workspace& ws = ctx.workspace();
  const auto code = static_cast<Option>(option->code);
  const std::string_view type = types[code];
  if (code == iges || code == step) {
    if (!ws.has_surface()) throw Report(reports::surface_not_found);
  } else if (code == duct) {
    if (!ws.has_surface() && !ws.image) throw Report(reports::surface_not_found);
  } else if (!ws.image) {
    throw Report(reports::image_not_found);
  }
  std::string name;
  CadChoice choice;
  bool image = false;  // EXPORT DUCT name IMAGE
  if (code == iges || code == step) {
    // The name, then FACES and a unit, on the line or typed at the question.
    ask_for(ctx, file_prompt, [&](const std::vector<std::string>& words) {
      const auto cms = cms_name(words[0]);
      if (!cms) throw ParameterError(name_rule);
      choice = cad_choice(std::span(words).subspan(1));
      name = *cms;
      return true;
    });
  } else if (code == duct) {
    name = ask_duct_name(ctx, image);
    if (image && !ws.image) throw Report(reports::image_not_found);
    if (!image && !ws.has_surface())
      throw Report(reports::surface_not_found,
                   "EXPORT DUCT NAME IMAGE WRITES THE CURRENT IMAGE AS PROJECTED");
  } else {
    name = ask_file_name(ctx, file_prompt);
  }
  const bool existed = ctx.disk().exists(name, type);
  std::uint64_t size = 0;
  std::string_view holds;
  bool counts_fit = true;  // EXPORT DUCT: every count in its I6 field
  try {
    switch (code) {
      case svg: {
        // Written while it is made: a document may be tens of megabytes.
        const Picture picture = picture_of(ws.image);
        size =
            write_user_file(ctx.disk(), name, type, [&](TextOut& out) { write_svg(picture, out); });
        break;
      }
      case tek: {
        const std::string bytes = tek_stream(picture_of(ws.image), ctx.options().tek);
        write_user_file(ctx.disk(), name, type, bytes);
        size = bytes.size();
        break;
      }
      case hpgl: {
        // Written while it is made: a plot may be tens of megabytes.
        const Picture picture = picture_of(ws.image);
        size = write_user_file(ctx.disk(), name, type,
                               [&](TextOut& out) { plot_hpgl(picture, ctx.options().plot, out); });
        break;
      }
      case duct:
        // Made while it is written: a picture may be hundreds of megabytes.
        holds = image ? "THE IMAGE AS PROJECTED" : "THE SURFACE IN SPACE";
        size = write_user_file(ctx.disk(), name, type,
                               [&](TextOut& out) { counts_fit = duct_file(ws, name, image, out); });
        break;
      case iges:
      case step:
        size = write_user_file(ctx.disk(), name, type,
                               [&](TextOut& out) { cad_file(ws, name, code, choice, out); });
        break;
    }
  } catch (const DataError& e) {
    throw worded(e, "NO FILE WRITTEN");
  }
  if (holds.empty())
    ctx.say(fmt::format("{}.{}: {} BYTES", name, type, size));
  else
    ctx.say(fmt::format("{}.{}: {}, {} BYTES", name, type, holds, size));
  if (!counts_fit)
    ctx.say(
        fmt::format("{}.{}: A MILLION PIXELS OR MORE: ITS COUNTS DO NOT FIT DUCT'S I6 "
                    "FIELDS AND ARE WRITTEN FREE-FORM",
                    name, type));
  if (existed) ctx.say(fmt::format("{}.{} REPLACED", name, type));
}

constexpr const Prompt* questions[] = {&file_prompt, &duct_prompt};

}  // namespace

extern const Command export_command{
    .name = "EXPORT",
    .options = options,
    .follows = {},
    .option_prompt = {"SVG, TEK, HPGL, DUCT, IGES OR STEP?",
                      "The kind of file: SVG (a picture for a browser), TEK (a Tektronix 4013 "
                      "stream), HPGL (a plot), DUCT (a DUCT picture), IGES or STEP (CAD).",
                      options},
    .summary = "writes the current image (SVG, TEK, HPGL, DUCT) or the surface (DUCT, IGES, STEP)",
    .long_help =
        "EXPORT writes the current image (the one last displayed), with its description, or the "
        "current surface itself, to a file on the disk for other programs:\n"
        "\n"
        "  EXPORT SVG [name]   NAME.SVG, a picture any web browser shows, laid out as on the "
        "Tektronix screen\n"
        "  EXPORT TEK [name]   NAME.TEK, the bytes a Tektronix 4013 would receive (a clean "
        "screen, the image, the description); tek2plot and xterm -t read it\n"
        "  EXPORT HPGL [name]  NAME.HPGL, the plot PLOT would send, for a plotter or hp2xx\n"
        "  EXPORT DUCT [name [IMAGE]]  NAME.DUCTPIC, a DUCT 4.4 picture file: the current "
        "surface's curves and stringers as exact Bezier spans in space, the input points and "
        "border tangents in colour 2, whatever the current image; with IMAGE the current image "
        "as projected instead (a picture read by DISPLAY PICTURE, an image from a file)\n"
        "  EXPORT IGES [name]  NAME.IGS, the surface for CAD systems: one exact bicubic B-spline "
        "surface, one face, and the input curves and stringers as B-spline curves in a group "
        "CURVES (IGES 5.3)\n"
        "  EXPORT STEP [name]  NAME.STP, the same geometry in STEP (AP214)\n"
        "\n"
        "After the name of an IGES or STEP file, FACES writes each patch as a surface of its own "
        "(a face each, borders equal bit for bit), and M, MM, CM, INCH, FOOT or NONE is the unit "
        "the file declares (MM when none is given; NONE declares no unit, and readers assume "
        "one). IGDS's numbers are written as they are, whatever the unit.\n"
        "\n"
        "A file of the same name and type is replaced, and EXPORT says so (HULL.SVG REPLACED). "
        "With no current image EXPORT SVG, TEK or HPGL (and DUCT name IMAGE) says IMAGE NOT "
        "FOUND; with no surface EXPORT DUCT, IGES or STEP says SURFACE NOT FOUND; a name that "
        "is not 1 to 8 letters, digits or $ # @ + - _ gets INCORRECT PARAMETER. The exchange "
        "files are dated now, or by SOURCE_DATE_EPOCH.\n"
        "\n"
        "Example (EX S is EXPORT SVG, EX I is EXPORT IGES):\n"
        "  DISPLAY SURFACE ASSONOMETRIC 110 130 120\n"
        "  EXPORT SVG HULL\n"
        "  EX T HULL\n"
        "  EXPORT DUCT HULL\n"
        "  EX I HULL\n"
        "  EXPORT STEP HULL FACES M",
    .questions = questions,
    .run = run_export,
};

}  // namespace igds
