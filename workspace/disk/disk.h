// The user's disk (CMS's P-disk): CMS file names and the files igds reads and writes there
// (docs/disk.md). Nothing is ever read or written outside the disk's folder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/state.h"
#include "workspace/text_out.h"

namespace igds {

// A CMS file name as typed: 1 to 8 of letters, digits and $ # @ + - _, returned in capitals;
// nullopt for anything else (INCORRECT PARAMETER).
std::optional<std::string> cms_name(std::string_view typed);

// A file of the disk as LIST FILES shows it.
struct DiskFile {
  std::string name, type;  // NAME and TYPE of NAME.TYPE
  std::uintmax_t bytes = 0;
  std::int64_t written = 0;  // last written, in seconds since 1970-01-01 UTC
};

class Disk {
 public:
  // Throws Report when `dir` is not a folder igds can use.
  explicit Disk(std::filesystem::path dir);
  const std::filesystem::path& dir() const { return dir_; }
  // NAME.TYPE on the disk. `name` must already be a cms_name().
  std::filesystem::path path(std::string_view name, std::string_view type) const;
  bool exists(std::string_view name, std::string_view type) const;
  // The regular files NAME.TYPE directly in the disk's folder (NAME a cms_name() in capitals,
  // TYPE letters and digits), by type then name. Folders, links and anything else are left out;
  // nothing outside the folder is looked at.
  std::vector<DiskFile> files() const;

 private:
  std::filesystem::path dir_;
};

// Writes NAME.TYPE on the disk whole or not at all (workspace/disk/files.h): every file a
// command writes for the user goes through here. `replace`: an existing file of that name is
// replaced; else false is returned and nothing changes. Throws Report "CANNOT WRITE NAME.TYPE
// (REASON); `kept`" when the disk refuses.
bool write_user_file(const Disk& disk, std::string_view name, std::string_view type,
                     std::string_view bytes, bool replace = true,
                     std::string_view kept = "NO FILE CHANGED");

// The same for a text made while it is written (disk::write_made): make(out) puts the file's
// bytes into `out`. Returns the file's size in bytes. Whatever `make` throws leaves no file
// changed and goes on to the caller.
std::uint64_t write_user_file(const Disk& disk, std::string_view name, std::string_view type,
                              const std::function<void(TextOut& out)>& make,
                              std::string_view kept = "NO FILE CHANGED");
// The same for a new file only: nullopt, and nothing changed, when one of that name is there by
// the time it is written.
std::optional<std::uint64_t> write_new_user_file(const Disk& disk, std::string_view name,
                                                 std::string_view type,
                                                 const std::function<void(TextOut& out)>& make,
                                                 std::string_view kept = "NO FILE CHANGED");

// A file another program wrote (FIT's NAME.CADADATA, DISPLAY PICTURE's NAME.DUCTPIC): its
// bytes, read once its size was checked against `max_bytes`. Throws Report FILE NOT FOUND, or
// "CANNOT READ NAME.TYPE (REASON); `kept`" (a folder, a file too large, a system error).
std::string read_user_file(const Disk& disk, std::string_view name, std::string_view type,
                           std::size_t max_bytes, std::string_view kept);

// SAVE: NAME.IGDSDATA, replacing a file of that name (written whole or not at all).
void save_surface(const Disk& disk, std::string_view name, const Workspace& ws);

// RESTORE: the surface of NAME.IGDSDATA (NOCUR NOSTR INTCU INTST INPPN INPTG PATCHES INTPN)
// replaces the one in `ws`, once every variable was checked (workspace/variables.h). Throws
// Report FILE NOT FOUND, or FILE DAMAGED: NAME.IGDSDATA (REASON); CURRENT SURFACE KEPT with `ws`
// untouched.
void restore_surface(const Disk& disk, std::string_view name, Workspace& ws);

// STORE FILE / DISPLAY FILE: NAME.IGDSIMAG holds one image and its description.
void store_image(const Disk& disk, std::string_view name, const Image& image);
Image load_image(const Disk& disk, std::string_view name);  // FILE NOT FOUND / FILE DAMAGED

// WRITE: NAME.IGDSCHAR in the card format of docs/disk.md. Returns how many values did not fit
// F10.3 and were written as ten asterisks.
std::size_t write_char(const Disk& disk, std::string_view name, const Workspace& ws);

// The largest IGDSDATA and IGDSIMAG files a legal surface or image makes (larger ones are
// refused before they are read).
std::size_t max_surface_file_bytes();
std::size_t max_image_file_bytes();

}  // namespace igds
