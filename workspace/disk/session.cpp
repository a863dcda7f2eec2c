#include "workspace/disk/session.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <set>
#include <thread>

#include <fmt/format.h>

#include "workspace/disk/format.h"
#include "workspace/error.h"

namespace igds {

namespace {

// The session is BINSAVE.IGDSCONT, a small file holding the scalars, STATUS, the small arrays
// and references to one file per large variable (Bnnnnnnn.IGDSVARS, never rewritten once
// written), so that a save rewrites only what changed (docs/disk.md).
constexpr std::string_view session_name = "BINSAVE";
constexpr std::string_view session_type = "IGDSCONT";
constexpr std::string_view session_magic = "IGDSCONT";
constexpr std::string_view lock_type = "IGDSLOCK";
constexpr std::string_view variable_type = "IGDSVARS";
constexpr std::string_view variable_magic = "IGDSVARS";
constexpr std::string_view bad_type = "IGDSBAD";
constexpr std::size_t inline_limit = 1024;  // a variable this small stays in BINSAVE.IGDSCONT
constexpr std::uint32_t blob_numbers = 0x10000000;  // seven hex digits

// The variables kept one by one, in the order of BINSAVE.IGDSCONT.
constexpr std::size_t slot_count = 7;  // INPPN INPTG PATCHES INTPN IMAGE TEMP1 TEMP2

struct Slot {
  enum Kind : std::uint8_t { absent = 0, inline_bytes = 1, file = 2 } kind = absent;
  std::string bytes;         // inline_bytes: the encoded variable
  std::uint32_t number = 0;  // file: Bnnnnnnn.IGDSVARS
  std::uint64_t length = 0;  // file: its size and its trailing checksum
  std::uint64_t sum = 0;
};

const Array* slot_array(const Workspace& ws, std::size_t i) {
  switch (i) {
    case 0:
      return &ws.inppn;
    case 1:
      return &ws.inptg;
    case 2:
      return &ws.patches;
    case 3:
      return &ws.intpn;
    default:
      return nullptr;
  }
}

const ImageRef& slot_image(const Workspace& ws, std::size_t i) {
  return i == 4 ? ws.image : i == 5 ? ws.temp1 : ws.temp2;
}

bool same_slot(const Workspace& a, const Workspace& b, std::size_t i) {
  if (auto x = slot_array(a, i)) return disk::same_bits(*x, *slot_array(b, i));
  return disk::same_bits(slot_image(a, i), slot_image(b, i));
}

void copy_slot(const Workspace& from, Workspace& to, std::size_t i) {
  switch (i) {
    case 0:
      to.inppn = from.inppn;
      break;
    case 1:
      to.inptg = from.inptg;
      break;
    case 2:
      to.patches = from.patches;
      break;
    case 3:
      to.intpn = from.intpn;
      break;
    case 4:
      to.image = from.image;
      break;
    case 5:
      to.temp1 = from.temp1;
      break;
    default:
      to.temp2 = from.temp2;
      break;
  }
}

// The encoded variable; nullopt for an image that is not there.
std::optional<std::string> encode_slot(const Workspace& ws, std::size_t i) {
  disk::Writer w;
  if (auto a = slot_array(ws, i)) {
    w.array(*a);
  } else {
    const auto& image = slot_image(ws, i);
    if (!image) return std::nullopt;
    w.image(*image);
  }
  return std::move(w.str());
}

void decode_slot(std::string_view bytes, Workspace& ws, std::size_t i) {
  disk::Reader r(bytes);
  switch (i) {
    case 0:
      ws.inppn = r.array();
      break;
    case 1:
      ws.inptg = r.array();
      break;
    case 2:
      ws.patches = r.array();
      break;
    case 3:
      ws.intpn = r.array();
      break;
    case 4:
      ws.image = std::make_shared<const Image>(r.image(false));
      break;
    case 5:
      ws.temp1 = std::make_shared<const Image>(r.image(false));
      break;
    default:
      ws.temp2 = std::make_shared<const Image>(r.image(false));
      break;
  }
  r.finish();
}

std::string blob_name(std::uint32_t number) {
  return fmt::format("B{:07X}", number);
}

// The number of a Bnnnnnnn.IGDSVARS file name, or nullopt.
std::optional<std::uint32_t> blob_number(std::string_view file) {
  std::string suffix = fmt::format(".{}", variable_type);
  if (file.size() != 8 + suffix.size() || file[0] != 'B' || !file.ends_with(suffix))
    return std::nullopt;
  std::uint32_t n = 0;
  for (char c : file.substr(1, 7)) {
    int d = (c >= '0' && c <= '9') ? c - '0' : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : -1;
    if (d < 0) return std::nullopt;
    n = n * 16 + static_cast<std::uint32_t>(d);
  }
  return n;
}

std::vector<std::string> folder_entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d)) names.emplace_back(e->d_name);
    ::closedir(d);
  }
  return names;
}

// Renames `from` (NAME.TYPE) to a free NAME.IGDSBAD, never replacing a file; the new name.
std::string put_aside(const std::filesystem::path& dir, std::string_view name,
                      std::string_view file) {
  for (int k = 0; k < 100000; ++k) {
    std::string candidate(name);
    if (k > 0) {
      std::string digits = std::to_string(k);
      candidate = candidate.substr(0, 8 - digits.size()) + digits;
    }
    std::string target = fmt::format("{}.{}", candidate, bad_type);
    auto from = dir / file, to = dir / target;
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
      return target;
    // File systems without RENAME_NOREPLACE: look first (we hold the disk's lock).
    if ((errno == EINVAL || errno == ENOSYS) && ::access(to.c_str(), F_OK) != 0) {
      if (::rename(from.c_str(), to.c_str()) == 0) return target;
      throw disk::IoError{errno};
    }
    if (errno != EEXIST && errno != EINVAL && errno != ENOSYS) throw disk::IoError{errno};
  }
  throw disk::IoError{EEXIST};
}

// The process number in a lock file, or "" when it holds anything else.
std::string process_number(const char* text, ssize_t n) {
  std::string digits(text, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!digits.empty() && (digits.back() == '\n' || digits.back() == ' ')) digits.pop_back();
  bool ok = !digits.empty() && digits.size() <= 10 &&
            std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  return ok ? digits : "";
}

std::string session_file() {
  return fmt::format("{}.{}", session_name, session_type);
}

}  // namespace

struct Session::State {
  Disk disk;
  std::filesystem::path lock_path;
  int lock_fd = -1;
  std::vector<std::string> notices;
  Workspace saved;           // the session on disk, bit for bit
  bool saved_known = false;  // false: the next save writes every variable
  std::array<Slot, slot_count> slots;
  std::uint32_t next_blob = 1;

  explicit State(const Disk& d) : disk(d) {}

  std::filesystem::path blob_path(std::uint32_t number) const {
    return disk.path(blob_name(number), variable_type);
  }

  bool referenced(std::uint32_t number, const std::array<Slot, slot_count>& in) const {
    return std::any_of(in.begin(), in.end(),
                       [&](const Slot& s) { return s.kind == Slot::file && s.number == number; });
  }

  // A number whose file is neither referenced now nor present on the disk.
  std::uint32_t new_blob(const std::array<Slot, slot_count>& pending) {
    for (;;) {
      std::uint32_t n = next_blob;
      next_blob = next_blob + 1 == blob_numbers ? 1 : next_blob + 1;
      if (referenced(n, slots) || referenced(n, pending)) continue;
      struct stat st;
      if (::lstat(blob_path(n).c_str(), &st) == 0) continue;  // anything there, even a link
      return n;
    }
  }

  void take_lock();
  Workspace read_session();
  void collect_garbage(bool variables);
};

void Session::State::take_lock() {
  lock_path = disk.path(session_name, lock_type);
  std::string where = disk.dir().string();
  for (int attempt = 0;; ++attempt) {
    int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      throw Report(fmt::format("DISK {} CANNOT BE LOCKED ({})", where, disk::system_reason(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      int error = errno;
      char buf[32] = {};
      ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
      ::close(fd);
      if (error != EWOULDBLOCK)
        throw Report(
            fmt::format("DISK {} CANNOT BE LOCKED ({})", where, disk::system_reason(error)));
      std::string holder = process_number(buf, n);
      // The holder writes its number just after locking: give it a moment.
      if (holder.empty() && attempt < 20) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        continue;
      }
      if (holder.empty())
        throw Report(fmt::format("DISK {} IN USE BY ANOTHER IGDS PROCESS", where));
      throw Report(fmt::format("DISK {} IN USE BY IGDS PROCESS {}", where, holder));
    }
    // A holder that ended removed the file after we opened it: lock the file now in its place.
    struct stat mine, named;
    if (::fstat(fd, &mine) != 0 || ::stat(lock_path.c_str(), &named) != 0 ||
        mine.st_ino != named.st_ino || mine.st_dev != named.st_dev) {
      ::close(fd);
      continue;
    }
    char buf[32] = {};
    ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
    if (n > 0) {
      std::string previous = process_number(buf, n);
      notices.push_back(previous.empty()
                            ? std::string("DISK LOCK LEFT BY AN IGDS THAT HAS ENDED, TAKEN OVER")
                            : fmt::format("DISK LOCK LEFT BY IGDS PROCESS {}, WHICH HAS ENDED, "
                                          "TAKEN OVER",
                                          previous));
    }
    std::string pid = fmt::format("{}\n", ::getpid());
    if (::ftruncate(fd, 0) != 0 ||
        ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
      int error = errno;
      ::unlink(lock_path.c_str());
      ::close(fd);
      throw Report(fmt::format("DISK {} CANNOT BE LOCKED ({})", where, disk::system_reason(error)));
    }
    lock_fd = fd;
    return;
  }
}

Workspace Session::State::read_session() {
  auto bytes = disk::read_whole_file(disk.path(session_name, session_type));
  if (!bytes) return Workspace{};
  disk::Reader r(disk::unframe(session_magic, *bytes));
  Workspace ws;
  ws.nocur = r.i32();
  ws.nostr = r.i32();
  ws.intcu = r.i32();
  ws.intst = r.i32();
  for (int& s : ws.status) s = r.i32();
  std::uint32_t next = r.u32();
  if (r.u32() != slot_count) throw disk::Damage{"FORMAT"};
  std::array<Slot, slot_count> read;
  for (std::size_t i = 0; i < slot_count; ++i) {
    Slot& s = read[i];
    std::uint8_t kind = r.u8();
    if (kind == Slot::absent) {
      if (slot_array(ws, i)) throw disk::Damage{"FORMAT"};
      s.kind = Slot::absent;
    } else if (kind == Slot::inline_bytes) {
      s.kind = Slot::inline_bytes;
      std::uint64_t n = r.u64();
      if (n > inline_limit) throw disk::Damage{"FORMAT"};
      s.bytes = std::string(r.bytes(static_cast<std::size_t>(n)));
      decode_slot(s.bytes, ws, i);
    } else if (kind == Slot::file) {
      s.kind = Slot::file;
      s.number = r.u32();
      s.length = r.u64();
      s.sum = r.u64();
      std::string file = fmt::format("{}.{}", blob_name(s.number), variable_type);
      std::optional<disk::MappedFile> mapped;
      try {
        mapped.emplace(blob_path(s.number));
      } catch (const disk::IoError& e) {
        throw disk::Damage{fmt::format("{}: {}", file, e.reason())};
      }
      if (!mapped->exists()) throw disk::Damage{fmt::format("{} MISSING", file)};
      const std::string_view blob = mapped->bytes();
      try {
        auto payload = disk::unframe(variable_magic, blob);
        std::uint64_t sum = 0;
        for (int k = 0; k < 8; ++k)
          sum |= std::uint64_t(static_cast<unsigned char>(blob[blob.size() - 8 + k])) << (8 * k);
        if (blob.size() != s.length || sum != s.sum) throw disk::Damage{"NOT THE ONE SAVED"};
        decode_slot(payload, ws, i);
      } catch (const disk::Damage& d) {
        throw disk::Damage{fmt::format("{}: {}", file, d.reason)};
      }
    } else {
      throw disk::Damage{"FORMAT"};
    }
  }
  r.finish();
  // What the checksum vouches for is what was saved: loaded as it is, bit for bit, even a
  // state that RESTORE would refuse from a file.
  slots = std::move(read);
  next_blob = next == 0 || next >= blob_numbers ? 1 : next;
  saved = ws;
  saved_known = true;
  return ws;
}

// Removes what a crash can leave behind: temporaries, and (`variables`) the variable files the
// session does not name.
void Session::State::collect_garbage(bool variables) {
  for (const auto& name : folder_entries(disk.dir())) {
    auto path = disk.dir() / name;
    if (name.ends_with(disk::temporary_suffix)) {
      ::unlink(path.c_str());
    } else if (auto n = blob_number(name); variables && n && !referenced(*n, slots)) {
      ::unlink(path.c_str());
    }
  }
}

Session::Session(const Disk& disk) : state_(std::make_unique<State>(disk)) {
  state_->take_lock();
  // Numbers already on the disk are never reused, even before load() reads the session.
  for (const auto& name : folder_entries(disk.dir()))
    if (auto n = blob_number(name); n && *n >= state_->next_blob && *n + 1 < blob_numbers)
      state_->next_blob = *n + 1;
}

Session::~Session() {
  if (state_ && state_->lock_fd >= 0) {
    // Unlinked while still locked, so that whoever locks next finds the file gone (take_lock).
    ::unlink(state_->lock_path.c_str());
    ::close(state_->lock_fd);
  }
}

Workspace Session::load() {
  State& s = *state_;
  std::string what;
  try {
    Workspace ws = s.read_session();
    s.collect_garbage(true);
    return ws;
  } catch (const disk::Damage& d) {
    what = fmt::format("SESSION FILE {} DAMAGED ({})", session_file(), d.reason);
  } catch (const disk::IoError& e) {
    what = fmt::format("SESSION FILE {} CANNOT BE READ ({})", session_file(), e.reason());
  }
  // Never half-loaded: the bad session and its variable files go aside, nothing is deleted.
  bool aside = false;
  try {
    std::string kept = put_aside(s.disk.dir(), session_name, session_file());
    for (const auto& name : folder_entries(s.disk.dir()))
      if (blob_number(name)) put_aside(s.disk.dir(), name.substr(0, 8), name);
    s.notices.push_back(fmt::format("{}: KEPT AS {}; THE WORKSPACE STARTS EMPTY", what, kept));
    aside = true;
  } catch (const disk::IoError& e) {
    s.notices.push_back(
        fmt::format("{}: NOT KEPT ASIDE ({}); THE WORKSPACE STARTS EMPTY", what, e.reason()));
  }
  s.slots = {};
  s.saved = Workspace{};
  s.saved_known = false;
  s.collect_garbage(aside);  // what could not go aside stays where it is
  return Workspace{};
}

void Session::save(const Workspace& ws) {
  State& s = *state_;
  const Workspace& old = s.saved;
  std::array<bool, slot_count> changed{};
  bool any = !s.saved_known || ws.nocur != old.nocur || ws.nostr != old.nostr ||
             ws.intcu != old.intcu || ws.intst != old.intst || ws.status != old.status;
  for (std::size_t i = 0; i < slot_count; ++i) {
    changed[i] = !s.saved_known || !same_slot(ws, old, i);
    any = any || changed[i];
  }
  if (!any) return;  // the session on disk is this one already

  auto slots = s.slots;
  std::vector<std::uint32_t> written;
  auto fail = [&](const disk::IoError& e) {
    for (auto n : written) ::unlink(s.blob_path(n).c_str());
    return Report(fmt::format("CANNOT SAVE THE SESSION IN {} ({}); THE LAST SAVED SESSION IS KEPT",
                              session_file(), e.reason()));
  };
  try {
    for (std::size_t i = 0; i < slot_count; ++i) {
      if (!changed[i]) continue;
      auto bytes = encode_slot(ws, i);
      Slot& slot = slots[i];
      slot = Slot{};
      if (!bytes) continue;
      if (bytes->size() <= inline_limit) {
        slot.kind = Slot::inline_bytes;
        slot.bytes = std::move(*bytes);
        continue;
      }
      slot.kind = Slot::file;
      slot.number = s.new_blob(slots);
      std::string file = disk::frame(variable_magic, *bytes);
      written.push_back(slot.number);
      disk::write_new_file(s.blob_path(slot.number), file);
      slot.length = file.size();
      disk::Reader tail(std::string_view(file).substr(file.size() - 8));
      slot.sum = tail.u64();
    }
    // The new variable files must be on the disk before the session that names them.
    if (!written.empty()) disk::sync_folder(s.disk.dir());

    disk::Writer w;
    w.i32(ws.nocur);
    w.i32(ws.nostr);
    w.i32(ws.intcu);
    w.i32(ws.intst);
    for (int v : ws.status) w.i32(v);
    w.u32(s.next_blob);
    w.u32(slot_count);
    for (const Slot& slot : slots) {
      w.u8(slot.kind);
      if (slot.kind == Slot::inline_bytes) {
        w.u64(slot.bytes.size());
        w.bytes(slot.bytes);
      } else if (slot.kind == Slot::file) {
        w.u32(slot.number);
        w.u64(slot.length);
        w.u64(slot.sum);
      }
    }
    disk::replace_file(s.disk.path(session_name, session_type),
                       disk::frame(session_magic, w.str()));
  } catch (const disk::IoError& e) {
    throw fail(e);
  }

  // The new session is durable: the files only the old one named can go.
  for (std::size_t i = 0; i < slot_count; ++i)
    if (s.slots[i].kind == Slot::file && !s.referenced(s.slots[i].number, slots))
      ::unlink(s.blob_path(s.slots[i].number).c_str());
  s.slots = std::move(slots);
  s.saved.nocur = ws.nocur;
  s.saved.nostr = ws.nostr;
  s.saved.intcu = ws.intcu;
  s.saved.intst = ws.intst;
  s.saved.status = ws.status;
  for (std::size_t i = 0; i < slot_count; ++i)
    if (changed[i]) copy_slot(ws, s.saved, i);
  s.saved_known = true;
}

const std::vector<std::string>& Session::notices() const {
  return state_->notices;
}

}  // namespace igds
