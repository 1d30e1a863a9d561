// The "boot" workload kind: a bootable file (what `iserver -sb FILE` sends) booted through the host
// link onto a network of transputers that execute real machine code (IssNode), its host requests
// served by a sandboxed iserver (HostServer). docs/iss.md.
#include <filesystem>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "network/input_file.hpp"
#include "t800/sim_now.hpp"
#include "workloads/boot/boot_session.hpp"
#include "workloads/boot/host_server.hpp"
#include "workloads/boot/iss_node.hpp"
#include "workloads/registry.hpp"
#include "workloads/run/output_file.hpp"
#include "workloads/run/workload.hpp"
#include "workloads/setting_error.hpp"

namespace workloads {

namespace {

using boot::Bytes;

// A boot file larger than any memory a T800 can address is not a boot file.
constexpr std::int64_t kMaxBootFileBytes = std::int64_t(1) << 32;
// Every processor's memory is host memory: the whole network's is bounded well inside what a
// 24 GB host holds beside the simulator.
constexpr std::int64_t kMaxSimulatedMemory = std::int64_t(16) << 30;

Bytes read_boot_file(const std::string& path) {
  std::string text;
  try {
    text = network::read_input_file(path, std::size_t(kMaxBootFileBytes));
  } catch (const network::InputFileError& e) {
    throw SettingError({"workload.file"}, fmt::format("workload.file: {}: {}{}", path, e.what(),
                                                      e.missing ? "" : " (a T800 addresses 4 GB)"));
  }
  const Bytes bytes(text.begin(), text.end());
  if (bytes.empty())
    throw SettingError({"workload.file"},
                       "workload.file: " + path +
                           " is empty; a boot file starts with a control byte: 0 (poke), 1 "
                           "(peek) or the length 2..255 of the first stage that follows");
  return bytes;
}

// What can be seen of a boot file before it runs: its leading pokes and peeks and its first stage
// are the chip's protocol; what follows is the loaded code's business, seen when it runs.
void check_boot_file(const std::string& path, const Bytes& b) {
  std::size_t at = 0;
  while (at < b.size()) {
    const std::uint8_t control = b[at];
    const std::size_t need = control == 0 ? 8 : control == 1 ? 4 : control;
    if (b.size() - at - 1 < need)
      throw SettingError(
          {"workload.file"},
          fmt::format("workload.file: {} is truncated: the control byte {} at byte offset {} "
                      "announces {} {} but only {} follow",
                      path, control, at, need,
                      control == 0   ? "bytes of address and value (poke)"
                      : control == 1 ? "bytes of address (peek)"
                                     : "bytes of first-stage code",
                      b.size() - at - 1));
    if (control >= 2) return;
    at += 1 + need;
  }
  throw SettingError({"workload.file"},
                     "workload.file: " + path +
                         " only pokes and peeks: it never sends code (a control byte of 2..255)");
}

std::vector<std::string> split_args(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> args;
  for (std::string a; in >> a;) args.push_back(a);
  return args;
}

ResultValue halt_value(const t800::iss::HaltReport& h) {
  ResultValue v;
  v.set("reason", h.reason);
  v.set("iptr", fmt::format("#{:08X}", h.iptr));
  std::string bytes;
  for (auto b : h.bytes) bytes += fmt::format("{}{:02X}", bytes.empty() ? "" : " ", b);
  v.set("bytes", bytes);
  v.set("registers", fmt::format("A #{:08X} B #{:08X} C #{:08X} Wdesc #{:08X}", h.registers.a,
                                 h.registers.b, h.registers.c, h.registers.wdesc()));
  return v;
}

// How the ISS ran the code: in blocks replayed or timed afresh, or one instruction at a time.
ResultValue blocks_value(const t800::iss::BlockCounts& b) {
  ResultValue v;
  v.set("decoded", b.decoded);
  v.set("replayed", b.replayed);
  v.set("timed", b.timed);
  v.set("instructions", b.instructions);
  return v;
}

class BootWorkload : public Workload {
 public:
  explicit BootWorkload(const WorkloadContext& c)
      : path_(c.params.text("file")), boot_file_(read_boot_file(path_)) {
    check_boot_file(path_, boot_file_);
    if (!c.topology.host)
      throw SettingError({kNetworkKey},
                         "boot: the network has no host link to boot through; give the "
                         "topology a `host = \"PROCESSOR.linkN\"`");
    options_.installed_bytes = c.params.integer("memory");
    const std::int64_t processors = std::int64_t(c.topology.processors.size());
    if (options_.installed_bytes * processors > kMaxSimulatedMemory)
      throw SettingError(
          {"workload.memory"},
          fmt::format("workload.memory: {} processors of {} bytes each is {} GiB of simulated "
                      "memory, more than the {} GiB this simulator holds; give each less",
                      processors, options_.installed_bytes,
                      double(options_.installed_bytes * processors) / double(1 << 30),
                      kMaxSimulatedMemory >> 30));
    options_.policy = c.params.text("addressing") == "strict" ? t800::iss::AddressPolicy::strict
                                                              : t800::iss::AddressPolicy::wrap;
    options_.max_instructions = c.params.integer("max_instructions");
    const std::string dir = c.params.text("host_dir").empty() ? "." : c.params.text("host_dir");
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
      throw SettingError({"workload.host_dir"},
                         "workload.host_dir: " + dir + " is not a directory");
    server_.root = dir;
    server_.allow_system = c.params.flag("allow_system");
    server_.program_name = std::filesystem::path(path_).filename().string();
    server_.program_args = split_args(c.params.text("args"));
    server_.newline_is_return = true;  // stdin is a stream of lines: Return ends a typed one
    server_.environment.fixed["IBOARDSIZE"] = fmt::format("#{:X}", options_.installed_bytes);
    profile_path_ = c.params.text("profile");
    options_.profile = !profile_path_.empty();
    options_.run_ahead = c.params.flag("run_ahead");
    simulated_clock_ = c.params.text("clock") == "simulated";
    clock_start_ = c.params.integer("clock_start");
  }

  void build(network::Machine& machine) override {
    boot::register_byte_payload();
    session_ = std::make_unique<boot::BootSession>(std::size_t(machine.processors()));
    for (int n = 0; n < machine.processors(); ++n) {
      nodes_.push_back(std::make_unique<boot::IssNode>(machine, n, *session_, options_));
      boot::IssNode* node = nodes_.back().get();
      machine.spawn(n, "iss", t800::Priority::low, [node](network::Process& p) { node->run(p); });
    }
    host_ = std::make_unique<boot::HostServer>(
        machine, *session_, boot_file_, std::make_unique<t800::host::SpServer>(server_, sp_host()));
    network::Process& host = machine.spawn(network::Machine::kHost, "iserver", t800::Priority::low,
                                           [this](network::Process& p) { host_->run(p); });
    host.set_daemon();  // it serves for as long as the program runs
  }

  ResultValue results(const network::Machine& machine) const override {
    // A core still ahead of where a limit stopped the run comes back to it before it reports.
    for (const auto& node : nodes_) node->settle();
    ResultValue v;
    const boot::BootSession& s = *session_;
    v.set("file", path_);
    if (s.exit_status) {
      v.set("exit_status", std::int64_t(*s.exit_status));
      v.set("exit_code", s.exit_code);
    }
    v.set("ended", ended(machine));
    v.set("instructions", s.instructions());
    const double us = machine.simulated_us();
    v.set("host_requests", host_->requests());
    if (host_->replies_cut_short()) v.set("host_replies_cut_short", host_->replies_cut_short());
    ResultValue processors = ResultValue::list();
    std::string failure = s.host_error;
    if (!s.host_error.empty()) v.set("host_protocol_error", s.host_error);
    std::int64_t syncs = 0;
    for (const boot::ProcessorAccount& a : s.accounts()) {
      ResultValue p;
      p.set("name", a.name);
      p.set("booted", a.booted);
      if (a.booted) p.set("boot_link", a.boot_link);
      if (!a.booted && a.waiting_link >= 0) {
        const std::string waits =
            fmt::format("{} waits on link {} after {} of {} bytes of a boot block", a.name,
                        a.waiting_link, a.block_got, a.block_expected);
        p.set("boot_waits", waits);
        if (failure.empty()) failure = "the boot file is truncated: " + waits;
      }
      p.set("pokes", a.pokes);
      p.set("peeks", a.peeks);
      p.set("instructions", a.instructions);
      p.set("cycles", a.cycles);
      p.set("synchronisations", a.synchronisations);
      p.set("runs_ahead", a.runs_ahead);
      p.set("runs_ahead_undone", a.runs_ahead_undone);
      p.set("cycles_undone", a.cycles_undone);
      p.set("dma_stall_cycles", a.dma_stall_cycles);
      p.set("blocks", blocks_value(a.blocks));
      p.set("state", nodes_[std::size_t(&a - s.accounts().data())]->state());
      if (a.halt) {
        p.set("halt", halt_value(*a.halt));
        if (failure.empty()) failure = a.name + " halted: " + a.halt->reason;
      }
      if (a.instruction_limit) v.set("instruction_limit", true);
      syncs += a.synchronisations;
      processors.push(std::move(p));
    }
    v.set("synchronisations", syncs);
    v.set("synchronisations_per_instruction",
          s.instructions() ? double(syncs) / double(s.instructions()) : 0.0);
    v.set("simulated_instructions_per_us", us > 0 ? double(s.instructions()) / us : 0.0);
    v.set("processors", std::move(processors));
    if (!failure.empty()) v.set("failure", failure);
    if (!profile_path_.empty()) {
      write_output_file(profile_path_, profile(machine).to_json(), "workload.profile");
      v.set("profile", profile_path_);
    }
    return v;
  }

  const boot::BootSession& session() const { return *session_; }

  // The profile file (workload.profile; docs/iss.md, "Profiles"): per processor, what it executed
  // by operation and by block of code, and what it waited for.
  ResultValue profile(const network::Machine& machine) const {
    ResultValue processors = ResultValue::list();
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      const boot::IssNode& node = *nodes_[n];
      const boot::ProcessorAccount& a = session_->account(int(n));
      ResultValue p;
      p.set("name", a.name);
      p.set("type", std::string(node.core().processor().name));
      p.set("cycle_ns", node.core().processor().cycle_ns);
      p.set("instructions", a.instructions);
      p.set("cycles", a.cycles);
      p.set("synchronisations", a.synchronisations);
      p.set("dma_stall_cycles", a.dma_stall_cycles);
      ResultValue ops = ResultValue::list();
      for (const auto& [op, tally] : node.profile().instructions.operations()) {
        ResultValue o;
        o.set("op", std::string(t800::isa::mnemonic(op)));
        o.set("count", tally.instructions);
        o.set("cycles", tally.cycles);
        ops.push(std::move(o));
      }
      p.set("operations", std::move(ops));
      ResultValue hot = ResultValue::list();
      for (const auto& [from, tally] : node.profile().instructions.hottest_blocks(kHotBlocks)) {
        ResultValue b;
        b.set("from", fmt::format("#{:08X}", from));
        b.set("to", fmt::format("#{:08X}", from + t800::iss::InstructionProfile::kBlockBytes));
        b.set("instructions", tally.instructions);
        b.set("cycles", tally.cycles);
        hot.push(std::move(b));
      }
      p.set("hot_code", std::move(hot));
      p.set("idle_us", node.profile().idle_us);
      ResultValue waits;
      for (const auto& [what, us] : node.profile().waiting_us) waits.set(what, us);
      p.set("waiting_us", std::move(waits));
      processors.push(std::move(p));
    }
    ResultValue v;
    v.set("file", path_);
    v.set("simulated_us", machine.simulated_us());
    v.set("block_bytes", std::int64_t(t800::iss::InstructionProfile::kBlockBytes));
    v.set("processors", std::move(processors));
    return v;
  }

  // The host the server touches: the process's streams, and a clock that tells the simulated
  // time -- the run's start plus the simulated seconds, so that a program that times itself
  // (SP.TIME) measures the simulated chip -- or the host's own clock when asked for.
  t800::host::SpHost sp_host() const {
    t800::host::SpHost host;
    if (!simulated_clock_) return host;
    const std::int64_t start =
        clock_start_ >= 0 ? clock_start_ : t800::host::host_clock_now().utc_seconds;
    host.clock = [start] {
      return t800::host::host_time_at(start + std::int64_t(t800::sim_now().to_seconds()));
    };
    return host;
  }
  bool reports_when_stopped() const override { return true; }

 private:
  // How the run ended: the program's exit, a limit, a halt, or every process finished.
  std::string ended(const network::Machine& machine) const {
    if (session_->over()) return session_->why();
    if (machine.limit_reached() != network::Limit::none)
      return std::string("stopped: ") + network::to_string(machine.limit_reached());
    for (const boot::ProcessorAccount& a : session_->accounts())
      if (a.halt) return a.name + " halted: " + a.halt->reason;
    return "nothing left to run";
  }

  static constexpr std::size_t kHotBlocks = 40;
  std::string path_;
  std::string profile_path_;
  Bytes boot_file_;
  boot::IssNodeOptions options_;
  t800::host::SpServerOptions server_;
  bool simulated_clock_ = true;
  std::int64_t clock_start_ = -1;  // UTC seconds; < 0: the host's clock when the run starts
  std::unique_ptr<boot::BootSession> session_;
  std::vector<std::unique_ptr<boot::IssNode>> nodes_;
  std::unique_ptr<boot::HostServer> host_;
};

using T = ParamType;
// clang-format off
const Registration registered_boot{
    WorkloadInfo{"boot",
     "a bootable file (INMOS toolset .btl, or t800sim's own) booted through the host link and run "
     "instruction by instruction on every processor, with a sandboxed iserver on the host link",
     {
         {"file", T::input_file, std::string{}, "the bootable file, sent down the host link", {}, {}, {}},
         {"host_dir", T::text, std::string{},
          "the directory the program's files live in (no absolute names, no ..); empty: the current one",
          {}, {}, {}},
         {"allow_system", T::flag, false, "let the program run host commands (SP.SYSTEM)", {}, {}, {}},
         {"args", T::text, std::string{}, "the program's command line, blank-separated", {}, {}, {}},
         {"memory", T::integer, std::int64_t{2} << 20,
          "bytes of memory from MostNeg on each processor, on-chip RAM included", 4096,
          double(std::int64_t(1) << 31), {}},
         {"addressing", T::text, std::string{"wrap"},
          "\"wrap\" (addresses modulo the memory, as boards decode them) or \"strict\" (an access "
          "outside halts the processor)", {}, {}, {"wrap", "strict"}},
         {"profile", T::output_file, std::string{},
          "write the run's profile here as JSON: per processor, each operation's count and "
          "cycles, the hottest code, time waiting per link and timer (empty: none)", {}, {}, {}},
         {"clock", T::text, std::string{"simulated"},
          "what SP.TIME tells: \"simulated\" (clock_start plus the simulated seconds) or \"host\" "
          "(the host's clock, as iserver gives it)", {}, {}, {"simulated", "host"}},
         {"clock_start", T::integer, std::int64_t{-1},
          "with clock = \"simulated\": the run's start, in seconds since 1970-01-01 UTC (-1: the "
          "host's clock when the run starts); the local time adds the host zone's offset", -1,
          double(std::int64_t(1) << 40), {}},
         {"run_ahead", T::flag, true,
          "where only an arrival could change what a processor does, run it ahead of its "
          "neighbours from a checkpoint and back if one comes: far less host time, the same run "
          "but for where link DMA stalls fall (docs/iss.md, \"Running ahead\"); false: never past "
          "the look-ahead", {}, {}, {}},
         {"max_instructions", T::integer, std::int64_t{0},
          "end the run when a processor has executed this many instructions (0: no limit)", 0,
          double(std::int64_t(1) << 62), {}},
     }},
    [](const WorkloadContext& c) { return std::make_unique<BootWorkload>(c); }};
// clang-format on

}  // namespace

}  // namespace workloads
