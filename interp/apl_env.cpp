#include "interp/apl_env.h"

#include <algorithm>
#include <array>

#include "interp/words.h"
#include "workspace/apl.h"

namespace igds {

namespace {

constexpr std::array<std::string_view, 15> all_names{
    "DESIM", "DEST1", "DEST2", "IMAGE",   "INPPN",  "INPTG", "INTCU", "INTPN",
    "INTST", "NOCUR", "NOSTR", "PATCHES", "STATUS", "TEMP1", "TEMP2"};

constexpr std::string_view rho = "\xE2\x8D\xB4";  // ⍴ U+2374

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

// Characters on the screen: ¯ is two bytes of UTF-8 but one column.
std::size_t columns(std::string_view text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

bool is_name(std::string_view word) {
  if (word.empty()) return false;
  for (char c : word) {
    bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    if (!letter && !(c >= '0' && c <= '9') && c != '_') return false;
  }
  return !(word[0] >= '0' && word[0] <= '9');
}

std::string trim(std::string_view text) {
  auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  auto last = text.find_last_not_of(" \t\r");
  return std::string(text.substr(first, last - first + 1));
}

}  // namespace

std::optional<Array> workspace_variable(const Workspace& ws, std::string_view typed) {
  const std::string name = upper(typed);
  if (name == "NOCUR") return scalar(ws.nocur);
  if (name == "NOSTR") return scalar(ws.nostr);
  if (name == "INTCU") return scalar(ws.intcu);
  if (name == "INTST") return scalar(ws.intst);
  if (name == "INPPN") return ws.inppn;
  if (name == "INPTG") return ws.inptg;
  if (name == "PATCHES") return ws.patches;
  if (name == "INTPN") return ws.intpn;
  if (name == "STATUS") return vector(std::vector<double>(ws.status.begin(), ws.status.end()));
  const ImageRef* image = nullptr;
  if (name == "IMAGE" || name == "DESIM") image = &ws.image;
  if (name == "TEMP1" || name == "DEST1") image = &ws.temp1;
  if (name == "TEMP2" || name == "DEST2") image = &ws.temp2;
  if (!image || !*image) return std::nullopt;
  if (name.starts_with("DES")) return desim((*image)->desim);
  return (*image)->points;
}

std::vector<std::string> defined_variables(const Workspace& ws) {
  std::vector<std::string> names;
  for (auto name : all_names) {
    if (workspace_variable(ws, name)) names.emplace_back(name);
  }
  return names;
}

std::vector<std::string> apl_display(const Array& a) {
  if (a.empty()) return {""};
  if (a.rank() == 0) return {format_apl_number(a.ravel[0])};
  if (a.rank() == 1) {
    std::string line;
    for (double v : a.ravel) {
      if (!line.empty()) line += ' ';
      line += format_apl_number(v);
    }
    return {line};
  }
  const std::size_t cols = a.shape.back();
  const std::size_t rows = a.shape[a.rank() - 2];
  // Each number split at its decimal point (or exponent): the integer parts right-aligned, the
  // fractions left-aligned, so that the points of a column line up.
  std::vector<std::string> integer(a.size()), fraction(a.size());
  std::vector<std::size_t> integer_width(cols, 0), fraction_width(cols, 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::string text = format_apl_number(a.ravel[i]);
    auto cut = text.find_first_of(".E");
    if (cut == std::string::npos) cut = text.size();
    integer[i] = text.substr(0, cut);
    fraction[i] = text.substr(cut);
    integer_width[i % cols] = std::max(integer_width[i % cols], columns(integer[i]));
    fraction_width[i % cols] = std::max(fraction_width[i % cols], columns(fraction[i]));
  }
  std::vector<std::string> lines;
  const std::size_t matrices = a.size() / (rows * cols);
  for (std::size_t m = 0; m < matrices; ++m) {
    if (m > 0) {
      // One blank line per outer axis that moves on between this matrix and the previous one.
      std::size_t blanks = 0, period = 1;
      for (std::size_t axis = a.rank() - 2; axis-- > 0;) {
        if (m % period == 0) ++blanks;
        period *= a.shape[axis];
        if (m % period != 0) break;
      }
      lines.insert(lines.end(), blanks, "");
    }
    for (std::size_t r = 0; r < rows; ++r) {
      std::string line;
      for (std::size_t c = 0; c < cols; ++c) {
        std::size_t i = (m * rows + r) * cols + c;
        if (c > 0) line += ' ';
        line.append(integer_width[c] - columns(integer[i]), ' ');
        line += integer[i];
        line += fraction[i];
        line.append(fraction_width[c] - columns(fraction[i]), ' ');
      }
      line.erase(line.find_last_not_of(' ') + 1);
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

std::string apl_shape(const Array& a) {
  if (a.rank() == 0) return a.empty() ? "0" : "";
  std::string line;
  for (auto d : a.shape) {
    if (!line.empty()) line += ' ';
    line += std::to_string(d);
  }
  return line;
}

AplReply apl_line(const Workspace& ws, std::string_view typed) {
  std::string line = trim(typed);
  if (line.empty()) return {};
  std::string command = upper(line);
  if (command == ")VARS") {
    std::string names;
    for (const auto& name : defined_variables(ws)) {
      if (!names.empty()) names += ' ';
      names += name;
    }
    return {{names}, AplNext::stay};
  }
  if (command == ")OFF" || command.starts_with(")OFF ")) return {{}, AplNext::off};
  if (command == "START") return {{}, AplNext::start};
  bool shape = false;
  std::string name = line;
  if (line.starts_with(rho)) {
    shape = true;
    name = trim(std::string_view(line).substr(rho.size()));
  } else if (command.starts_with("RHO ")) {
    shape = true;
    name = trim(std::string_view(line).substr(4));
  }
  if (!is_name(name)) return {{"SYNTAX ERROR"}, AplNext::stay};
  auto value = workspace_variable(ws, name);
  if (!value) return {{"VALUE ERROR"}, AplNext::stay};
  if (shape) return {{apl_shape(*value)}, AplNext::stay};
  return {apl_display(*value), AplNext::stay};
}

}  // namespace igds
