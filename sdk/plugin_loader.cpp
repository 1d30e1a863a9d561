#include "sdk/plugin_loader.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <vector>

#include "t800sim/version.hpp"
#include "workloads/run/thrown.hpp"

namespace t800sim::detail {

namespace {

namespace fs = std::filesystem;

// What happens while a plugin loads, for the registrations its initialisers make.
struct Loading {
  std::string path;
  std::vector<std::string> registration_errors;
};
Loading* loading = nullptr;  // set while a plugin loads

std::map<std::string, std::string>& plugin_of_kind() {
  static std::map<std::string, std::string> plugins;
  return plugins;
}

std::string file_kind(const fs::file_status& status) {
  switch (status.type()) {
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::block:
    case fs::file_type::character:
      return "a device";
    default:
      return "not a regular file";
  }
}

bool starts_as_elf(std::istream& in) {
  std::array<char, 4> magic{};
  in.read(magic.data(), magic.size());
  return in.gcount() == 4 && magic == std::array<char, 4>{'\x7f', 'E', 'L', 'F'};
}

// The version T800SIM_PLUGIN() recorded in the file after its marker string, or "" if there is
// none. Read a block at a time, as far as the marker: a plugin is never held whole.
std::string recorded_version(std::istream& in) {
  const std::string marker = T800SIM_PLUGIN_MARKER;
  constexpr std::size_t kVersionBytes = 64;  // longer than any version string
  std::vector<char> block(std::size_t(1) << 20);
  std::string window;  // the end of what was read that a marker could still start in
  for (;;) {
    in.read(block.data(), std::streamsize(block.size()));
    window.append(block.data(), std::size_t(in.gcount()));
    const bool more = bool(in);
    const std::size_t at = window.find(marker);
    if (at != std::string::npos && (!more || window.size() - at >= marker.size() + kVersionBytes)) {
      const std::string rest = window.substr(at + marker.size(), kVersionBytes);
      return rest.substr(0, rest.find('\0'));
    }
    if (!more) return {};
    const std::size_t keep = at != std::string::npos ? window.size() - at : marker.size() - 1;
    window.erase(0, window.size() - std::min(keep, window.size()));
  }
}

// Everything that can be told from the file without running any of it; throws PluginError.
void check_is_plugin(const fs::path& path, const std::string& shown) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw PluginError("plugin " + shown + " not found");
  if (!fs::is_regular_file(status))
    throw PluginError("plugin " + shown + " is " + file_kind(status) +
                      ", not a file (a plugin is a shared library, lib*.so)");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (!ec && bytes > kMaxPluginBytes)
    throw PluginError("plugin " + shown + " is " + std::to_string(bytes) +
                      " bytes, more than the " + std::to_string(kMaxPluginBytes) +
                      " a plugin may have (a plugin is a shared library, lib*.so)");
  const std::string not_a_plugin =
      "plugin " + shown +
      " is not a t800sim plugin: a plugin is a shared library built with T800SIM_PLUGIN() in one "
      "of its sources (t800sim/workload.hpp)";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PluginError("plugin " + shown + " cannot be read");
  if (!starts_as_elf(in)) throw PluginError(not_a_plugin + "; this file is not ELF");
  const std::string version = recorded_version(in);
  if (version.empty()) throw PluginError(not_a_plugin);
  if (version != T800SIM_VERSION)
    throw PluginError("plugin " + shown + " was built against t800sim SDK " + version +
                      ", this t800sim is " + T800SIM_VERSION +
                      ": rebuild the plugin against this t800sim's SDK (find_package(t800sim " +
                      T800SIM_VERSION + " EXACT))");
}

// dlopen runs the plugin's static initialisers, which may throw. glibc declares dlopen noexcept
// (__THROW), so g++ gives a call to it no entry in the caller's call-site table, and an exception
// coming out of it ends in std::terminate (exit 134, "terminate called after throwing ..."). Called
// through a pointer to a function that may throw -- volatile, so that the compiler cannot see
// dlopen behind it -- the exception reaches the handler: glibc's frames between the initialiser
// and here have unwind tables and no handlers of their own. What it leaves behind is why the
// command then ends: the library stays mapped, half initialised, and glibc's loader lock stays
// held by this thread (recursive, so this thread still loads libraries; another would wait for
// ever).
void* open_library(const fs::path& canonical, const std::string& shown) {
  using Dlopen = void* (*)(const char*, int);
  Dlopen volatile dlopen_may_throw = &dlopen;
  try {
    // RTLD_NOW: a missing symbol is found here, not in the middle of a run.
    return dlopen_may_throw(canonical.c_str(), RTLD_NOW | RTLD_LOCAL);
  } catch (...) {
    throw PluginError("plugin " + shown +
                      ": while it was being loaded, a static initialiser threw " +
                      workloads::describe_thrown(std::current_exception()));
  }
}

// Opens the library (never closed: the registered kinds' factories live in it), its initialisers
// registering its kinds; throws PluginError.
void open_and_register(const fs::path& canonical, const std::string& shown) {
  Loading state{shown, {}};
  loading = &state;
  struct Loaded {
    ~Loaded() { loading = nullptr; }
  } loaded;
  void* handle = open_library(canonical, shown);
  if (!handle) throw PluginError("plugin " + shown + " cannot be loaded: " + dlerror());
  if (!state.registration_errors.empty())
    throw PluginError("plugin " + shown + ": " + state.registration_errors.front());
}

}  // namespace

bool note_plugin_registration_error(const std::string& message) {
  if (!loading) return false;
  loading->registration_errors.push_back(message);
  return true;
}

void note_plugin_kind(const std::string& kind) {
  if (loading) plugin_of_kind()[kind] = loading->path;
}

std::string workload_label(const std::string& kind) {
  const auto plugin = plugin_of_kind().find(kind);
  return plugin == plugin_of_kind().end() ? kind : kind + " (plugin " + plugin->second + ")";
}

void load_plugin(const std::string& path) {
  static std::set<fs::path> loaded;
  // Refused again without a second dlopen, which would find the library mapped and succeed.
  static std::map<fs::path, PluginError> failed;
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(path, ec);
  if (loaded.count(canonical)) return;
  if (const auto f = failed.find(canonical); f != failed.end()) throw f->second;
  check_is_plugin(path, path);
  try {
    open_and_register(canonical, path);
  } catch (const PluginError& e) {
    failed.emplace(canonical, e);
    throw;
  }
  loaded.insert(canonical);
}

}  // namespace t800sim::detail
