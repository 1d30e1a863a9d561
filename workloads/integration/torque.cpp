#include "workloads/integration/torque.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace integration {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

bool skipped(const std::string& line) {
  const std::string t = trim(line);
  return t.empty() || t[0] == '#';
}

double number(const std::string& cell, const std::string& where, int column) {
  const std::string text = trim(cell);
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(v))
    throw std::invalid_argument(where + ": column " + std::to_string(column) + " is \"" + text +
                                "\", not a finite number");
  return v;
}

constexpr const char* kHeader = "t,tau1,tau2,tau3,tau4,tau5,tau6";

}  // namespace

TorqueTable TorqueTable::parse(std::istream& in, const std::string& name, TorqueInterpolation how) {
  TorqueTable table;
  table.how_ = how;
  std::string line;
  bool header = false;
  for (int number_of_line = 1; std::getline(in, line); ++number_of_line) {
    if (skipped(line)) continue;
    const std::string where = name + ":" + std::to_string(number_of_line);
    std::vector<std::string> cells = split(line);
    if (cells.size() != 1 + dynamics::kJoints)
      throw std::invalid_argument(where + ": " + std::to_string(cells.size()) +
                                  " columns; a torque table has 7: " + kHeader);
    if (!header) {  // the first line names the columns
      if (trim(cells[0]) != "t")
        throw std::invalid_argument(where + ": the first line must be the header " + kHeader);
      header = true;
      continue;
    }
    const double t = number(cells[0], where, 1);
    if (!table.t_.empty() && !(t > table.t_.back()))
      throw std::invalid_argument(where + ": t = " + trim(cells[0]) +
                                  " does not increase on the row before");
    dynamics::JointVector tau;
    for (int j = 0; j < dynamics::kJoints; ++j)
      tau(j) = number(cells[std::size_t(j) + 1], where, j + 2);
    table.t_.push_back(t);
    table.tau_.push_back(tau);
  }
  if (table.t_.empty())
    throw std::invalid_argument(name + ": no torque rows (after the header " + kHeader + ")");
  return table;
}

dynamics::JointVector TorqueTable::at(double t) const {
  if (t <= t_.front()) return tau_.front();
  if (t >= t_.back()) return tau_.back();
  const std::size_t after = std::size_t(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  const std::size_t before = after - 1;
  if (how_ == TorqueInterpolation::hold) return tau_[before];
  const double w = (t - t_[before]) / (t_[after] - t_[before]);
  return tau_[before] + w * (tau_[after] - tau_[before]);
}

}  // namespace integration
