// Files made as someone who wants to hurt igds would make them: with igds's own encoders, frame
// and checksum, so that every length and the checksum hold and only the meaning is wrong (the
// checksum has no key: docs/disk.md, "What is checked where").
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/frame.h"
#include "workspace/disk/session_file.h"

namespace igds::test::forge {

inline std::filesystem::path session_path(const Disk& disk) {
  return disk.path("BINSAVE", "IGDSCONT");
}

// The table of the session file on `disk`.
inline disk::SessionTable session_table(const Disk& disk) {
  const std::string file = read_file(session_path(disk));
  return disk::decode_session(disk::unframe("IGDSCONT", file).payload);
}

// `table` as the session file on `disk`, framed as igds frames it (format version 2).
inline void write_session(const Disk& disk, const disk::SessionTable& table) {
  const auto path = session_path(disk);
  std::filesystem::remove(path);
  write_file(path, disk::frame("IGDSCONT", disk::encode_session(table), 2));
}

// The payload of variable file `number` (type IGDSVARS) on `disk`.
inline std::string variable_payload(const Disk& disk, std::uint32_t number) {
  const std::string file = read_file(disk.path(disk::variable_file_name(number), "IGDSVARS"));
  return std::string(disk::unframe("IGDSVARS", file).payload);
}

// A variable file `number` holding `payload`, framed as `magic` (IGDSVARS, or IGDSIMAG for the
// copy of an image file), under the type `type`; the reference a session names it by.
inline disk::FileRef variable_file(const Disk& disk, std::uint32_t number, std::string_view payload,
                                   std::string_view type = "IGDSVARS",
                                   std::string_view magic = "IGDSVARS") {
  const std::string framed = disk::frame(magic, payload);
  const auto path = disk.path(disk::variable_file_name(number), type);
  std::filesystem::remove(path);
  write_file(path, framed);
  return {number, framed.size(), disk::trailing_checksum(framed)};
}

// A piece of a blob held by the variable file `ref`.
inline disk::Piece file_piece(const disk::FileRef& ref) {
  disk::Piece p;
  p.in_file = true;
  p.file = ref;
  p.size = ref.length - disk::frame_header_bytes - disk::frame_trailer_bytes;
  return p;
}

}  // namespace igds::test::forge
