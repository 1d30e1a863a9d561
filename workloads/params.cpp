#include "workloads/params.hpp"

#include <stdexcept>

namespace workloads {

const ParamSpec* WorkloadInfo::find(const std::string& name) const {
  for (const ParamSpec& p : params)
    if (p.name == name) return &p;
  return nullptr;
}

const ParamSpec* find_of_type(const WorkloadInfo& info, ParamType type) {
  for (const ParamSpec& p : info.params)
    if (p.type == type) return &p;
  return nullptr;
}

const ParamValue& Params::at(const std::string& name) const {
  auto it = values_.find(name);
  // A workload asking for a parameter it did not declare is a programming error, not a user error.
  if (it == values_.end()) throw std::logic_error("workload parameter not declared: " + name);
  return it->second;
}

bool Params::flag(const std::string& name) const {
  return std::get<bool>(at(name));
}

std::int64_t Params::integer(const std::string& name) const {
  return std::get<std::int64_t>(at(name));
}

double Params::real(const std::string& name) const {
  const ParamValue& v = at(name);
  if (auto i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  return std::get<double>(v);
}

const std::string& Params::text(const std::string& name) const {
  return std::get<std::string>(at(name));
}

const std::vector<double>& Params::real_list(const std::string& name) const {
  return std::get<std::vector<double>>(at(name));
}

const char* to_string(ParamType type) {
  switch (type) {
    case ParamType::flag:
      return "boolean";
    case ParamType::integer:
      return "integer";
    case ParamType::real:
      return "number";
    case ParamType::text:
      return "string";
    case ParamType::real_list:
      return "array of numbers";
    case ParamType::processor:
      return "processor name";
    case ParamType::input_file:
      return "input file";
    case ParamType::output_file:
      return "output file";
    case ParamType::robot_file:
      return "robot model file";
    case ParamType::precision:
      return "precision";
  }
  return "?";
}

}  // namespace workloads
