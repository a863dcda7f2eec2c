// Doubles of every kind to check number writers on: random bits, decimals of few digits (the
// coordinates people type), exact binary ties of 7 digits, and the neighbours of powers of ten.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace igds::test {

inline std::vector<double> varied_values(std::size_t count) {
  std::mt19937_64 random(1975);
  std::vector<double> v;
  for (std::size_t k = 0; k < count; ++k) {
    v.push_back(std::bit_cast<double>(random()));
    const int exponent = int(random() % 40) - 20;
    v.push_back(double(std::int64_t(random() % 20000001) - 10000000) * std::pow(10.0, exponent));
    v.push_back(double(random() % 100000000) / 1000.0);
    v.push_back((double(random() % 9000000) + 1000000.5) * std::pow(2.0, int(random() % 20) - 10));
  }
  for (int e = -30; e <= 30; ++e) {
    double p = std::pow(10.0, e);
    for (int k = 0; k < 8; ++k) {
      v.push_back(p);
      v.push_back(-p);
      v.push_back(p * (1 - 5e-8));
      v.push_back(p * (1 - 4.9999999e-8));
      p = std::nextafter(p, 0.0);
    }
  }
  return v;
}

}  // namespace igds::test
