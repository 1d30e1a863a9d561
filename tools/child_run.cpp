#include "tools/child_run.hpp"

#include <sys/resource.h>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <array>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstring>
#include <stdexcept>

namespace tools {

std::string self_executable() {
  std::array<char, PATH_MAX> buffer{};
  const ssize_t n = readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
  if (n <= 0) throw std::runtime_error("cannot find the t800sim executable (/proc/self/exe)");
  return std::string(buffer.data(), std::size_t(n));
}

int spawn_child(const std::vector<std::string>& argv, int out_fd, int err_fd) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid != 0) return pid;
  // The child, until exec: only what is safe between fork and exec.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);  // the parent died before the line above
  const int null = open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (null >= 0) dup2(null, STDIN_FILENO);
  dup2(out_fd, STDOUT_FILENO);
  dup2(err_fd, STDERR_FILENO);
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  execv(args[0], args.data());
  const std::string message = "cannot execute " + argv[0] + ": " + std::strerror(errno) + "\n";
  if (write(STDERR_FILENO, message.data(), message.size()) < 0) {
  }
  _exit(127);
}

namespace {

// Reads both pipes until both close, so a child writing much to one cannot block on the other.
void drain(int out_fd, int err_fd, ChildOutput& result) {
  pollfd fds[2] = {{out_fd, POLLIN, 0}, {err_fd, POLLIN, 0}};
  std::string* sinks[2] = {&result.out, &result.err};
  int open = 2;
  std::array<char, 65536> buffer;
  while (open > 0) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = read(fds[i].fd, buffer.data(), buffer.size());
      if (n > 0) {
        sinks[i]->append(buffer.data(), std::size_t(n));
      } else {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open;
      }
    }
  }
}

}  // namespace

ChildOutput run_program(const std::string& exe, const std::vector<std::string>& args) {
  std::vector<std::string> argv{exe};
  argv.insert(argv.end(), args.begin(), args.end());
  int out_pipe[2], err_pipe[2];
  if (pipe2(out_pipe, O_CLOEXEC) != 0) throw std::runtime_error("cannot create pipes");
  if (pipe2(err_pipe, O_CLOEXEC) != 0) {
    close(out_pipe[0]);
    close(out_pipe[1]);
    throw std::runtime_error("cannot create pipes");
  }
  ChildOutput result;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = spawn_child(argv, out_pipe[1], err_pipe[1]);
  if (pid < 0) throw std::runtime_error("cannot start a child process");
  close(out_pipe[1]);
  close(err_pipe[1]);
  drain(out_pipe[0], err_pipe[0], result);
  rusage usage{};
  while (wait4(pid, &result.status, 0, &usage) < 0 && errno == EINTR) {
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.maxrss_kib = usage.ru_maxrss;  // Linux: kilobytes
  result.exit_code = WIFEXITED(result.status) ? WEXITSTATUS(result.status) : -1;
  return result;
}

ChildOutput run_self(const std::vector<std::string>& args) {
  return run_program(self_executable(), args);
}

nlohmann::json run_scene_child(const std::string& scene,
                               const std::vector<std::string>& overrides) {
  std::vector<std::string> args{"run", scene, "--json"};
  for (const std::string& o : overrides) {
    args.push_back("--set");
    args.push_back(o);
  }
  const ChildOutput child = run_self(args);
  if (child.exit_code != 0) {
    std::string message = child.err.empty() ? child.out : child.err;
    while (!message.empty() && message.back() == '\n') message.pop_back();
    if (message.empty())
      message = "the simulation exited with code " + std::to_string(child.exit_code);
    throw std::runtime_error(message);
  }
  try {
    return nlohmann::json::parse(child.out);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("unreadable report from the simulation: ") + e.what());
  }
}

}  // namespace tools
