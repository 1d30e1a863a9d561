#include <iostream>
#include <string>

#include "network/config_error.hpp"
#include "tools/commands.hpp"
#include "tools/run_inputs.hpp"
#include "tools/scene.hpp"

namespace tools {

void add_check_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("check", "Validate a scene or topology file and exit non-zero on errors");
  auto file = std::make_shared<std::string>();
  cmd->add_option("file", *file, "scene or topology TOML file")->required();
  cmd->callback([file] {
    run_command([&] {
      const std::string summary = check_input(*file);  // throws before anything is printed
      std::cout << "ok: " << summary << "\n";
      return kExitOk;
    });
  });
}

}  // namespace tools
