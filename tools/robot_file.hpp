// Robot files (TOML) -> dynamics::RobotModel. workloads/ knows nothing of TOML
// (docs/architecture.md), so the reader lives here. Format: see configs/robots/stanford.toml (its
// header documents keys and units).
#pragma once

#include <string>

#include "workloads/dynamics/robot_model.hpp"

namespace tools {

// Reads and validates a robot file. Throws network::ConfigError ("file:line:column: error: ...") on
// a syntax error, an unknown key, a missing key, a wrong type, a joint count other than
// dynamics::kJoints, a negative mass or inertia, an inertia violating the triangle inequality
// (unless the file says `triangle_inequality = false` with a `triangle_inequality_note`), or limits
// with min > max.
dynamics::RobotModel load_robot(const std::string& path);

// The same from text already in memory; `file` names it in error messages.
dynamics::RobotModel parse_robot(const std::string& text, const std::string& file);

}  // namespace tools
