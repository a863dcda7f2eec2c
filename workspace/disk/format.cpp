#include "workspace/disk/format.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace igds::disk {

namespace {

constexpr std::uint64_t prime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t prime2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::size_t max_rank = 8;

std::uint64_t load64(const char* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  return v;
}

// One step: bijective in `h` for a fixed `w` and in `w` for a fixed `h`.
std::uint64_t step(std::uint64_t h, std::uint64_t w) {
  return std::rotl(h ^ (w * prime2), 31) * prime1;
}

std::optional<std::size_t> write_limit;
std::size_t bytes_written = 0;  // by this process's disk writes, for the tests

// write(2) that honours the test hook's limit.
ssize_t limited_write(int fd, const char* p, std::size_t n) {
  if (write_limit) {
    if (*write_limit == 0) {
      errno = ENOSPC;
      return -1;
    }
    n = std::min(n, *write_limit);
  }
  ssize_t done = ::write(fd, p, n);
  if (done > 0) bytes_written += static_cast<std::size_t>(done);
  if (done > 0 && write_limit) *write_limit -= static_cast<std::size_t>(done);
  return done;
}

void write_all(int fd, std::string_view bytes) {
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    ssize_t done = limited_write(fd, p, left);
    if (done < 0) {
      if (errno == EINTR) continue;
      throw IoError{errno};
    }
    p += done;
    left -= static_cast<std::size_t>(done);
  }
}

// An open descriptor closed on every path; close() errors are reported by finish().
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }
  void finish() {
    int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && errno != EINTR) throw IoError{errno};
  }

 private:
  int fd_;
};

// Opens a file to read it whole: -1 when there is no such file, IoError for a folder or
// anything else that is not a regular file. O_NONBLOCK: a FIFO put where a file should be must
// not hang igds.
int open_regular(const std::filesystem::path& path, std::size_t& size) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
  if (fd.get() < 0) {
    if (errno == ENOENT) return -1;
    throw IoError{errno};
  }
  struct stat st;
  if (::fstat(fd.get(), &st) != 0) throw IoError{errno};
  if (S_ISDIR(st.st_mode)) throw IoError{EISDIR};
  if (!S_ISREG(st.st_mode)) throw IoError{EINVAL, "NOT A REGULAR FILE"};
  size = static_cast<std::size_t>(st.st_size);
  return fd.release();
}

// Creates (or truncates) `path` without following a symbolic link, writes `bytes`, syncs.
void write_and_sync(const std::filesystem::path& path, std::string_view bytes) {
  Fd fd(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644));
  if (fd.get() < 0) {
    if (errno == ELOOP) throw IoError{ELOOP, "A SYMBOLIC LINK IS IN THE WAY"};
    throw IoError{errno};
  }
  try {
    write_all(fd.get(), bytes);
    if (::fdatasync(fd.get()) != 0) throw IoError{errno};
    fd.finish();
  } catch (const IoError&) {
    ::unlink(path.c_str());
    throw;
  }
}

}  // namespace

std::uint64_t checksum(std::string_view bytes) {
  const char* p = bytes.data();
  std::size_t n = bytes.size();
  std::uint64_t lane[4] = {prime1, prime2, prime1 ^ prime2, ~prime1};
  std::size_t i = 0;
  // Four independent lanes: the multiplications of one block overlap.
  for (; i + 32 <= n; i += 32) {
    lane[0] = step(lane[0], load64(p + i));
    lane[1] = step(lane[1], load64(p + i + 8));
    lane[2] = step(lane[2], load64(p + i + 16));
    lane[3] = step(lane[3], load64(p + i + 24));
  }
  std::uint64_t h = step(0x27D4EB2F165667C5ull, n);
  for (auto l : lane) h = step(h, l);
  for (; i + 8 <= n; i += 8) h = step(h, load64(p + i));
  if (i < n) {
    char tail[8] = {};
    std::memcpy(tail, p + i, n - i);
    h = step(h, load64(tail));
  }
  h ^= h >> 33;
  h *= prime2;
  h ^= h >> 29;
  return h;
}

void Writer::u32(std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out_.push_back(static_cast<char>(v >> (8 * i)));
}

void Writer::u64(std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out_.push_back(static_cast<char>(v >> (8 * i)));
}

void Writer::f64(double v) {
  u64(std::bit_cast<std::uint64_t>(v));
}

void Writer::array(const Array& a) {
  u32(static_cast<std::uint32_t>(a.shape.size()));
  for (auto d : a.shape) u64(d);
  u64(a.ravel.size());
  if constexpr (std::endian::native == std::endian::little) {
    out_.append(reinterpret_cast<const char*>(a.ravel.data()), a.ravel.size() * sizeof(double));
  } else {
    for (double v : a.ravel) f64(v);
  }
}

void Writer::image(const Image& image) {
  i32(image.desim.what);
  i32(static_cast<std::int32_t>(image.desim.projection));
  for (double p : image.desim.parameters) f64(p);
  array(image.points);
  array(image.arrows);
}

std::string_view Reader::take(std::size_t n) {
  if (n > in_.size() - pos_) throw Damage{"FORMAT"};
  auto s = in_.substr(pos_, n);
  pos_ += n;
  return s;
}

std::uint8_t Reader::u8() {
  return static_cast<std::uint8_t>(take(1)[0]);
}

std::uint32_t Reader::u32() {
  auto s = take(4);
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<unsigned char>(s[i])) << (8 * i);
  return v;
}

std::uint64_t Reader::u64() {
  return load64(take(8).data());
}

double Reader::f64() {
  return std::bit_cast<double>(u64());
}

std::string_view Reader::bytes(std::size_t n) {
  return take(n);
}

Array Reader::array() {
  std::uint32_t rank = u32();
  if (rank > max_rank) throw Damage{"FORMAT"};
  Array a;
  std::uint64_t count = rank == 0 ? 0 : 1;
  for (std::uint32_t k = 0; k < rank; ++k) {
    std::uint64_t d = u64();
    // Every element takes 8 bytes of the file, so a real count never comes near overflowing.
    if (d != 0 && count > (std::uint64_t(1) << 60) / d) throw Damage{"FORMAT"};
    count *= d;
    a.shape.push_back(static_cast<std::size_t>(d));
  }
  std::uint64_t n = u64();
  if (n != count || n > (in_.size() - pos_) / sizeof(double)) throw Damage{"FORMAT"};
  auto raw = take(static_cast<std::size_t>(n) * sizeof(double));
  a.ravel.resize(static_cast<std::size_t>(n));
  if constexpr (std::endian::native == std::endian::little) {
    if (n > 0) std::memcpy(a.ravel.data(), raw.data(), raw.size());
  } else {
    for (std::size_t k = 0; k < n; ++k)
      a.ravel[k] = std::bit_cast<double>(load64(raw.data() + 8 * k));
  }
  return a;
}

Image Reader::image(bool checked) {
  Image image;
  image.desim.what = i32();
  std::int32_t projection = i32();
  if (checked && (image.desim.what < 0 || image.desim.what > 1 || projection < 1 || projection > 4))
    throw Damage{"FORMAT"};
  image.desim.projection = static_cast<Projection>(projection);
  for (double& p : image.desim.parameters) p = f64();
  image.points = array();
  image.arrows = array();
  return image;
}

void Reader::finish() const {
  if (!at_end()) throw Damage{"FORMAT"};
}

std::string frame(std::string_view magic, std::string_view payload) {
  Writer w;
  w.bytes(magic.substr(0, 8));
  w.u32(format_version);
  w.u32(0);
  w.u64(payload.size());
  w.bytes(payload);
  std::uint64_t sum = checksum(w.str());
  w.u64(sum);
  return std::move(w.str());
}

std::string_view unframe(std::string_view magic, std::string_view file) {
  if (file.empty()) throw Damage{"EMPTY FILE"};
  std::size_t m = std::min<std::size_t>(8, file.size());
  if (file.substr(0, m) != magic.substr(0, m)) throw Damage{fmt::format("NOT AN {} FILE", magic)};
  if (file.size() < frame_header_bytes) throw Damage{"TRUNCATED"};
  Reader r(file.substr(8, frame_header_bytes - 8));
  std::uint32_t version = r.u32();
  r.u32();
  std::uint64_t length = r.u64();
  if (version == 0) throw Damage{"FORMAT VERSION 0"};
  if (version > format_version)
    throw Damage{fmt::format("FORMAT VERSION {} OF A NEWER IGDS", version)};
  std::uint64_t body = file.size() - frame_header_bytes;
  if (body < frame_trailer_bytes || length > body - frame_trailer_bytes) throw Damage{"TRUNCATED"};
  if (length < body - frame_trailer_bytes) throw Damage{"LENGTH"};
  std::size_t end = frame_header_bytes + static_cast<std::size_t>(length);
  if (checksum(file.substr(0, end)) != load64(file.data() + end)) throw Damage{"CHECKSUM"};
  return file.substr(frame_header_bytes, static_cast<std::size_t>(length));
}

bool same_bits(const Array& a, const Array& b) {
  return a.shape == b.shape && a.ravel.size() == b.ravel.size() &&
         (a.ravel.empty() ||
          std::memcmp(a.ravel.data(), b.ravel.data(), a.ravel.size() * sizeof(double)) == 0);
}

bool same_bits(const ImageRef& a, const ImageRef& b) {
  if (a == b) return true;
  if (!a || !b) return false;
  return a->desim.what == b->desim.what && a->desim.projection == b->desim.projection &&
         std::memcmp(a->desim.parameters.data(), b->desim.parameters.data(),
                     sizeof(a->desim.parameters)) == 0 &&
         same_bits(a->points, b->points) && same_bits(a->arrows, b->arrows);
}

std::string surface_shape_error(const Workspace& ws) {
  if (ws.nocur == 0) {
    bool empty = ws.nostr == 0 && ws.intcu == 0 && ws.intst == 0 && ws.inppn.empty() &&
                 ws.inptg.empty() && ws.patches.empty() && ws.intpn.empty();
    return empty ? "" : "SHAPES";
  }
  if (ws.nocur < 1 || ws.nostr < 1 || ws.nocur * ws.nostr < 2 || ws.intcu < 0 || ws.intst < 0)
    return "SHAPES";
  using S = std::vector<std::size_t>;
  auto cu = static_cast<std::size_t>(ws.nocur), st = static_cast<std::size_t>(ws.nostr);
  auto ic = static_cast<std::size_t>(ws.intcu), is = static_cast<std::size_t>(ws.intst);
  bool ok = ws.inppn.shape == S{cu * st, 3} && ws.inptg.shape == S{2 * (cu + st), 4} &&
            (ws.patches.empty() || ws.patches.shape == S{cu - 1, st - 1, 3, 4, 4}) &&
            (ws.intpn.empty() || ws.intpn.shape == S{cu + ic * (cu - 1), st + is * (st - 1), 3});
  return ok ? "" : "SHAPES";
}

void write_surface(Writer& w, const Workspace& ws) {
  w.i32(ws.nocur);
  w.i32(ws.nostr);
  w.i32(ws.intcu);
  w.i32(ws.intst);
  w.array(ws.inppn);
  w.array(ws.inptg);
  w.array(ws.patches);
  w.array(ws.intpn);
}

void read_surface(Reader& r, Workspace& ws) {
  ws.nocur = r.i32();
  ws.nostr = r.i32();
  ws.intcu = r.i32();
  ws.intst = r.i32();
  ws.inppn = r.array();
  ws.inptg = r.array();
  ws.patches = r.array();
  ws.intpn = r.array();
}

std::string system_reason(int error) {
  std::string s = std::strerror(error);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::filesystem::path temporary_for(const std::filesystem::path& target) {
  auto tmp = target;
  tmp += temporary_suffix;
  return tmp;
}

void replace_file(const std::filesystem::path& target, std::string_view bytes) {
  auto tmp = temporary_for(target);
  write_and_sync(tmp, bytes);
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    int error = errno;
    ::unlink(tmp.c_str());
    throw IoError{error};
  }
  sync_folder(target.parent_path());
}

void write_new_file(const std::filesystem::path& target, std::string_view bytes) {
  write_and_sync(target, bytes);
}

void sync_folder(const std::filesystem::path& dir) {
  Fd fd(::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) throw IoError{errno};
  if (::fsync(fd.get()) != 0) throw IoError{errno};
  fd.finish();
}

std::optional<std::string> read_whole_file(const std::filesystem::path& path) {
  std::size_t size = 0;
  Fd fd(open_regular(path, size));
  if (fd.get() < 0) return std::nullopt;
  std::string data;
  // One byte more than the file: the read that finds its end needs no second, copying buffer.
  data.resize(size + 1);
  std::size_t got = 0;
  for (;;) {
    if (got == data.size()) data.resize(data.size() + 4096);  // the file grew meanwhile
    ssize_t n = ::read(fd.get(), data.data() + got, data.size() - got);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw IoError{errno};
    }
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  data.resize(got);
  return data;
}

MappedFile::MappedFile(const std::filesystem::path& path) {
  Fd fd(open_regular(path, size_));
  if (fd.get() < 0) return;
  exists_ = true;
  if (size_ == 0) return;
  data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd.get(), 0);
  if (data_ == MAP_FAILED) {
    data_ = nullptr;
    size_ = 0;
    throw IoError{errno};
  }
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(data_, size_);
}

std::size_t bytes_written_for_testing() {
  return bytes_written;
}

void set_write_limit_for_testing(std::optional<std::size_t> limit) {
  write_limit = limit;
}

}  // namespace igds::disk
