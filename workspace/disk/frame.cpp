#include "workspace/disk/frame.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include <fmt/format.h>

#include "workspace/exchange/duct.h"
#include "workspace/images.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/parallel.h"

namespace igds::disk {

namespace {

constexpr std::uint64_t prime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t prime2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::size_t max_rank = 8;
constexpr std::size_t owned_run = 4096;  // small values gather in runs of about this size

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

void blocks(std::uint64_t lane[4], const char* p, std::size_t n) {
  // Four independent lanes: the multiplications of one block overlap.
  for (std::size_t i = 0; i + 32 <= n; i += 32) {
    lane[0] = step(lane[0], load64(p + i));
    lane[1] = step(lane[1], load64(p + i + 8));
    lane[2] = step(lane[2], load64(p + i + 16));
    lane[3] = step(lane[3], load64(p + i + 24));
  }
}

std::uint64_t finish_sum(const std::uint64_t lane[4], const char* tail, std::size_t n,
                         std::size_t total) {
  std::uint64_t h = step(0x27D4EB2F165667C5ull, total);
  for (int k = 0; k < 4; ++k) h = step(h, lane[k]);
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) h = step(h, load64(tail + i));
  if (i < n) {
    char last[8] = {};
    std::memcpy(last, tail + i, n - i);
    h = step(h, load64(last));
  }
  h ^= h >> 33;
  h *= prime2;
  h ^= h >> 29;
  return h;
}

}  // namespace

std::uint64_t checksum(std::string_view bytes) {
  Checksum sum;
  sum.add(bytes);
  return sum.value();
}

Checksum::Checksum() : lane_{prime1, prime2, prime1 ^ prime2, ~prime1} {}

void Checksum::add(std::string_view bytes) {
  total_ += bytes.size();
  const char* p = bytes.data();
  std::size_t n = bytes.size();
  if (held_ > 0) {
    const std::size_t take = std::min(n, 32 - held_);
    std::memcpy(block_ + held_, p, take);
    held_ += take;
    p += take;
    n -= take;
    if (held_ < 32) return;
    blocks(lane_, block_, 32);
    held_ = 0;
  }
  const std::size_t whole = n / 32 * 32;
  blocks(lane_, p, whole);
  std::memcpy(block_, p + whole, n - whole);
  held_ = n - whole;
}

std::uint64_t Checksum::value() const {
  return finish_sum(lane_, block_, held_, total_);
}

std::string& Writer::tail() {
  if (!tail_owned_ || owned_.back().size() >= owned_run) {
    owned_.emplace_back();
    owned_.back().reserve(owned_run + 64);
    runs_.emplace_back();
    tail_owned_ = true;
  }
  return owned_.back();
}

void Writer::bytes(std::string_view b) {
  if (b.empty()) return;
  if (b.size() > owned_run) {
    // A large block gets a run of its own, so that no owned run ever moves its bytes.
    owned_.emplace_back(b);
    runs_.emplace_back(owned_.back());
    tail_owned_ = false;
    size_ += b.size();
    return;
  }
  std::string& t = tail();
  // reserve() above keeps t's bytes in place while it stays within its capacity.
  if (t.size() + b.size() > t.capacity()) {
    owned_.emplace_back(b);
    owned_.back().reserve(owned_run + 64);
    runs_.emplace_back();
  } else {
    t.append(b);
  }
  runs_.back() = owned_.back();
  size_ += b.size();
}

void Writer::u8(std::uint8_t v) {
  const char c = static_cast<char>(v);
  bytes(std::string_view(&c, 1));
}

void Writer::u32(std::uint32_t v) {
  char b[4];
  for (int i = 0; i < 4; ++i) b[i] = static_cast<char>(v >> (8 * i));
  bytes(std::string_view(b, 4));
}

void Writer::u64(std::uint64_t v) {
  char b[8];
  for (int i = 0; i < 8; ++i) b[i] = static_cast<char>(v >> (8 * i));
  bytes(std::string_view(b, 8));
}

void Writer::f64(double v) {
  u64(std::bit_cast<std::uint64_t>(v));
}

void Writer::borrow(std::string_view b) {
  if (b.empty()) return;
  runs_.push_back(b);
  tail_owned_ = false;
  size_ += b.size();
}

void Writer::array(const Array& a) {
  u32(static_cast<std::uint32_t>(a.shape.size()));
  for (auto d : a.shape) u64(d);
  u64(a.ravel.size());
  if constexpr (std::endian::native == std::endian::little) {
    borrow({reinterpret_cast<const char*>(a.ravel.data()), a.ravel.size() * sizeof(double)});
  } else {
    for (double v : a.ravel) f64(v);
  }
}

// DESIM[1] with this bit added: a hidden-line image (Description::hidden), which no earlier
// igds wrote and an earlier one refuses as a DESIM[1] it does not know.
constexpr std::int32_t hidden_bit = 0x100;

void Writer::description(const Description& d) {
  i32(d.hidden ? d.what | hidden_bit : d.what);
  i32(static_cast<std::int32_t>(d.projection));
  for (double p : d.parameters) f64(p);
}

void Writer::image(const Image& image) {
  description(image.desim);
  array(image.points);
  array(image.arrows);
  if (image.desim.hidden) array(image.nearness);
  // A picture (DESIM[1] = 2, which no earlier igds wrote) adds its name and its DUCT text.
  if (image.desim.what == 2 && image.picture) {
    u64(image.picture->name.size());
    bytes(image.picture->name);
    u64(image.picture->text.size());
    borrow(image.picture->text);
  }
  // Combs (DESIM[1] = 3, likewise new) add their ends and their scale.
  if (image.desim.what == 3) {
    array(image.combs);
    f64(image.comb_scale);
  }
}

void Writer::append(const Writer& other) {
  for (auto run : other.runs_) {
    runs_.push_back(run);
    size_ += run.size();
  }
  // The other writer's owned runs must live as long as this one: copy the small ones.
  tail_owned_ = false;
}

std::string Writer::str() const {
  std::string s;
  s.reserve(size_);
  for (auto run : runs_) s.append(run);
  return s;
}

std::string_view Reader::take(std::size_t n) {
  if (n > in_.size() - pos_) throw Damage("FORMAT");
  auto s = in_.substr(pos_, n);
  pos_ += n;
  return s;
}

void Reader::add_read() {
  if (sum_ && summed_ < pos_) sum_->add(in_.substr(summed_, pos_ - summed_));
  summed_ = pos_;
}

std::uint64_t Reader::sum() {
  if (sum_ && summed_ < in_.size()) sum_->add(in_.substr(summed_));
  summed_ = in_.size();
  return sum_ ? sum_->value() : 0;
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

Array Reader::array(std::size_t max_elements) {
  std::uint32_t rank = u32();
  if (rank > max_rank) throw Damage("FORMAT");
  Array a;
  std::uint64_t count = rank == 0 ? 0 : 1;
  for (std::uint32_t k = 0; k < rank; ++k) {
    std::uint64_t d = u64();
    // Every element takes 8 bytes of the file, so a real count never comes near overflowing.
    if (d != 0 && count > (std::uint64_t(1) << 60) / d) throw Damage("FORMAT");
    count *= d;
    a.shape.push_back(static_cast<std::size_t>(d));
  }
  std::uint64_t n = u64();
  if (n != count || n > left() / sizeof(double)) throw Damage("FORMAT");
  if (n > max_elements) throw Damage("FORMAT");
  add_read();
  auto raw = take(static_cast<std::size_t>(n) * sizeof(double));
  a.reshape_for_output(std::move(a.shape));  // every number is copied in below
  if constexpr (std::endian::native == std::endian::little) {
    // Copied a run at a time, each run then added to the checksum from the copy, in the cache.
    constexpr std::size_t run = std::size_t{64} << 10;
    char* to = reinterpret_cast<char*>(a.ravel.data());
    for (std::size_t at = 0; at < raw.size(); at += run) {
      const std::size_t m = std::min(run, raw.size() - at);
      std::memcpy(to + at, raw.data() + at, m);
      if (sum_) sum_->add(std::string_view(to + at, m));
    }
    summed_ = pos_;
  } else {
    for (std::size_t k = 0; k < n; ++k)
      a.ravel[k] = std::bit_cast<double>(load64(raw.data() + 8 * k));
  }
  return a;
}

Description Reader::description() {
  Description d;
  d.what = i32();
  if (d.what >= 0 && (d.what & hidden_bit) != 0) d.what &= ~hidden_bit, d.hidden = true;
  d.projection = static_cast<Projection>(i32());
  for (double& p : d.parameters) p = f64();
  return d;
}

Image Reader::image(std::size_t max_elements) {
  Image image;
  image.desim = description();
  image.points = array(max_elements);
  image.arrows = array(max_elements);
  if (image.desim.hidden) image.nearness = array(max_elements);
  if (image.desim.what == 2) {
    // bytes() refuses a length beyond what is left before anything is allocated.
    std::string name(bytes(static_cast<std::size_t>(u64())));
    std::string text(bytes(static_cast<std::size_t>(u64())));
    const int p = static_cast<int>(image.desim.projection);
    if (p < 1 || p > 4) throw Damage("FORMAT");
    try {
      image = picture_image(std::move(name), std::move(text),
                            {image.desim.projection, image.desim.parameters});
    } catch (const DuctError& e) {
      throw Damage("PICTURE " + e.reason());
    } catch (const DataError&) {
      throw Damage("PICTURE: ITS VIEW");
    }
  }
  if (image.desim.what == 3) {
    image.combs = array(max_elements);
    image.comb_scale = f64();
  }
  return image;
}

void Reader::finish() const {
  if (!at_end()) throw Damage("FORMAT");
}

Writer frame(std::string_view magic, const Writer& payload, std::uint32_t version) {
  Writer w;
  w.bytes(magic.substr(0, 8));
  w.u32(version);
  w.u32(0);
  w.u64(payload.size());
  w.append(payload);
  Checksum sum;
  for (auto run : w.runs()) sum.add(run);
  w.u64(sum.value());
  return w;
}

std::string frame(std::string_view magic, std::string_view payload, std::uint32_t version) {
  Writer p;
  p.borrow(payload);
  return frame(magic, p, version).str();
}

std::uint32_t newest_version(std::string_view magic) {
  return magic == "IGDSCONT" || magic == "IGDSDATA" ? 2 : 1;
}

Frame unframe(std::string_view magic, std::string_view file) {
  const Frame frame = open_frame(magic, file);
  if (checksum(file.substr(0, frame_header_bytes + frame.payload.size())) != frame.sum)
    throw Damage("CHECKSUM");
  return frame;
}

Frame open_frame(std::string_view magic, std::string_view file) {
  if (file.empty()) throw Damage("EMPTY FILE");
  std::size_t m = std::min<std::size_t>(8, file.size());
  if (file.substr(0, m) != magic.substr(0, m)) throw Damage(fmt::format("NOT AN {} FILE", magic));
  if (file.size() < frame_header_bytes) throw Damage("TRUNCATED");
  Reader r(file.substr(8, frame_header_bytes - 8));
  std::uint32_t version = r.u32();
  r.u32();
  std::uint64_t length = r.u64();
  if (version == 0) throw Damage("FORMAT VERSION 0");
  if (version > newest_version(magic))
    throw Damage(fmt::format("FORMAT VERSION {} OF A NEWER IGDS", version));
  std::uint64_t body = file.size() - frame_header_bytes;
  if (body < frame_trailer_bytes || length > body - frame_trailer_bytes) throw Damage("TRUNCATED");
  if (length < body - frame_trailer_bytes) throw Damage("LENGTH");
  std::size_t end = frame_header_bytes + static_cast<std::size_t>(length);
  return {file.substr(frame_header_bytes, static_cast<std::size_t>(length)), version,
          load64(file.data() + end)};
}

std::uint64_t trailing_checksum(std::string_view file) {
  return file.size() < 8 ? 0 : load64(file.data() + file.size() - 8);
}

}  // namespace igds::disk
