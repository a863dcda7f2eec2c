// The input of fuzz_records (tests/fuzz/fuzz_records.cpp): a disk's session and variable files as
// one byte string, read, written to a disk, made from a disk, and mutated record by record.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tests/fuzz/fuzz.h"
#include "workspace/disk/frame.h"
#include "workspace/disk/session_file.h"

namespace igds::fuzz {

struct RecordsFile {
  std::uint8_t kind = 0;  // 0 the session, 1 a variable file (IGDSVARS), 2 an image's copy
  std::uint32_t number = 0;
  std::string payload;
};

struct RecordsInput {
  std::uint8_t flags = 1;  // 1: the session's references made to hold
  std::vector<RecordsFile> files;
};

inline RecordsInput read_records(const std::uint8_t* data, std::size_t size) {
  RecordsInput in;
  if (size == 0) return in;
  in.flags = data[0];
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(data[at + i]) << (8 * i);
    return v;
  };
  for (std::size_t at = 1; at + 9 <= size;) {
    RecordsFile f;
    f.kind = data[at] % 3;
    f.number = u32(at + 1);
    const std::uint32_t length = u32(at + 5);
    at += 9;
    if (length > size - at) break;
    f.payload.assign(reinterpret_cast<const char*>(data) + at, length);
    at += length;
    in.files.push_back(std::move(f));
  }
  return in;
}

inline std::string records_bytes(const RecordsInput& in) {
  std::string out(1, static_cast<char>(in.flags));
  auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out += static_cast<char>(v >> (8 * i));
  };
  for (const RecordsFile& f : in.files) {
    out += static_cast<char>(f.kind);
    u32(f.number);
    u32(static_cast<std::uint32_t>(f.payload.size()));
    out += f.payload;
  }
  return out;
}

// The name a file of the input has on the disk, and its frame's magic.
inline std::string records_name(const RecordsFile& f) {
  if (f.kind == 0) return "BINSAVE.IGDSCONT";
  return disk::variable_file_name(f.number) + (f.kind == 1 ? ".IGDSVARS" : ".IGDSVIMG");
}

inline std::string records_framed(const RecordsFile& f) {
  return disk::frame(f.kind == 0   ? "IGDSCONT"
                     : f.kind == 1 ? "IGDSVARS"
                                   : "IGDSIMAG",
                     f.payload, f.kind == 0 ? 2 : 1);
}

// The files of `in` on the disk `dir`, framed; the session's references made to name their files'
// lengths and checksums when the flags ask.
inline void write_records(const std::filesystem::path& dir, const RecordsInput& in) {
  std::map<std::uint32_t, disk::FileRef> refs[2];  // IGDSVARS, IGDSVIMG
  for (const RecordsFile& f : in.files) {
    if (f.kind == 0 || f.number == 0 || f.number >= disk::file_numbers) continue;
    const std::string framed = records_framed(f);
    std::ofstream(dir / records_name(f), std::ios::binary)
        .write(framed.data(), static_cast<long>(framed.size()));
    refs[f.kind - 1][f.number] = {f.number, framed.size(), disk::trailing_checksum(framed)};
  }
  for (const RecordsFile& f : in.files) {
    if (f.kind != 0) continue;
    std::string payload = f.payload;
    if (in.flags & 1) {
      try {
        disk::SessionTable t = disk::decode_session(payload);
        auto fix = [&](disk::Blob& b) {
          for (disk::Piece& p : b.pieces) {
            if (!p.in_file) continue;
            if (auto r = refs[0].find(p.file.number); r != refs[0].end()) {
              p.file = r->second;
              p.size = r->second.length - disk::frame_header_bytes - disk::frame_trailer_bytes;
            }
          }
        };
        for (disk::Record& r : t.records) {
          fix(r.inppn.ravel);
          fix(r.inptg.ravel);
        }
        fix(t.patches.ravel);
        fix(t.intpn.ravel);
        for (disk::ImageEntry& e : t.images) {
          fix(e.data);
          if (auto r = refs[1].find(e.linked.number);
              e.kind == disk::ImageEntry::linked_file && r != refs[1].end())
            e.linked = r->second;
        }
        payload = disk::encode_session(t);
      } catch (const disk::Damage&) {
        // Not a session table: its bytes as they are.
      }
    }
    const std::string framed = disk::frame("IGDSCONT", payload, 2);
    std::ofstream(dir / "BINSAVE.IGDSCONT", std::ios::binary)
        .write(framed.data(), static_cast<long>(framed.size()));
  }
}

// The session and the variable files of the disk `dir` as an input (seeds).
inline RecordsInput pack_records(const std::filesystem::path& dir) {
  RecordsInput in;
  auto payload_of = [](const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::stringstream s;
    s << file.rdbuf();
    const std::string bytes = s.str();
    return std::string(
        bytes.substr(disk::frame_header_bytes,
                     bytes.size() - disk::frame_header_bytes - disk::frame_trailer_bytes));
  };
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    RecordsFile f;
    if (name == "BINSAVE.IGDSCONT") {
      f.kind = 0;
    } else if (const std::uint32_t n = disk::variable_file_number(name)) {
      f.kind = name.ends_with(".IGDSVARS") ? 1 : 2;
      f.number = n;
    } else {
      continue;
    }
    f.payload = payload_of(e.path());
    in.files.push_back(std::move(f));
  }
  std::sort(in.files.begin(), in.files.end(), [](const RecordsFile& a, const RecordsFile& b) {
    return std::pair(a.kind, a.number) < std::pair(b.kind, b.number);
  });
  return in;
}

// ---- the mutations ---------------------------------------------------------------------------

// Numbers that sit at the edges of what the readers check.
inline std::int64_t interesting_int(std::minstd_rand& rng, std::int64_t near) {
  static constexpr std::int64_t values[] = {0,
                                            1,
                                            2,
                                            3,
                                            -1,
                                            7,
                                            255,
                                            1000000,
                                            1000001,
                                            4000000,
                                            1 << 16,
                                            0x7FFFFFFF,
                                            -0x80000000LL,
                                            1LL << 40,
                                            1LL << 60};
  // Wrapping arithmetic: a field's neighbours at the ends of its range.
  const auto n = static_cast<std::uint64_t>(near);
  switch (rng() % 3) {
    case 0:
      return static_cast<std::int64_t>(n + rng() % 5 - 2);
    case 1:
      return static_cast<std::int64_t>(n * 2);
    default:
      return values[rng() % std::size(values)];
  }
}

inline double interesting_double(std::minstd_rand& rng) {
  static constexpr double values[] = {0.0,  -0.0, 1.0,   1e308, -1e308, 1e-310,
                                      45.0, 90.0, 135.0, 1e6,   25.0};
  switch (rng() % 4) {
    case 0:
      return std::numeric_limits<double>::quiet_NaN();
    case 1:
      return std::numeric_limits<double>::infinity();
    default:
      return values[rng() % std::size(values)];
  }
}

// The offsets and widths of the numbers of an undo journal (workspace/disk/journal_file.cpp), as
// far as it reads: where a structure-aware change puts its value.
struct JournalField {
  std::size_t at, width;
  bool real;
};
inline std::vector<JournalField> journal_fields(std::string_view j) {
  std::vector<JournalField> fields;
  std::size_t at = 0;
  auto take = [&](std::size_t width, bool real = false) -> std::uint64_t {
    if (width > j.size() - at) throw std::out_of_range("journal");
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < width; ++i)
      v |= std::uint64_t(static_cast<unsigned char>(j[at + i])) << (8 * i);
    fields.push_back({at, width, real});
    at += width;
    return v;
  };
  auto skip = [&](std::uint64_t n) {
    if (n > j.size() - at) throw std::out_of_range("journal");
    at += static_cast<std::size_t>(n);
  };
  auto description = [&] {
    take(4);
    take(4);
    for (int k = 0; k < 3; ++k) take(8, true);
  };
  try {
    take(4);
    const std::uint64_t count = take(4);
    take(4);
    const std::uint64_t images = take(4);
    for (std::uint64_t k = 0; k < images && k < 1200; ++k) {
      const std::uint64_t kind = take(1);
      if (kind == 3) {
        skip(take(8));
        continue;
      }
      take(4);
      if (kind == 2) description();
    }
    for (std::uint64_t s = 0; s < count && s < 200; ++s) {
      skip(take(4));
      for (int k = 0; k < 2 * 14; ++k) take(4);
      for (int c = 0; c < 2; ++c) {
        const std::uint64_t whole = take(1);
        for (int shape = 0; shape < 2; ++shape) {
          const std::uint64_t rank = take(4);
          for (std::uint64_t d = 0; d < rank && d < 8; ++d) take(8);
        }
        if (whole == 0) {
          const std::uint64_t ranges = take(4);
          for (std::uint64_t r = 0; r < ranges && r < 4096; ++r) {
            take(8);
            take(8);
          }
        }
        for (int v = 0; v < 2; ++v) {
          const std::uint64_t n = take(8);
          for (std::uint64_t k = 0; k < n && k < 64; ++k) take(8, true);
          if (n > 64) skip((n - 64) * 8);
        }
      }
      for (int k = 0; k < 6; ++k) take(4);
    }
  } catch (const std::out_of_range&) {
  }
  return fields;
}

// One change of the session table `t`, chosen by `rng`.
inline void mutate_table(disk::SessionTable& t, std::minstd_rand& rng) {
  auto pick_record = [&]() -> disk::Record* {
    return t.records.empty() ? nullptr : &t.records[rng() % t.records.size()];
  };
  auto pick_blob = [&]() -> disk::Blob* {
    std::vector<disk::Blob*> blobs;
    for (disk::Record& r : t.records) {
      blobs.push_back(&r.inppn.ravel);
      blobs.push_back(&r.inptg.ravel);
    }
    blobs.push_back(&t.patches.ravel);
    blobs.push_back(&t.intpn.ravel);
    for (disk::ImageEntry& e : t.images) blobs.push_back(&e.data);
    return blobs[rng() % blobs.size()];
  };
  auto as_int = [](std::int64_t v) { return static_cast<int>(static_cast<std::int32_t>(v)); };
  switch (rng() % 12) {
    case 0:
      if (disk::Record* r = pick_record()) {
        int* fields[] = {&r->nocur, &r->nostr, &r->intcu, &r->intst};
        int& f = *fields[rng() % 4];
        f = as_int(interesting_int(rng, f));
      }
      break;
    case 1:
      if (disk::Record* r = pick_record()) {
        auto& shape = rng() % 2 ? r->inppn.shape : r->inptg.shape;
        if (!shape.empty() && rng() % 4)
          shape[rng() % shape.size()] = static_cast<std::size_t>(interesting_int(rng, 3));
        else
          shape.push_back(rng() % 5);
      }
      break;
    case 2: {
      disk::Blob& b = *pick_blob();
      if (b.pieces.empty()) break;
      disk::Piece& p = b.pieces[rng() % b.pieces.size()];
      switch (rng() % 4) {
        case 0:
          b.pieces.push_back(p);  // the same piece (the same file) twice
          b.pieces.back().size = static_cast<std::uint64_t>(interesting_int(rng, 8));
          b.pieces.back().file.length = b.pieces.back().size + 32;
          break;
        case 1:
          b.pieces.erase(b.pieces.begin() + static_cast<long>(rng() % b.pieces.size()));
          break;
        case 2:
          p.file.number = static_cast<std::uint32_t>(1 + rng() % 8);
          break;
        default:
          p.size =
              static_cast<std::uint64_t>(interesting_int(rng, static_cast<std::int64_t>(p.size)));
          if (!p.in_file) p.bytes.resize(std::min<std::uint64_t>(p.size, disk::inline_limit));
          break;
      }
      break;
    }
    case 3:
      t.current = static_cast<std::uint32_t>(rng() % 4);
      break;
    case 4:
      t.derived = !t.derived;
      break;
    case 5: {
      disk::ImageEntry& e = t.images[rng() % 3];
      switch (rng() % 5) {
        case 0:
          e.kind = static_cast<disk::ImageEntry::Kind>(rng() % 4);
          break;
        case 1:
          e.record = static_cast<std::uint32_t>(rng() % 4);
          break;
        case 2:
          e.desim.what = as_int(interesting_int(rng, e.desim.what));
          break;
        case 3:
          e.desim.projection = static_cast<Projection>(rng() % 6);
          break;
        default:
          e.desim.parameters[rng() % 3] = interesting_double(rng);
          break;
      }
      break;
    }
    case 6:
      t.status[rng() % 10] = as_int(interesting_int(rng, 1));
      break;
    case 7:
      switch (rng() % 4) {
        case 0:
          t.functions.push_back({"Z←F X", std::string(rng() % 8, 'Z')});
          break;
        case 1:
          if (!t.functions.empty()) t.functions.pop_back();
          break;
        case 2: {
          // END APL's variables: a name APL may or may not have, elements that may not fill
          // the shape, numbers that may not be finite.
          static const char* const names[] = {"A", "Z_", "∆1", "INPPN", "a", "1A", ""};
          AplVariable v;
          v.name = names[rng() % 7];
          for (std::size_t k = rng() % 3; k > 0; --k)
            v.shape.push_back(static_cast<std::size_t>(interesting_int(rng, 2)));
          v.characters = rng() % 2;
          for (std::size_t k = rng() % 4; k > 0; --k) {
            if (v.characters)
              v.text.push_back(static_cast<char32_t>(interesting_int(rng, 65)));
            else
              v.numbers.push_back(interesting_double(rng));
          }
          t.apl_variables.push_back(std::move(v));
          break;
        }
        default:
          if (!t.apl_variables.empty()) t.apl_variables.erase(t.apl_variables.begin());
          break;
      }
      break;
    case 8:
      if (disk::Record* r = pick_record()) {
        r->twists = static_cast<std::uint8_t>(rng() % 3);
        r->auto_tangents = static_cast<std::uint8_t>(rng() % 3);
      }
      break;
    case 9:
      if (disk::Record* r = pick_record()) t.records.push_back(*r);  // two of one id
      break;
    case 10:
      t.next_number = static_cast<std::uint32_t>(interesting_int(rng, t.next_number));
      break;
    default:
      if (!t.journal.empty()) {
        const auto fields = journal_fields(t.journal);
        if (fields.empty()) break;
        const JournalField f = fields[rng() % fields.size()];
        std::uint64_t v;
        if (f.real) {
          const double d = interesting_double(rng);
          std::memcpy(&v, &d, 8);
        } else {
          std::int64_t old = 0;
          std::memcpy(&old, t.journal.data() + f.at, f.width);
          v = static_cast<std::uint64_t>(interesting_int(rng, old));
        }
        for (std::size_t i = 0; i < f.width; ++i)
          t.journal[f.at + i] = static_cast<char>(v >> (8 * i));
      }
      break;
  }
}

// fuzz_records' mutator: most of the time one change of the session table or of its journal,
// else libFuzzer's own mutation of a file's payload or of the whole input.
inline std::size_t mutate_records(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                  unsigned seed) {
  std::minstd_rand rng(seed);
  RecordsInput in = read_records(data, size);
  const auto session = std::find_if(in.files.begin(), in.files.end(),
                                    [](const RecordsFile& f) { return f.kind == 0; });
  if (in.files.empty() || rng() % 16 == 0) return LLVMFuzzerMutate(data, size, max_size);
  const unsigned action = rng() % 8;
  if (action < 5 && session != in.files.end()) {
    try {
      disk::SessionTable t = disk::decode_session(session->payload);
      mutate_table(t, rng);
      session->payload = disk::encode_session(t);
    } catch (const disk::Damage&) {
      return LLVMFuzzerMutate(data, size, max_size);
    }
  } else if (action == 5) {
    in.flags ^= 1;
  } else {
    RecordsFile& f = in.files[rng() % in.files.size()];
    const std::size_t used = f.payload.size();
    const std::size_t room = std::max(used * 2, std::size_t(64));
    f.payload.resize(room);
    f.payload.resize(
        LLVMFuzzerMutate(reinterpret_cast<std::uint8_t*>(f.payload.data()), used, room));
  }
  const std::string out = records_bytes(in);
  if (out.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

}  // namespace igds::fuzz
