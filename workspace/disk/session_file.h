// The session file BINSAVE.IGDSCONT, format version 2 (docs/disk.md): what it holds, written and
// read. It is small: the scalars, STATUS, and references to the files that hold the large
// variables. workspace/disk/session.cpp decides what goes in it; this file only encodes it and
// checks that a file read back is well formed (the meaning is checked by the session against
// workspace/variables.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/state.h"

namespace igds::disk {

// A variable file of the session: Bnnnnnnn.IGDSVARS (a piece of a variable, framed) or
// Bnnnnnnn.IGDSVIMG (a second name of an IGDSIMAG file shown by DISPLAY FILE); its length and
// the checksum it ends with, so that a file replaced by another is noticed.
struct FileRef {
  std::uint32_t number = 0;
  std::uint64_t length = 0, sum = 0;
  friend bool operator==(const FileRef&, const FileRef&) = default;
};

// Bytes kept by the session: pieces in the session file itself (up to inline_limit bytes) or in
// variable files, in order.
struct Piece {
  bool in_file = false;
  std::string bytes;       // !in_file: the bytes
  FileRef file;            // in_file: the file, whose payload is the bytes
  std::uint64_t size = 0;  // bytes in the piece
};
struct Blob {
  std::vector<Piece> pieces;
  std::uint64_t size() const;
};

// An array: its shape and its ravel's bytes (little-endian doubles).
struct StoredArray {
  std::vector<std::size_t> shape;
  Blob ravel;
};

// The inputs of a surface: the current one, and older ones that images were drawn from.
struct Record {
  std::uint32_t id = 0;
  int nocur = 0, nostr = 0, intcu = 0, intst = 0;
  StoredArray inppn, inptg;
  // STATUS[3] and STATUS[4] of that surface (Workspace::status_twists, status_auto): its twists
  // and AUTO tangents. Written after the functions, for the records where one is not 0 (a file
  // without that section has none).
  std::uint8_t twists = 0, auto_tangents = 0;
  std::uint64_t generation = 0;  // in memory only: the Changes::surface it stands for
};

// IMAGE, TEMP1 or TEMP2.
struct ImageEntry {
  enum Kind : std::uint8_t { absent = 0, recipe = 1, stored = 2, linked_file = 3 } kind = absent;
  std::uint32_t record = 0;  // recipe: the record drawn from, with `desim`
  Description desim;
  Blob data;       // stored: the image as the payload of an IGDSIMAG file encodes it
  FileRef linked;  // linked_file: the IGDSIMAG file
  std::weak_ptr<const void> shown;  // in memory only: the image this entry is (ImageRef::watch)
};

struct SessionTable {
  std::uint32_t next_number = 1;
  std::array<int, 10> status{};
  std::vector<Record> records;
  std::uint32_t current = 0;   // the record of the current surface; 0: no surface
  bool derived = true;         // PATCHES and INTPN are made again from the inputs
  StoredArray patches, intpn;  // else these
  std::array<ImageEntry, 3> images;
  // END APL's defined functions, each its lines (written after the images; a file without them,
  // from an igds that did not keep them, has none).
  std::vector<std::vector<std::string>> functions;
  // The user's own variables of END APL (workspace/disk/apl_file.h), a tagged section before the
  // journal's; a file without it has none. A section that does not read costs itself alone:
  // decode_session leaves the variables empty and says why in `apl_variables_damage`.
  std::vector<AplVariable> apl_variables;
  std::string apl_variables_damage;  // in memory only
  // The undo journal (workspace/disk/journal_file.h), as its own encoding: the last section,
  // tagged; a file without it has an empty journal.
  std::string journal;

  const Record* record(std::uint32_t id) const;
  Record* record(std::uint32_t id);
  // Every variable file the table names, with the type of its name (IGDSVARS, IGDSVIMG).
  std::vector<std::pair<FileRef, std::string_view>> files() const;
};

inline constexpr std::size_t inline_limit = 1024;          // bytes kept in the session file
inline constexpr std::size_t piece_bytes = 2u << 20;       // an input array's pieces: 2 MB
inline constexpr std::uint32_t file_numbers = 0x10000000;  // seven hex digits
// The most bytes END APL's variables take in the session file (itself at most 16 MB): a larger
// variable is kept by )SAVE only.
inline constexpr std::size_t max_session_apl_bytes = std::size_t(8) << 20;

std::string encode_session(const SessionTable& table);
// Throws Damage("FORMAT") for anything malformed (lengths, kinds, counts).
SessionTable decode_session(std::string_view payload);

// Bnnnnnnn: the name of variable file `number`.
std::string variable_file_name(std::uint32_t number);
// The number of a Bnnnnnnn.TYPE name of a variable file (IGDSVARS or IGDSVIMG), or 0.
std::uint32_t variable_file_number(std::string_view file);

}  // namespace igds::disk
