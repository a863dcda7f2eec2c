#include "workspace/disk/disk.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <system_error>
#include <tuple>

#include <fmt/format.h>

#include "workspace/disk/cards.h"
#include "workspace/disk/files.h"
#include "workspace/disk/frame.h"
#include "workspace/error.h"
#include "workspace/exchange/duct.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/interrupt.h"
#include "workspace/kernels/limits.h"
#include "workspace/kernels/surface.h"
#include "workspace/variables.h"

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
  if (!n || *n != name) throw ParameterError();
  return *n;
}

std::string file_name(std::string_view name, std::string_view type) {
  return fmt::format("{}.{}", name, type);
}

void write_or_report(const Disk& disk, std::string_view name, std::string_view type,
                     const disk::Writer& bytes) {
  try {
    disk::write_file(disk.path(name, type), bytes);
  } catch (const disk::IoError& e) {
    throw Report(
        fmt::format("CANNOT WRITE {} ({}); NO FILE CHANGED", file_name(name, type), e.reason()));
  }
}

// NAME.TYPE mapped, after its size was checked; FILE NOT FOUND / CANNOT READ otherwise.
disk::MappedFile open_or_report(const Disk& disk, std::string_view name, std::string_view type,
                                std::size_t max_bytes, std::string_view kept) {
  try {
    disk::MappedFile file(disk.path(name, type), max_bytes);
    if (!file.exists()) throw Report(reports::file_not_found);
    return file;
  } catch (const disk::IoError& e) {
    throw Report(fmt::format("CANNOT READ {} ({}); {}", file_name(name, type), e.reason(), kept));
  }
}

Report damaged(std::string_view name, std::string_view type, std::string_view reason,
               std::string_view kept) {
  return Report(fmt::format("FILE DAMAGED: {} ({}); {}", file_name(name, type), reason, kept));
}

// An array's bytes in a file, not copied: its shape and its doubles.
struct RawArray {
  std::vector<std::size_t> shape;
  std::string_view bytes;
};

RawArray raw_array(disk::Reader& r) {
  RawArray a;
  const std::uint32_t rank = r.u32();
  if (rank > 8) throw disk::Damage("FORMAT");
  std::uint64_t count = rank == 0 ? 0 : 1;
  for (std::uint32_t k = 0; k < rank; ++k) {
    const std::uint64_t d = r.u64();
    if (d != 0 && count > (std::uint64_t(1) << 60) / d) throw disk::Damage("FORMAT");
    count *= d;
    a.shape.push_back(static_cast<std::size_t>(d));
  }
  const std::uint64_t n = r.u64();
  if (n != count || n > r.left() / sizeof(double)) throw disk::Damage("FORMAT");
  a.bytes = r.bytes(static_cast<std::size_t>(n) * sizeof(double));
  return a;
}

bool same_bytes(const Array& a, const RawArray& raw) {
  return a.shape == raw.shape && a.size() * sizeof(double) == raw.bytes.size() &&
         (raw.bytes.empty() || std::memcmp(a.data(), raw.bytes.data(), raw.bytes.size()) == 0);
}

// Its every byte copied (raw_array checked that they fill the shape): not cleared first.
Array copied(const RawArray& raw) {
  Array a = Array::for_output(raw.shape);
  if (!raw.bytes.empty()) std::memcpy(a.data(), raw.bytes.data(), raw.bytes.size());
  return a;
}

std::size_t array_bytes(std::size_t rank, double elements) {
  return 4 + 8 * rank + 8 + static_cast<std::size_t>(8 * elements);
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
  return std::filesystem::exists(std::filesystem::symlink_status(path(name, type), ec));
}

std::vector<DiskFile> Disk::files() const {
  std::vector<DiskFile> out;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code e;
    // symlink_status: a link is not followed out of the folder.
    if (!std::filesystem::is_regular_file(it->symlink_status(e)) || e) continue;
    const std::string file = it->path().filename().string();
    const auto dot = file.find('.');
    if (dot == std::string::npos || file.find('.', dot + 1) != std::string::npos) continue;
    const std::string name = file.substr(0, dot), type = file.substr(dot + 1);
    if (cms_name(name) != name || type.empty() ||
        !std::all_of(type.begin(), type.end(),
                     [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }))
      continue;
    const auto bytes = it->file_size(e);
    if (e) continue;
    const auto time = it->last_write_time(e);
    if (e) continue;
    const auto since = std::chrono::file_clock::to_sys(time).time_since_epoch();
    out.push_back({name, type, bytes, std::chrono::floor<std::chrono::seconds>(since).count()});
  }
  std::sort(out.begin(), out.end(), [](const DiskFile& a, const DiskFile& b) {
    return std::tie(a.type, a.name) < std::tie(b.type, b.name);
  });
  return out;
}

namespace {

// write_user_file and write_new_user_file.
std::optional<std::uint64_t> write_made_file(const Disk& disk, std::string_view name,
                                             std::string_view type,
                                             const std::function<void(TextOut& out)>& make,
                                             bool replace, std::string_view kept) {
  const std::string n = checked(name);
  try {
    return disk::write_made(disk.path(n, type), make, replace);
  } catch (const disk::IoError& e) {
    throw Report(fmt::format("CANNOT WRITE {} ({}); {}", file_name(n, type), e.reason(), kept));
  }
}

}  // namespace

bool write_user_file(const Disk& disk, std::string_view name, std::string_view type,
                     std::string_view bytes, bool replace, std::string_view kept) {
  const std::string n = checked(name);
  try {
    return disk::write_file(disk.path(n, type), bytes, replace);
  } catch (const disk::IoError& e) {
    throw Report(fmt::format("CANNOT WRITE {} ({}); {}", file_name(n, type), e.reason(), kept));
  }
}

std::uint64_t write_user_file(const Disk& disk, std::string_view name, std::string_view type,
                              const std::function<void(TextOut& out)>& make,
                              std::string_view kept) {
  return *write_made_file(disk, name, type, make, true, kept);
}

std::optional<std::uint64_t> write_new_user_file(const Disk& disk, std::string_view name,
                                                 std::string_view type,
                                                 const std::function<void(TextOut& out)>& make,
                                                 std::string_view kept) {
  return write_made_file(disk, name, type, make, false, kept);
}

std::string read_user_file(const Disk& disk, std::string_view name, std::string_view type,
                           std::size_t max_bytes, std::string_view kept) {
  const std::string n = checked(name);
  disk::MappedFile file = open_or_report(disk, n, type, max_bytes, kept);
  return std::string(file.bytes());
}

std::size_t max_surface_file_bytes() {
  // The largest arrays of a legal surface: INPPN of max_input_points, INPTG of a single curve
  // of them, PATCHES of a square grid of them, INTPN of max_grid_points.
  const double p = double(max_input_points);
  return disk::frame_header_bytes + disk::frame_trailer_bytes + 16 + array_bytes(2, 3 * p) +
         array_bytes(2, 8 * (p + 1)) + array_bytes(5, 48 * p) +
         array_bytes(3, 3 * double(max_grid_points)) + 8;
}

std::size_t max_image_file_bytes() {
  // The points of max_grid_points, an arrow (6 numbers) for every border tangent of
  // max_input_points in a line, the ends of two combs for every point and their scale.
  const std::size_t grid = disk::frame_header_bytes + disk::frame_trailer_bytes + 8 + 24 +
                           array_bytes(3, 2 * double(max_grid_points)) +
                           array_bytes(2, 6 * 2 * (double(max_input_points) + 1)) +
                           array_bytes(3, 4 * double(max_grid_points)) + 8;
  // Or a DUCT picture: empty points and arrows, a name of up to 8 characters, the text.
  const std::size_t picture = disk::frame_header_bytes + disk::frame_trailer_bytes + 8 + 24 +
                              2 * array_bytes(0, 0) + 8 + 8 + 8 + duct_max_file_bytes;
  return std::max(grid, picture);
}

void save_surface(const Disk& disk, std::string_view name, const Workspace& ws) {
  const std::string n = checked(name);
  disk::Writer w;
  w.i32(ws.nocur);
  w.i32(ws.nostr);
  w.i32(ws.intcu);
  w.i32(ws.intst);
  w.array(ws.inppn);
  w.array(ws.inptg);
  // PATCHES and INTPN that are the interpolation of the inputs are made again when the file is
  // read, as the session's are: 1 then, else 0 and the arrays.
  // (A single curve or stringer's arrays are written: its PATCHES hold no number.)
  const bool derived = ws.changes.derived && ws.nocur > 1 && ws.nostr > 1;
  w.i32(derived ? 1 : 0);
  if (!derived) {
    w.array(ws.patches);
    w.array(ws.intpn);
  }
  w.i32(ws.marks_twists() ? 1 : 0);
  w.i32(ws.auto_tangents() ? 1 : 0);
  write_or_report(disk, n, "IGDSDATA",
                  disk::frame(data_magic, w, disk::newest_version(data_magic)));
}

void restore_surface(const Disk& disk, std::string_view name, Workspace& ws) {
  const std::string n = checked(name);
  constexpr std::string_view kept = "CURRENT SURFACE KEPT";
  disk::MappedFile file = open_or_report(disk, n, "IGDSDATA", max_surface_file_bytes(), kept);
  Workspace in;
  RawArray patches, intpn;
  bool stored = true;  // PATCHES and INTPN are in the file
  try {
    stored =
        disk::read_framed(data_magic, file.bytes(), [&](disk::Reader& r, std::uint32_t version) {
          bool in_file = true;
          in.nocur = r.i32();
          in.nostr = r.i32();
          in.intcu = r.i32();
          in.intst = r.i32();
          in.inppn = r.array(3 * max_input_points);
          in.inptg = r.array(8 * (max_input_points + 1));
          // Version 2: 1 when PATCHES and INTPN are the interpolation of the inputs and not stored.
          if (version >= 2) {
            const std::int32_t derived = r.i32();
            if (derived < 0 || derived > 1) throw disk::Damage("FORMAT");
            in_file = derived == 0;
          }
          if (in_file) {
            patches = raw_array(r);
            intpn = raw_array(r);
          }
          // Version 1 files written before the twists and AUTO mark end after INTPN: zero twists
          // and typed tangents.
          if (version >= 2 || !r.at_end()) {
            const std::int32_t twists = r.i32(), automatic = r.i32();
            if (twists < 0 || twists > 1 || automatic < 0 || automatic > 1)
              throw disk::Damage("FORMAT");
            in.set_surface_modes(twists == 1, automatic == 1);
          }
          r.finish();
          return in_file;
        });
  } catch (const disk::Damage& d) {
    throw damaged(n, "IGDSDATA", d.reason(), kept);
  }
  // Every variable is checked before anything trusts it: shapes, relations, limits, numbers.
  // A saved surface always has input (SAVE refuses without).
  if (in.nocur == 0) throw damaged(n, "IGDSDATA", "SHAPES: NOCUR IS 0", kept);
  if (auto p = surface_problem(in))
    throw damaged(n, "IGDSDATA", fmt::format("SHAPES: {}", p->reason), kept);
  const bool none = stored && patches.shape.empty() && intpn.shape.empty();
  if (stored && !none) {
    for (auto [v, raw] : {std::pair{Variable::patches, &patches}, {Variable::intpn, &intpn}})
      if (raw->shape != expected_shape(in, v))
        throw damaged(n, "IGDSDATA",
                      fmt::format("SHAPES: {} DOES NOT MATCH NOCUR AND NOSTR", info(v).name), kept);
  }
  // PATCHES and INTPN are made again from the inputs. Those the file holds (every version 1 file,
  // and a version 2 file whose were not the interpolation) are kept as they are when they differ,
  // once every number was found finite (the interpolation's too: inputs near the largest numbers
  // overflow).
  Surface surface;
  try {
    // PATCHES kept only to be compared with the file's.
    if (auto overflow = interpolate_into(surface_input(in), surface,
                                         stored ? PatchesOut::kept : PatchesOut::dropped))
      throw *overflow;
  } catch (const DataError& e) {
    const bool overflow = e.problem == DataError::Problem::patch_not_finite ||
                          e.problem == DataError::Problem::grid_point_not_finite;
    throw damaged(
        n, "IGDSDATA",
        overflow ? "ITS SURFACE OVERFLOWS: " + made_surface_reason(e) : made_surface_reason(e),
        kept);
  }
  const bool derived = !stored || (!none && same_bytes(surface.patches, patches) &&
                                   same_bytes(surface.intpn, intpn));
  if (derived) {
    in.patches = std::move(surface.patches);
    in.intpn = std::move(surface.intpn);
  } else {
    surface = {};
    in.patches = none ? Array{} : copied(patches);
    in.intpn = none ? Array{} : copied(intpn);
    for (auto [v, a] : {std::pair{Variable::patches, &in.patches}, {Variable::intpn, &in.intpn}})
      if (auto p = finite_problem(v, *a)) throw damaged(n, "IGDSDATA", p->reason, kept);
  }
  ws.nocur = in.nocur;
  ws.nostr = in.nostr;
  ws.intcu = in.intcu;
  ws.intst = in.intst;
  ws.inppn = std::move(in.inppn);
  ws.inptg = std::move(in.inptg);
  ws.patches = std::move(in.patches);
  ws.intpn = std::move(in.intpn);
  ws.set_surface_modes(in.marks_twists(), in.auto_tangents());
  ws.changes.replaced(derived);
  keep_splines(ws, std::move(surface.tangents));  // none when the file's surface is kept
  drop_derived_patches(ws);
}

void store_image(const Disk& disk, std::string_view name, const Image& image) {
  const std::string n = checked(name);
  disk::Writer w;
  w.image(image);
  write_or_report(disk, n, "IGDSIMAG", disk::frame(image_magic, w));
}

Image load_image(const Disk& disk, std::string_view name) {
  const std::string n = checked(name);
  constexpr std::string_view kept = "CURRENT IMAGE KEPT";
  disk::MappedFile file = open_or_report(disk, n, "IGDSIMAG", max_image_file_bytes(), kept);
  Image image;
  try {
    image = disk::read_framed(image_magic, file.bytes(), [](disk::Reader& r, std::uint32_t) {
      Image read = r.image();
      r.finish();
      return read;
    });
  } catch (const disk::Damage& d) {
    throw damaged(n, "IGDSIMAG", d.reason(), kept);
  }
  if (auto p = image_problem(image, Variable::image, &image.extent))
    throw damaged(n, "IGDSIMAG", "FORMAT: " + p->reason, kept);
  image.file = disk.path(n, "IGDSIMAG");
  image.file_sum = disk::trailing_checksum(file.bytes());
  return image;
}

std::size_t write_char(const Disk& disk, std::string_view name, const Workspace& ws) {
  const std::string n = checked(name);
  std::size_t overflow = 0;
  try {
    disk::write_made(disk.path(n, "IGDSCHAR"),
                     [&](TextOut& out) { overflow = disk::put_char_cards(ws, out); });
  } catch (const disk::IoError& e) {
    throw Report(
        fmt::format("CANNOT WRITE {} ({}); NO FILE CHANGED", file_name(n, "IGDSCHAR"), e.reason()));
  }
  return overflow;
}

}  // namespace igds
