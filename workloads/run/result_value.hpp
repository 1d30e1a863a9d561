// A small tree of results (numbers, text, lists, keyed records) that a workload hands back. The
// command line renders it as text or JSON; workloads stay free of any output format.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace workloads {

// `s` as a JSON string, quotes included: control characters escaped and each byte that is not part
// of well-formed UTF-8 replaced by U+FFFD, so any label (a process name, a fault's description)
// gives valid JSON. The one JSON string writer for reports and traces.
std::string json_string(const std::string& s);
void append_json_string(std::string& out, const std::string& s);

class ResultValue {
 public:
  using List = std::vector<ResultValue>;
  using Record = std::vector<std::pair<std::string, ResultValue>>;

  ResultValue() : v_(Record{}) {}
  ResultValue(double x) : v_(x) {}
  ResultValue(int x) : v_(std::int64_t{x}) {}
  ResultValue(std::int64_t x) : v_(x) {}
  ResultValue(bool x) : v_(x) {}
  ResultValue(std::string s) : v_(std::move(s)) {}
  ResultValue(const char* s) : v_(std::string(s)) {}
  ResultValue(List l) : v_(std::move(l)) {}
  static ResultValue list() { return ResultValue(List{}); }

  // Records keep insertion order (reports read top to bottom as the workload wrote them).
  ResultValue& set(const std::string& key, ResultValue value);
  void push(ResultValue value);
  const ResultValue* get(const std::string& key) const;
  double number() const;
  // Where the first NaN or infinity is ("c[0]", "per_worker[2].end_us", under `path`), or "" when
  // every number is finite: JSON cannot hold them, and a result that has one is not a result.
  std::string first_non_finite(const std::string& path = "") const;

  bool is_record() const { return std::holds_alternative<Record>(v_); }
  bool is_list() const { return std::holds_alternative<List>(v_); }
  const Record& record() const { return std::get<Record>(v_); }
  const List& items() const { return std::get<List>(v_); }

  std::string to_json() const;
  void append_json(std::string& out) const;  // to_json's text, appended to `out`
  // Indented "key: value" lines, for the text report.
  std::string to_text(int indent = 0) const;

 private:
  std::variant<double, std::int64_t, bool, std::string, List, Record> v_;
};

}  // namespace workloads
