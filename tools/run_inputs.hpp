// A validated scene -> the plain inputs of one simulation (workloads::RunInputs), checked as far as
// anything can be checked before simulating, so that `t800sim check` saying ok means `run` does not
// fail on its input.
#pragma once

#include <functional>

#include "tools/scene.hpp"
#include "workloads/run/run.hpp"

namespace tools {

// No trace is kept (tools/trace_files.hpp: keep_trace asks for one). Loads the files the
// workload names (the robot), builds the workload once without a network so that settings the
// network rules out are reported at the scene line or flag that gave them, and checks that
// workload.output_csv could be written. Throws network::ConfigError (or std::invalid_argument for
// an error inside a named CSV file).
workloads::RunInputs inputs_from(const Scene& scene);

// Runs `code`; a workloads::SettingError it throws becomes a network::ConfigError at the scene line
// or flag that set the first of its keys.
void at_scene_keys(const Scene& scene, const std::function<void()>& code);

// `t800sim check FILE`: a topology file, or a scene checked as `run` would check it (inputs_from)
// and realised as `run` would realise it, without simulating (workloads::realise). Returns the
// one-line summary of tools::check_file.
std::string check_input(const std::string& path);

}  // namespace tools
