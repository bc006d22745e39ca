#pragma once
// Reading the data of an instance (a solve input, as key.json carries it) for a kind's grader.
// Throws std::runtime_error naming the field, as the solve contract would.
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

#include "geometry/vec.h"
#include "grading/faces.h"

namespace epure::grading::kinds {

inline double instance_number(const nlohmann::json& j, const char* field) {
  auto it = j.find(field);
  if (it == j.end() || !it->is_number()) throw std::runtime_error(std::string("field '") + field + "': expected a number");
  return it->get<double>();
}

inline std::pair<double, double> instance_pair(const nlohmann::json& j, const char* field) {
  auto it = j.find(field);
  if (it == j.end() || !it->is_array() || it->size() != 2 || !(*it)[0].is_number() || !(*it)[1].is_number())
    throw std::runtime_error(std::string("field '") + field + "': expected [x, y]");
  return {(*it)[0].get<double>(), (*it)[1].get<double>()};
}

inline geo::Point2 instance_point(const nlohmann::json& j, const char* field) {
  const auto [x, y] = instance_pair(j, field);
  return {x, y};
}

inline geo::Vec2 instance_vec(const nlohmann::json& j, const char* field) {
  const auto [x, y] = instance_pair(j, field);
  return {x, y};
}

// The unit direction of u; throws for a zero vector (the contract refuses it too).
inline geo::Vec2 unit_direction(geo::Vec2 u) {
  const auto n = geo::normalized(u);
  if (!n) throw std::runtime_error("field 'u': zero direction");
  return *n;
}

// The outward normal of a side of the canonical square, by its face bit (+x, +y, -x, -y).
inline geo::Vec2 side_normal(int bit) {
  switch (bit) {
    case 0: return {1, 0};
    case 1: return {0, 1};
    case 3: return {-1, 0};
    case 4: return {0, -1};
  }
  return {0, 0};
}

// The sides of the square, as bit positions of FaceBits.
inline constexpr int kSquareSides[] = {0, 1, 3, 4};

}  // namespace epure::grading::kinds
