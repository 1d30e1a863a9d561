#include "fuzz/iss_harness.hpp"

#include "fuzz/harness.hpp"

#include <unistd.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "t800/asm/assembler.hpp"
#include "t800/host/sp_server.hpp"
#include "t800/iss/core.hpp"

namespace fuzz {

namespace {

namespace fs = std::filesystem;
using t800::iss::Word;

constexpr std::size_t kMaxMessage = 5000;

void check_message(const std::string& what, const std::string& text) {
  if (text.empty()) throw Finding(what + " without a message");
  if (text.size() > kMaxMessage)
    throw Finding(what + " of " + std::to_string(text.size()) + " bytes: " + text.substr(0, 200));
}

// ---------------------------------------------------------------------------------------------
// Machine code.

constexpr t800::ProcessorType kTypes[] = {
    t800::ProcessorType::T800_20, t800::ProcessorType::T805_20, t800::ProcessorType::T414_20,
    t800::ProcessorType::T805_30};
// Installed memory: on-chip only, powers of two (addresses wrap by masking) and others (modulo).
constexpr std::int64_t kSizes[] = {4096, 6144, 8192, 12288, 65536, 100000, 1 << 18, 1 << 20};
constexpr std::size_t kMaxLinkBytes = 1 << 16;  // all the links deliver, per run
constexpr int kMaxRounds = 4096;                // run / deliver / advance rounds, per run

// Links whose far ends answer at once: outputs are taken, inputs are served from the input's own
// bytes (over and over) until kMaxLinkBytes have gone; an input for more than that waits for ever.
class FuzzLinks : public t800::iss::LinkEngine {
 public:
  FuzzLinks(const std::uint8_t* feed, std::size_t size) : feed_(feed), feed_size_(size) {}

  void start_output(int link, std::vector<std::uint8_t>) override { output_[link] = true; }
  void start_input(int link, Word count) override { wanted_[link] = count; }
  bool input_pending(int) const override { return feed_size_ > 0 && sent_ < kMaxLinkBytes; }
  void watch_input(int link, bool on) override { watched_[link] = on; }
  void reset(int link, bool output) override {
    if (output)
      output_[link] = false;
    else
      wanted_[link] = 0;
  }

  // Completes what can complete; true if anything did.
  bool deliver(t800::iss::Core& core) {
    bool any = false;
    for (int l = 0; l < t800::iss::kLinks; ++l) {
      if (core.halted()) return any;
      if (output_[l]) {
        output_[l] = false;
        core.output_done(l);
        any = true;
      }
      const bool can = feed_size_ > 0 && wanted_[l] <= kMaxLinkBytes - sent_;
      if (wanted_[l] && can) {
        std::vector<std::uint8_t> bytes(wanted_[l]);
        for (std::uint8_t& b : bytes) b = feed_[sent_++ % feed_size_];
        wanted_[l] = 0;
        core.input_done(l, bytes);
        any = true;
      } else if (watched_[l] && input_pending(l)) {
        watched_[l] = false;
        core.input_arrived(l);
        any = true;
      }
    }
    return any;
  }

 private:
  const std::uint8_t* feed_;
  std::size_t feed_size_;
  std::size_t sent_ = 0;
  bool output_[t800::iss::kLinks] = {};
  Word wanted_[t800::iss::kLinks] = {};
  bool watched_[t800::iss::kLinks] = {};
};

// One run; true if it ended in a halt.
bool run_once(const std::uint8_t* code, std::size_t size, std::uint8_t config,
              t800::iss::AddressPolicy policy) {
  const t800::ProcessorModel& model = t800::processor_model(kTypes[config & 3]);
  const std::int64_t installed = kSizes[(config >> 2) & 7];
  const bool connected = (config & 0x20) != 0;
  const int boot_link = config >> 6;

  t800::iss::Core core({&model, installed, policy, 0});
  FuzzLinks links(code, size);
  if (connected) core.set_link_engine(&links);
  const std::size_t room = std::size_t(installed - model.reserved_bytes);
  const std::size_t length = std::min(size, room);
  core.memory().write(core.mem_start(), code, length);
  core.start_boot_program(Word(length), boot_link);

  using t800::iss::StopReason;
  for (int round = 0; round < kMaxRounds && !core.halted(); ++round) {
    const std::int64_t left = kMaxInstructions - core.instructions();
    if (left <= 0 || core.cycle() >= kMaxCycles) break;
    const StopReason why = core.run(kMaxCycles, left);
    if (why == StopReason::halted || why == StopReason::limit || why == StopReason::running) break;
    // Idle (or any other pause a newer core has): let the links and then time move on.
    if (connected && links.deliver(core)) continue;
    if (why != StopReason::idle) continue;
    const std::optional<std::int64_t> due = core.next_timer_cycle();
    if (!due || *due >= kMaxCycles) break;
    core.advance_to(std::max(*due, core.cycle()));
  }

  if (core.instructions() > kMaxInstructions)
    throw Finding("ran " + std::to_string(core.instructions()) + " instructions, past its budget");
  core.waiting();  // what a deadlock report lists: must be computable in any state
  if (!core.halted()) return false;
  const t800::iss::HaltReport& report = *core.halt_report();
  check_message("a halt", report.reason);
  // The instruction's bytes (none when Iptr itself is outside the installed memory).
  if (report.bytes.size() > 64)
    throw Finding("a halt report with " + std::to_string(report.bytes.size()) +
                  " instruction bytes: " + report.reason);
  if (!report.bytes.empty())
    t800::assembly::disassemble(report.bytes, 0, report.iptr);  // what the report shows
  return true;
}

// ---------------------------------------------------------------------------------------------
// SP requests.

const char* const kSecret = "outside the root";

struct SpSandbox {
  fs::path base, root, outside;
};

const SpSandbox& sp_sandbox() {
  static const SpSandbox box = [] {
    SpSandbox b;
    b.base = fs::temp_directory_path() / ("t800sim-fuzz-sp-" + std::to_string(getpid()));
    b.root = b.base / "root";
    b.outside = b.base / "outside";
    fs::create_directories(b.outside);
    return b;
  }();
  static const ScratchDirectory removed_at_exit(box.base);
  return box;
}

// A fresh root for each input: a text file, a binary file in a subdirectory, and a symbolic link
// that leads out of the root (the server must refuse it); beside the root a directory whose one
// file must never change.
void lay_out(const SpSandbox& box) {
  fs::remove_all(box.root);
  fs::create_directories(box.root / "sub");
  std::ofstream(box.root / "a.txt", std::ios::binary) << "alpha\nbeta\n";
  std::ofstream(box.root / "sub" / "b.bin", std::ios::binary) << std::string("\0\1\2\3\377", 5);
  fs::create_symlink("../outside/secret", box.root / "out");
  std::ofstream(box.outside / "secret", std::ios::binary | std::ios::trunc) << kSecret;
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

void check_outside(const SpSandbox& box) {
  if (entries(box.base) != std::set<std::string>{"outside", "root"})
    throw Finding("a file appeared beside the SP server's root");
  if (entries(box.outside) != std::set<std::string>{"secret"})
    throw Finding("the directory beside the SP server's root changed");
  std::ifstream in(box.outside / "secret", std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (text != kSecret) throw Finding("a file outside the SP server's root was written");
}

void check_reply(const std::vector<std::uint8_t>& reply) {
  if (reply.size() < t800::host::kSpMinBodySize || reply.size() > t800::host::kSpMaxBodySize ||
      reply.size() % 2 != 0)
    throw Finding("an SP reply body of " + std::to_string(reply.size()) + " bytes");
}

}  // namespace

Verdict run_machine_code(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return Verdict::refused;
  bool halted = false;
  try {
    for (auto policy : {t800::iss::AddressPolicy::strict, t800::iss::AddressPolicy::wrap})
      halted = run_once(data + 1, size - 1, data[0], policy) || halted;
  } catch (const Finding&) {
    throw;
  } catch (const std::exception& e) {
    throw Finding(std::string("the ISS threw: ") + e.what());
  }
  return halted ? Verdict::refused : Verdict::accepted;
}

Verdict serve_sp_requests(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return Verdict::refused;
  const SpSandbox& box = sp_sandbox();
  lay_out(box);

  std::istringstream keyboard("keys\n");
  std::ostringstream out, err;
  bool system_called = false;
  t800::host::SpServerOptions options;
  options.root = box.root;
  options.allow_system = false;
  options.program_name = "fuzz.btl";
  options.program_args = {"-x", "two words"};
  options.core = std::vector<std::uint8_t>(64, 0xA5);
  t800::host::SpHost host;
  host.in = &keyboard;
  host.out = &out;
  host.err = &err;
  host.clock = [] { return t800::host::HostTime{1000000, 1000000}; };
  host.getenv = [](const std::string& name) -> std::optional<std::string> {
    return "value of " + name;
  };
  host.system = [&](const std::string&) {
    system_called = true;
    return 0;
  };

  std::vector<std::vector<std::uint8_t>> bodies;
  if (data[0] & 1) {
    bodies.emplace_back(data + 1, data + size);
  } else {
    for (std::size_t at = 1; at + 2 <= size && int(bodies.size()) < kMaxRequests;) {
      const std::size_t length = std::min<std::size_t>(data[at] | data[at + 1] << 8, size - at - 2);
      bodies.emplace_back(data + at + 2, data + at + 2 + length);
      at += 2 + length;
    }
  }

  bool any_ok = false;
  try {
    t800::host::SpServer server(options, host);
    for (const auto& body : bodies) {
      const std::vector<std::uint8_t> reply = server.handle(body);
      check_reply(reply);
      any_ok = any_ok || reply[0] == 0;
      if (server.exited()) break;  // the iserver stops after SP.EXIT's reply
    }
  } catch (const Finding&) {
    throw;
  } catch (const std::exception& e) {
    throw Finding(std::string("the SP server threw: ") + e.what());
  }
  if (system_called) throw Finding("SP.SYSTEM ran a command with allow_system off");
  check_outside(box);
  return any_ok ? Verdict::accepted : Verdict::refused;
}

Verdict assemble_source(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const int lines = int(std::count(text.begin(), text.end(), '\n')) + 1;
  try {
    const t800::assembly::Program program = t800::assembly::assemble(text, {0x80000070u, "fuzz.s"});
    for (std::size_t at = 0; at < program.bytes.size();) {
      const t800::assembly::Instruction i =
          t800::assembly::disassemble(program.bytes, at, program.origin);
      if (i.length <= 0) throw Finding("disassembled an instruction of no bytes");
      at += std::size_t(i.length);
    }
    if (program.bytes.size() <= 65536) program.listing_text();
    return Verdict::accepted;
  } catch (const t800::assembly::AssemblyError& e) {
    check_message("an assembly error", e.what());
    if (e.line() < 1 || e.line() > lines || e.column() < 1)
      throw Finding("an assembly error at " + std::to_string(e.line()) + ":" +
                    std::to_string(e.column()) + " of a " + std::to_string(lines) +
                    "-line text: " + e.what());
    return Verdict::refused;
  } catch (const Finding&) {
    throw;
  } catch (const std::exception& e) {
    throw Finding(std::string("the assembler threw something else than AssemblyError: ") +
                  e.what());
  }
}

}  // namespace fuzz
