#include "sdk/plugin_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <vector>

#include "t800sim/version.hpp"

namespace t800sim::detail {

namespace {

namespace fs = std::filesystem;

std::vector<std::string>* registration_errors = nullptr;  // set while a plugin loads

// The version T800SIM_PLUGIN() recorded in the file (its marker string), or "" if there is none.
std::string recorded_version(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string marker = T800SIM_PLUGIN_MARKER;
  const std::size_t at = bytes.find(marker);
  if (at == std::string::npos) return {};
  const std::size_t start = at + marker.size();
  const std::size_t end = bytes.find('\0', start);
  return bytes.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

void check_is_plugin(const fs::path& path, const std::string& shown) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw PluginError("plugin " + shown + " not found");
  if (!fs::is_regular_file(path, ec))
    throw PluginError("plugin " + shown + " is not a file (a plugin is a shared library, lib*.so)");
  const std::string version = recorded_version(path);
  if (version.empty())
    throw PluginError("plugin " + shown +
                      " is not a t800sim plugin: a plugin is a shared library built with "
                      "T800SIM_PLUGIN() in one of its sources (t800sim/workload.hpp)");
  if (version != T800SIM_VERSION)
    throw PluginError("plugin " + shown + " was built against t800sim SDK " + version +
                      ", this t800sim is " + T800SIM_VERSION +
                      ": rebuild the plugin against this t800sim's SDK (find_package(t800sim " +
                      T800SIM_VERSION + " EXACT))");
}

}  // namespace

bool note_plugin_registration_error(const std::string& message) {
  if (!registration_errors) return false;
  registration_errors->push_back(message);
  return true;
}

void load_plugin(const std::string& path) {
  static std::set<fs::path> loaded;
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(path, ec);
  if (loaded.count(canonical)) return;
  check_is_plugin(path, path);

  std::vector<std::string> errors;
  registration_errors = &errors;
  // Never closed: the registered kinds' factories live in it. RTLD_NOW: a missing symbol is found
  // here, not in the middle of a run.
  void* handle = dlopen(canonical.c_str(), RTLD_NOW | RTLD_LOCAL);
  registration_errors = nullptr;
  if (!handle) throw PluginError("plugin " + path + " cannot be loaded: " + dlerror());
  loaded.insert(canonical);
  if (!errors.empty()) throw PluginError("plugin " + path + ": " + errors.front());
}

}  // namespace t800sim::detail
