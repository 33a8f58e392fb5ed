#pragma once
// Eigen vectors to and from JSON arrays (the calibration's stage files).
#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace dtwin::calib {

inline nlohmann::json vectorJson(const Eigen::VectorXd& v) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v(i));
  return a;
}

inline Eigen::VectorXd vectorFromJson(const nlohmann::json& j) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(j.size()));
  for (std::size_t i = 0; i < j.size(); ++i) v(static_cast<Eigen::Index>(i)) = j[i].get<double>();
  return v;
}

}  // namespace dtwin::calib
