#include "interp/apl_env.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "commands/command.h"
#include "commands/reports.h"
#include "interp/apl/array_bridge.h"
#include "interp/apl/keyboard.h"
#include "interp/apl_args.h"
#include "interp/words.h"
#include "workspace/disk/apl_file.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/session_file.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/surface.h"
#include "workspace/kernels/vec3.h"
#include "workspace/variables.h"

namespace igds {

extern const Command save_command, restore_command;

namespace {

using apl::ErrorKind;
using apl::Value;

Array scalar(double v) {
  Array a;
  a.ravel = {v};
  return a;
}

Array vector(Ravel values) {
  Array a;
  a.shape = {values.size()};
  a.ravel = std::move(values);
  return a;
}

// The image slot a name reads or writes: IMAGE and DESIM, TEMP1 and DEST1, TEMP2 and DEST2.
ImageRef* image_slot(Workspace& ws, Variable v) {
  switch (v) {
    case Variable::image:
    case Variable::desim:
      return &ws.image;
    case Variable::temp1:
    case Variable::dest1:
      return &ws.temp1;
    case Variable::temp2:
    case Variable::dest2:
      return &ws.temp2;
    default:
      return nullptr;
  }
}

bool whole(double x) {
  return std::isfinite(x) && std::floor(x) == x;
}

// The explanation of the APL environment: SHORT, then LONG.
constexpr std::string_view short_help =
    "Type an APL statement (the IGDS variables are APL variables), )VARS, )FNS, START to go back "
    "to IGDS or )OFF to leave; )HELP LONG explains.";
constexpr std::string_view long_help =
    R"(The APL environment is APL\360: any statement, on the IGDS workspace variables
(manual section 7) and on variables and functions of your own.
  NOCUR NOSTR INTCU INTST   the grid: input curves and stringers, interpolated ones
  INPPN    input points, (NOCUR x NOSTR) x 3      INPTG   border tangents and point numbers
  PATCHES  the Coons matrices of every patch      INTPN   the interpolated grid
  IMAGE DESIM               the current image and its description
  TEMP1 DEST1 TEMP2 DEST2   the copies of STORE FIRST and SECOND
  STATUS   STATUS[1] is 1 for HELP LONG, 0 for SHORT
The manual's functions (section 7) are there: FIT COONS CURVILINEO DISTA F0 F1 G0 G1
ASSON CONIC ISOM ORTHOG PROSPAR SCALE DESCR DISPLA PLOTHP STATE WRT ... ()FNS lists
them); COMDIS 'SURFACE ISOMETRIC 3 30' or COMDIS 5 3 3 30 runs that command.
A function that fails, or that Ctrl-C stops, is suspended: )SI lists it, its local
names are there, →N goes on at its line N, → leaves it.
START goes back to IGDS (READY): what was made from a changed variable is made again
(PATCHES from the inputs, INTPN from PATCHES); a workspace that does not agree with
itself is refused, with the reason, and APL goes on. )SAVE NAME and )LOAD NAME keep
and bring back the surface with your variables and functions (the session keeps
them too), )COPY NAME [names] takes theirs, )CLEAR empties yours; )OFF leaves.
Here HELP is a name like any other, and a line starting with * a statement.
Without an APL keyboard, ` then a key types a symbol (`r is ⍴, `- is ×; list below).
Example:
      INPPN[5;3]←2
      ⍴INTPN
9 9 3)";

// A variable of the user's as the workspace keeps it, and back.
AplVariable stored(const std::string& name, const Value& v) {
  AplVariable a;
  a.name = name;
  a.shape.assign(v.shape().begin(), v.shape().end());
  a.characters = v.is_character();
  if (a.characters) {
    auto c = v.characters();
    a.text.assign(c.begin(), c.end());
  } else {
    auto x = v.numbers();
    a.numbers.assign(x.begin(), x.end());
  }
  return a;
}

Value value_of(const AplVariable& a) {
  const apl::Shape shape(a.shape.begin(), a.shape.end());
  if (!a.characters) return Value::of_numbers(shape, std::span<const double>(a.numbers));
  apl::Characters c(a.text.begin(), a.text.end());
  return Value::of_characters(shape, std::move(c));
}

bool is_error_report(std::string_view line) {
  for (auto kind : {ErrorKind::syntax, ErrorKind::value, ErrorKind::domain, ErrorKind::length,
                    ErrorKind::rank, ErrorKind::index, ErrorKind::ws_full, ErrorKind::defn,
                    ErrorKind::depth, ErrorKind::interrupt})
    if (line.starts_with(apl::error_words(kind))) return true;
  return line.starts_with("INCORRECT ") || line.starts_with("CANNOT ");
}

}  // namespace

std::optional<Array> workspace_variable(const Workspace& ws, std::string_view typed) {
  const VariableInfo* info = find_variable(upper(typed));
  if (!info) return std::nullopt;
  switch (info->id) {
    case Variable::nocur:
      return scalar(ws.nocur);
    case Variable::nostr:
      return scalar(ws.nostr);
    case Variable::intcu:
      return scalar(ws.intcu);
    case Variable::intst:
      return scalar(ws.intst);
    case Variable::inppn:
      return ws.inppn;
    case Variable::inptg:
      return ws.inptg;
    case Variable::patches: {
      Array made;
      const Array& patches = patches_of(ws, made);
      if (&patches == &made) return made;
      return patches;
    }
    case Variable::intpn:
      return ws.intpn;
    case Variable::status:
      return vector(Ravel(ws.status.begin(), ws.status.end()));
    default:
      break;
  }
  const ImageRef* image = image_slot(const_cast<Workspace&>(ws), info->id);
  if (!image || !*image) return std::nullopt;
  if (info->kept == Kept::image_view) return apl_args::desim_array((*image)->desim);
  return (*image)->points;
}

std::vector<std::string> defined_variables(const Workspace& ws) {
  std::vector<std::string> names;
  // Every variable has a value but an image slot that is empty (workspace_variable).
  for (const auto& v : variables()) {
    const ImageRef* image = image_slot(const_cast<Workspace&>(ws), v.id);
    if (!image || *image) names.emplace_back(v.name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

AplEnvironment::AplEnvironment(Workspace& ws, Hooks hooks)
    : ws_(ws), hooks_(std::move(hooks)), session_(*this) {
  define_manual_functions();
  // The functions of the session on the disk; one that no longer defines (a name taken by a
  // manual function since) is said and left out.
  for (const auto& source : ws_.functions) {
    try {
      session_.define_function(source);
    } catch (const apl::Error& e) {
      hooks_.report(fmt::format("{}: {}", e.what(), source.empty() ? "" : source[0]));
    }
  }
  ws_.functions = session_.defined_functions();
  // The variables likewise; the workspace keeps those the session has (keep_variables).
  const std::vector<AplVariable> saved = std::move(ws_.apl_variables);
  ws_.apl_variables.clear();
  for (const AplVariable& v : saved) {
    try {
      if (owns(v.name)) throw apl::Error(ErrorKind::defn);  // an IGDS variable's name
      session_.assign(v.name, value_of(v));
    } catch (const apl::Error& e) {
      hooks_.report(fmt::format("{}: {}", e.what(), v.name));
    }
  }
  keep_variables();
}

void AplEnvironment::keep_variables() {
  const std::uint64_t now = session_.variables_version();
  if (now == kept_version_) return;
  // Only the variables assigned or erased since the last time are copied: a statement costs its
  // own assignments, not the workspace's. The session file is written after every line and read
  // whole at start: the variables it keeps are bounded in all (disk::max_session_apl_bytes); one
  // that does not fit when assigned is said once.
  auto& kept = ws_.apl_variables;
  auto bytes_of = [](std::string_view name, const apl::Value& v) {
    return disk::stored_bytes(name.size(), v.shape().size(), v.size(), v.is_character());
  };
  for (const auto& [name, value] : session_.variables_changed(kept_version_)) {
    auto at =
        std::lower_bound(kept.begin(), kept.end(), name,
                         [](const AplVariable& v, const std::string& n) { return v.name < n; });
    if (at != kept.end() && at->name == name) {
      kept_bytes_ -=
          disk::stored_bytes(at->name.size(), at->shape.size(),
                             at->characters ? at->text.size() : at->numbers.size(), at->characters);
      at = kept.erase(at);
    }
    if (!value) continue;
    const std::size_t bytes = bytes_of(name, *value);
    if (bytes > disk::max_session_apl_bytes - kept_bytes_) {
      if (not_kept_.insert(name).second)
        hooks_.say(
            fmt::format("{} IS NOT KEPT WITH THE SESSION (MORE THAN {} MB IN ALL); )SAVE "
                        "KEEPS IT",
                        name, disk::max_session_apl_bytes >> 20));
      continue;
    }
    kept_bytes_ += bytes;
    kept.insert(at, stored(name, *value));
  }
  kept_version_ = now;
}

std::string AplEnvironment::help(bool long_text) {
  if (!long_text) return std::string(short_help);
  std::string text(long_help);
  text += "\nThe prefix keys:";
  for (const auto& line : apl::keyboard_help()) text += "\n" + line;
  return text;
}

apl::AplSession::Next AplEnvironment::execute(std::string_view line) {
  // )HELP, )HELP SHORT, )HELP LONG (or )H S ...): the explanation, its length kept in STATUS[1]
  // as HELP keeps it (HELP itself is a name in APL).
  std::vector<std::string> words = split_words(line);
  const std::string command = words.empty() ? "" : upper(std::string_view(words[0]).substr(1));
  if (!session_.defining() && !words.empty() && words.size() <= 2 && words[0].starts_with(')') &&
      command.size() > 0 && help_word().starts_with(command)) {
    if (words.size() == 2) {
      const Choice* length = choose(help_lengths(), words[1]);
      if (!length) {
        hooks_.report("INCORRECT COMMAND");
        return apl::AplSession::Next::stay;
      }
      ws_.status[0] = length->code;  // STATUS[1], as HELP SHORT and HELP LONG set it
    }
    values_.erase("STATUS");
    hooks_.document(help(ws_.status[0] == 1));
    return apl::AplSession::Next::stay;
  }
  const auto next = session_.execute(line);
  // Defined functions and variables are part of the workspace: the session keeps them.
  if (!session_.defining()) {
    auto functions = session_.defined_functions();
    if (functions != ws_.functions) ws_.functions = std::move(functions);
  }
  keep_variables();
  return next;
}

void AplEnvironment::print(std::string_view line) {
  if (is_error_report(line))
    hooks_.report(line);
  else
    hooks_.say(line);
}

std::optional<std::string> AplEnvironment::read_line(std::string_view prompt) {
  return hooks_.read(prompt);
}

bool AplEnvironment::owns(std::string_view name) const {
  return find_variable(name) != nullptr;
}

std::optional<Value> AplEnvironment::get(std::string_view name) {
  if (auto kept = values_.find(name); kept != values_.end()) return kept->second;
  auto a = workspace_variable(ws_, name);
  if (!a) return std::nullopt;
  return values_.emplace(std::string(name), apl::to_value(*a)).first->second;
}

void AplEnvironment::check(std::string_view name, const Value& value) {
  const VariableInfo& info = *find_variable(name);
  if (value.is_character()) throw apl::Error(ErrorKind::domain);
  const auto x = value.numbers();
  // No infinity or NaN enters the workspace (APL makes none; a native function might).
  if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); }))
    throw apl::Error(ErrorKind::domain);
  if (info.integer && !std::all_of(x.begin(), x.end(), whole)) throw apl::Error(ErrorKind::domain);
  switch (info.kept) {
    case Kept::surface_number:
      if (value.size() != 1) throw apl::Error(ErrorKind::length);
      if (x[0] < 0 || x[0] > std::numeric_limits<int>::max()) throw apl::Error(ErrorKind::domain);
      return;
    case Kept::status:
      if (value.rank() != 1) throw apl::Error(ErrorKind::rank);
      if (value.size() != 10) throw apl::Error(ErrorKind::length);
      return;
    case Kept::image_view:
      if (value.rank() != 1) throw apl::Error(ErrorKind::rank);
      if (value.size() != 5) throw apl::Error(ErrorKind::length);
      // A description needs the image it describes.
      if (!*image_slot(ws_, info.id)) throw apl::Error(ErrorKind::value);
      return;
    case Kept::image_points:
      if (value.rank() != 3) throw apl::Error(ErrorKind::rank);
      if (value.shape()[2] != 2) throw apl::Error(ErrorKind::length);
      return;
    case Kept::input:
    case Kept::derived:
      // An empty vector leaves a derived array to be made again at START.
      if (!(info.kept == Kept::derived && value.empty()) && value.rank() != info.rank)
        throw apl::Error(ErrorKind::rank);
      return;
  }
}

void AplEnvironment::set(std::string_view name, const Value& value) {
  const VariableInfo& info = *find_variable(name);
  Array a = apl::to_array(value);
  // PATCHES are those of the surface before END APL until START makes them again: the
  // interpolation's are made (state.h) before the first change of a variable of the surface.
  if (info.id != Variable::patches &&
      (info.kept == Kept::surface_number || info.kept == Kept::input ||
       info.kept == Kept::derived || info.kept == Kept::status))
    keep_patches(ws_);
  switch (info.id) {
    case Variable::nocur:
      ws_.nocur = static_cast<int>(a.ravel[0]);
      break;
    case Variable::nostr:
      ws_.nostr = static_cast<int>(a.ravel[0]);
      break;
    case Variable::intcu:
      ws_.intcu = static_cast<int>(a.ravel[0]);
      break;
    case Variable::intst:
      ws_.intst = static_cast<int>(a.ravel[0]);
      break;
    case Variable::inppn:
      ws_.inppn = std::move(a);
      break;
    case Variable::inptg:
      ws_.inptg = std::move(a);
      break;
    case Variable::patches:
      ws_.patches = a.empty() ? Array() : std::move(a);
      break;
    case Variable::intpn:
      ws_.intpn = a.empty() ? Array() : std::move(a);
      break;
    case Variable::status:
      if (!modes_before_) modes_before_ = {ws_.marks_twists(), ws_.auto_tangents()};
      for (std::size_t k = 0; k < 10; ++k) ws_.status[k] = static_cast<int>(a.ravel[k]);
      break;
    default: {
      // An image assigned is an image of its own: it is no longer a projection igds can redraw.
      ImageRef& slot = *image_slot(ws_, info.id);
      Image image = slot ? *slot : Image{};
      image.drawn_from = 0;
      image.file.clear();
      // Nor can igds tell what of it is hidden: it is drawn whole.
      image.desim.hidden = false;
      image.nearness = Array();
      // Combs are made with the surface's image: IMAGE or DESIM of APL's own have none.
      image.combs = Array();
      image.comb_scale = 0;
      if (info.kept == Kept::image_view) {
        image.desim = apl_args::description_of(a.ravel);
      } else {
        image.points = std::move(a);
        image.extent.reset();
        image.arrows = Array();
      }
      slot = std::make_shared<const Image>(std::move(image));
      values_.clear();  // an image and its description change together
      break;
    }
  }
  // The value stays as APL has it: the next statement reads it without a copy.
  values_.insert_or_assign(std::string(info.name), value);
  assigned_.insert(std::string(info.name));
}

namespace {

// The input point a derived array does not pass through (1, 2, ...), or 0. PATCHES holds each
// patch's corners as they are in INPPN and INTPN the input points at its nodes, bit for bit
// (docs/kernels.md), whoever made them.
std::size_t point_off_inputs(const Workspace& ws, Variable v) {
  const std::size_t nc = ws.nocur, ns = ws.nostr;
  if (nc < 2 || ns < 2 || ws.inppn.size() != nc * ns * 3) return 0;
  auto point = [&](std::size_t k, std::size_t c) { return ws.inppn.ravel[k * 3 + c]; };
  if (v == Variable::patches) {
    if (ws.patches.size() != (nc - 1) * (ns - 1) * 48) return 0;
    for (std::size_t i = 0; i + 1 < nc; ++i)
      for (std::size_t j = 0; j + 1 < ns; ++j)
        for (std::size_t c = 0; c < 3; ++c) {
          const double* m = ws.patches.ravel.data() + ((i * (ns - 1) + j) * 3 + c) * 16;
          const std::size_t k00 = i * ns + j, k10 = k00 + 1, k01 = k00 + ns, k11 = k01 + 1;
          const std::pair<std::size_t, double> corners[] = {
              {k00, m[0]}, {k01, m[1]}, {k10, m[4]}, {k11, m[5]}};
          for (const auto& [k, x] : corners)
            if (x != point(k, c)) return k + 1;
        }
    return 0;
  }
  const std::size_t rows = nc + ws.intcu * (nc - 1), cols = ns + ws.intst * (ns - 1);
  if (ws.intpn.size() != rows * cols * 3) return 0;
  for (std::size_t i = 0; i < nc; ++i)
    for (std::size_t j = 0; j < ns; ++j)
      for (std::size_t c = 0; c < 3; ++c) {
        const std::size_t node = (i * (ws.intcu + 1) * cols + j * (ws.intst + 1)) * 3 + c;
        if (ws.intpn.ravel[node] != point(i * ns + j, c)) return i * ns + j + 1;
      }
  return 0;
}

}  // namespace

std::optional<std::string> AplEnvironment::start() {
  if (assigned_.empty()) return std::nullopt;
  values_.clear();
  auto was = [&](std::initializer_list<std::string_view> names) {
    return std::any_of(names.begin(), names.end(),
                       [&](std::string_view n) { return assigned_.count(std::string(n)) > 0; });
  };
  // Each derived variable given a value of its own is kept (checked against the inputs below);
  // otherwise it is made again when what it is made from changed: PATCHES from NOCUR NOSTR
  // INPPN INPTG (COONS), INTPN from PATCHES and INTCU INTST (FIT). An emptied one is made again,
  // and what is made from it.
  // An emptied PATCHES takes INTPN with it.
  const bool own_patches = was({"PATCHES"}) && !ws_.patches.empty();
  const bool own_intpn =
      was({"INTPN"}) && !ws_.intpn.empty() && !(was({"PATCHES"}) && ws_.patches.empty());
  // STATUS[3] and STATUS[4] belong to the surface (docs/decisions.md): other twists make PATCHES
  // again, and either makes it another surface (its images, drawn before, are not of this one).
  const bool twists = modes_before_ && modes_before_->first != ws_.marks_twists();
  const bool modes = twists || (modes_before_ && modes_before_->second != ws_.auto_tangents());
  const bool patch_inputs = twists || was({"NOCUR", "NOSTR", "INPPN", "INPTG"});
  const bool remake_patches = !own_patches && (patch_inputs || was({"PATCHES"}));
  const bool remake_intpn =
      !own_intpn && (remake_patches || own_patches || was({"INTCU", "INTST", "INTPN"}));
  auto reason = [](const VariableProblem& p) { return p.reason; };
  const bool surface = modes || remake_patches || remake_intpn || own_patches || own_intpn ||
                       was({"NOCUR", "NOSTR", "INTCU", "INTST", "INPPN", "INPTG"});
  if (surface) {
    if (auto p = size_problem(ws_.nocur, ws_.nostr, ws_.intcu, ws_.intst)) return reason(*p);
    // The inputs are checked alone first, then what is made from them; a refusal gives back
    // PATCHES and INTPN as they were.
    Array old_patches = std::move(ws_.patches), old_intpn = std::move(ws_.intpn);
    ws_.patches = Array();
    ws_.intpn = Array();
    auto give_back = [&] {
      ws_.patches = std::move(old_patches);
      ws_.intpn = std::move(old_intpn);
    };
    if (auto p = surface_problem(ws_, true)) {
      give_back();
      return reason(*p);
    }
    Array patches, intpn;
    std::shared_ptr<const SplineTangents> tangents;  // those the interpolation made
    if (ws_.nocur > 0) {
      try {
        if (remake_patches) {
          Surface s = interpolate(igds::surface_input(ws_));
          patches = std::move(s.patches);
          intpn = std::move(s.intpn);
          tangents = std::move(s.tangents);
        } else if (remake_intpn) {
          intpn = refit(igds::surface_input(ws_), old_patches);
        }
      } catch (const DataError& e) {
        give_back();
        return std::string(worded(e).reason());
      }
    }
    // What is kept is moved back; what was made replaces it (the old kept aside, for a refusal).
    if (remake_patches) std::swap(patches, old_patches);
    if (remake_intpn) std::swap(intpn, old_intpn);
    ws_.patches = std::move(old_patches);
    ws_.intpn = std::move(old_intpn);
    old_patches = std::move(patches);
    old_intpn = std::move(intpn);
    auto keep_original = [&] {
      if (!remake_patches) old_patches = std::move(ws_.patches);
      if (!remake_intpn) old_intpn = std::move(ws_.intpn);
      give_back();
    };
    std::optional<std::string> problem;
    if (auto p = surface_problem(ws_, true)) problem = reason(*p);
    for (Variable v : {Variable::patches, Variable::intpn}) {
      if (problem || !(v == Variable::patches ? own_patches : own_intpn)) continue;
      if (const std::size_t k = point_off_inputs(ws_, v))
        problem = fmt::format("{} DOES NOT PASS THROUGH INPPN AT POINT {}", info(v).name, k);
    }
    if (problem) {
      keep_original();
      return problem;
    }
    // igds's interpolation when PATCHES was made here, or was and is kept (a FIT's stays its own).
    ws_.changes.replaced(!own_patches && !own_intpn && (remake_patches || ws_.changes.derived));
    keep_splines(ws_, std::move(tangents));
  }
  drop_derived_patches(ws_);
  for (Variable v : {Variable::image, Variable::temp1, Variable::temp2}) {
    const ImageRef& slot = *image_slot(ws_, v);
    if (slot)
      if (auto p = image_problem(*slot, v)) return reason(*p);
  }
  if (auto p = status_problem(ws_.status)) return reason(*p);
  assigned_.clear();
  modes_before_.reset();
  return std::nullopt;
}

void AplEnvironment::surface_replaced() {
  values_.clear();
  modes_before_.reset();  // the new surface's modes are its own
  for (const char* n : {"NOCUR", "NOSTR", "INTCU", "INTST", "INPPN", "INPTG", "PATCHES", "INTPN"})
    assigned_.erase(n);
}

void AplEnvironment::run_command(std::vector<std::string> words) {
  // The command sees the workspace whole: what APL changed is made consistent first.
  if (auto problem = start())
    throw apl::Error(ErrorKind::domain, fmt::format("CANNOT START: {}", *problem));
  ReadingFor igds(false);
  const bool done = hooks_.command(words);
  values_.clear();
  // The command's own report was printed; the function fails with it.
  if (!done) throw apl::Error(ErrorKind::domain, fmt::format("{} FAILED", words.front()));
}

std::vector<std::string> AplEnvironment::names() const {
  std::vector<std::string> out = defined_variables(ws_);
  for (auto& f : session_.function_names()) out.push_back(f);
  for (const auto& [name, v] : session_.variables()) out.push_back(name);
  for (const char* c : {")VARS", ")FNS", ")ERASE", ")DIGITS", ")ORIGIN", ")WIDTH", ")SI", ")SIC",
                        ")SAVE", ")LOAD", ")COPY", ")CLEAR", ")HELP", ")OFF"})
    out.emplace_back(c);
  return out;
}

std::vector<std::string> AplEnvironment::variable_names() const {
  return defined_variables(ws_);
}

std::vector<std::string> AplEnvironment::save_workspace(std::string_view typed) {
  // )SAVE NAME: the surface in NAME.IGDSDATA as SAVE writes it (when there is one), then the
  // user's functions and variables in NAME.IGDSAPLW, which says whether the surface went with
  // them.
  const auto name = cms_name(typed);
  if (!name || !hooks_.disk) {
    hooks_.report(reports::incorrect_parameter);
    return {};
  }
  // A surface that does not agree with itself is never written.
  if (auto problem = start()) return {fmt::format("NOT SAVED: {}", *problem)};
  disk::AplWorkspace apl;
  apl.surface = ws_.has_input();
  if (apl.surface && !hooks_.command({std::string(save_command.name), *name})) return {};
  apl.functions = session_.defined_functions();
  for (const auto& [n, v] : session_.variables()) apl.variables.push_back(stored(n, v));
  try {
    // The surface is saved by then: a refusal says so.
    disk::save_apl_workspace(*hooks_.disk, *name, apl,
                             apl.surface ? "ONLY THE SURFACE SAVED" : "NOT SAVED");
  } catch (const Report& r) {
    hooks_.report(r.what());
    return {};
  }
  return {fmt::format("SAVED {}", *name)};
}

// The functions and variables of a saved APL workspace into the session, those `wanted` (all
// when empty), replacing the session's of the same names; the names that could not be.
std::vector<std::string> AplEnvironment::take(const disk::AplWorkspace& from,
                                              const std::set<std::string>& wanted,
                                              std::set<std::string>& found) {
  auto chosen = [&](const std::string& n) {
    if (!wanted.empty() && !wanted.count(n)) return false;
    found.insert(n);
    return true;
  };
  std::vector<std::string> refused;
  for (const auto& source : from.functions) {
    std::string name;
    try {
      name = apl::AplSession::function_name(source);
    } catch (const apl::Error&) {
      refused.push_back(source.empty() ? "?" : source[0]);
      continue;
    }
    if (!chosen(name)) continue;
    // A variable of that name gives way to the function, and comes back if it does not define.
    const std::optional<apl::Value> was = session_.variable(name);
    if (was) session_.erase(name);
    try {
      session_.define_function(source);
    } catch (const apl::Error&) {
      if (was) session_.assign(name, *was);
      refused.push_back(name);
    }
  }
  for (const AplVariable& v : from.variables) {
    if (!chosen(v.name)) continue;
    try {
      if (owns(v.name)) throw apl::Error(ErrorKind::defn);  // an IGDS variable's name
      session_.erase(v.name);
      session_.assign(v.name, value_of(v));
    } catch (const apl::Error&) {
      refused.push_back(v.name);
    }
  }
  return refused;
}

std::vector<std::string> AplEnvironment::load_workspace(std::string_view typed) {
  // )LOAD NAME: the functions and variables of NAME.IGDSAPLW replace the session's, and its
  // surface (NAME.IGDSDATA, as RESTORE reads it) the current one when )SAVE wrote one with
  // them. Without NAME.IGDSAPLW (a SAVE of IGDS's), the surface alone. The APL file is read and
  // checked first: a damaged one changes nothing.
  const auto name = cms_name(typed);
  if (!name || !hooks_.disk) {
    hooks_.report(reports::incorrect_parameter);
    return {};
  }
  std::optional<disk::AplWorkspace> loaded;
  try {
    if (hooks_.disk->exists(*name, disk::apl_workspace_type))
      loaded = disk::load_apl_workspace(*hooks_.disk, *name);
  } catch (const Report& r) {
    hooks_.report(r.what());
    return {};
  }
  if (!loaded || loaded->surface) {
    if (!hooks_.command({std::string(restore_command.name), *name})) return {};
    // Nothing APL held of the old surface is written back by START.
    surface_replaced();
  }
  if (loaded) {
    session_.clear();
    std::set<std::string> found;
    for (const auto& r : take(*loaded, {}, found)) hooks_.report(fmt::format("NOT LOADED: {}", r));
  }
  return {fmt::format("LOADED {}", *name)};
}

std::vector<std::string> AplEnvironment::copy_workspace(std::string_view typed,
                                                        const std::vector<std::string>& names) {
  // )COPY NAME [names]: the functions and variables of NAME.IGDSAPLW (those named, or all) added
  // to the session's, replacing those of the same names; the surface is not touched.
  const auto name = cms_name(typed);
  if (!name || !hooks_.disk) {
    hooks_.report(reports::incorrect_parameter);
    return {};
  }
  disk::AplWorkspace loaded;
  try {
    loaded = disk::load_apl_workspace(*hooks_.disk, *name, "NOTHING COPIED");
  } catch (const Report& r) {
    hooks_.report(r.what());
    return {};
  }
  const std::set<std::string> wanted(names.begin(), names.end());
  std::set<std::string> found;
  const auto refused = take(loaded, wanted, found);
  std::string missing;
  for (const auto& n : wanted)
    if (!found.count(n)) missing += " " + n;
  if (!missing.empty()) hooks_.report("NOT FOUND:" + missing);
  for (const auto& r : refused) hooks_.report(fmt::format("NOT COPIED: {}", r));
  return {fmt::format("COPIED {}", *name)};
}

}  // namespace igds
