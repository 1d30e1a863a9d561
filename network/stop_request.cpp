#include "network/stop_request.hpp"

#include <atomic>
#include <csignal>

namespace network {

namespace {
std::atomic<int> requested{0};
std::atomic<bool> caught{false};

extern "C" void on_stop_signal(int signal) {
  // The run stops at its next look; a second signal is not asked twice.
  std::signal(signal, SIG_DFL);
  requested.store(signal);
}
}  // namespace

void catch_stop_signals() {
  caught.store(true);
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
}

bool stop_signals_caught() {
  return caught.load();
}
int stop_requested() {
  return requested.load();
}
void request_stop(int signal) {
  requested.store(signal);
}

}  // namespace network
