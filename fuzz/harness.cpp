#include "fuzz/harness.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "network/config_error.hpp"
#include "network/toml_util.hpp"
#include "network/topology_file.hpp"
#include "tools/paper_data.hpp"
#include "tools/robot_file.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"

namespace fuzz {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxMessage = 5000;  // network::bounded_message cuts at 4 KB

const std::vector<std::string> kScenes = {"pingpong", "link-stream", "dynamics-farm", "elimination",
                                          "trajectory"};

// A scratch configs/ for this process: the shipped topologies, robots and calibration linked in,
// and copies of the shipped scenes, so an input's relative paths ("../topologies/pair.toml")
// resolve and nothing it writes lands in the repository.
const fs::path& sandbox() {
  static const ScratchDirectory root([] {
    const fs::path dir = fs::temp_directory_path() / ("t800sim-fuzz-" + std::to_string(getpid()));
    const fs::path source = fs::path(T800SIM_SOURCE_DIR) / "configs";
    fs::create_directories(dir / "scenes");
    for (const char* linked : {"topologies", "robots", "paper", "calibration.toml"})
      if (!fs::exists(dir / linked)) fs::create_symlink(source / linked, dir / linked);
    for (const std::string& scene : kScenes)
      fs::copy_file(source / "scenes" / (scene + ".toml"), dir / "scenes" / (scene + ".toml"),
                    fs::copy_options::overwrite_existing);
    fs::copy_file(source / "scenes" / "trajectory-torque.csv",
                  dir / "scenes" / "trajectory-torque.csv", fs::copy_options::overwrite_existing);
    return dir;
  }());
  return root.path();
}

void check_message(const std::string& text) {
  if (text.empty()) throw Finding("an error without a message");
  if (text.size() > kMaxMessage)
    throw Finding("an error message of " + std::to_string(text.size()) +
                  " bytes: " + text.substr(0, 200));
}

// Runs a reader; a clean refusal is a verdict, anything else is thrown on.
template <class F>
Verdict judge(F&& read) {
  try {
    read();
    return Verdict::accepted;
  } catch (const network::ConfigError& e) {
    if (e.where().file.empty())
      throw Finding(std::string("a configuration error naming no file: ") + e.what());
    check_message(e.what());
  } catch (const std::invalid_argument& e) {  // a CSV file's error, "path:line: why"
    check_message(e.what());
  }
  return Verdict::refused;
}

std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace

Verdict read_config(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return Verdict::refused;
  const std::string text = text_of(data + 1, size - 1);
  const fs::path file = sandbox() / "scenes" / "input.toml";
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  switch (data[0] % 4) {
    case 0:
      return judge([&] { tools::check_input(file.string()); });
    case 1:
      return judge([&] { network::load_topology(file.string()); });
    case 2:
      return judge([&] { tools::parse_robot(text, "robot.toml"); });
    default:
      return judge([&] { tools::load_paper_tables(file.string()); });
  }
}

Verdict apply_overrides(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return Verdict::refused;
  const fs::path scene = sandbox() / "scenes" / (kScenes[data[0] % kScenes.size()] + ".toml");
  std::vector<std::string> overrides;
  const std::string text = text_of(data + 1, size - 1);
  for (std::size_t start = 0; start <= text.size() && overrides.size() < 16;) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    overrides.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return judge([&] { tools::inputs_from(tools::load_scene(scene.string(), overrides)); });
}

}  // namespace fuzz
