#include "interp/apl_env.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "commands/command.h"
#include "commands/picture.h"
#include "commands/reports.h"
#include "interp/apl/array_bridge.h"
#include "interp/words.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/surface.h"
#include "workspace/kernels/vec3.h"
#include "workspace/variables.h"

namespace igds {

extern const Command help_command, end_command;

namespace {

using apl::ErrorKind;
using apl::Value;

Array scalar(double v) {
  Array a;
  a.ravel = {v};
  return a;
}

Array vector(std::vector<double> values) {
  Array a;
  a.shape = {values.size()};
  a.ravel = std::move(values);
  return a;
}

// DESIM as the manual's 5-element vector.
Array desim(const Description& d) {
  return vector({static_cast<double>(d.what), static_cast<double>(static_cast<int>(d.projection)),
                 d.parameters[0], d.parameters[1], d.parameters[2]});
}

Description description_of(std::span<const double> v) {
  Description d;
  d.what = static_cast<int>(v[0]);
  d.projection = static_cast<Projection>(static_cast<int>(v[1]));
  d.parameters = {v[2], v[3], v[4]};
  return d;
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

// A kernel's refusal as an APL report in igds's words.
[[noreturn]] void refuse(const DataError& e) {
  throw apl::Error(ErrorKind::domain, worded(e).what());
}

// The points of a projection function's left argument: any rank, 3 on the last axis.
Array points_argument(const Value* v) {
  if (!v || v->is_character()) throw apl::Error(ErrorKind::domain);
  if (v->rank() == 0 || v->shape().back() != 3) throw apl::Error(ErrorKind::length);
  return apl::to_array(*v);
}

// The projection of `points` by one of the manual's four functions: the same shape with 2 on
// the last axis.
template <typename F>
Value projected(const Array& points, F project) {
  Array out;
  out.shape = points.shape;
  out.shape.back() = 2;
  out.ravel.assign(points.size() / 3 * 2, 0.0);
  try {
    project(as_vec3(points), as_point2(out));
  } catch (const DataError& e) {
    refuse(e);
  }
  return apl::to_value(out);
}

std::vector<double> numbers_of(const Value* v, std::size_t count) {
  if (!v || v->is_character()) throw apl::Error(ErrorKind::domain);
  if (v->rank() > 1) throw apl::Error(ErrorKind::rank);
  if (v->size() != count) throw apl::Error(ErrorKind::length);
  auto x = v->numbers();
  return {x.begin(), x.end()};
}

// The words of a COMxxx function's argument: a character vector, or an empty vector.
std::vector<std::string> words_of(const Value* v) {
  if (!v || v->empty()) return {};
  if (!v->is_character() || v->rank() > 1) throw apl::Error(ErrorKind::domain);
  return split_words(v->utf8());
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
    case Variable::patches:
      return ws.patches;
    case Variable::intpn:
      return ws.intpn;
    case Variable::status:
      return vector(std::vector<double>(ws.status.begin(), ws.status.end()));
    default:
      break;
  }
  const ImageRef* image = image_slot(const_cast<Workspace&>(ws), info->id);
  if (!image || !*image) return std::nullopt;
  if (info->kept == Kept::image_view) return desim((*image)->desim);
  return (*image)->points;
}

std::vector<std::string> defined_variables(const Workspace& ws) {
  std::vector<std::string> names;
  for (const auto& v : variables())
    if (workspace_variable(ws, v.name)) names.emplace_back(v.name);
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
}

apl::AplSession::Next AplEnvironment::execute(std::string_view line) {
  const auto next = session_.execute(line);
  // Defined functions are part of the workspace: the session keeps them.
  if (!session_.defining()) {
    auto functions = session_.defined_functions();
    if (functions != ws_.functions) ws_.functions = std::move(functions);
  }
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
  values_.clear();  // an image and its description change together; START may remake others
  Array a = apl::to_array(value);
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
      for (std::size_t k = 0; k < 10; ++k) ws_.status[k] = static_cast<int>(a.ravel[k]);
      break;
    default: {
      // An image assigned is an image of its own: it is no longer a projection igds can redraw.
      ImageRef& slot = *image_slot(ws_, info.id);
      Image image = slot ? *slot : Image{};
      image.drawn_from = 0;
      image.file.clear();
      if (info.kept == Kept::image_view) {
        image.desim = description_of(a.ravel);
      } else {
        image.points = std::move(a);
        image.arrows = Array();
      }
      slot = std::make_shared<const Image>(std::move(image));
      break;
    }
  }
  assigned_.insert(std::string(info.name));
}

std::optional<std::string> AplEnvironment::start() {
  if (assigned_.empty()) return std::nullopt;
  values_.clear();
  auto was = [&](std::initializer_list<std::string_view> names) {
    return std::any_of(names.begin(), names.end(),
                       [&](std::string_view n) { return assigned_.count(std::string(n)) > 0; });
  };
  const bool inputs = was({"NOCUR", "NOSTR", "INTCU", "INTST", "INPPN", "INPTG"});
  // PATCHES or INTPN given values of their own are kept; emptied, they are made again.
  const bool assigned_derived = was({"PATCHES", "INTPN"});
  const bool emptied = assigned_derived && (ws_.patches.empty() || ws_.intpn.empty());
  const bool derived = assigned_derived && !emptied;
  auto reason = [](const VariableProblem& p) { return p.reason; };
  if ((inputs || emptied) && !derived) {
    // The inputs changed: PATCHES and INTPN are made again from them, as CHANGE does.
    if (auto p = size_problem(ws_.nocur, ws_.nostr, ws_.intcu, ws_.intst)) return reason(*p);
    Array patches = std::move(ws_.patches), intpn = std::move(ws_.intpn);
    ws_.patches = Array();
    ws_.intpn = Array();
    auto problem = surface_problem(ws_, true);
    if (!problem && ws_.nocur > 0) {
      try {
        Surface s = interpolate(igds::surface_input(ws_));
        ws_.patches = std::move(s.patches);
        ws_.intpn = std::move(s.intpn);
      } catch (const DataError& e) {
        ws_.patches = std::move(patches);
        ws_.intpn = std::move(intpn);
        return std::string(worded(e).reason());
      }
    } else if (problem) {
      ws_.patches = std::move(patches);
      ws_.intpn = std::move(intpn);
      return reason(*problem);
    }
    ws_.changes.replaced(true);
  } else if (inputs || derived) {
    if (auto p = surface_problem(ws_, true)) return reason(*p);
    ws_.changes.replaced(!derived);
  }
  for (Variable v : {Variable::image, Variable::temp1, Variable::temp2}) {
    const ImageRef& slot = *image_slot(ws_, v);
    if (slot)
      if (auto p = image_problem(*slot, v)) return reason(*p);
  }
  if (auto p = status_problem(ws_.status)) return reason(*p);
  assigned_.clear();
  return std::nullopt;
}

std::vector<std::string> AplEnvironment::names() const {
  std::vector<std::string> out = defined_variables(ws_);
  for (auto& f : session_.function_names()) out.push_back(f);
  for (const char* c : {")VARS", ")FNS", ")ERASE", ")DIGITS", ")ORIGIN", ")SAVE", ")LOAD", ")OFF"})
    out.emplace_back(c);
  return out;
}

std::vector<std::string> AplEnvironment::variable_names() const {
  return defined_variables(ws_);
}

std::string AplEnvironment::save_workspace(std::string_view name) {
  // A surface that does not agree with itself is never written.
  if (auto problem = start()) return fmt::format("NOT SAVED: {}", *problem);
  return hooks_.save(name);
}

std::string AplEnvironment::load_workspace(std::string_view name) {
  return hooks_.load(name);
}

void AplEnvironment::define_manual_functions() {
  using Args = const Value*;
  auto surface_input = [this] {
    if (ws_.nocur == 0) throw apl::Error(ErrorKind::value);
    return igds::surface_input(ws_);
  };
  session_.define_native(
      "FIT", 0,
      [this, surface_input](Args, Args) -> std::optional<Value> {
        if (ws_.patches.empty()) throw apl::Error(ErrorKind::value);
        try {
          return apl::to_value(refit(surface_input(), ws_.patches));
        } catch (const DataError& e) {
          refuse(e);
        }
      },
      "FIT: the grid INTPN from NOCUR NOSTR INTCU INTST INPPN PATCHES (the result)");
  session_.define_native(
      "COONS", 0,
      [this, surface_input](Args, Args) -> std::optional<Value> {
        try {
          session_.assign("PATCHES", apl::to_value(interpolate(surface_input()).patches));
        } catch (const DataError& e) {
          refuse(e);
        }
        return std::nullopt;
      },
      "COONS: PATCHES from NOCUR NOSTR INPPN INPTG");
  session_.define_native(
      "ORTHOG", 2,
      [](Args points, Args dropped) -> std::optional<Value> {
        const double d = numbers_of(dropped, 1)[0];
        if (d != 1 && d != 2 && d != 3) throw apl::Error(ErrorKind::domain);
        const int plane = d == 3 ? 1 : d == 2 ? 2 : 3;  // the plane of the other two coordinates
        return projected(points_argument(points),
                         [&](Vec3View in, MutablePoint2View out) { orthog(in, plane, out); });
      },
      "P ORTHOG K: the points P (last axis 3) without their coordinate K (1 X, 2 Y, 3 Z)");
  session_.define_native(
      "ISOM", 2,
      [](Args points, Args parameters) -> std::optional<Value> {
        const auto p = numbers_of(parameters, 2);
        if (p[0] != 1 && p[0] != 2 && p[0] != 3) throw apl::Error(ErrorKind::domain);
        return projected(points_argument(points), [&](Vec3View in, MutablePoint2View out) {
          isom(in, static_cast<int>(p[0]), p[1], out);
        });
      },
      "P ISOM AXIS ANGLE: the isometric projection of the points P");
  session_.define_native(
      "ASSON", 2,
      [](Args points, Args angles) -> std::optional<Value> {
        const auto a = numbers_of(angles, 3);
        return projected(points_argument(points), [&](Vec3View in, MutablePoint2View out) {
          asson(in, {a[0], a[1], a[2]}, out);
        });
      },
      "P ASSON A B C: the axonometric projection of the points P, angles in degrees");
  session_.define_native(
      "CONIC", 2,
      [](Args points, Args view) -> std::optional<Value> {
        const auto v = numbers_of(view, 3);
        const Array p = points_argument(points);
        return projected(p, [&](Vec3View in, MutablePoint2View out) {
          conic(in, {v[0], v[1], v[2]}, bounding_box_centre(in), out);
        });
      },
      "P CONIC V: the perspective of the points P seen from V towards their centre");
  session_.define_native(
      "SCALE", 2,
      [](Args box, Args points) -> std::optional<Value> {
        // The points' bounding box into the rectangle from (X0, Y0) to (XMAX, YMAX), one scale
        // for both axes, from the corner (X0, Y0), as DISPLA scaled IMAGE for the screen.
        const auto b = numbers_of(box, 4);
        if (!points || points->is_character()) throw apl::Error(ErrorKind::domain);
        if (points->rank() == 0 || points->shape().back() != 2) throw apl::Error(ErrorKind::length);
        Array p = apl::to_array(*points);
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (std::size_t i = 0; i < p.size(); ++i) {
          lo[i % 2] = std::min(lo[i % 2], p.ravel[i]);
          hi[i % 2] = std::max(hi[i % 2], p.ravel[i]);
        }
        const double w = hi[0] - lo[0], h = hi[1] - lo[1];
        const double sx = w > 0 ? (b[2] - b[0]) / w : INFINITY,
                     sy = h > 0 ? (b[3] - b[1]) / h : INFINITY;
        double s = std::min(sx, sy);
        if (!std::isfinite(s)) s = 1;
        for (std::size_t i = 0; i < p.size(); ++i)
          p.ravel[i] = b[i % 2] + s * (p.ravel[i] - lo[i % 2]);
        return apl::to_value(p);
      },
      "X0 Y0 XMAX YMAX SCALE P: the points P (last axis 2) scaled into that rectangle");
  session_.define_native(
      "DESCR", 1,
      [](Args, Args d) -> std::optional<Value> {
        const auto v = numbers_of(d, 5);
        Image image;
        image.desim = description_of(v);
        if (image_problem(image)) throw apl::Error(ErrorKind::domain);
        return Value::text(describe_line(image.desim));
      },
      "DESCR DESIM: the description of an image, as DISPLAY writes it");
  session_.define_native(
      "LUT", 2,
      [](Args table, Args word) -> std::optional<Value> {
        // The first row of the character matrix that starts with the word (its row number,
        // from 1), else 0: how GETCOM looked commands up in their table.
        if (!table || !word || !table->is_character() || !word->is_character())
          throw apl::Error(ErrorKind::domain);
        if (table->rank() != 2 || word->rank() > 1) throw apl::Error(ErrorKind::rank);
        const auto t = table->characters();
        const auto w = word->characters();
        const std::size_t rows = table->shape()[0], cols = table->shape()[1];
        for (std::size_t r = 0; r < rows; ++r)
          if (w.size() <= cols && std::equal(w.begin(), w.end(), t.begin() + r * cols))
            return Value::number(static_cast<double>(r + 1));
        return Value::number(0);
      },
      "TABLE LUT WORD: the first row of TABLE that starts with WORD, else 0");
  session_.define_native(
      "INIT", 0,
      [this](Args, Args) -> std::optional<Value> {
        hooks_.say("INIT: THE SESSION WAS RESTORED WHEN IGDS STARTED; RESTORE READS A SURFACE");
        return std::nullopt;
      },
      "INIT: done by igds when it starts (the session comes back by itself)");
  // The command functions of the manual's commands (those before HELP in the table): COM and
  // the command's first three letters (COMBUI is BUILD, COMDIS DISPLAY, ...); the argument is
  // the words that follow the command, as typed after READY.
  std::vector<std::pair<std::string, std::string>> commands;
  for (const Command* c : command_table()) {
    if (c == &help_command) break;
    commands.emplace_back("COM" + std::string(c->name.substr(0, 3)), std::string(c->name));
  }
  for (const auto& [function, command] : commands) {
    const std::string word = command;
    const bool end = word == end_command.name;
    session_.define_native(
        function, 1,
        [this, word, end](Args, Args argument) -> std::optional<Value> {
          std::vector<std::string> line{word};
          for (auto& w : words_of(argument)) line.push_back(std::move(w));
          if (end) {
            // Already in APL: END APL stays, END CMS leaves igds.
            const Choice* option = line.size() > 1 ? choose(end_command.options, line[1]) : nullptr;
            if (!option) throw apl::Error(ErrorKind::domain, reports::incorrect_choice);
            if (option != &end_command.options.front())  // END APL stays
              session_.request(apl::AplSession::Next::off);
            return std::nullopt;
          }
          // The command sees the workspace whole: what APL changed is made consistent first.
          if (auto problem = start())
            throw apl::Error(ErrorKind::domain, fmt::format("CANNOT START: {}", *problem));
          hooks_.command(line);
          values_.clear();
          return std::nullopt;
        },
        fmt::format("{} 'WORDS': the command {} with those words", function, command));
  }
}

}  // namespace igds
