#include "workspace/disk/session.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "workspace/disk/files.h"
#include "workspace/disk/frame.h"
#include "workspace/disk/journal_file.h"
#include "workspace/disk/lock.h"
#include "workspace/disk/session_file.h"
#include "workspace/error.h"
#include "workspace/images.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/surface.h"
#include "workspace/variables.h"

namespace igds {

namespace {

using disk::Blob;
using disk::FileRef;
using disk::ImageEntry;
using disk::Piece;
using disk::Record;
using disk::SessionTable;
using disk::StoredArray;

constexpr std::string_view session_name = "BINSAVE";
constexpr std::string_view session_type = "IGDSCONT";
constexpr std::string_view session_magic = "IGDSCONT";
constexpr std::string_view variable_magic = "IGDSVARS";
constexpr std::string_view pieces_type = "IGDSVARS";
constexpr std::string_view linked_type = "IGDSVIMG";
constexpr std::size_t max_session_bytes = 16u << 20;
// A variable file is a piece of an input (2 MB) or a whole variable: never more than the largest
// legal surface file.
const std::size_t max_piece_file_bytes = max_surface_file_bytes();

std::string session_file() {
  return fmt::format("{}.{}", session_name, session_type);
}

std::string_view raw_bytes(const Array& a) {
  return {reinterpret_cast<const char*>(a.data()), a.size() * sizeof(double)};
}

// The image slots in the order of the session file.
ImageRef& image_slot(Workspace& ws, std::size_t k) {
  return k == 0 ? ws.image : k == 1 ? ws.temp1 : ws.temp2;
}
constexpr Variable image_variables[] = {Variable::image, Variable::temp1, Variable::temp2};

// Two entries that are the same image (STORE FIRST of the current image shares it).
bool same_entry(const ImageEntry& a, const ImageEntry& b) {
  if (a.kind != b.kind || a.kind == ImageEntry::absent) return false;
  switch (a.kind) {
    case ImageEntry::recipe:
      return a.record == b.record && a.desim == b.desim;
    case ImageEntry::linked_file:
      return a.linked == b.linked;
    default:
      return a.data.pieces.size() == b.data.pieces.size() && !a.data.pieces.empty() &&
             a.data.pieces[0].in_file && b.data.pieces[0].in_file &&
             a.data.pieces[0].file == b.data.pieces[0].file;
  }
}

}  // namespace

struct Session::State {
  Disk disk;
  std::vector<std::string> notices;
  std::unique_ptr<disk::DiskLock> lock;
  SessionTable saved;
  bool saved_known = false;        // false: the next save writes everything
  bool rewrite = false;            // the session file differs from `saved`: written at next save
  std::set<std::string> obsolete;  // files of a version 1 session, removed after the next save
  std::uint32_t next_number = 1;
  std::optional<Journal> journal;  // the undo journal read by the last load
  // During a load: the variable files read and checked so far, their payloads and the reference
  // they were checked against.
  struct Checked {
    disk::MappedFile file;
    std::string_view payload;
    FileRef ref;
  };
  mutable std::map<std::uint32_t, Checked> checked_;

  explicit State(const Disk& d) : disk(d) {}

  std::filesystem::path file_path(std::uint32_t number, std::string_view type) const {
    return disk.path(disk::variable_file_name(number), type);
  }

  // A number whose file is neither named by `tables` nor present on the disk in any type.
  std::uint32_t new_number(std::initializer_list<const SessionTable*> tables) {
    for (std::uint32_t tries = 0; tries < disk::file_numbers; ++tries) {
      std::uint32_t n = next_number;
      next_number = next_number + 1 >= disk::file_numbers ? 1 : next_number + 1;
      bool named = false;
      for (const SessionTable* t : tables)
        for (const auto& [f, type] : t->files()) named = named || f.number == n;
      struct stat st;
      if (named || ::lstat(file_path(n, pieces_type).c_str(), &st) == 0 ||
          ::lstat(file_path(n, linked_type).c_str(), &st) == 0)
        continue;
      return n;
    }
    throw disk::IoError(ENOSPC, "NO FREE VARIABLE FILE NAME");
  }

  // ---- writing -------------------------------------------------------------------------

  // One save in progress: the files it wrote (removed again if it fails).
  struct Writing {
    State& state;
    SessionTable& next;
    std::vector<std::pair<std::uint32_t, std::string_view>> written;

    Piece piece(std::string_view bytes) {
      Piece p;
      p.size = bytes.size();
      if (bytes.size() <= disk::inline_limit) {
        p.bytes = std::string(bytes);
        return p;
      }
      disk::Writer payload;
      payload.borrow(bytes);
      return file_piece(payload);
    }

    Piece file_piece(const disk::Writer& payload) {
      Piece p;
      p.size = payload.size();
      p.in_file = true;
      const std::uint32_t n = state.new_number({&state.saved, &next});
      const disk::Writer framed = disk::frame(variable_magic, payload);
      written.emplace_back(n, pieces_type);
      disk::write_new_file(state.file_path(n, pieces_type), framed);
      p.file = {n, framed.size(), disk::trailing_checksum(framed.runs().back())};
      return p;
    }

    // An array whole: inline when small, else one file.
    StoredArray whole(const Array& a) {
      StoredArray s;
      s.shape = a.shape;
      if (!a.empty()) s.ravel.pieces.push_back(piece(raw_bytes(a)));
      return s;
    }

    // An input array in pieces: those of `before` that `edits` left alone are kept.
    StoredArray input(const Array& a, const StoredArray* before, const Edits& edits) {
      if (a.size() * sizeof(double) <= disk::inline_limit) return whole(a);
      StoredArray s;
      s.shape = a.shape;
      const std::string_view bytes = raw_bytes(a);
      const std::size_t count = (bytes.size() + disk::piece_bytes - 1) / disk::piece_bytes;
      const bool reuse = before && before->shape == a.shape && !edits.whole &&
                         before->ravel.pieces.size() == count;
      for (std::size_t k = 0; k < count; ++k) {
        const std::size_t from = k * disk::piece_bytes;
        const std::size_t to = std::min(bytes.size(), from + disk::piece_bytes);
        bool touched = !reuse;
        for (const auto& [first, end] : edits.ranges)
          touched = touched || (first * sizeof(double) < to && end * sizeof(double) > from);
        if (!touched && before->ravel.pieces[k].size == to - from)
          s.ravel.pieces.push_back(before->ravel.pieces[k]);
        else
          s.ravel.pieces.push_back(piece(bytes.substr(from, to - from)));
      }
      return s;
    }

    // The image as IGDSIMAG's payload encodes it, inline or in one file.
    Blob image_data(const Image& image) {
      disk::Writer w;
      w.image(image);
      Blob b;
      if (w.size() <= disk::inline_limit)
        b.pieces.push_back(piece(w.str()));
      else
        b.pieces.push_back(file_piece(w));
      return b;
    }

    // The session's own copy of the IGDSIMAG file an image was read from (a reflink where the
    // file system shares blocks), if that file is still the one read: never a second name of
    // the user's file, which a copy over it in place would change under the session.
    std::optional<FileRef> copy(const Image& image) {
      const std::uint32_t n = state.new_number({&state.saved, &next});
      const auto to = state.file_path(n, linked_type);
      written.emplace_back(n, linked_type);
      if (!disk::copy_file(image.file, to)) {
        written.pop_back();
        return std::nullopt;
      }
      disk::Writer encoded;
      encoded.image(image);
      const std::uint64_t expected =
          encoded.size() + disk::frame_header_bytes + disk::frame_trailer_bytes;
      struct stat st;
      std::uint64_t sum = 0;
      bool same = false;
      int fd = ::open(to.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
      if (fd >= 0) {
        char tail[8];
        same = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
               static_cast<std::uint64_t>(st.st_size) == expected &&
               ::pread(fd, tail, 8, st.st_size - 8) == 8;
        if (same) sum = disk::trailing_checksum(std::string_view(tail, 8));
        ::close(fd);
      }
      if (!same || sum != image.file_sum) {
        ::unlink(to.c_str());
        written.pop_back();
        return std::nullopt;
      }
      return FileRef{n, expected, sum};
    }

    void undo() {
      for (const auto& [n, type] : written) ::unlink(state.file_path(n, type).c_str());
    }
  };

  // True when every variable file of `b` is on the disk with its length (a file removed or
  // replaced behind igds's back would make the session unreadable).
  bool present(const FileRef& f, std::string_view type) const {
    struct stat st;
    return ::lstat(file_path(f.number, type).c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
           static_cast<std::uint64_t>(st.st_size) == f.length;
  }
  bool present(const Blob& b) const {
    return std::all_of(b.pieces.begin(), b.pieces.end(),
                       [&](const Piece& p) { return !p.in_file || present(p.file, pieces_type); });
  }
  bool present(const StoredArray& a) const { return present(a.ravel); }

  // ---- reading -------------------------------------------------------------------------

  // The payload of a piece's file, read and checked once per load (records share pieces); a
  // piece that names a file already read with another length or checksum, or another size than
  // the file holds, is damage (a session is checked, never trusted: docs/disk.md).
  std::string_view piece_payload(const Piece& p) const {
    const std::string name =
        fmt::format("{}.{}", disk::variable_file_name(p.file.number), pieces_type);
    if (auto known = checked_.find(p.file.number); known != checked_.end()) {
      if (!(known->second.ref == p.file) || known->second.payload.size() != p.size)
        throw disk::Damage(fmt::format("{}: NOT THE ONE SAVED", name));
      return known->second.payload;
    }
    std::optional<disk::MappedFile> file;
    try {
      file.emplace(file_path(p.file.number, pieces_type), max_piece_file_bytes);
    } catch (const disk::IoError& e) {
      throw disk::Damage(fmt::format("{}: {}", name, e.reason()));
    }
    if (!file->exists()) throw disk::Damage(fmt::format("{} MISSING", name));
    const std::string_view bytes = file->bytes();
    std::string_view payload;
    try {
      payload = disk::unframe(variable_magic, bytes).payload;
    } catch (const disk::Damage& d) {
      throw disk::Damage(fmt::format("{}: {}", name, d.reason()));
    }
    if (bytes.size() != p.file.length || disk::trailing_checksum(bytes) != p.file.sum ||
        payload.size() != p.size)
      throw disk::Damage(fmt::format("{}: NOT THE ONE SAVED", name));
    checked_.emplace(p.file.number, Checked{std::move(*file), payload, p.file});
    return payload;
  }

  // The bytes of a blob into `out`, which holds `room` bytes: each piece is copied only once
  // its size is known to be what its bytes are and to fit what is left.
  void read_blob(const Blob& b, char* out, std::size_t room) const {
    for (const Piece& p : b.pieces) {
      const std::string_view bytes = p.in_file ? piece_payload(p) : std::string_view(p.bytes);
      if (bytes.size() != p.size || bytes.size() > room) throw disk::Damage("FORMAT");
      if (!bytes.empty()) std::memcpy(out, bytes.data(), bytes.size());
      out += bytes.size();
      room -= bytes.size();
    }
    if (room != 0) throw disk::Damage("FORMAT");
  }

  // The files of a blob read and checked (mapped, not copied): what its pieces say they hold is
  // there before anything of that size is made.
  void check_pieces(const Blob& b) const {
    for (const Piece& p : b.pieces)
      if (p.in_file) piece_payload(p);
  }

  // An array whose shape was checked against the variables' table: its size is known, and held
  // by its files, before anything of that size is made.
  Array read_array(const StoredArray& s) const {
    const std::size_t bytes = Array::count(s.shape) * sizeof(double);
    if (bytes != s.ravel.size()) throw disk::Damage("FORMAT");
    check_pieces(s.ravel);
    // Every byte is read into it (else read_blob throws and it is dropped): not cleared first.
    Array a = Array::for_output(s.shape);
    read_blob(s.ravel, reinterpret_cast<char*>(a.data()), bytes);
    return a;
  }

  // The inputs of a record, checked against the variables' table and limits.
  Workspace inputs_of(const Record& r) const {
    Workspace ws;
    ws.nocur = r.nocur;
    ws.nostr = r.nostr;
    ws.intcu = r.intcu;
    ws.intst = r.intst;
    // Sizes and shapes first: nothing is read or made for a record that claims too much.
    if (auto p = size_problem(ws.nocur, ws.nostr, ws.intcu, ws.intst))
      throw disk::Damage("SHAPES: " + p->reason);
    for (auto [v, stored] : {std::pair{Variable::inppn, &r.inppn}, {Variable::inptg, &r.inptg}}) {
      if (stored->shape != expected_shape(ws, v))
        throw disk::Damage(fmt::format("SHAPES: {} DOES NOT MATCH NOCUR AND NOSTR", info(v).name));
    }
    ws.inppn = read_array(r.inppn);
    ws.inptg = read_array(r.inptg);
    if (auto p = surface_problem(ws)) throw disk::Damage("SHAPES: " + p->reason);
    ws.set_surface_modes(r.twists == 1, r.auto_tangents == 1);
    return ws;
  }

  // The image of an entry: a recipe is made when first looked at, from the inputs of its record
  // (read and checked now); the others are read and checked now.
  ImageRef read_image(const ImageEntry& e, Variable slot, SessionTable& t,
                      std::map<std::uint32_t, std::shared_ptr<const Workspace>>& sources) const {
    Image image;
    if (e.kind == ImageEntry::recipe) {
      image.desim = e.desim;
      if (auto p = image_problem(image, slot)) throw disk::Damage("IMAGE: " + p->reason);
      auto& source = sources[e.record];
      if (!source) {
        const Record& r = *t.record(e.record);
        auto inputs = std::make_shared<Workspace>(inputs_of(r));
        inputs->changes.surface = r.generation;
        source = std::move(inputs);
      }
      return image_by_recipe(source, e.desim);
    }
    if (e.kind == ImageEntry::stored) {
      if (e.data.size() > max_image_file_bytes()) throw disk::Damage("IMAGE: TOO LARGE");
      check_pieces(e.data);
      std::string bytes(e.data.size(), '\0');
      read_blob(e.data, bytes.data(), bytes.size());
      disk::Reader r(bytes);
      image = r.image();
      r.finish();
    } else {
      const std::string name =
          fmt::format("{}.{}", disk::variable_file_name(e.linked.number), linked_type);
      std::optional<disk::MappedFile> file;
      if (e.linked.length > max_image_file_bytes()) throw disk::Damage("IMAGE: TOO LARGE");
      try {
        file.emplace(file_path(e.linked.number, linked_type), max_image_file_bytes());
      } catch (const disk::IoError& err) {
        throw disk::Damage(fmt::format("{}: {}", name, err.reason()));
      }
      if (!file->exists()) throw disk::Damage(fmt::format("{} MISSING", name));
      // Its frame and checksum, then whether it is the file saved, are reported with the file's
      // name; then what its payload holds, as the reading says it.
      struct InPayload {
        disk::Damage damage;
      };
      const bool one_saved = file->bytes().size() == e.linked.length &&
                             disk::trailing_checksum(file->bytes()) == e.linked.sum;
      try {
        image = disk::read_framed("IGDSIMAG", file->bytes(), [&](disk::Reader& r, std::uint32_t) {
          if (!one_saved) throw InPayload{disk::Damage(fmt::format("{}: NOT THE ONE SAVED", name))};
          try {
            Image read = r.image();
            r.finish();
            return read;
          } catch (const disk::Damage& d) {
            throw InPayload{d};
          }
        });
      } catch (const InPayload& p) {
        throw p.damage;
      } catch (const disk::Damage& d) {
        throw disk::Damage(fmt::format("{}: {}", name, d.reason()));
      }
    }
    if (auto p = image_problem(image, slot, &image.extent))
      throw disk::Damage("IMAGE: " + p->reason);
    return std::make_shared<const Image>(std::move(image));
  }

  Workspace read_session();
  Workspace read_legacy(std::string_view payload);
  // An image of the session that could not be read: its entry as the file had it, and why.
  struct Lost {
    ImageEntry entry;
    std::string reason;
  };
  void keep_lost_images_aside(SessionTable& t, const std::array<std::optional<Lost>, 3>& lost);
  void collect_garbage(const SessionTable& table);
  void keep_apl_variables_aside(const std::string& reason);
};

Workspace Session::State::read_session() {
  checked_.clear();
  disk::MappedFile file(disk.path(session_name, session_type), max_session_bytes);
  if (!file.exists()) {
    // Variable files without a session: kept aside, never deleted (issue of a session moved
    // away, or a crash while a damaged one was being put aside).
    std::vector<std::string> names = disk::folder_entries(disk.dir()), kept;
    std::sort(names.begin(), names.end());
    for (const auto& name : names) {
      if (name.ends_with(disk::temporary_suffix))
        ::unlink((disk.dir() / name).c_str());  // an unfinished write: never data
      else if (disk::variable_file_number(name))
        kept.push_back(disk::put_aside(disk.dir(), name.substr(0, 8), name));
    }
    if (!kept.empty())
      notices.push_back(fmt::format("{} VARIABLE FILES WITHOUT A SESSION FILE: KEPT AS {}{}",
                                    kept.size(), kept.front(), kept.size() > 1 ? " ..." : ""));
    return Workspace{};
  }
  const disk::Frame u = disk::unframe(session_magic, file.bytes());
  if (u.version == 1) return read_legacy(u.payload);
  SessionTable t = disk::decode_session(u.payload);
  if (auto p = status_problem(t.status)) throw disk::Damage("STATUS: " + p->reason);

  // Generations: every record a number of its own.
  for (Record& r : t.records) r.generation = new_generation();
  const std::uint64_t generation = t.current ? t.record(t.current)->generation : new_generation();
  Workspace ws;
  ws.status = t.status;
  if (t.current != 0) {
    // The current surface's modes are STATUS[3] and STATUS[4] (docs/disk.md, "The surfaces'
    // modes"); its record is made to say the same, so that an image drawn from it is made with
    // the workspace's modes: one generation, one surface.
    Record& r = *t.record(t.current);
    const std::uint8_t twists = ws.status[Workspace::status_twists] == 1 ? 1 : 0;
    const std::uint8_t automatic = ws.status[Workspace::status_auto] == 1 ? 1 : 0;
    rewrite = rewrite || r.twists != twists || r.auto_tangents != automatic;
    r.twists = twists;
    r.auto_tangents = automatic;
    ws = inputs_of(r);
    ws.status = t.status;
  }
  ws.functions = t.functions;
  ws.apl_variables = t.apl_variables;
  if (t.current != 0) {
    if (!t.derived) {
      for (auto [v, stored] :
           {std::pair{Variable::patches, &t.patches}, {Variable::intpn, &t.intpn}}) {
        if (!stored->shape.empty() && stored->shape != expected_shape(ws, v))
          throw disk::Damage(
              fmt::format("SHAPES: {} DOES NOT MATCH NOCUR AND NOSTR", info(v).name));
      }
      ws.patches = read_array(t.patches);
      ws.intpn = read_array(t.intpn);
      ws.changes.derived = false;  // PATCHES are then the session's: they must be there
      if (auto p = surface_problem(ws)) throw disk::Damage("SHAPES: " + p->reason);
      for (auto [v, a] : {std::pair{Variable::patches, &ws.patches}, {Variable::intpn, &ws.intpn}})
        if (auto p = finite_problem(v, *a)) throw disk::Damage(p->reason);
    }
  } else if (!t.derived) {
    throw disk::Damage("FORMAT");
  }
  ws.changes.surface = generation;
  ws.changes.derived = t.derived;
  // PATCHES and INTPN, when they are igds's interpolation of the inputs, are not stored: they are
  // made again from the inputs just read and checked. A surface the kernels refuse, or one that
  // overflows (inputs near the largest numbers), was not saved by igds: the reason is the
  // kernels'.
  if (t.current != 0 && t.derived) {
    try {
      Surface made;
      if (auto overflow = interpolate_into(surface_input(ws), made, PatchesOut::dropped))
        throw *overflow;
      ws.patches = std::move(made.patches);
      ws.intpn = std::move(made.intpn);
      keep_splines(ws, std::move(made.tangents));
    } catch (const DataError& e) {
      throw disk::Damage(made_surface_reason(e));
    }
  }
  std::map<std::uint32_t, std::shared_ptr<const Workspace>> sources;
  // A damaged image costs that image alone: its slot starts empty and its files are kept aside.
  std::array<std::optional<Lost>, 3> lost;
  for (std::size_t k = 0; k < 3; ++k) {
    ImageEntry& e = t.images[k];
    if (e.kind == ImageEntry::absent) continue;
    // The same image in two slots (STORE FIRST of the current image) is one image again.
    ImageRef image;
    for (std::size_t j = 0; j < k; ++j)
      if (same_entry(t.images[j], e)) image = image_slot(ws, j);
    if (!image) {
      try {
        image = read_image(e, image_variables[k], t, sources);
      } catch (const disk::Damage& d) {
        lost[k] = Lost{std::exchange(e, ImageEntry{}), d.reason()};
        continue;
      }
    }
    e.shown = image.watch();
    image_slot(ws, k) = image;
  }
  if (lost[0] || lost[1] || lost[2]) keep_lost_images_aside(t, lost);
  ws.changes.inppn.saved();
  ws.changes.inptg.saved();
  checked_.clear();
  // The undo journal: refused alone (with a notice) when it does not fit the workspace; the
  // images lost above are no images in the states that had them.
  journal.reset();
  if (!t.journal.empty()) {
    try {
      journal = disk::decode_journal(t.journal, ws, {!!lost[0], !!lost[1], !!lost[2]});
    } catch (const disk::Damage& d) {
      notices.push_back(fmt::format("UNDO JOURNAL IN {} DAMAGED ({}): NOTHING TO UNDO",
                                    session_file(), d.reason()));
    } catch (const DataError&) {
      notices.push_back(
          fmt::format("UNDO JOURNAL IN {} DAMAGED (DATA): NOTHING TO UNDO", session_file()));
    }
    // Refused, it is written no more: the next save writes the session with the journal then.
    rewrite = rewrite || !journal;
  }
  // The rest of the session read: a forged section of END APL's variables costs itself alone.
  if (!t.apl_variables_damage.empty()) keep_apl_variables_aside(t.apl_variables_damage);
  next_number = std::max(next_number, t.next_number < disk::file_numbers ? t.next_number : 1);
  saved = std::move(t);
  saved_known = true;
  collect_garbage(saved);
  return ws;
}

Workspace Session::State::read_legacy(std::string_view payload) {
  disk::Reader r(payload);
  Workspace ws;
  ws.nocur = r.i32();
  ws.nostr = r.i32();
  ws.intcu = r.i32();
  ws.intst = r.i32();
  for (int& s : ws.status) s = r.i32();
  const std::uint32_t next = r.u32();
  if (r.u32() != 7) throw disk::Damage("FORMAT");
  std::set<std::string> files;
  for (std::size_t i = 0; i < 7; ++i) {
    const std::uint8_t kind = r.u8();
    std::string inline_bytes;
    std::optional<disk::MappedFile> mapped;
    std::string_view bytes;
    if (kind == 0) {
      if (i < 4) throw disk::Damage("FORMAT");
      continue;
    } else if (kind == 1) {
      const std::uint64_t n = r.u64();
      if (n > disk::inline_limit) throw disk::Damage("FORMAT");
      bytes = r.bytes(static_cast<std::size_t>(n));
    } else if (kind == 2) {
      const std::uint32_t number = r.u32();
      const std::uint64_t length = r.u64(), sum = r.u64();
      const std::string name = fmt::format("{}.{}", disk::variable_file_name(number), pieces_type);
      try {
        mapped.emplace(file_path(number, pieces_type), max_surface_file_bytes());
      } catch (const disk::IoError& e) {
        throw disk::Damage(fmt::format("{}: {}", name, e.reason()));
      }
      if (!mapped->exists()) throw disk::Damage(fmt::format("{} MISSING", name));
      try {
        bytes = disk::unframe(variable_magic, mapped->bytes()).payload;
      } catch (const disk::Damage& d) {
        throw disk::Damage(fmt::format("{}: {}", name, d.reason()));
      }
      if (mapped->bytes().size() != length || disk::trailing_checksum(mapped->bytes()) != sum)
        throw disk::Damage(fmt::format("{}: NOT THE ONE SAVED", name));
      files.insert(name);
    } else {
      throw disk::Damage("FORMAT");
    }
    disk::Reader v(bytes);
    if (i < 4) {
      Array* a[] = {&ws.inppn, &ws.inptg, &ws.patches, &ws.intpn};
      ws.changes.derived = false;  // PATCHES and INTPN as read, until compared below
      *a[i] = v.array();
    } else {
      auto image = std::make_shared<const Image>(v.image());
      if (auto p = image_problem(*image, image_variables[i - 4]))
        throw disk::Damage("IMAGE: " + p->reason);
      image_slot(ws, i - 4) = image;
    }
    v.finish();
  }
  r.finish();
  if (auto p = status_problem(ws.status)) throw disk::Damage("STATUS: " + p->reason);
  if (auto p = surface_problem(ws)) throw disk::Damage("SHAPES: " + p->reason);
  for (auto [v, a] : {std::pair{Variable::patches, &ws.patches}, {Variable::intpn, &ws.intpn}})
    if (auto p = finite_problem(v, *a)) throw disk::Damage(p->reason);
  // PATCHES and INTPN igds's own interpolation: made again from now on, not saved.
  bool derived = false;
  if (ws.has_input() && ws.has_surface()) {
    try {
      Surface s = interpolate(surface_input(ws));
      derived = s.patches == ws.patches && s.intpn == ws.intpn;
    } catch (const DataError&) {
    }
  }
  ws.changes.replaced(derived || !ws.has_input());
  drop_derived_patches(ws);
  next_number = std::max(next_number, next > 0 && next < disk::file_numbers ? next : 1);
  obsolete = files;
  saved_known = false;
  collect_garbage(SessionTable{});
  return ws;
}

// The images that could not be read (`lost`) are gone from `t`: the records only they were
// drawn from go too, the variable files nothing else names are kept aside (Bnnnnnnn.IGDSBAD),
// each loss is said, and the next save writes the session without them.
void Session::State::keep_lost_images_aside(SessionTable& t,
                                            const std::array<std::optional<Lost>, 3>& lost) {
  // What each lost image named: its own files, and those of a record that nothing else needs.
  std::array<SessionTable, 3> only;
  for (std::size_t k = 0; k < 3; ++k) {
    if (!lost[k]) continue;
    only[k].images[k] = lost[k]->entry;
    const Record* r = t.record(lost[k]->entry.record);
    if (lost[k]->entry.kind == ImageEntry::recipe && r && r->id != t.current &&
        std::none_of(t.images.begin(), t.images.end(), [&](const ImageEntry& e) {
          return e.kind == ImageEntry::recipe && e.record == r->id;
        }))
      only[k].records.push_back(*r);
  }
  std::erase_if(t.records, [&](const Record& r) {
    return r.id != t.current &&
           std::none_of(t.images.begin(), t.images.end(), [&](const ImageEntry& e) {
             return e.kind == ImageEntry::recipe && e.record == r.id;
           });
  });
  std::set<std::uint32_t> kept;
  for (const auto& [f, type] : t.files()) kept.insert(f.number);
  for (std::size_t k = 0; k < 3; ++k) {
    if (!lost[k]) continue;
    std::vector<std::string> aside;
    for (const auto& [f, type] : only[k].files()) {
      if (kept.count(f.number)) continue;
      kept.insert(f.number);  // another lost slot may name it too
      const std::string name = fmt::format("{}.{}", disk::variable_file_name(f.number), type);
      struct stat st;
      if (::lstat((disk.dir() / name).c_str(), &st) != 0) continue;
      try {
        aside.push_back(disk::put_aside(disk.dir(), name.substr(0, 8), name));
      } catch (const disk::IoError&) {
        // Left where it is: a save removes only the files a session named.
      }
    }
    const std::string_view slot = info(image_variables[k]).name;
    notices.push_back(fmt::format(
        "{} IN {} DAMAGED ({}): {}{} STARTS EMPTY", slot, session_file(), lost[k]->reason,
        aside.empty() ? "" : fmt::format("KEPT AS {}; ", fmt::join(aside, ", ")), slot));
  }
  rewrite = true;
}

// END APL's variables that do not read cost themselves alone: a copy of the session file goes
// aside (BINSAVEn.IGDSBAD) before the next save writes the session without them.
void Session::State::keep_apl_variables_aside(const std::string& reason) {
  const std::string what =
      fmt::format("END APL'S VARIABLES IN {} DAMAGED ({})", session_file(), reason);
  const auto copy = disk::temporary_for(disk.path(session_name, "IGDSAPLV"));
  std::string kept;
  try {
    ::unlink(copy.c_str());  // a temporary: never data
    if (disk::copy_file(disk.path(session_name, session_type), copy))
      kept = disk::put_aside(disk.dir(), session_name, copy.filename().string());
  } catch (const disk::IoError& e) {
    ::unlink(copy.c_str());
    notices.push_back(fmt::format("{}: NOT KEPT ASIDE ({}); THEY START EMPTY", what, e.reason()));
    rewrite = true;
    return;
  }
  notices.push_back(
      kept.empty() ? fmt::format("{}: THEY START EMPTY", what)
                   : fmt::format("{}: THE SESSION FILE KEPT AS {}; THEY START EMPTY", what, kept));
  rewrite = true;
}

// Removes what a crash can leave behind: temporaries, and the variable files the session does
// not name (written by a save that did not finish, or left by one whose removals did not).
void Session::State::collect_garbage(const SessionTable& table) {
  std::set<std::uint32_t> named;
  for (const auto& [f, type] : table.files()) named.insert(f.number);
  for (const auto& name : disk::folder_entries(disk.dir())) {
    const auto path = disk.dir() / name;
    if (name.ends_with(disk::temporary_suffix)) {
      ::unlink(path.c_str());
    } else if (auto n = disk::variable_file_number(name);
               n && !named.count(n) && !obsolete.count(name)) {
      ::unlink(path.c_str());
    }
  }
}

Session::Session(const Disk& disk) : state_(std::make_unique<State>(disk)) {
  State& s = *state_;
  s.lock = std::make_unique<disk::DiskLock>(disk.dir(), s.notices);
  if (!s.lock->disk_had_room())
    s.notices.push_back(fmt::format(
        "DISK {} IS FULL: THE SESSION IS SAVED AGAIN WHEN THERE IS ROOM", disk.dir().string()));
  // Numbers already on the disk are never reused, even before load() reads the session.
  for (const auto& name : disk::folder_entries(disk.dir()))
    if (auto n = disk::variable_file_number(name);
        n && n >= s.next_number && n + 1 < disk::file_numbers)
      s.next_number = n + 1;
}

Session::~Session() = default;

Workspace Session::load() {
  State& s = *state_;
  std::string what;
  try {
    return s.read_session();
  } catch (const disk::Damage& d) {
    s.checked_.clear();
    what = fmt::format("SESSION FILE {} DAMAGED ({})", session_file(), d.reason());
  } catch (const disk::IoError& e) {
    what = fmt::format("SESSION FILE {} CANNOT BE READ ({})", session_file(), e.reason());
  } catch (const std::bad_alloc&) {
    s.checked_.clear();
    what = fmt::format("SESSION FILE {} CANNOT BE READ (NOT ENOUGH MEMORY)", session_file());
  } catch (const DataError&) {
    s.checked_.clear();
    what = fmt::format("SESSION FILE {} DAMAGED (DATA)", session_file());
  }
  // Never half-loaded: the bad session and its variable files go aside, nothing is deleted. The
  // session goes first: a crash after that leaves variable files without a session, which the
  // next start keeps aside too.
  bool aside = false;
  try {
    std::string kept = disk::put_aside(s.disk.dir(), session_name, session_file());
    for (const auto& name : disk::folder_entries(s.disk.dir()))
      if (disk::variable_file_number(name)) disk::put_aside(s.disk.dir(), name.substr(0, 8), name);
    s.notices.push_back(fmt::format("{}: KEPT AS {}; THE WORKSPACE STARTS EMPTY", what, kept));
    aside = true;
  } catch (const disk::IoError& e) {
    s.notices.push_back(
        fmt::format("{}: NOT KEPT ASIDE ({}); THE WORKSPACE STARTS EMPTY", what, e.reason()));
  }
  s.saved = SessionTable{};
  s.saved_known = false;
  s.obsolete.clear();
  if (aside) {
    s.collect_garbage(s.saved);
  } else {
    // What could not go aside stays where it is (a save never removes a file it did not name):
    // only temporaries are removed.
    for (const auto& name : disk::folder_entries(s.disk.dir()))
      if (name.ends_with(disk::temporary_suffix)) ::unlink((s.disk.dir() / name).c_str());
  }
  return Workspace{};
}

Journal Session::take_journal(const Workspace& ws) {
  std::optional<Journal> j = std::exchange(state_->journal, std::nullopt);
  return j ? std::move(*j) : Journal(ws);
}

std::vector<UnsavedImage> Session::save(Workspace& ws, const Journal* journal) {
  State& s = *state_;
  const SessionTable& old = s.saved;
  const Record* current = old.record(old.current);
  const bool surface_same =
      s.saved_known &&
      (current ? current->generation == ws.changes.surface && current->nocur == ws.nocur &&
                     current->nostr == ws.nostr && current->intcu == ws.intcu &&
                     current->intst == ws.intst && old.derived == ws.changes.derived
               : !ws.has_input() && ws.inppn.empty() && old.derived == ws.changes.derived);
  bool images_same = s.saved_known;
  for (std::size_t k = 0; k < 3; ++k) {
    const ImageRef& now = image_slot(ws, k);
    const ImageEntry& e = old.images[k];
    // An image kept out as one that cannot be made is the same as long as it is there.
    images_same = images_same && (now ? now.is(e.shown) : e.kind == ImageEntry::absent);
  }
  if (!s.rewrite && surface_same && images_same && old.status == ws.status &&
      old.functions == ws.functions && old.apl_variables == ws.apl_variables)
    return {};

  // Never a session that the next start would refuse (PATCHES and INTPN are read only when the
  // session keeps them: made again, they are checked where they are made). A surface the session
  // holds already was checked when it was saved: a DISPLAY or a ZOOM does not read it again.
  std::optional<VariableProblem> problem;
  if (!surface_same) {
    problem = surface_problem(ws);
    for (auto [v, a] : {std::pair{Variable::patches, &ws.patches}, {Variable::intpn, &ws.intpn}})
      if (!problem && !ws.changes.derived) problem = finite_problem(v, *a);
  }
  if (problem)
    throw Report(fmt::format("CANNOT SAVE THE SESSION ({}); THE LAST SAVED SESSION IS KEPT",
                             problem->reason));

  SessionTable next = old;
  next.status = ws.status;
  next.functions = ws.functions;
  next.apl_variables = ws.apl_variables;
  State::Writing w{s, next, {}};
  std::vector<UnsavedImage> unsaved;
  try {
    // The surface: a new record when it changed, sharing the pieces its edits left alone. A
    // record whose files went missing behind igds's back is written again.
    const bool current_present = current && s.present(current->inppn) && s.present(current->inptg);
    if (!surface_same || (current && !current_present)) {
      if (!ws.has_input()) {
        next.current = 0;
      } else {
        Record r;
        r.id = 1;
        while (next.record(r.id)) ++r.id;
        r.nocur = ws.nocur;
        r.nostr = ws.nostr;
        r.intcu = ws.intcu;
        r.intst = ws.intst;
        r.generation = ws.changes.surface;
        r.twists = ws.marks_twists() ? 1 : 0;
        r.auto_tangents = ws.auto_tangents() ? 1 : 0;
        // Pieces are kept only from a record whose files are all there.
        const Record* base = current && current_present ? current : nullptr;
        r.inppn = w.input(ws.inppn, base ? &base->inppn : nullptr, ws.changes.inppn);
        r.inptg = w.input(ws.inptg, base ? &base->inptg : nullptr, ws.changes.inptg);
        // A record of the same generation (its files were missing) is replaced.
        std::erase_if(next.records, [&](const Record& o) { return o.generation == r.generation; });
        next.records.push_back(std::move(r));
        next.current = next.records.back().id;
      }
      next.derived = ws.changes.derived;
      next.patches = next.derived ? StoredArray{} : w.whole(ws.patches);
      next.intpn = next.derived ? StoredArray{} : w.whole(ws.intpn);
    } else if (!next.derived && (!s.present(next.patches) || !s.present(next.intpn))) {
      next.patches = w.whole(ws.patches);
      next.intpn = w.whole(ws.intpn);
    }

    // The images: the same image as another slot shares its entry; one drawn from a surface the
    // session has is that recipe; one read from an IGDSIMAG file is a second name of the file;
    // any other is written whole.
    // An entry that still stands for `now`, with everything it needs on the disk.
    auto usable = [&](const ImageEntry& e, const ImageRef& now) {
      if (!now || e.kind == ImageEntry::absent || !now.is(e.shown)) return false;
      switch (e.kind) {
        case ImageEntry::recipe:
          return next.record(e.record) != nullptr;
        case ImageEntry::linked_file:
          return s.present(e.linked, linked_type);
        default:
          return s.present(e.data);
      }
    };
    // An image that has to be made to be kept and cannot be (a recipe its surface does not
    // allow: only a forged session or journal holds one) is kept out, once, and said.
    auto unmade = [&](std::size_t k, const DataError& error) {
      unsaved.push_back({image_variables[k], error});
      next.images[k] = ImageEntry{};
      next.images[k].shown = image_slot(ws, k).watch();
    };
    for (std::size_t k = 0; k < 3; ++k) {
      const ImageRef& now = image_slot(ws, k);
      ImageEntry& e = next.images[k];
      if (s.saved_known && usable(e, now)) continue;
      if (s.saved_known && now && e.kind == ImageEntry::absent && now.is(e.shown)) continue;
      e = ImageEntry{};
      e.shown = now.watch();
      if (!now) continue;
      for (std::size_t j = 0; j < 3; ++j) {
        const ImageEntry& o = j < k ? next.images[j] : old.images[j];
        if (j != k && usable(o, now)) {
          e = o;
          break;
        }
      }
      if (e.kind != ImageEntry::absent) continue;
      if (const auto recipe = now.recipe()) {  // a deferred image is not made for it
        for (const Record& r : next.records) {
          if (r.generation == recipe->first) {
            e.kind = ImageEntry::recipe;
            e.record = r.id;
            e.desim = recipe->second;
          }
        }
      }
      if (e.kind != ImageEntry::absent) continue;
      try {
        const Image& image = *now;  // made now when it was not yet
        if (!image.file.empty()) {
          if (auto f = w.copy(image)) {
            e.kind = ImageEntry::linked_file;
            e.linked = *f;
            continue;
          }
        }
        e.kind = ImageEntry::stored;
        e.data = w.image_data(image);
      } catch (const DataError& error) {
        unmade(k, error);
      }
    }

    // Records that neither the surface nor an image needs any more are dropped.
    std::erase_if(next.records, [&](const Record& r) {
      if (r.id == next.current) return false;
      return std::none_of(next.images.begin(), next.images.end(), [&](const ImageEntry& e) {
        return e.kind == ImageEntry::recipe && e.record == r.id;
      });
    });
    // An image drawn from a record whose files are gone is written whole instead.
    for (std::size_t k = 0; k < 3; ++k) {
      ImageEntry& e = next.images[k];
      if (e.kind != ImageEntry::recipe || e.record == next.current) continue;
      const Record* r = next.record(e.record);
      if (!s.present(r->inppn) || !s.present(r->inptg)) {
        const ImageRef& now = image_slot(ws, k);
        const std::uint32_t gone = e.record;
        e = ImageEntry{};
        try {
          e.data = w.image_data(*now);
          e.kind = ImageEntry::stored;
          e.shown = now.watch();
        } catch (const DataError& error) {
          unmade(k, error);
        }
        std::erase_if(next.records, [&](const Record& o) {
          return o.id == gone &&
                 std::none_of(next.images.begin(), next.images.end(), [&](const ImageEntry& i) {
                   return i.kind == ImageEntry::recipe && i.record == gone;
                 });
        });
      }
    }

    // The journal names the images the session keeps by their slots, and only those (not one
    // kept out, now or at an earlier save).
    ImageSlots kept;
    for (std::size_t k = 0; k < 3; ++k)
      if (next.images[k].kind != ImageEntry::absent) kept[k] = image_slot(ws, k);
    next.journal = journal ? disk::encode_journal(*journal, kept) : std::string();
    next.next_number = s.next_number;
    // The new variable files must be on the disk before the session that names them.
    if (!w.written.empty()) disk::sync_folder(s.disk.dir());
    disk::write_file(s.disk.path(session_name, session_type),
                     disk::frame(session_magic, disk::encode_session(next),
                                 disk::newest_version(session_magic)));
  } catch (const disk::IoError& e) {
    w.undo();
    throw Report(fmt::format("CANNOT SAVE THE SESSION IN {} ({}); THE LAST SAVED SESSION IS KEPT",
                             session_file(), e.reason()));
  } catch (...) {
    w.undo();  // no memory, say: the files of a save that did not happen go
    throw;
  }

  // The new session is durable: the files only the old one named can go.
  std::set<std::uint32_t> named;
  for (const auto& [f, type] : next.files()) named.insert(f.number);
  for (const auto& [f, type] : old.files())
    if (!named.count(f.number)) ::unlink(s.file_path(f.number, type).c_str());
  for (const auto& name : s.obsolete) ::unlink((s.disk.dir() / name).c_str());
  s.obsolete.clear();
  s.saved = std::move(next);
  s.saved_known = true;
  s.rewrite = false;
  ws.changes.inppn.saved();
  ws.changes.inptg.saved();
  return unsaved;
}

const std::vector<std::string>& Session::notices() const {
  return state_->notices;
}

}  // namespace igds
