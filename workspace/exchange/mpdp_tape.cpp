#include "workspace/exchange/mpdp_tape.h"

#include <cmath>

#include <fmt/format.h>

#include "workspace/numbers/fortran.h"

namespace igds::exchange {

namespace {

constexpr std::uint32_t word_mask = 0777777;  // 18 bits

// The places of B whose sign MPDP reverses (docs/marks.md): S_V, SE_V, E_H, SE_H.
constexpr bool reversed(int row, int col) {
  return (col == 3 && row < 2) || (row == 3 && col < 2);
}

void punch(std::string& out, std::uint32_t word) {
  // Most significant six bits first, the two leftmost holes always punched (Diagram IV).
  for (int shift = 12; shift >= 0; shift -= 6)
    out += static_cast<char>(tape_holes | ((word >> shift) & 077));
}

TapeError error_at(TapeError::Problem problem, std::size_t frame, std::size_t patch = 0) {
  TapeError e(problem);
  e.frame = frame;
  e.patch = patch;
  return e;
}

}  // namespace

const char* TapeError::what() const noexcept {
  try {
    switch (problem) {
      case Problem::shape:
        text_ = "PATCHES has not the shape of patch matrices";
        break;
      case Problem::out_of_range:
        text_ = fmt::format("patch {}: {} does not fit 18 bits", patch, value);
        break;
      case Problem::no_holes:
        text_ = fmt::format("frame {} lacks the two leftmost holes", frame);
        break;
      case Problem::truncated_number:
        text_ = fmt::format("the tape ends inside the number at frame {}", frame);
        break;
      case Problem::truncated_patch:
        text_ = fmt::format("the tape ends inside patch {}", patch);
        break;
      case Problem::no_end_mark:
        text_ = fmt::format("no end mark after {} patches", patch);
        break;
      case Problem::after_end:
        text_ = fmt::format("frame {} follows the end mark", frame);
        break;
    }
  } catch (...) {
    return "tape error";
  }
  return text_.c_str();
}

std::string write_tape(const Array& patches) {
  const auto& s = patches.shape;
  if (s.size() != 5 || s[2] != 3 || s[3] != 4 || s[4] != 4 || patches.size() != Array::count(s))
    throw TapeError(TapeError::Problem::shape);
  const std::size_t count = s[0] * s[1];
  // Every number is checked before anything is punched, so that a refusal names the first patch.
  std::vector<std::int32_t> numbers;
  numbers.reserve(count * numbers_per_patch);
  for (std::size_t p = 0; p < count; ++p) {
    auto refuse = [p](double value) {
      TapeError e(TapeError::Problem::out_of_range);
      e.patch = p + 1;
      e.value = value;
      return e;
    };
    if (p + 1 > std::size_t(tape_max)) throw refuse(double(p + 1));
    numbers.insert(numbers.end(), {std::int32_t(p + 1), 0, 0, 0, 0, 0});
    const double* m = patches.data() + 48 * p;
    for (int k = 0; k < 3; ++k) {
      for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
          const double value = reversed(r, c) ? -m[16 * k + 4 * r + c] : m[16 * k + 4 * r + c];
          const double rounded = std::round(value);  // halves away from zero, as NINT
          if (!(rounded >= tape_min && rounded <= tape_max)) throw refuse(value);
          numbers.push_back(std::int32_t(rounded));
        }
      }
    }
  }
  std::string out;
  out.reserve((numbers.size() + 1) * frames_per_number);
  for (std::int32_t v : numbers) punch(out, std::uint32_t(v) & word_mask);  // two's complement
  punch(out, tape_end);
  return out;
}

std::vector<TapePatch> read_tape(std::string_view frames) {
  const std::size_t size = frames.size();
  std::size_t at = 0;
  while (at < size && frames[at] == 0) ++at;  // leader
  // The number whose three frames start at `at`, as an 18-bit word.
  auto word = [&]() -> std::uint32_t {
    if (size - at < frames_per_number) throw error_at(TapeError::Problem::truncated_number, at + 1);
    std::uint32_t w = 0;
    for (std::size_t f = 0; f < frames_per_number; ++f, ++at) {
      const auto byte = static_cast<unsigned char>(frames[at]);
      if ((byte & tape_holes) != tape_holes) throw error_at(TapeError::Problem::no_holes, at + 1);
      w = (w << 6) | (byte & 077u);
    }
    return w;
  };
  auto number = [](std::uint32_t w) {
    return static_cast<std::int32_t>(w >= 0400000 ? std::int64_t(w) - 01000000 : std::int64_t(w));
  };
  std::vector<TapePatch> patches;
  for (;;) {
    if (at == size) throw error_at(TapeError::Problem::no_end_mark, 0, patches.size());
    const std::uint32_t first = word();
    if (first == tape_end) break;
    TapePatch p;
    p.number = number(first);
    auto next = [&] {
      if (at == size) throw error_at(TapeError::Problem::truncated_patch, 0, patches.size() + 1);
      return number(word());
    };
    p.internal_lines = next();
    for (auto& v : p.links) v = next();
    for (auto& v : p.b) v = next();
    patches.push_back(p);
  }
  for (; at < size; ++at) {
    if (frames[at] != 0) throw error_at(TapeError::Problem::after_end, at + 1);  // trailer only
  }
  return patches;
}

std::string tape_text(const std::vector<TapePatch>& patches) {
  std::string out;
  for (const auto& p : patches) {
    out += fmt::format("PATCH {} LINES {} LINKS {} {} {} {}\n", p.number, p.internal_lines,
                       p.links[0], p.links[1], p.links[2], p.links[3]);
    for (int r = 0; r < 4; ++r) {
      for (int k = 0; k < 3; ++k) {
        for (int c = 0; c < 4; ++c) {
          // I7, I10 opening the y and z matrices: an 18-bit number always fits.
          const int width = k > 0 && c == 0 ? 10 : 7;
          char field[10];
          fortran::put_i(field, p.b[16 * k + 4 * r + c], width);
          out.append(field, std::size_t(width));
        }
      }
      out += '\n';
    }
    out += '\n';
  }
  out += "END\n";
  return out;
}

}  // namespace igds::exchange
