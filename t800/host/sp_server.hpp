// The host's side of the SP protocol: what the iserver does for a transputer program's requests,
// one request body in, one reply body out (frame them with sp_protocol.hpp). Pure C++, no SystemC.
//
// It follows INMOS iserver 1.50 (github.com/machineroom/modern_iserver, iserver/iserver/filec.c,
// hostc.c, serverc.c) field for field, and differs where a simulator must not do what the iserver
// did on the user's own machine:
// - files live under one root directory; absolute names, ".." and symbolic links that lead out
//   of it (or nowhere) are refused with kNoPrivilege, also when another host process swaps a link
//   in while the name is opened (sandbox.hpp);
// - SP.SYSTEM runs nothing unless allow_system is set;
// - SP.GETENV reveals only the variables the policy lists (by default the INMOS toolset's own), not
//   the whole host environment;
// - a reply never exceeds the 512-byte packet: READ, GETS, CORE and long strings are clipped to
//   kSpMaxReplyData (iserver 1.50 would overrun its 4094-byte buffer, t4 stops);
// - a request too short for its fields is answered kBadParameters instead of being read past;
// - SP.TELL of a position past INT32's range answers an error, not the position wrapped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "t800/host/sp_protocol.hpp"

namespace t800::host {

// SP.TIME's answer: seconds since 1970-01-01, in the host's local time and in UTC (iserver hostc.c
// SpTime: local = UTC + the zone's offset). Sent as the low 32 bits of each.
struct HostTime {
  std::int64_t local_seconds = 0;
  std::int64_t utc_seconds = 0;
};

// The host's clock now, as the iserver reads it (time() and the local zone's tm_gmtoff).
HostTime host_clock_now();
// The time `utc_seconds` (since 1970-01-01 UTC) as SP.TIME gives it: with the local zone's offset
// at that instant, as host_clock_now applies it.
HostTime host_time_at(std::int64_t utc_seconds);
// The host environment's value of name, if it has one.
std::optional<std::string> host_getenv(const std::string& name);
// std::system, whose raw status the iserver returns.
int host_system(const std::string& command);

// Which variables SP.GETENV may reveal. iserver 1.50 answers any (hostc.c SpGetenv); today's host
// environments hold credentials, and a run that reads them is neither private nor reproducible, so
// by default only the INMOS toolset's own variables pass (ISEARCH, IBOARDSIZE, ITERM: the D7205
// setup, t4 itools/d7205/d7205-env.sh). `fixed` answers first whatever the mode, e.g. IBOARDSIZE
// set to the simulated memory size as t4 does (main.c).
struct SpEnvironmentPolicy {
  enum class Mode { kNone, kListed, kAll };
  Mode mode = Mode::kListed;
  std::vector<std::string> listed = {"ISEARCH", "IBOARDSIZE", "ITERM"};
  std::map<std::string, std::string> fixed;
};

// SP.VERSION's four bytes (iserver serverc.c SpId; hostio.inc sph./spo./spb.). version is
// major * 10 + minor / 10: iserver 1.50 sends 15. The host is none of INMOS's boxes (sph.unknown)
// and no INMOS board (spb.unknown); the OS is spo.SUNOS, as t4 reports, so programs that choose by
// OS use Unix file names.
struct SpIdentity {
  std::uint8_t version = 15;
  std::uint8_t host = 0;
  std::uint8_t os = 4;
  std::uint8_t board = 0;
};

struct SpServerOptions {
  // Every file name is taken relative to this directory; it must exist.
  std::filesystem::path root = ".";
  bool allow_system = false;
  SpEnvironmentPolicy environment;
  // SP.COMMANDLINE: the short line is program_args (what the user gave after "--"), the whole line
  // program_name and then program_args, each argument with a blank or tab in double quotes
  // (iserver parsecl.c MakeCommandLine, ParseCommandLine). The iserver's whole line also held its
  // own options; a simulated run has none to give.
  std::string program_name;
  std::vector<std::string> program_args;
  // SP.CORE's memory image (iserver's CoreDump, peeked with -sa); without one, SP.CORE fails.
  std::optional<std::vector<std::uint8_t>> core;
  SpIdentity identity;
  // GETKEY and POLLKEY read keys from the host's input stream. The iserver puts the terminal in
  // raw mode, where the Return key is a carriage return, and programs end a typed line on it
  // (hostio's so.read.echo.int waits for #0D); a stream of text lines (a pipe, a file, a terminal
  // in its usual line mode) ends them with a newline instead. Set, a newline is given as the
  // carriage return a raw terminal would give.
  bool newline_is_return = false;
};

// What the server touches outside its root: the three predefined streams, the clock, the
// environment and the shell. Tests and reproducible runs replace them.
struct SpHost {
  std::istream* in = &std::cin;    // stream 0, and the keyboard of GETKEY/POLLKEY
  std::ostream* out = &std::cout;  // stream 1
  std::ostream* err = &std::cerr;  // stream 2
  std::function<HostTime()> clock = host_clock_now;
  std::function<std::optional<std::string>(const std::string&)> getenv = host_getenv;
  std::function<int(const std::string&)> system = host_system;
};

class Sandbox;

namespace detail {
class SpStream;
}

class SpServer {
 public:
  // Throws std::invalid_argument if options.root is not an existing directory.
  explicit SpServer(SpServerOptions options = {}, SpHost host = {});
  ~SpServer();
  SpServer(const SpServer&) = delete;
  SpServer& operator=(const SpServer&) = delete;

  // One request body (tag first, as SpPacketReassembler gives it) -> its reply body (result first,
  // padded as SpReplyWriter::finish). Never reads outside `request`; never throws for any bytes.
  std::vector<std::uint8_t> handle(const std::vector<std::uint8_t>& request);

  // After SP.EXIT: the program asked the server to stop (the iserver replies, then exits).
  bool exited() const { return exited_; }
  std::int32_t exit_status() const { return exit_status_; }
  // The host exit code the iserver gives for that status (iserver_exit_code); 0 before SP.EXIT.
  int exit_code() const { return exited_ ? iserver_exit_code(exit_status_) : 0; }

  const std::filesystem::path& root() const;  // canonical

 private:
  std::vector<std::uint8_t> open(SpRequestReader& fields);
  std::vector<std::uint8_t> close(SpRequestReader& fields);
  std::vector<std::uint8_t> read(SpRequestReader& fields);
  std::vector<std::uint8_t> write(SpRequestReader& fields);
  std::vector<std::uint8_t> gets(SpRequestReader& fields);
  std::vector<std::uint8_t> puts(SpRequestReader& fields);
  std::vector<std::uint8_t> flush(SpRequestReader& fields);
  std::vector<std::uint8_t> seek(SpRequestReader& fields);
  std::vector<std::uint8_t> tell(SpRequestReader& fields);
  std::vector<std::uint8_t> eof(SpRequestReader& fields);
  std::vector<std::uint8_t> ferror(SpRequestReader& fields);
  std::vector<std::uint8_t> remove(SpRequestReader& fields);
  std::vector<std::uint8_t> rename(SpRequestReader& fields);
  std::vector<std::uint8_t> getkey();
  std::vector<std::uint8_t> pollkey();
  std::vector<std::uint8_t> getenv(SpRequestReader& fields);
  std::vector<std::uint8_t> time();
  std::vector<std::uint8_t> system(SpRequestReader& fields);
  std::vector<std::uint8_t> exit(SpRequestReader& fields);
  std::vector<std::uint8_t> commandline(SpRequestReader& fields);
  std::vector<std::uint8_t> core(SpRequestReader& fields);
  std::vector<std::uint8_t> version();
  std::uint8_t key(int c) const;  // a key read for GETKEY or POLLKEY, as the program gets it

  // The open stream with this id, or null (iserver files.c FindFileDes).
  detail::SpStream* stream(std::int32_t id);

  SpServerOptions options_;
  SpHost host_;
  std::unique_ptr<Sandbox> sandbox_;                        // the files it may name
  std::vector<std::unique_ptr<detail::SpStream>> streams_;  // index = stream id
  bool exited_ = false;
  std::int32_t exit_status_ = 0;
};

}  // namespace t800::host
