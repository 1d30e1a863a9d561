// Plugins: shared libraries, built against the installed SDK, that register workload kinds
// (T800SIM_WORKLOAD) and say once which SDK they were built with (T800SIM_PLUGIN). A scene names
// one in `workload.plugin`; it is loaded before the workload's kind is looked up.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace t800sim::detail {

// Why a plugin could not be loaded (the file, what is wrong with it); the scene reader puts the
// scene's file and line in front.
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The largest plugin file loaded: twice the largest shared library found on a CUDA development
// machine (libcublasLt, 517 MiB). Anything larger is refused before it is read.
constexpr std::uintmax_t kMaxPluginBytes = std::uintmax_t(1) << 30;

// Loads the plugin at `path` once (a second call for the same file does nothing, or throws the
// first call's error again). Nothing of a plugin built against another SDK version runs: its
// recorded version is read from the file before it is opened. Throws PluginError for a missing
// file, one that is not a regular file, is larger than kMaxPluginBytes, is not ELF or is not a
// plugin, another SDK version, a library that cannot be opened (a symbol it needs is missing), a
// kind it registers that another already has, or a static initialiser of the plugin that throws.
void load_plugin(const std::string& path);

// While a plugin loads, registrations report their errors here instead of throwing, so that the
// plugin's other initialisers still run and it is not left half initialised; false when no plugin
// is loading.
bool note_plugin_registration_error(const std::string& message);

// While a plugin loads, the kinds it registers are noted as its own.
void note_plugin_kind(const std::string& kind);

// A kind for messages: "kind", or "kind (plugin PATH)" for a kind a plugin registered.
std::string workload_label(const std::string& kind);

}  // namespace t800sim::detail
