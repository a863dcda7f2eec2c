#include "workspace/disk/session_file.h"

#include <fmt/format.h>

#include "workspace/disk/apl_file.h"
#include "workspace/disk/frame.h"

namespace igds::disk {

namespace {

// Far more than any legal session needs; a count beyond is a damaged file.
constexpr std::uint32_t max_records = 16;
constexpr std::uint32_t max_pieces = 1u << 16;
// A piece is far smaller than this (2 MB, or a whole image): sizes added up never overflow.
constexpr std::uint64_t max_piece_bytes = std::uint64_t(1) << 40;
// The fewest bytes a piece takes in the file (an empty one kept in the session file).
constexpr std::size_t min_piece_bytes = 9;
// The tags of the journal's section ("JRNL") and of END APL's variables' ("APLV").
constexpr std::uint32_t journal_tag = 0x4c4e524a;
constexpr std::uint32_t apl_variables_tag = 0x564c5041;

void write_ref(Writer& w, const FileRef& f) {
  w.u32(f.number);
  w.u64(f.length);
  w.u64(f.sum);
}

FileRef read_ref(Reader& r) {
  FileRef f;
  f.number = r.u32();
  f.length = r.u64();
  f.sum = r.u64();
  if (f.number == 0 || f.number >= file_numbers) throw Damage("FORMAT");
  return f;
}

void write_blob(Writer& w, const Blob& b) {
  w.u32(static_cast<std::uint32_t>(b.pieces.size()));
  for (const Piece& p : b.pieces) {
    w.u8(p.in_file ? 1 : 0);
    w.u64(p.size);
    if (p.in_file)
      write_ref(w, p.file);
    else
      w.bytes(p.bytes);
  }
}

Blob read_blob(Reader& r) {
  Blob b;
  const std::uint32_t n = r.u32();
  if (n > max_pieces || n > r.left() / min_piece_bytes) throw Damage("FORMAT");
  for (std::uint32_t k = 0; k < n; ++k) {
    Piece p;
    const std::uint8_t kind = r.u8();
    if (kind > 1) throw Damage("FORMAT");
    p.in_file = kind == 1;
    p.size = r.u64();
    if (p.size > max_piece_bytes) throw Damage("FORMAT");
    if (p.in_file) {
      p.file = read_ref(r);
      // A piece's file is its frame around its bytes.
      if (p.file.length != p.size + frame_header_bytes + frame_trailer_bytes)
        throw Damage("FORMAT");
    } else {
      if (p.size > inline_limit) throw Damage("FORMAT");
      p.bytes = std::string(r.bytes(static_cast<std::size_t>(p.size)));
    }
    b.pieces.push_back(std::move(p));
  }
  return b;
}

void write_array(Writer& w, const StoredArray& a) {
  w.u32(static_cast<std::uint32_t>(a.shape.size()));
  for (auto d : a.shape) w.u64(d);
  write_blob(w, a.ravel);
}

StoredArray read_array(Reader& r) {
  StoredArray a;
  const std::uint32_t rank = r.u32();
  if (rank > 8) throw Damage("FORMAT");
  std::uint64_t count = rank == 0 ? 0 : 1;
  for (std::uint32_t k = 0; k < rank; ++k) {
    const std::uint64_t d = r.u64();
    if (d != 0 && count > (std::uint64_t(1) << 40) / d) throw Damage("FORMAT");
    count *= d;
    a.shape.push_back(static_cast<std::size_t>(d));
  }
  a.ravel = read_blob(r);
  if (a.ravel.size() != count * sizeof(double)) throw Damage("FORMAT");
  return a;
}

}  // namespace

std::uint64_t Blob::size() const {
  std::uint64_t n = 0;
  for (const Piece& p : pieces) n += p.size;
  return n;
}

const Record* SessionTable::record(std::uint32_t id) const {
  for (const Record& r : records)
    if (r.id == id) return &r;
  return nullptr;
}

Record* SessionTable::record(std::uint32_t id) {
  for (Record& r : records)
    if (r.id == id) return &r;
  return nullptr;
}

std::vector<std::pair<FileRef, std::string_view>> SessionTable::files() const {
  std::vector<std::pair<FileRef, std::string_view>> out;
  auto blob = [&](const Blob& b) {
    for (const Piece& p : b.pieces)
      if (p.in_file) out.emplace_back(p.file, "IGDSVARS");
  };
  for (const Record& r : records) {
    blob(r.inppn.ravel);
    blob(r.inptg.ravel);
  }
  if (!derived) {
    blob(patches.ravel);
    blob(intpn.ravel);
  }
  for (const ImageEntry& e : images) {
    if (e.kind == ImageEntry::stored) blob(e.data);
    if (e.kind == ImageEntry::linked_file) out.emplace_back(e.linked, "IGDSVIMG");
  }
  return out;
}

std::string encode_session(const SessionTable& t) {
  Writer w;
  w.u32(t.next_number);
  for (int s : t.status) w.i32(s);
  w.u32(static_cast<std::uint32_t>(t.records.size()));
  for (const Record& r : t.records) {
    w.u32(r.id);
    for (int v : {r.nocur, r.nostr, r.intcu, r.intst}) w.i32(v);
    write_array(w, r.inppn);
    write_array(w, r.inptg);
  }
  w.u32(t.current);
  w.u8(t.derived ? 1 : 0);
  if (!t.derived) {
    write_array(w, t.patches);
    write_array(w, t.intpn);
  }
  for (const ImageEntry& e : t.images) {
    w.u8(e.kind);
    switch (e.kind) {
      case ImageEntry::absent:
        break;
      case ImageEntry::recipe:
        w.u32(e.record);
        w.description(e.desim);
        break;
      case ImageEntry::stored:
        write_blob(w, e.data);
        break;
      case ImageEntry::linked_file:
        write_ref(w, e.linked);
        break;
    }
  }
  write_functions(w, t.functions);
  // The surfaces' twists and AUTO tangents, after the functions (a section added later).
  std::uint32_t marked = 0;
  for (const Record& rec : t.records) marked += (rec.twists | rec.auto_tangents) != 0;
  w.u32(marked);
  for (const Record& rec : t.records) {
    if ((rec.twists | rec.auto_tangents) == 0) continue;
    w.u32(rec.id);
    w.u8(rec.twists);
    w.u8(rec.auto_tangents);
  }
  if (!t.apl_variables.empty()) {
    Writer v;
    write_variables(v, t.apl_variables);
    const std::string bytes = v.str();
    w.u32(apl_variables_tag);
    w.u64(bytes.size());
    w.bytes(bytes);
  }
  if (!t.journal.empty()) {
    w.u32(journal_tag);
    w.u64(t.journal.size());
    w.bytes(t.journal);
  }
  return w.str();
}

SessionTable decode_session(std::string_view payload) {
  Reader r(payload);
  SessionTable t;
  t.next_number = r.u32();
  for (int& s : t.status) s = r.i32();
  const std::uint32_t records = r.u32();
  if (records > max_records) throw Damage("FORMAT");
  for (std::uint32_t k = 0; k < records; ++k) {
    Record rec;
    rec.id = r.u32();
    if (rec.id == 0 || t.record(rec.id)) throw Damage("FORMAT");
    rec.nocur = r.i32();
    rec.nostr = r.i32();
    rec.intcu = r.i32();
    rec.intst = r.i32();
    rec.inppn = read_array(r);
    rec.inptg = read_array(r);
    t.records.push_back(std::move(rec));
  }
  t.current = r.u32();
  if (t.current != 0 && !t.record(t.current)) throw Damage("FORMAT");
  const std::uint8_t derived = r.u8();
  if (derived > 1) throw Damage("FORMAT");
  t.derived = derived == 1;
  if (!t.derived) {
    t.patches = read_array(r);
    t.intpn = read_array(r);
  }
  for (ImageEntry& e : t.images) {
    const std::uint8_t kind = r.u8();
    if (kind > ImageEntry::linked_file) throw Damage("FORMAT");
    e.kind = static_cast<ImageEntry::Kind>(kind);
    switch (e.kind) {
      case ImageEntry::absent:
        break;
      case ImageEntry::recipe:
        e.record = r.u32();
        if (!t.record(e.record)) throw Damage("FORMAT");
        e.desim = r.description();
        break;
      case ImageEntry::stored:
        e.data = read_blob(r);
        break;
      case ImageEntry::linked_file:
        e.linked = read_ref(r);
        break;
    }
  }
  if (!r.at_end()) t.functions = read_functions(r);
  if (!r.at_end()) {
    const std::uint32_t marked = r.u32();
    if (marked > t.records.size()) throw Damage("FORMAT");
    for (std::uint32_t k = 0; k < marked; ++k) {
      Record* rec = t.record(r.u32());
      if (!rec) throw Damage("FORMAT");
      rec->twists = r.u8();
      rec->auto_tangents = r.u8();
      if (rec->twists > 1 || rec->auto_tangents > 1) throw Damage("FORMAT");
    }
  }
  bool more = !r.at_end();
  std::uint32_t tag = more ? r.u32() : 0;
  if (more && tag == apl_variables_tag) {
    const std::uint64_t n = r.u64();
    if (n == 0 || n > r.left()) throw Damage("FORMAT");
    Reader section(r.bytes(static_cast<std::size_t>(n)));
    try {
      // More than igds writes there: a forged section.
      if (n > max_session_apl_bytes + 4) throw Damage("FORMAT: MORE THAN 8 MB");
      t.apl_variables = read_variables(section);
      if (!section.at_end()) throw Damage("FORMAT: BYTES AFTER THE VARIABLES");
    } catch (const Damage& d) {
      t.apl_variables.clear();
      t.apl_variables_damage = d.reason();
    }
    more = !r.at_end();
    tag = more ? r.u32() : 0;
  }
  if (more) {
    if (tag != journal_tag) throw Damage("FORMAT");
    const std::uint64_t n = r.u64();
    if (n == 0 || n > r.left()) throw Damage("FORMAT");
    t.journal = std::string(r.bytes(static_cast<std::size_t>(n)));
  }
  r.finish();
  return t;
}

std::string variable_file_name(std::uint32_t number) {
  return fmt::format("B{:07X}", number);
}

std::uint32_t variable_file_number(std::string_view file) {
  const bool vars = file.ends_with(".IGDSVARS"), image = file.ends_with(".IGDSVIMG");
  if (file.size() != 17 || file[0] != 'B' || !(vars || image)) return 0;
  std::uint32_t n = 0;
  for (char c : file.substr(1, 7)) {
    int d = (c >= '0' && c <= '9') ? c - '0' : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : -1;
    if (d < 0) return 0;
    n = n * 16 + static_cast<std::uint32_t>(d);
  }
  return n;
}

}  // namespace igds::disk
