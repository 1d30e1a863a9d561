#include "tools/sweep_runner.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstring>
#include <list>

#include "tools/child_run.hpp"

namespace tools {

namespace {

using Clock = std::chrono::steady_clock;

struct Child {
  std::size_t index = 0;
  pid_t pid = -1;
  int fd[2] = {-1, -1};  // read ends of its stdout and stderr pipes
  Clock::time_point start;
  ChildOutcome outcome;
  bool exited = false;
};

// Both ends close-on-exec, so one child never holds another's pipe open (which would hide its end
// of file); posix_spawn's dup2 onto 1 and 2 clears the flag on the child's copies.
bool make_pipe(int ends[2]) {
  if (pipe2(ends, O_CLOEXEC) != 0) return false;
  fcntl(ends[0], F_SETFL, O_NONBLOCK);
  return true;
}

std::string& stream(Child& c, int which) {
  return which == 0 ? c.outcome.out : c.outcome.err;
}

void drain(Child& c, int which) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(c.fd[which], buffer, sizeof buffer);
    if (n > 0) {
      stream(c, which).append(buffer, std::size_t(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0 || errno != EAGAIN) {  // end of file or a broken pipe: nothing more will come
      close(c.fd[which]);
      c.fd[which] = -1;
    }
    return;
  }
}

Child start(std::size_t index, const std::vector<std::string>& argv) {
  Child c;
  c.index = index;
  c.start = Clock::now();
  int out[2], err[2];
  if (!make_pipe(out) || !make_pipe(err)) {
    c.outcome.exit_code = 127;
    c.outcome.err = std::string("cannot create a pipe: ") + std::strerror(errno);
    c.exited = true;
    return c;
  }
  c.pid = spawn_child(argv, out[1], err[1]);
  const int failed = c.pid < 0 ? errno : 0;
  close(out[1]);
  close(err[1]);
  c.fd[0] = out[0];
  c.fd[1] = err[0];
  if (failed) {
    c.outcome.exit_code = 127;
    c.outcome.err = "cannot start " + argv[0] + ": " + std::strerror(failed);
    c.exited = true;
  }
  return c;
}

// Waits (briefly) for output from any running child and collects it.
void collect_output(std::list<Child>& running) {
  std::vector<pollfd> fds;
  std::vector<std::pair<Child*, int>> owner;
  for (Child& c : running)
    for (int w = 0; w < 2; ++w)
      if (c.fd[w] >= 0) {
        fds.push_back({c.fd[w], POLLIN, 0});
        owner.emplace_back(&c, w);
      }
  if (fds.empty()) {
    usleep(20000);  // only children that closed their output but have not exited yet
    return;
  }
  if (poll(fds.data(), fds.size(), 250) <= 0) return;
  for (std::size_t i = 0; i < fds.size(); ++i)
    if (fds[i].revents) drain(*owner[i].first, owner[i].second);
}

void check_exit(Child& c, double timeout_s) {
  const double age = std::chrono::duration<double>(Clock::now() - c.start).count();
  if (!c.exited && timeout_s > 0 && age > timeout_s && !c.outcome.timed_out) {
    kill(c.pid, SIGKILL);
    c.outcome.timed_out = true;
  }
  if (c.exited || c.pid < 0) return;
  int status = 0;
  if (waitpid(c.pid, &status, WNOHANG) != c.pid) return;
  c.exited = true;
  c.outcome.wall_s = age;
  if (WIFEXITED(status)) c.outcome.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) c.outcome.signal = WTERMSIG(status);
}

bool finished(Child& c) {
  if (!c.exited) return false;
  // It has exited: whatever is still in its pipes is all there is.
  for (int w = 0; w < 2; ++w)
    if (c.fd[w] >= 0) drain(c, w);
  for (int w = 0; w < 2; ++w)
    if (c.fd[w] >= 0) close(c.fd[w]);
  c.fd[0] = c.fd[1] = -1;
  return true;
}

volatile std::sig_atomic_t g_signal = 0;

void note_signal(int signal) { g_signal = signal; }

// While children run, SIGINT, SIGTERM and SIGHUP are noted instead of ending this process at once, so
// that it can end its children first.
class SignalsNoted {
 public:
  SignalsNoted() {
    g_signal = 0;
    struct sigaction action {};
    action.sa_handler = note_signal;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &action, &old_[i]);
  }
  ~SignalsNoted() {
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &old_[i], nullptr);
  }

 private:
  static constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> old_{};
};

void end_children(std::list<Child>& running) {
  for (Child& c : running)
    if (!c.exited && c.pid > 0) kill(c.pid, SIGKILL);
  for (Child& c : running) {
    if (!c.exited && c.pid > 0)
      while (waitpid(c.pid, nullptr, 0) < 0 && errno == EINTR) {
      }
    for (int w = 0; w < 2; ++w)
      if (c.fd[w] >= 0) close(c.fd[w]);
  }
  running.clear();
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + strsignal(signal)), signal(signal) {}

void run_children(const std::vector<std::vector<std::string>>& commands, const ChildPool& pool) {
  const std::size_t parallel = std::size_t(std::max(1, pool.parallel));
  std::list<Child> running;
  std::size_t next = 0;
  auto last_tick = Clock::now();
  const SignalsNoted signals;
  while (next < commands.size() || !running.empty()) {
    if (g_signal) {
      end_children(running);
      throw Interrupted(g_signal);
    }
    while (running.size() < parallel && next < commands.size())
      running.push_back(start(next, commands[next])), ++next;
    collect_output(running);
    for (auto it = running.begin(); it != running.end();) {
      check_exit(*it, pool.timeout_s);
      if (g_signal) break;  // a child ended by the same signal is not a result
      if (!finished(*it)) {
        ++it;
        continue;
      }
      if (pool.done) pool.done(it->index, it->outcome);
      it = running.erase(it);
    }
    if (pool.tick && Clock::now() - last_tick > std::chrono::milliseconds(250)) {
      pool.tick();
      last_tick = Clock::now();
    }
  }
}

}  // namespace tools
