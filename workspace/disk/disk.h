// The user's disk (CMS's P-disk): CMS file names and the files igds reads and writes there
// (spec igds.md section 5). Nothing is ever read or written outside the disk's folder.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "workspace/state.h"

namespace igds {

// A CMS file name as typed: 1 to 8 of letters, digits and $ # @ + - _, returned in capitals;
// nullopt for anything else (INCORRECT PARAMETER).
std::optional<std::string> cms_name(std::string_view typed);

class Disk {
 public:
  // Throws Report when `dir` is not a folder igds can use.
  explicit Disk(std::filesystem::path dir);
  const std::filesystem::path& dir() const { return dir_; }
  // NAME.TYPE on the disk. `name` must already be a cms_name().
  std::filesystem::path path(std::string_view name, std::string_view type) const;
  bool exists(std::string_view name, std::string_view type) const;

 private:
  std::filesystem::path dir_;
};

// SAVE: NAME.IGDSDATA, replacing a file of that name (written whole or not at all).
// Throws Report (e.g. INPUT NOT FOUND is the caller's; a write failure says what and that
// nothing was lost).
void save_surface(const Disk& disk, std::string_view name, const Workspace& ws);

// RESTORE: the surface of NAME.IGDSDATA (NOCUR NOSTR INTCU INTST INPPN INPTG PATCHES INTPN)
// replaces the one in `ws`. Throws Report FILE NOT FOUND, or FILE DAMAGED: ... with `ws` untouched.
void restore_surface(const Disk& disk, std::string_view name, Workspace& ws);

// STORE FILE / DISPLAY FILE: NAME.IGDSIMAG holds one image and its description.
void store_image(const Disk& disk, std::string_view name, const Image& image);
Image load_image(const Disk& disk, std::string_view name);  // FILE NOT FOUND / FILE DAMAGED

// WRITE: NAME.IGDSCHAR in the card format of the spec. Returns how many values did not fit
// F10.3 and were written as ten asterisks.
std::size_t write_char(const Disk& disk, std::string_view name, const Workspace& ws);

}  // namespace igds
