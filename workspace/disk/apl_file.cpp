#include "workspace/disk/apl_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "workspace/error.h"
#include "workspace/variables.h"

namespace igds::disk {

namespace {

// The largest IGDSAPLW file read (larger ones are refused before they are read).
constexpr std::size_t max_apl_file_bytes = std::size_t(1) << 31;
constexpr std::uint32_t max_rank = 8;
constexpr std::uint64_t max_axis = std::uint64_t(1) << 53;

// An APL name as END APL folds it: A-Z, then A-Z, 0-9, _, ∆ or ⍙ (UTF-8).
bool apl_name(std::string_view name) {
  if (name.empty()) return false;
  for (std::size_t i = 0; i < name.size();) {
    const char c = name[i];
    const bool letter = (c >= 'A' && c <= 'Z') || c == '_';
    if (letter || (i > 0 && c >= '0' && c <= '9')) {
      ++i;
      continue;
    }
    const std::string_view rest = name.substr(i);
    if (rest.starts_with("\xE2\x88\x86") || rest.starts_with("\xE2\x8D\x99")) {  // ∆ ⍙
      i += 3;
      continue;
    }
    return false;
  }
  return true;
}

bool code_point(std::uint32_t c) {
  return c < 0x110000 && !(c >= 0xD800 && c <= 0xDFFF);
}

}  // namespace

void write_functions(Writer& w, const std::vector<std::vector<std::string>>& functions) {
  w.u32(static_cast<std::uint32_t>(functions.size()));
  for (const auto& f : functions) {
    w.u32(static_cast<std::uint32_t>(f.size()));
    for (const auto& line : f) {
      w.u32(static_cast<std::uint32_t>(line.size()));
      w.bytes(line);
    }
  }
}

std::vector<std::vector<std::string>> read_functions(Reader& r) {
  // Each count is checked against what is left, so a crafted count cannot make a huge table.
  const std::uint32_t functions = r.u32();
  if (functions > r.left() / 8)  // a count of lines and one line
    throw Damage("FORMAT: MORE FUNCTIONS THAN THE FILE HOLDS");
  std::vector<std::vector<std::string>> out(functions);
  for (auto& f : out) {
    const std::uint32_t lines = r.u32();
    if (lines == 0 || lines > r.left() / 4)
      throw Damage("FORMAT: A FUNCTION WITHOUT LINES OR WITH MORE THAN THE FILE HOLDS");
    f.resize(lines);
    for (auto& line : f) line = std::string(r.bytes(r.u32()));
  }
  return out;
}

void write_variables(Writer& w, const std::vector<AplVariable>& variables) {
  w.u32(static_cast<std::uint32_t>(variables.size()));
  for (const AplVariable& v : variables) {
    w.u32(static_cast<std::uint32_t>(v.name.size()));
    w.bytes(v.name);
    w.u8(v.characters ? 1 : 0);
    w.u32(static_cast<std::uint32_t>(v.shape.size()));
    for (std::size_t d : v.shape) w.u64(d);
    if (v.characters) {
      for (char32_t c : v.text) w.u32(static_cast<std::uint32_t>(c));
    } else {
      for (double x : v.numbers) w.f64(x);
    }
  }
}

std::vector<AplVariable> read_variables(Reader& r) {
  const std::uint32_t count = r.u32();
  // The smallest variable takes 10 bytes and a name.
  if (count > r.left() / 10) throw Damage("FORMAT: MORE VARIABLES THAN THE FILE HOLDS");
  std::vector<AplVariable> out(count);
  for (std::size_t k = 0; k < out.size(); ++k) {
    AplVariable& v = out[k];
    v.name = std::string(r.bytes(r.u32()));  // as long as APL's names: bounded by the bytes
    if (!apl_name(v.name)) throw Damage("FORMAT: A VARIABLE'S NAME THAT IS NO APL NAME");
    // IGDS's own variables are the workspace's, never the user's.
    if (find_variable(v.name)) throw Damage(fmt::format("FORMAT: {} IS AN IGDS VARIABLE", v.name));
    if (k > 0 && !(out[k - 1].name < v.name))
      throw Damage("FORMAT: VARIABLES OUT OF ORDER OR TWICE");
    const std::uint8_t kind = r.u8();
    if (kind > 1) throw Damage("FORMAT: A VARIABLE NEITHER OF NUMBERS NOR OF CHARACTERS");
    v.characters = kind == 1;
    const std::uint32_t rank = r.u32();
    if (rank > max_rank) throw Damage("FORMAT: A VARIABLE OF RANK ABOVE 8");
    const std::size_t size = v.characters ? 4 : 8;
    for (std::uint32_t a = 0; a < rank; ++a) {
      const std::uint64_t d = r.u64();
      // Even an empty array's axes are lengths APL's numbers say exactly.
      if (d > max_axis) throw Damage("FORMAT: AN AXIS LONGER THAN 2*53");
      v.shape.push_back(static_cast<std::size_t>(d));
    }
    // The elements must fit in what is left of the file, checked axis by axis so that the
    // product never overflows.
    std::uint64_t elements = 1;
    if (std::find(v.shape.begin(), v.shape.end(), 0) != v.shape.end()) elements = 0;
    for (std::size_t d : v.shape) {
      if (elements != 0 && elements > r.left() / size / d)
        throw Damage("FORMAT: A VARIABLE LARGER THAN THE FILE HOLDS");
      elements *= d;
    }
    if (elements > r.left() / size) throw Damage("FORMAT: A VARIABLE LARGER THAN THE FILE HOLDS");
    if (v.characters) {
      v.text.resize(static_cast<std::size_t>(elements));
      for (char32_t& c : v.text) {
        const std::uint32_t u = r.u32();
        if (!code_point(u)) throw Damage("FORMAT: A CHARACTER THAT IS NO UNICODE CHARACTER");
        c = static_cast<char32_t>(u);
      }
    } else {
      v.numbers.resize(static_cast<std::size_t>(elements));
      for (double& x : v.numbers) {
        x = r.f64();
        if (!std::isfinite(x)) throw Damage("FORMAT: A NUMBER THAT IS NOT FINITE");
      }
    }
  }
  return out;
}

void save_apl_workspace(const Disk& disk, std::string_view name, const AplWorkspace& ws,
                        std::string_view kept) {
  Writer w;
  w.u8(ws.surface ? 1 : 0);
  write_functions(w, ws.functions);
  write_variables(w, ws.variables);
  write_user_file(disk, name, apl_workspace_type, frame(apl_workspace_type, w.str()), true, kept);
}

std::size_t stored_bytes(std::size_t name_bytes, std::size_t rank, std::size_t elements,
                         bool characters) {
  return 4 + name_bytes + 1 + 4 + 8 * rank + elements * (characters ? 4 : 8);
}

AplWorkspace load_apl_workspace(const Disk& disk, std::string_view name, std::string_view kept) {
  const std::string bytes =
      read_user_file(disk, name, apl_workspace_type, max_apl_file_bytes, kept);
  try {
    Reader r(unframe(apl_workspace_type, bytes).payload);
    AplWorkspace ws;
    const std::uint8_t surface = r.u8();
    if (surface > 1) throw Damage("FORMAT: NEITHER WITH NOR WITHOUT A SURFACE");
    ws.surface = surface == 1;
    ws.functions = read_functions(r);
    ws.variables = read_variables(r);
    if (!r.at_end()) throw Damage("FORMAT: BYTES AFTER THE VARIABLES");
    return ws;
  } catch (const Damage& d) {
    throw Report(
        fmt::format("FILE DAMAGED: {}.{} ({}); {}", name, apl_workspace_type, d.reason(), kept));
  }
}

}  // namespace igds::disk
