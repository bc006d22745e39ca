#include "geometry/big_integer.h"

#include <algorithm>

namespace epure::geo::exact {

BigInteger::BigInteger(std::int64_t x) {
  const bool negative = x < 0;
  // |INT64_MIN| as unsigned without overflow
  const std::uint64_t magnitude = negative ? ~static_cast<std::uint64_t>(x) + 1 : static_cast<std::uint64_t>(x);
  *this = from_unsigned(magnitude, negative);
}

BigInteger BigInteger::from_unsigned(std::uint64_t x, bool negative) {
  BigInteger r;
  while (x != 0) {
    r.limbs_.push_back(static_cast<std::uint32_t>(x));
    x >>= 32;
  }
  r.negative_ = negative && !r.limbs_.empty();
  return r;
}

BigInteger BigInteger::from_digits(std::string_view digits) {
  BigInteger r;
  // nine digits at a time: one multiply-add by 10^9 per group
  std::uint32_t group = 0, scale = 1;
  for (char c : digits) {
    if (c < '0' || c > '9') continue;
    group = group * 10 + static_cast<std::uint32_t>(c - '0');
    scale *= 10;
    if (scale == 1'000'000'000) {
      r.multiply_small(scale, group);
      group = 0;
      scale = 1;
    }
  }
  if (scale > 1) r.multiply_small(scale, group);
  r.trim();
  return r;
}

void BigInteger::multiply_small(std::uint32_t m, std::uint32_t add) {
  std::uint64_t carry = add;
  for (std::uint32_t& limb : limbs_) {
    const std::uint64_t v = static_cast<std::uint64_t>(limb) * m + carry;
    limb = static_cast<std::uint32_t>(v);
    carry = v >> 32;
  }
  if (carry != 0) limbs_.push_back(static_cast<std::uint32_t>(carry));
}

void BigInteger::trim() {
  while (!limbs_.empty() && limbs_.back() == 0) limbs_.pop_back();
  if (limbs_.empty()) negative_ = false;
}

int BigInteger::compare_magnitudes(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

std::vector<std::uint32_t> BigInteger::add_magnitudes(const std::vector<std::uint32_t>& a,
                                                      const std::vector<std::uint32_t>& b) {
  const std::vector<std::uint32_t>& longer = a.size() >= b.size() ? a : b;
  const std::vector<std::uint32_t>& shorter = a.size() >= b.size() ? b : a;
  std::vector<std::uint32_t> r(longer.size() + 1);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < longer.size(); ++i) {
    const std::uint64_t v = static_cast<std::uint64_t>(longer[i]) + (i < shorter.size() ? shorter[i] : 0) + carry;
    r[i] = static_cast<std::uint32_t>(v);
    carry = v >> 32;
  }
  r[longer.size()] = static_cast<std::uint32_t>(carry);
  return r;
}

std::vector<std::uint32_t> BigInteger::subtract_magnitudes(const std::vector<std::uint32_t>& a,
                                                           const std::vector<std::uint32_t>& b) {
  std::vector<std::uint32_t> r(a.size());
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int64_t v = static_cast<std::int64_t>(a[i]) - (i < b.size() ? b[i] : 0) - borrow;
    borrow = v < 0;
    if (v < 0) v += std::int64_t(1) << 32;
    r[i] = static_cast<std::uint32_t>(v);
  }
  return r;
}

BigInteger operator+(const BigInteger& a, const BigInteger& b) {
  BigInteger r;
  if (a.negative_ == b.negative_) {
    r.limbs_ = BigInteger::add_magnitudes(a.limbs_, b.limbs_);
    r.negative_ = a.negative_;
  } else if (BigInteger::compare_magnitudes(a.limbs_, b.limbs_) >= 0) {
    r.limbs_ = BigInteger::subtract_magnitudes(a.limbs_, b.limbs_);
    r.negative_ = a.negative_;
  } else {
    r.limbs_ = BigInteger::subtract_magnitudes(b.limbs_, a.limbs_);
    r.negative_ = b.negative_;
  }
  r.trim();
  return r;
}

BigInteger operator-(const BigInteger& a, const BigInteger& b) { return a + (-b); }

BigInteger operator*(const BigInteger& a, const BigInteger& b) {
  BigInteger r;
  if (a.is_zero() || b.is_zero()) return r;
  r.limbs_.assign(a.limbs_.size() + b.limbs_.size(), 0);
  for (std::size_t i = 0; i < a.limbs_.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.limbs_.size(); ++j) {
      const std::uint64_t v = static_cast<std::uint64_t>(a.limbs_[i]) * b.limbs_[j] + r.limbs_[i + j] + carry;
      r.limbs_[i + j] = static_cast<std::uint32_t>(v);
      carry = v >> 32;
    }
    r.limbs_[i + b.limbs_.size()] = static_cast<std::uint32_t>(carry);
  }
  r.negative_ = a.negative_ != b.negative_;
  r.trim();
  return r;
}

BigInteger BigInteger::times_pow10(int k) const {
  BigInteger r = *this;
  if (r.is_zero()) return r;
  for (; k >= 9; k -= 9) r.multiply_small(1'000'000'000);
  std::uint32_t rest = 1;
  for (; k > 0; --k) rest *= 10;
  if (rest > 1) r.multiply_small(rest);
  return r;
}

BigInteger BigInteger::times_pow2(int k) const {
  BigInteger r = *this;
  if (r.is_zero() || k <= 0) return r;
  const int words = k / 32, bits = k % 32;
  r.limbs_.insert(r.limbs_.begin(), static_cast<std::size_t>(words), 0);
  if (bits != 0) r.multiply_small(std::uint32_t(1) << bits);
  return r;
}

BigInteger BigInteger::times_pow5(int k) const {
  BigInteger r = *this;
  if (r.is_zero()) return r;
  for (; k >= 13; k -= 13) r.multiply_small(1'220'703'125);  // 5^13 < 2^32
  std::uint32_t rest = 1;
  for (; k > 0; --k) rest *= 5;
  if (rest > 1) r.multiply_small(rest);
  return r;
}

int BigInteger::bit_length() const {
  if (limbs_.empty()) return 0;
  int top = 0;
  for (std::uint32_t v = limbs_.back(); v != 0; v >>= 1) ++top;
  return static_cast<int>(limbs_.size() - 1) * 32 + top;
}

std::string BigInteger::to_string() const {
  if (limbs_.empty()) return "0";
  // nine digits at a time: the remainders of repeated divisions by 10^9, least significant first
  std::vector<std::uint32_t> n = limbs_;
  std::vector<std::uint32_t> groups;
  while (!n.empty()) {
    std::uint64_t rest = 0;
    for (std::size_t i = n.size(); i-- > 0;) {
      const std::uint64_t v = (rest << 32) | n[i];
      n[i] = static_cast<std::uint32_t>(v / 1'000'000'000);
      rest = v % 1'000'000'000;
    }
    groups.push_back(static_cast<std::uint32_t>(rest));
    while (!n.empty() && n.back() == 0) n.pop_back();
  }
  std::string s = negative_ ? "-" : "";
  s += std::to_string(groups.back());
  for (std::size_t i = groups.size() - 1; i-- > 0;) {
    const std::string g = std::to_string(groups[i]);
    s.append(9 - g.size(), '0');
    s += g;
  }
  return s;
}

}  // namespace epure::geo::exact
