#include <filesystem>
#include <iostream>

#include "network/config_error.hpp"
#include "network/unwound_frames.hpp"
#include "tools/commands.hpp"
#include "workloads/run/thrown.hpp"

namespace tools {

CommandError command_error(const std::exception_ptr& thrown) {
  try {
    std::rethrow_exception(thrown);
  } catch (const network::ConfigError& e) {
    return {kExitBadInput, e.what()};  // already "file:line:column: error: ..."
  } catch (const std::invalid_argument& e) {
    return {kExitBadInput, network::bounded_message("error: " + std::string(e.what()))};
  } catch (const std::filesystem::filesystem_error& e) {
    return {kExitBadInput, network::bounded_message("error: " + std::string(e.what()))};
  } catch (const std::exception& e) {
    return {kExitFailure, network::bounded_message("error: " + std::string(e.what()))};
  } catch (...) {  // from a plugin's code: anything may be thrown
    return {kExitFailure, network::bounded_message("error: " + workloads::describe_thrown(thrown))};
  }
}

void run_command(const std::function<int()>& body) {
  int code = kExitOk;
  try {
    code = body();
  } catch (...) {
    network::forget_unwound_frames();
    const CommandError error = command_error(std::current_exception());
    std::cerr << error.message << "\n";
    code = error.code;
  }
  throw CommandExit{code};
}

}  // namespace tools
