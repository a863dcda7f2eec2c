// LIST POINTS | TANGENTS | SURFACE | FILES | IMAGES: what the workspace and the disk hold, as
// text (paged by the terminal like HELP LONG). Not in the 1975 manual: its users had listings.
#include <ctime>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/picture.h"
#include "workspace/error.h"

namespace igds {

extern const Command export_command;

namespace {

enum Option { points, tangents, surface, files, images };

constexpr Choice options[] = {
    {"POINTS", points, {}, "the input points with their numbers, curve by curve"},
    {"TANGENTS", tangents, {}, "the border tangents with their points and directions"},
    {"SURFACE", surface, {}, "the surface's sizes, tangent mode and twist mode"},
    {"FILES", files, {}, "the files on the disk by type, with sizes and dates"},
    {"IMAGES", images, {}, "what the current image, FIRST and SECOND hold"},
};

// A number right-aligned in the columns of a listing.
std::string column(double value) {
  return fmt::format("{:>14}", plain_number(value));
}

std::string point_listing(const Workspace& ws) {
  std::string out = fmt::format("INPUT POINTS: {} CURVES OF {} POINTS\n", ws.nocur, ws.nostr);
  out += fmt::format("{:>5}{:>6}{:>6}{:>14}{:>14}{:>14}\n", "K", "CURVE", "PLACE", "X", "Y", "Z");
  // Only rows that are there (the variables are checked at every START, but a listing never
  // reads past them).
  const std::size_t rows = ws.inppn.rank() == 2 && ws.inppn.shape[1] == 3 ? ws.inppn.shape[0] : 0;
  const double* p = ws.inppn.data();
  for (int c = 1; c <= ws.nocur; ++c) {
    if (c > 1) out += '\n';  // curve by curve
    for (int place = 1; place <= ws.nostr; ++place) {
      const int k = (c - 1) * ws.nostr + place;  // point-number order (docs/interp.md, "END APL")
      if (static_cast<std::size_t>(k) > rows) break;
      const double* xyz = p + 3 * (k - 1);
      out += fmt::format("{:>5}{:>6}{:>6}{}{}{}\n", k, c, place, column(xyz[0]), column(xyz[1]),
                         column(xyz[2]));
    }
  }
  return out;
}

std::string tangent_listing(const Workspace& ws) {
  // INPTG's rows (workspace/state.h): 2 NOCUR along the curves, then 2 NOSTR along the stringers.
  const std::size_t rows =
      ws.inptg.rank() == 2 && ws.inptg.shape[1] == 4 && ws.nostr > 0 ? ws.inptg.shape[0] : 0;
  std::string out = fmt::format("BORDER TANGENTS: {} ALONG THE CURVES, {} ALONG THE STRINGERS\n",
                                2 * ws.nocur, 2 * ws.nostr);
  out += fmt::format("{:>5}{:>6}{:>6}  {:<9}{:>14}{:>14}{:>14}\n", "K", "CURVE", "PLACE", "ALONG",
                     "X", "Y", "Z");
  const double* t = ws.inptg.data();
  for (std::size_t i = 0; i < rows; ++i) {
    const double* row = t + 4 * i;
    const int k = static_cast<int>(row[3]);
    const bool along_curve = i < 2 * static_cast<std::size_t>(ws.nocur);
    if (i == 2 * static_cast<std::size_t>(ws.nocur)) out += '\n';
    out += fmt::format("{:>5}{:>6}{:>6}  {:<9}{}{}{}\n", k, (k - 1) / ws.nostr + 1,
                       (k - 1) % ws.nostr + 1, along_curve ? "CURVE" : "STRINGER", column(row[0]),
                       column(row[1]), column(row[2]));
  }
  return out;
}

// How the surface's tangents and twists were chosen. The workspace knows one way today: the
// border tangents as typed (zero ones included) and zero twists (docs/kernels.md, the manual's
// choice).
std::vector<std::string> interpolation_modes(const Workspace& ws) {
  return {
      ws.auto_tangents() ? "TANGENTS: AUTO (MARKS'S RULE)" : "TANGENTS: TYPED",
      ws.marks_twists() ? "TWISTS: MARKS TWISTS (BIRKHOFF AND DE BOOR)" : "TWISTS: ZERO TWISTS"};
}

std::string surface_listing(const Workspace& ws) {
  std::string out = fmt::format("NOCUR {}  NOSTR {}  INTCU {}  INTST {}\n", ws.nocur, ws.nostr,
                                ws.intcu, ws.intst);
  out += fmt::format("INPUT POINTS {}, BORDER TANGENTS {}\n", ws.nocur * ws.nostr,
                     2 * (ws.nocur + ws.nostr));
  if (ws.has_surface() && ws.intpn.rank() == 3) {
    out += fmt::format("PATCHES {} BY {}\n", ws.nocur - 1, ws.nostr - 1);
    out += fmt::format("INTERPOLATED GRID {} BY {} POINTS\n", ws.intpn.shape[0], ws.intpn.shape[1]);
  } else {
    out += "NOT INTERPOLATED\n";
  }
  for (const auto& line : interpolation_modes(ws)) out += line + '\n';
  return out;
}

std::string date(std::int64_t seconds) {
  const std::time_t t = static_cast<std::time_t>(seconds);
  std::tm tm{};
  if (!localtime_r(&t, &tm)) return "?";
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &tm);
  return text;
}

// What each type of file on the disk is (docs/disk.md).
std::string_view type_meaning(std::string_view type) {
  if (type == "IGDSDATA") return "SURFACES (SAVE, RESTORE)";
  if (type == "IGDSCHAR") return "CARD IMAGES (WRITE)";
  if (type == "IGDSIMAG") return "IMAGES (STORE FILE, DISPLAY FILE)";
  if (type == "IGDSCONT") return "THE SESSION";
  if (type == "IGDSVARS") return "PARTS OF THE SESSION";
  if (type == "IGDSVIMG") return "IMAGES OF THE SESSION";
  if (type == "IGDSLOCK") return "THE LOCK OF THE SESSION";
  if (type == "IGDSBAD") return "DAMAGED SESSIONS, KEPT ASIDE";
  if (type == "IGDSHIST") return "THE HISTORY OF TYPED LINES";
  if (type == "IGDSAPLW") return "APL FUNCTIONS AND VARIABLES ()SAVE, )LOAD IN END APL)";
  return "";
}

// The types EXPORT writes are its options' words (commands/export.cpp).
std::string meaning_of(std::string_view type) {
  for (const Choice& o : export_command.options)
    if (o.word == type) return fmt::format("{} {}", export_command.name, o.word);
  return std::string(type_meaning(type));
}

std::string file_listing(const Disk& disk) {
  const auto all = disk.files();
  std::string out = fmt::format("DISK {}: {} FILES\n", disk.dir().string(), all.size());
  std::string type;
  for (const auto& f : all) {
    if (f.type != type) {
      type = f.type;
      const std::string meaning = meaning_of(type);
      out += fmt::format("\n{}{}{}\n", type, meaning.empty() ? "" : ": ", meaning);
    }
    out += fmt::format("  {:<8} {:>12} BYTES  {}\n", f.name, f.bytes, date(f.written));
  }
  return out;
}

std::string image_lines(const Workspace& ws, const ImageRef& image, std::string_view what) {
  const std::string label = fmt::format("{:<15}", what);
  const std::string indent(label.size(), ' ');
  if (!image) return label + "NONE\n";
  if (&image != &ws.image && image == ws.image) return label + "THE CURRENT IMAGE\n";
  std::string line = describe_line(image->desim);
  line = line.substr(line.find(": ") + 2);  // without "IMAGE: "
  std::string out = label + line + '\n';
  const auto& p = image->points;
  if (p.rank() == 3)
    out += indent + fmt::format("{} BY {} POINTS{}\n", p.shape[0], p.shape[1],
                                image->desim.what == 0 && image->arrows.rank() == 2
                                    ? fmt::format(", {} ARROWS", image->arrows.shape[0])
                                    : "");
  if (!image->file.empty())
    out += indent + fmt::format("FROM {}\n", image->file.filename().string());
  if (const auto& w = image->window) out += indent + zoom_words(*w) + '\n';
  return out;
}

std::string image_listing(const Workspace& ws) {
  return image_lines(ws, ws.image, "CURRENT IMAGE") + image_lines(ws, ws.temp1, "STORE FIRST") +
         image_lines(ws, ws.temp2, "STORE SECOND");
}

void run_list(Context& ctx, const Choice* option) {
  expect_no_more_words(ctx);
  const Workspace& ws = ctx.workspace();
  const auto code = static_cast<Option>(option->code);
  if ((code == points || code == tangents || code == surface) && !ws.has_input())
    throw Report(reports::input_not_found);
  switch (code) {
    case points:
      return ctx.document(point_listing(ws));
    case tangents:
      return ctx.document(tangent_listing(ws));
    case surface:
      return ctx.document(surface_listing(ws));
    case files:
      return ctx.document(file_listing(ctx.disk()));
    case images:
      return ctx.document(image_listing(ws));
  }
}

}  // namespace

extern const Command list_command{
    .name = "LIST",
    .options = options,
    .follows = {},
    .option_prompt = {"POINTS, TANGENTS, SURFACE, FILES OR IMAGES?",
                      "POINTS, TANGENTS or SURFACE: the current surface; FILES: the disk; "
                      "IMAGES: the current image and the copies of STORE FIRST and SECOND.",
                      options},
    .summary = "lists the points, the tangents, the surface, the files or the images",
    .long_help =
        "LIST writes what the workspace or the disk holds, as text (a long listing is shown a "
        "page at a time, as HELP LONG is). Nothing changes.\n"
        "\n"
        "  LIST POINTS    the input points, curve by curve: the point number K (the number CHANGE "
        "POINTS asks for), its curve, its place on the curve, and x y z\n"
        "  LIST TANGENTS  the border tangents: the point number, its curve and place, along the "
        "CURVE or the STRINGER, and x y z\n"
        "  LIST SURFACE   NOCUR NOSTR INTCU INTST, the sizes of the patches and of the "
        "interpolated grid, how the tangents and the twists were chosen\n"
        "  LIST FILES     the files on the disk, by type, with their sizes and the dates they "
        "were last written\n"
        "  LIST IMAGES    what the current image, FIRST and SECOND hold: what they show, the "
        "projection, their size, the file they came from, the window of a ZOOM\n"
        "\n"
        "POINTS, TANGENTS and SURFACE say INPUT NOT FOUND when there is no current surface.\n"
        "\n"
        "Example (L P is LIST POINTS):\n"
        "  LIST POINTS\n"
        "  L F",
    .questions = {},
    .run = run_list,
};

}  // namespace igds
