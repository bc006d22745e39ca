#pragma once
// Signed integers of any size, for the exact slow path of the decisions on decimals
// (exact_decimal.h): sums, differences and products, the sign, and the decimal digits. Only
// what a polynomial of the data needs; no division but by small numbers (for the digits).
//
// Why our own and not GMP: the explorer is the same C++ compiled to WebAssembly, and Debian has
// no GMP for emscripten. One integer type in both builds keeps `epure solve` and the page
// bit-identical by construction; the tests check it against GMP (libgmp-dev) natively.
// The magnitudes met here are a few hundred bits (a worksheet's decimals, squared twice), a few
// thousand at most (a subnormal beside 1e308): schoolbook products are the right size.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace epure::geo::exact {

class BigInteger {
 public:
  BigInteger() = default;
  BigInteger(std::int64_t x);  // NOLINT: an integer is a big integer
  static BigInteger from_unsigned(std::uint64_t x, bool negative = false);
  // The digits '0'…'9' of a non-negative integer (others are skipped: a '.' may stand among them).
  static BigInteger from_digits(std::string_view digits);

  int sign() const { return limbs_.empty() ? 0 : negative_ ? -1 : 1; }
  bool is_zero() const { return limbs_.empty(); }

  friend BigInteger operator+(const BigInteger& a, const BigInteger& b);
  friend BigInteger operator-(const BigInteger& a, const BigInteger& b);
  friend BigInteger operator*(const BigInteger& a, const BigInteger& b);
  BigInteger operator-() const {
    BigInteger r = *this;
    if (!r.limbs_.empty()) r.negative_ = !r.negative_;
    return r;
  }
  friend bool operator==(const BigInteger& a, const BigInteger& b) {
    return a.negative_ == b.negative_ && a.limbs_ == b.limbs_;
  }

  // this·10^k, this·2^k and this·5^k, k ≥ 0.
  BigInteger times_pow10(int k) const;
  BigInteger times_pow2(int k) const;
  BigInteger times_pow5(int k) const;

  // The decimal digits, with a leading '-' when negative ("0" for zero).
  std::string to_string() const;
  // The number of bits of the magnitude (0 for zero).
  int bit_length() const;

 private:
  // |a| vs |b|: −1, 0, +1.
  static int compare_magnitudes(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b);
  static std::vector<std::uint32_t> add_magnitudes(const std::vector<std::uint32_t>& a,
                                                   const std::vector<std::uint32_t>& b);
  // |a| − |b| for |a| ≥ |b|.
  static std::vector<std::uint32_t> subtract_magnitudes(const std::vector<std::uint32_t>& a,
                                                        const std::vector<std::uint32_t>& b);
  void multiply_small(std::uint32_t m, std::uint32_t add = 0);
  void trim();

  std::vector<std::uint32_t> limbs_;  // the magnitude, least significant first, no leading zero
  bool negative_ = false;             // never set for zero
};

}  // namespace epure::geo::exact
