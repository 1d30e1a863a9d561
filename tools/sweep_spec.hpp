// What a sweep runs: the axes given by --vary, and their cartesian product, one point per
// combination.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tools {

// One --vary KEY=VALUES flag: the scene key and its values, as the texts --set will be given.
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

// One point of a sweep: (key, value) for every axis, in --vary order.
using SweepPoint = std::vector<std::pair<std::string, std::string>>;

// Parses the text of one --vary flag. VALUES is one of
//   A..B      integers from A to B, step 1          (1..16)
//   A..B:xF   geometric: A, A*F, A*F^2, ... up to B (1..64:x2)
//   A..B:+S   arithmetic: A, A+S, ... up to B       (1..10:+3)
//   V1,V2,... a list of values, each as --set reads it (10,20 or tree,chain or a.toml,b.toml)
// A value with a '/' is never a range: "../topologies/a.toml" is a one-value list.
// Throws std::invalid_argument naming the flag and the valid forms.
SweepAxis parse_vary(const std::string& flag);

// The valid forms, for error messages and --help.
const char* vary_forms();

// Every combination, the last axis varying fastest. Throws std::invalid_argument when two axes
// share a key or the product is unreasonably large.
std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes);

// "network.workers=3 workload.bytes=64", for progress lines and messages.
std::string point_text(const SweepPoint& point);

}  // namespace tools
