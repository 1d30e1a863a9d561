// Parameters a workload declares (name, type, default, range, help). The scene loader validates a
// scene's [workload] table against these declarations; workloads read typed values back. No TOML
// here.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace workloads {

using ParamValue = std::variant<bool, std::int64_t, double, std::string, std::vector<double>>;

// processor: the name of one of the network's processors (checked against the topology), or empty
// for the workload's own choice.
// The file types are paths relative to the scene that names them (the run hands the workload the
// resolved path; empty = none): an input_file must exist, an output_file must be writable before
// anything runs, a robot_file is read as a robot model for the workload. precision (real32 or
// real64) is the arithmetic of the workload's occam program and so of the machine that runs it.
// A kind declares at most one robot_file and one precision.
enum class ParamType {
  flag,
  integer,
  real,
  text,
  real_list,
  processor,
  input_file,
  output_file,
  robot_file,
  precision
};

struct ParamSpec {
  std::string name;
  ParamType type;
  ParamValue default_value;
  std::string help;
  std::optional<double> min, max;    // numeric bounds (inclusive), integer and real
  std::vector<std::string> choices;  // allowed text values; empty = any
};

struct WorkloadInfo {
  std::string kind;  // the scene's workload.kind
  std::string summary;
  std::vector<ParamSpec> params;
  const ParamSpec* find(const std::string& name) const;
};

// Validated values: every declared parameter is present (defaults filled in).
class Params {
 public:
  void set(const std::string& name, ParamValue value) { values_[name] = std::move(value); }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  bool flag(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  double real(const std::string& name) const;              // accepts an integer value too
  const std::string& text(const std::string& name) const;  // text and processor values
  const std::vector<double>& real_list(const std::string& name) const;
  const std::map<std::string, ParamValue>& values() const { return values_; }

 private:
  const ParamValue& at(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

inline bool is_file(ParamType t) {
  return t == ParamType::input_file || t == ParamType::output_file || t == ParamType::robot_file;
}

// The kind's parameter of this type (robot_file, precision: at most one), or null.
const ParamSpec* find_of_type(const WorkloadInfo& info, ParamType type);

// Human-readable type name ("integer", "real", ...), for error messages and help.
const char* to_string(ParamType type);

}  // namespace workloads
