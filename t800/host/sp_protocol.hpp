// INMOS's SP protocol, the one a transputer program speaks to the host's iserver over the host
// link: tags, result codes, open types and modes, packet sizes, the little-endian fields and the
// framing (a 2-byte little-endian length, then the body). Pure C++, no SystemC.
//
// Sources (read for their facts, none of their code copied):
// - INMOS hostio.inc, "updated for iserver v1.50", the occam host library's definitions (KRoC's
//   copy, github.com/concurrency/kroc modules/inmoslibs/libsrc/hostio/hostio.inc): tags, spr.,
//   spt., spm., spo., sps. values, sp.max.packet.size 512 and sp.min.packet.size 8.
// - The INMOS iserver 1.50 source (github.com/machineroom/modern_iserver, iserver/iserver/): sp.h
//   (tags, ER_* results), pack.c (fields, even reply lengths), filec.c, hostc.c, serverc.c (each
//   request's fields and reply), files.c (stream ids), bsd.h (exit codes), linkops/lops.c (reading
//   a request: 8 bytes first, then the rest).
// - pahihu/t4's server.c and server.h (a T414/T800 emulator's iserver): request lengths accepted,
//   replies padded to the minimum packet.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace t800::host {

// hostio.inc "Packet and buffer Sizes": sp.max.packet.size 512 and sp.min.packet.size 8 count the
// 2-byte length too. t4 (server.c, server()) accepts request lengths 6..510 and only even ones; the
// hostio library always sends an even, padded packet. iserver 1.50 itself allows 4094-byte bodies
// (linkops.h SPMAXPACKET 4096), but the libraries were built for 512 ("apart from buffer size").
inline constexpr std::size_t kSpMaxPacketSize = 512;
inline constexpr std::size_t kSpMinPacketSize = 8;
inline constexpr std::size_t kSpMaxBodySize = kSpMaxPacketSize - 2;  // 510
inline constexpr std::size_t kSpMinBodySize = kSpMinPacketSize - 2;  // 6
// The most data one reply slice can carry: result byte + INT16 count + data = one whole body
// (hostio.inc sp.max.readbuffer.size = sp.max.packet.data.size - 3).
inline constexpr std::size_t kSpMaxReplyData = kSpMaxBodySize - 3;  // 507

// The first body byte of a request (iserver sp.h; hostio.inc "Command tags"). 40 and 42 are
// sp.commandline.tag and sp.version.tag in hostio.inc, SP_COMMAND and SP_ID in iserver's sp.h.
enum class SpTag : std::uint8_t {
  kOpen = 10,
  kClose = 11,
  kRead = 12,
  kWrite = 13,
  kGets = 14,
  kPuts = 15,
  kFlush = 16,
  kSeek = 17,
  kTell = 18,
  kEof = 19,
  kFerror = 20,
  kRemove = 21,
  kRename = 22,
  kGetKey = 30,
  kPollKey = 31,
  kGetEnv = 32,
  kTime = 33,
  kSystem = 34,
  kExit = 35,
  kCommandLine = 40,
  kCore = 41,
  kVersion = 42,
  // Not served here (answered kNotImplemented), named for the tests and for readers.
  kDos = 50,
  kHelios = 51,
  kVms = 52,
  kSunOs = 53,
  kTds = 65,  // t4's name; iserver 1.50 uses 65 for its Parmacs extension
  kOther = 128,
};

// The first body byte of a reply. Values from iserver sp.h (ER_*) and hostio.inc (spr.*): "anything
// 128 or above is a server dependent 'failure' result". iserver 1.50 answers a general failure with
// ER_ERROR = 129, which hostio.inc calls spr.failed.operation, "identical in meaning to
// spr.operation.failed [128] due to historical accident"; t4 answers 128. This server follows the
// iserver.
enum class SpResult : std::uint8_t {
  kOk = 0,                 // ER_SUCCESS, spr.ok
  kNotImplemented = 1,     // ER_UNIMPLEMENTED, spr.not.implemented
  kOperationFailed = 128,  // spr.operation.failed (t4's only failure); not sent by this server
  kError = 129,            // ER_ERROR, spr.failed.operation
  kNoPrivilege = 131,      // ER_NOPRIV: used here for what the sandbox refuses
  kNoResource = 132,       // ER_NORESOURCE: no free stream id
  kNoFile = 133,           // ER_NOFILE: SP.REMOVE of a file that is not there
  kTruncated = 134,        // ER_TRUNCATED
  kBadId = 135,            // ER_BADID: a stream id that is not open
  kNoPosition = 136,       // ER_NOPOSN: read after write (or write after read) without a seek
  kNotAvailable = 137,     // ER_NOTAVAILABLE
  kEof = 138,              // ER_EOF
  kBadParameters = 141,    // ER_BADPARAS: used here for a request too short for its fields
};

// SP.OPEN's type and mode bytes (hostio.inc spt., spm.; iserver files.h ORG_*, bsd.h fopen modes).
enum class SpOpenType : std::uint8_t { kBinary = 1, kText = 2 };
enum class SpOpenMode : std::uint8_t {
  kInput = 1,           // "r"
  kOutput = 2,          // "w"
  kAppend = 3,          // "a"
  kExistingUpdate = 4,  // "r+"
  kNewUpdate = 5,       // "w+"
  kAppendUpdate = 6,    // "a+"
};

// SP.SEEK's origin (hostio.inc spo.start/current/end; iserver filec.c SpSeek).
enum class SpSeekOrigin : std::int32_t { kStart = 1, kCurrent = 2, kEnd = 3 };

// Predefined stream ids (hostio.inc spid.; iserver files.h FD_STDIN..FD_STDERR). SP.OPEN hands out
// the lowest free id of iserver's table of MAX_FILES = 128 (files.c FindFreeSlot), so 3 first.
inline constexpr std::int32_t kSpStdin = 0;
inline constexpr std::int32_t kSpStdout = 1;
inline constexpr std::int32_t kSpStderr = 2;
inline constexpr std::int32_t kSpMaxStreams = 128;

// SP.COMMANDLINE's byte (hostio.inc sp.short.commandline / sp.whole.commandline).
inline constexpr std::uint8_t kSpShortCommandLine = 0;
inline constexpr std::uint8_t kSpWholeCommandLine = 1;

// SP.EXIT's status: the toolset's sps.success and sps.failure (hostio.inc) and the host exit codes
// iserver 1.50 turns them into (hostc.c SpExit; TERMINATE_OK_EXIT 0, TERMINATE_FAIL_EXIT 255 in
// both bsd.h and msdos.h). Any other status the iserver passes to exit(), and a shell keeps its low
// 8 bits, so that 256 would read as success: here a status from 1 to 254 is the exit code as given,
// and any other (negative, or above 255) is 255, a failure, whatever its low bits.
inline constexpr std::int32_t kSpsSuccess = 999999999;
inline constexpr std::int32_t kSpsFailure = -999999999;
inline constexpr int kIserverSuccessExit = 0;
inline constexpr int kIserverFailureExit = 255;
int iserver_exit_code(std::int32_t status);

// Little-endian fields: every INT16 and INT32 of the protocol (iserver pack.c).
std::uint16_t load_le16(const std::uint8_t* bytes);
std::uint32_t load_le32(const std::uint8_t* bytes);
void append_le16(std::vector<std::uint8_t>& out, std::uint16_t value);
void append_le32(std::vector<std::uint8_t>& out, std::uint32_t value);

// Reads a request's fields after its tag. Every read checks the bytes are there first: a short
// request gives false, never a read past the body (iserver reads blindly from its buffer).
class SpRequestReader {
 public:
  SpRequestReader(const std::uint8_t* fields, std::size_t size) : data_(fields), size_(size) {}

  bool read_u8(std::uint8_t& value);
  bool read_u16(std::uint16_t& value);
  bool read_i32(std::int32_t& value);
  // A slice: INT16 count, then that many bytes (iserver pack.c get_slice).
  bool read_slice(std::string& value);

  std::size_t remaining() const { return size_ - position_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// Builds a reply body: the result byte, then fields. finish() pads with zero bytes to an even
// length (iserver pack.c put_count) of at least kSpMinBodySize (hostio.inc sp.min.packet.size; t4
// pads every short reply to it, iserver 1.50 sends as few as 2 bytes). Callers keep slices within
// kSpMaxReplyData, so a body never exceeds kSpMaxBodySize.
class SpReplyWriter {
 public:
  explicit SpReplyWriter(SpResult result) { body_.push_back(static_cast<std::uint8_t>(result)); }

  void put_u8(std::uint8_t value) { body_.push_back(value); }
  void put_u16(std::uint16_t value) { append_le16(body_, value); }
  void put_u32(std::uint32_t value) { append_le32(body_, value); }
  void put_slice(std::string_view data);

  std::vector<std::uint8_t> finish() &&;

 private:
  std::vector<std::uint8_t> body_;
};

// Why a request length field cannot start an SP packet, or empty if it can: odd, shorter than
// kSpMinBodySize or longer than kSpMaxBodySize (t4 server(): "too short", "too long", "odd
// length").
std::string sp_length_problem(std::uint16_t length);

// The bytes on the link for one packet: the body's length, little-endian, then the body.
std::vector<std::uint8_t> sp_frame(const std::vector<std::uint8_t>& body);

// Collects the bytes the transputer sends on the host link, in pieces of any size, into request
// bodies. A length that no SP packet has (sp_length_problem) means the stream is not SP, or has
// lost its framing: nothing after it can be trusted to start a packet, so the reassembler stops and
// reports it (iserver 1.50 ends the session on an over-long header, lops.c LOPS_GetRequest; t4
// warns and serves nothing more).
class SpPacketReassembler {
 public:
  void feed(const std::uint8_t* bytes, std::size_t size);
  void feed(const std::vector<std::uint8_t>& bytes) { feed(bytes.data(), bytes.size()); }

  // The next complete request body (tag first), oldest first; none until one is complete.
  std::optional<std::vector<std::uint8_t>> next_packet();

  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  // Bytes received that do not yet complete a packet (after a failure: all bytes since).
  std::size_t pending_bytes() const { return partial_.size(); }

 private:
  std::vector<std::uint8_t> partial_;
  std::deque<std::vector<std::uint8_t>> ready_;
  std::string error_;
};

}  // namespace t800::host
