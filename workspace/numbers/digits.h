// The tables and digit writers the number formats of this folder share (not for other folders).
#pragma once

#include <cstdint>
#include <cstring>

namespace igds::numbers {

// 10^k, k = 0..22: the powers of ten that doubles hold exactly.
inline constexpr double exact_power[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                           1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                           1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// 10^k, k = 0..19: the powers of ten in 64 bits.
inline constexpr std::uint64_t power_of_ten[20] = {1u,
                                                   10u,
                                                   100u,
                                                   1000u,
                                                   10000u,
                                                   100000u,
                                                   1000000u,
                                                   10000000u,
                                                   100000000u,
                                                   1000000000u,
                                                   10000000000u,
                                                   100000000000u,
                                                   1000000000000u,
                                                   10000000000000u,
                                                   100000000000000u,
                                                   1000000000000000u,
                                                   10000000000000000u,
                                                   100000000000000000u,
                                                   1000000000000000000u,
                                                   10000000000000000000u};

// "00" to "99".
inline constexpr char two_digits[] =
    "0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546"
    "4748495051525354555657585960616263646566676869707172737475767778798081828384858687888990919293"
    "949596979899";

// The decimal digits of v ending just before `end`, two at a time; returns where they start.
inline char* digits_before(char* end, std::uint64_t v) {
  for (; v >= 100; v /= 100) {
    end -= 2;
    std::memcpy(end, two_digits + 2 * (v % 100), 2);
  }
  if (v < 10) {
    *--end = static_cast<char>('0' + v);
  } else {
    end -= 2;
    std::memcpy(end, two_digits + 2 * v, 2);
  }
  return end;
}

// The `count` digits of v (v < 10^count) at w, zeros first, two at a time; returns w + count.
inline char* put_digits(char* w, std::uint64_t v, int count) {
  char* p = w + count;
  for (; p - w >= 8; v /= 100000000) {
    // Eight digits as four pairs made independently.
    const auto eight = static_cast<std::uint32_t>(v % 100000000);
    const std::uint32_t high = eight / 10000, low = eight % 10000;
    p -= 8;
    std::memcpy(p, two_digits + 2 * (high / 100), 2);
    std::memcpy(p + 2, two_digits + 2 * (high % 100), 2);
    std::memcpy(p + 4, two_digits + 2 * (low / 100), 2);
    std::memcpy(p + 6, two_digits + 2 * (low % 100), 2);
  }
  auto rest = static_cast<std::uint32_t>(v);
  for (; p - w >= 2; rest /= 100) {
    p -= 2;
    std::memcpy(p, two_digits + 2 * (rest % 100), 2);
  }
  if (p > w) *--p = static_cast<char>('0' + rest);
  return w + count;
}

}  // namespace igds::numbers
