#include "interp/manual.h"

#include <fmt/format.h>

#include <string_view>

#include "commands/command.h"
#include "interp/command_line.h"

namespace igds {

namespace {

// Text for roff: backslashes escaped, a leading dot or quote kept literal, hyphens in option
// names as minus signs, characters beyond ASCII by their code point.
std::string roff(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\\') {
      out += "\\e";
    } else if (c == '-') {
      out += "\\-";
    } else if (c >= 0x80) {
      // One UTF-8 character.
      const int n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
      char32_t code = c & (0x7F >> n);
      for (int k = 1; k < n && i + 1 < text.size(); ++k)
        code = (code << 6) | (static_cast<unsigned char>(text[++i]) & 0x3F);
      out += fmt::format("\\[u{:04X}]", static_cast<std::uint32_t>(code));
    } else {
      if ((c == '.' || c == '\'') && (out.empty() || out.back() == '\n')) out += "\\&";
      out += static_cast<char>(c);
    }
  }
  return out;
}

// The option lines of the usage text (interp/command_line.cpp), one paragraph per option.
std::string options_section() {
  const std::string usage = usage_text();
  std::string out = ".SH OPTIONS\n";
  auto at = usage.find("options:\n");
  if (at == std::string::npos) return out;
  std::string_view rest = std::string_view(usage).substr(at + 9);
  bool open = false;
  while (!rest.empty()) {
    const auto end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (line.starts_with("  --")) {
      // "  --disk DIR             the user's disk": the option, then its text from column 25.
      constexpr std::size_t text_column = 25;
      std::string_view head = line.substr(2, text_column - 2);
      head = head.substr(0, head.find_last_not_of(' ') + 1);
      out += fmt::format(".TP\n.B {}\n", roff(head));
      if (line.size() > text_column) out += roff(line.substr(text_column)) + "\n";
      open = true;
    } else if (open) {
      const auto first = line.find_first_not_of(' ');
      if (first != std::string_view::npos) out += roff(line.substr(first)) + "\n";
    }
  }
  return out;
}

// Every command of the table, its forms and what it asks.
std::string commands_section() {
  std::string out = R"(.SH COMMANDS
Typed after
.BR READY ,
one to a line; words are separated by blanks or commas, and case does not matter.
Any command or option word may be cut down to its first letters: the first entry of the
table below, in its order, that starts with the letters typed is the one meant
.RB ( S
is STORE,
.B SA
is SAVE,
.B D SU
is DISPLAY SURFACE).
What is not on the line is asked for;
.B HELP
(or
.BR "HELP SHORT" ,
.BR "HELP LONG" )
at any question says what it awaits.
)";
  for (const Command* c : command_table()) {
    const auto forms = command_syntax(*c);
    out += ".TP\n";
    for (std::size_t i = 0; i < forms.size(); ++i) {
      if (i > 0) out += ".TQ\n";
      out += fmt::format(".B {}\n", roff(forms[i]));
    }
    out += roff(c->summary) + ".\n";
    for (const Choice& o : c->options)
      if (!o.help.empty()) out += fmt::format(".br\n{}: {}\n", roff(o.word), roff(o.help));
    for (const Prompt* q : c->questions) {
      out += fmt::format(".br\nAsks {}\n", roff(q->text));
      std::string help(q->short_help);
      for (char& ch : help)
        if (ch == '\n') ch = ' ';
      if (!help.empty()) out += fmt::format("({})\n", roff(help));
    }
  }
  return out;
}

constexpr std::string_view page_tail = R"(.SH FILES
Every file igds reads or writes is in the disk folder
.RB ( \-\-disk ,
else
.BR $IGDS_DISK ,
else the current folder); names are 1 to 8 letters, digits or
.B $ # @ + \- _
and are kept in capitals.
.TP
.B BINSAVE.IGDSCONT
the session, saved after every command and restored at the next start, with
.B Bnnnnnnn.IGDSVARS
(its large variables) and
.B Bnnnnnnn.IGDSVIMG
(second names of image files it shows).
.TQ
.B BINSAVE.IGDSLOCK
one igds per disk.
.TQ
.B BINSAVE.IGDSBAD
a damaged session, kept aside.
.TP
.B NAME.IGDSDATA
a surface (SAVE, RESTORE).
.TQ
.B NAME.IGDSIMAG
an image (STORE FILE, DISPLAY FILE).
.TQ
.B NAME.IGDSCHAR
a surface as FORTRAN card images (WRITE).
.TQ
.B PLOTnnnn.HPGL
a plot (PLOT).
.TQ
.B NAME.SVG NAME.TEK NAME.HPGL
the current image (EXPORT).
.TQ
.B HISTORY.IGDSHIST
the lines typed at the keyboard.
.SH ENVIRONMENT
.TP
.B IGDS_DISK
the disk folder when
.B \-\-disk
is not given.
.TP
.B TERM
with
.BR XTERM_VERSION ,
chooses the terminal mode when
.B \-\-term
is not given:
.B tek
for
.BR tek* ,
.B xterm
under xterm, else
.BR none .
.SH EXIT STATUS
.TP
.B 0
after END or the end of the input.
.TP
.B 1
a command file could not be read, the disk could not be used (another igds holds it), or at
the end the session could not be saved or the output could not be written.
.TP
.B 2
a command line igds does not understand.
.TP
.B 3
with
.BR \-\-strict ,
the first error report in a command file.
.SH EXAMPLES
.TP
.B igds\-tek
igds in the Tek window of a new xterm, where pictures are drawn.
.TP
.B igds \-\-term tek hull.igds > hull.tek
a command file's session as a Tektronix 4013 stream;
.B tek2plot \-T png hull.tek > hull.png
draws it.
.TP
.B igds \-\-disk ~/surfaces
the session of another folder.
.SH SEE ALSO
.BR xterm (1),
.BR tek2plot (1),
.BR hp2xx (1);
the documents in
.IR /usr/share/doc/igds .
)";

}  // namespace

std::string manual_page(const std::string& version, const std::string& date) {
  std::string out = fmt::format(
      ".TH IGDS 1 {} \"igds {}\" \"User Commands\"\n"
      ".SH NAME\n"
      "igds \\- Interactive Design of Interpolated Surfaces\n"
      ".SH SYNOPSIS\n"
      ".B igds\n"
      ".RB [ 4013 | 2250 ]\n"
      ".RI [ options ]\n"
      ".RI [ file \" ...]\"\n"
      ".RB [ \\- ]\n",
      date, version);
  out += R"(.SH DESCRIPTION
igds re-creates IGDS, the 1975 CNUCE/IBM Pisa system for the interactive design of
surfaces: a surface is a rectangular grid of points with the tangents at its border,
interpolated with bicubic Coons patches, and looked at in conic, isometric, axonometric
or orthogonal projection on a Tektronix 4013 screen (the Tek window of
.BR xterm ),
kept on the disk and plotted on an HP-GL pen plotter.
The conversation is the manual's: igds says
.BR READY ,
a command is typed, igds asks for what is missing.
The whole session is saved after every command and comes back at the next start.
.PP
The
.I files
are command files, read as if typed; igds ends after the last one unless
.B \-
follows. A standard input that is not a terminal is read as a command file.
After
.BR "END APL" ,
the workspace's variables are those of an APL\e360 session.
)";
  out += options_section();
  out += commands_section();
  out += page_tail;
  return out;
}

std::string launcher_page(const std::string& version, const std::string& date) {
  return fmt::format(R"(.TH IGDS\-TEK 1 {} "igds {}" "User Commands"
.SH NAME
igds\-tek \- igds in the Tek window of a new xterm
.SH SYNOPSIS
.B igds\-tek
.RI [ "igds arguments" ]
.SH DESCRIPTION
.B igds\-tek
opens
.B xterm \-t
with its Tektronix window the size of the 4013's screen (1024 x 780) and GIN reports ended by
a carriage return, and runs
.B igds
in it with the arguments given, so that DISPLAY draws its pictures where the dialogue is.
Without xterm, or without an X display, it says so and what to do instead.
.SH SEE ALSO
.BR igds (1),
.BR xterm (1)
)",
                     date, version);
}

std::string bash_completion() {
  std::string options, cases;
  for (const OptionSpec& o : command_line_options()) {
    if (!options.empty()) options += ' ';
    options += o.name;
    if (!o.values.empty()) {
      std::string values;
      for (auto v : o.values) {
        if (!values.empty()) values += ' ';
        values += v;
      }
      cases += fmt::format(
          "    {})\n      COMPREPLY=($(compgen -W \"{}\" -- \"$cur\"))\n"
          "      return ;;\n",
          o.name, values);
    } else if (o.value == "DIR") {
      cases += fmt::format(
          "    {})\n      COMPREPLY=($(compgen -d -- \"$cur\"))\n      return ;;\n", o.name);
    } else if (!o.value.empty()) {
      cases += fmt::format(
          "    {})\n      COMPREPLY=($(compgen -f -- \"$cur\"))\n      return ;;\n", o.name);
    }
  }
  return fmt::format(R"(# bash completion for igds(1), generated from igds's own option table.
_igds() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} prev=${{COMP_WORDS[COMP_CWORD-1]}}
  case $prev in
{}  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "{}" -- "$cur"))
  elif ((COMP_CWORD == 1)) && [[ $cur == [0-9]* ]]; then
    COMPREPLY=($(compgen -W "4013 2250" -- "$cur"))
  else
    COMPREPLY=($(compgen -f -X '!*.igds' -- "$cur") $(compgen -d -- "$cur"))
  fi
  return 0
}}
complete -o filenames -F _igds igds igds-tek
)",
                     cases, options);
}

}  // namespace igds
