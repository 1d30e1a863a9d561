#include <filesystem>
#include <iostream>

#include "network/config_error.hpp"
#include "tools/commands.hpp"

namespace tools {

void run_command(const std::function<int()>& body) {
  int code = kExitOk;
  try {
    code = body();
  } catch (const network::ConfigError& e) {
    std::cerr << e.what() << "\n";  // already "file:line:column: error: ..."
    code = kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << network::bounded_message("error: " + std::string(e.what())) << "\n";
    code = kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << network::bounded_message("error: " + std::string(e.what())) << "\n";
    code = kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << network::bounded_message("error: " + std::string(e.what())) << "\n";
    code = kExitFailure;
  }
  throw CommandExit{code};
}

}  // namespace tools
