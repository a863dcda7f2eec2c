#include "workspace/disk/disk.h"

#include <system_error>

#include <fmt/format.h>

#include "workspace/disk/cards.h"
#include "workspace/disk/format.h"
#include "workspace/error.h"

namespace igds {

namespace {

constexpr std::string_view data_magic = "IGDSDATA";
constexpr std::string_view image_magic = "IGDSIMAG";

bool cms_character(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '$' ||
         c == '#' || c == '@' || c == '+' || c == '-' || c == '_';
}

// The functions below take names from callers: one that is not a cms_name() never reaches the
// file system, whatever the caller checked.
std::string checked(std::string_view name) {
  auto n = cms_name(name);
  if (!n || *n != name) throw Report(reports::incorrect_parameter);
  return *n;
}

std::string file_name(std::string_view name, std::string_view type) {
  return fmt::format("{}.{}", name, type);
}

void write_or_report(const Disk& disk, std::string_view name, std::string_view type,
                     std::string_view bytes) {
  try {
    disk::replace_file(disk.path(name, type), bytes);
  } catch (const disk::IoError& e) {
    throw Report(
        fmt::format("CANNOT WRITE {} ({}); NO FILE CHANGED", file_name(name, type), e.reason()));
  }
}

// The payload of NAME.TYPE, or the report FILE NOT FOUND / CANNOT READ / FILE DAMAGED.
template <class Decode>
auto read_or_report(const Disk& disk, std::string_view name, std::string_view type,
                    std::string_view magic, std::string_view kept, Decode decode) {
  std::string file = file_name(name, type);
  std::optional<std::string> bytes;
  try {
    bytes = disk::read_whole_file(disk.path(name, type));
  } catch (const disk::IoError& e) {
    throw Report(fmt::format("CANNOT READ {} ({}); {}", file, e.reason(), kept));
  }
  if (!bytes) throw Report(reports::file_not_found);
  try {
    disk::Reader r(disk::unframe(magic, *bytes));
    auto value = decode(r);
    r.finish();
    return value;
  } catch (const disk::Damage& d) {
    throw Report(fmt::format("FILE DAMAGED: {} ({}); {}", file, d.reason, kept));
  }
}

}  // namespace

std::optional<std::string> cms_name(std::string_view typed) {
  if (typed.empty() || typed.size() > 8) return std::nullopt;
  std::string name;
  for (char c : typed) {
    if (!cms_character(c)) return std::nullopt;
    name += (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  }
  return name;
}

Disk::Disk(std::filesystem::path dir) {
  std::error_code ec;
  auto absolute = std::filesystem::absolute(dir, ec);
  dir_ = (ec ? dir : absolute).lexically_normal();
  if (dir_.has_filename() == false && dir_.has_parent_path() && dir_ != dir_.root_path())
    dir_ = dir_.parent_path();  // "/x/" names the folder /x
  auto st = std::filesystem::status(dir_, ec);
  if (ec || !std::filesystem::exists(st))
    throw Report(fmt::format("DISK {} NOT FOUND", dir_.string()));
  if (!std::filesystem::is_directory(st))
    throw Report(fmt::format("DISK {} IS NOT A FOLDER", dir_.string()));
}

std::filesystem::path Disk::path(std::string_view name, std::string_view type) const {
  return dir_ / file_name(name, type);
}

bool Disk::exists(std::string_view name, std::string_view type) const {
  std::error_code ec;
  return std::filesystem::exists(path(name, type), ec);
}

void save_surface(const Disk& disk, std::string_view name, const Workspace& ws) {
  std::string n = checked(name);
  disk::Writer w;
  disk::write_surface(w, ws);
  write_or_report(disk, n, "IGDSDATA", disk::frame(data_magic, w.str()));
}

void restore_surface(const Disk& disk, std::string_view name, Workspace& ws) {
  std::string n = checked(name);
  Workspace in =
      read_or_report(disk, n, "IGDSDATA", data_magic, "CURRENT SURFACE KEPT", [](disk::Reader& r) {
        Workspace w;
        disk::read_surface(r, w);
        // A saved surface always has input (SAVE refuses without).
        if (w.nocur == 0 || !disk::surface_shape_error(w).empty()) throw disk::Damage{"SHAPES"};
        return w;
      });
  ws.nocur = in.nocur;
  ws.nostr = in.nostr;
  ws.intcu = in.intcu;
  ws.intst = in.intst;
  ws.inppn = std::move(in.inppn);
  ws.inptg = std::move(in.inptg);
  ws.patches = std::move(in.patches);
  ws.intpn = std::move(in.intpn);
}

void store_image(const Disk& disk, std::string_view name, const Image& image) {
  std::string n = checked(name);
  disk::Writer w;
  w.image(image);
  write_or_report(disk, n, "IGDSIMAG", disk::frame(image_magic, w.str()));
}

Image load_image(const Disk& disk, std::string_view name) {
  std::string n = checked(name);
  return read_or_report(disk, n, "IGDSIMAG", image_magic, "CURRENT IMAGE KEPT",
                        [](disk::Reader& r) { return r.image(); });
}

std::size_t write_char(const Disk& disk, std::string_view name, const Workspace& ws) {
  std::string n = checked(name);
  std::size_t overflow = 0;
  std::string text = disk::char_cards(ws, &overflow);
  write_or_report(disk, n, "IGDSCHAR", text);
  return overflow;
}

}  // namespace igds
