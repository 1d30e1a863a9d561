// Plugins: shared libraries, built against the installed SDK, that register workload kinds
// (T800SIM_WORKLOAD) and say once which SDK they were built with (T800SIM_PLUGIN). A scene names
// one in `workload.plugin`; it is loaded before the workload's kind is looked up.
#pragma once

#include <stdexcept>
#include <string>

namespace t800sim::detail {

// Why a plugin could not be loaded (the file, what is wrong with it); the scene reader puts the
// scene's file and line in front.
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Loads the plugin at `path` once (a second call for the same file does nothing). Nothing of a
// plugin built against another SDK version runs: its recorded version is read from the file
// before it is opened. Throws PluginError for a missing file, a file that is not a plugin, another
// SDK version, a library that cannot be opened (a symbol it needs is missing), or a kind it
// registers that another already has.
void load_plugin(const std::string& path);

// While a plugin loads, registrations report their errors here instead of throwing (an exception
// cannot leave a shared library's initialisation); false when no plugin is loading.
bool note_plugin_registration_error(const std::string& message);

}  // namespace t800sim::detail
