// EXPORT SVG | TEK | HPGL [name]: the current image in a file for other programs.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/picture.h"
#include "devices/plot.h"
#include "devices/svg.h"
#include "devices/terminal.h"
#include "workspace/error.h"

namespace igds {

namespace {

enum Option { svg, tek, hpgl };

// The option's word is also the file's type: NAME.SVG, NAME.TEK, NAME.HPGL.
constexpr Choice options[] = {
    {"SVG", svg, "[name]", "NAME.SVG, a picture any web browser shows"},
    {"TEK", tek, "[name]", "NAME.TEK, the bytes a Tektronix 4013 would receive"},
    {"HPGL", hpgl, "[name]", "NAME.HPGL, the plot PLOT would send"},
};

const Prompt file_prompt{"FILE NAME?",
                         "A name for the file: 1 to 8 letters, digits or $ # @ + - _ (a file\n"
                         "of that name and type is replaced)."};

void run_export(Context& ctx, const Choice* option) {
  const Workspace& ws = ctx.workspace();
  if (!ws.image) throw Report(reports::image_not_found);
  const std::string name = ask_file_name(ctx, file_prompt);
  std::string_view type = option->word;
  const Picture picture = picture_of(ws.image);
  std::string bytes = option->code == svg   ? svg_of(picture)
                      : option->code == tek ? tek_stream(picture, ctx.options().tek)
                                            : plot_hpgl(picture, ctx.options().plot).hpgl;
  const bool existed = ctx.disk().exists(name, type);
  write_user_file(ctx.disk(), name, type, bytes);
  ctx.say(fmt::format("{}.{}: {} BYTES", name, type, bytes.size()));
  if (existed) ctx.say(fmt::format("{}.{} REPLACED", name, type));
}

constexpr const Prompt* questions[] = {&file_prompt};

}  // namespace

extern const Command export_command{
    .name = "EXPORT",
    .options = options,
    .follows = {},
    .option_prompt = {"SVG, TEK OR HPGL?",
                      "The kind of file: SVG (a picture for a browser), TEK (a Tektronix 4013\n"
                      "stream) or HPGL (a plot).",
                      options},
    .summary = "writes the current image into NAME.SVG, NAME.TEK or NAME.HPGL",
    .long_help = R"(EXPORT writes the current image (the one last displayed), with its
description, to a file on the disk for other programs:

  EXPORT SVG [name]   NAME.SVG, a picture any web browser shows, laid
                      out as on the Tektronix screen
  EXPORT TEK [name]   NAME.TEK, the bytes a Tektronix 4013 would
                      receive (a clean screen, the image, the
                      description); tek2plot and xterm -t read it
  EXPORT HPGL [name]  NAME.HPGL, the plot PLOT would send, for a
                      plotter or hp2xx

A file of the same name and type is replaced, and EXPORT says so
(HULL.SVG REPLACED). With no current image EXPORT says IMAGE NOT
FOUND; a name that is not 1 to 8 letters, digits or $ # @ + - _ gets
INCORRECT PARAMETER.

Example (EX S is EXPORT SVG):
  DISPLAY SURFACE ASSONOMETRIC 110 130 120
  EXPORT SVG HULL
  EX T HULL)",
    .questions = questions,
    .run = run_export,
};

}  // namespace igds
