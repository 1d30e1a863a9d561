// The SP server (sp_server.hpp). Each request's fields and reply follow INMOS iserver 1.50
// (github.com/machineroom/modern_iserver, iserver/iserver/): filec.c for the file requests, hostc.c
// for GETKEY..EXIT, serverc.c for COMMANDLINE, CORE and VERSION (SpCommand, SpCore, SpId).
#include "t800/host/sp_server.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "t800/host/sandbox.hpp"

namespace t800::host {

namespace fs = std::filesystem;

HostTime host_time_at(std::int64_t utc_seconds) {
  const std::time_t utc = static_cast<std::time_t>(utc_seconds);
  std::tm local{};
  localtime_r(&utc, &local);
  // iserver hostc.c SpTime (SUN): local = UTC + tm_gmtoff.
  return HostTime{utc_seconds + local.tm_gmtoff, utc_seconds};
}

HostTime host_clock_now() {
  return host_time_at(static_cast<std::int64_t>(std::time(nullptr)));
}

std::optional<std::string> host_getenv(const std::string& name) {
  const char* value = std::getenv(name.c_str());
  if (value == nullptr) return std::nullopt;
  return std::string(value);
}

int host_system(const std::string& command) {
  return std::system(command.c_str());
}

namespace detail {

// One open SP stream: a host file, or one of the three predefined streams. The operations are the
// C library's, whose semantics the iserver hands on (fread, getc, fwrite, fseek, feof, ferror).
class SpStream {
 public:
  // The iserver refuses a read straight after a write, and a write straight after a read, until a
  // seek (files.h FIOP_*, filec.c ER_NOPOSN): ANSI C needs a positioning call between them.
  enum class LastOp { kNone, kRead, kWrite };
  LastOp last_op = LastOp::kNone;

  virtual ~SpStream() = default;
  virtual std::size_t read(char* buffer, std::size_t count) = 0;
  virtual int get_byte() = 0;  // EOF at end of file or on error
  virtual std::size_t write(const char* data, std::size_t count) = 0;
  virtual bool flush() = 0;
  virtual bool seek(long offset, int whence) = 0;
  virtual long tell() = 0;  // -1 if the position is unknown
  virtual bool at_eof() const = 0;
  virtual bool has_error() const = 0;
  virtual int error_number() const = 0;  // errno of the last failure, 0 if none is known
  virtual bool close() = 0;
};

}  // namespace detail

namespace {

using detail::SpStream;
using Bytes = std::vector<std::uint8_t>;

// A file under the root, opened with fopen.
class FileStream final : public SpStream {
 public:
  explicit FileStream(std::FILE* file) : file_(file) {}
  ~FileStream() override {
    if (file_ != nullptr) std::fclose(file_);
  }

  std::size_t read(char* buffer, std::size_t count) override {
    const std::size_t got = std::fread(buffer, 1, count, file_);
    if (got < count && std::ferror(file_)) errno_ = errno;
    return got;
  }
  int get_byte() override {
    const int c = std::getc(file_);
    if (c == EOF && std::ferror(file_)) errno_ = errno;
    return c;
  }
  std::size_t write(const char* data, std::size_t count) override {
    const std::size_t put = std::fwrite(data, 1, count, file_);
    if (put < count) errno_ = errno;
    return put;
  }
  bool flush() override { return remember(std::fflush(file_) == 0); }
  bool seek(long offset, int whence) override {
    return remember(std::fseek(file_, offset, whence) == 0);
  }
  long tell() override {
    const long position = std::ftell(file_);
    remember(position >= 0);
    return position;
  }
  bool at_eof() const override { return std::feof(file_) != 0; }
  bool has_error() const override { return std::ferror(file_) != 0; }
  int error_number() const override { return errno_; }
  bool close() override {
    const bool ok = std::fclose(file_) == 0;
    file_ = nullptr;
    return ok;
  }

 private:
  bool remember(bool ok) {
    if (!ok) errno_ = errno;
    return ok;
  }

  std::FILE* file_;
  int errno_ = 0;
};

// Stream 0, 1 or 2 on the injected iostreams. Not seekable (as a terminal or pipe is not: the
// iserver's fseek and ftell fail there too); a read from an output stream, or a write to an input
// stream, transfers nothing and sets the error indicator, as fread/fwrite would.
class StandardStream final : public SpStream {
 public:
  StandardStream(std::istream* in, std::ostream* out) : in_(in), out_(out) {}

  std::size_t read(char* buffer, std::size_t count) override {
    if (in_ == nullptr) return fail(EBADF);
    if (count == 0) return 0;
    in_->read(buffer, static_cast<std::streamsize>(count));
    return static_cast<std::size_t>(in_->gcount());
  }
  int get_byte() override {
    if (in_ == nullptr) {
      fail(EBADF);
      return EOF;
    }
    const auto c = in_->get();
    return c == std::istream::traits_type::eof() ? EOF : static_cast<unsigned char>(c);
  }
  std::size_t write(const char* data, std::size_t count) override {
    if (out_ == nullptr) return fail(EBADF);
    out_->write(data, static_cast<std::streamsize>(count));
    // The iserver flushes stdout after every write (filec.c SpWrite); stderr is unbuffered.
    out_->flush();
    if (!*out_) return fail(EIO);
    return count;
  }
  bool flush() override {
    if (out_ == nullptr) return true;
    out_->flush();
    if (*out_) return true;
    fail(EIO);
    return false;
  }
  bool seek(long, int) override {
    fail(ESPIPE);
    return false;
  }
  long tell() override {
    fail(ESPIPE);
    return -1;
  }
  bool at_eof() const override { return in_ != nullptr && in_->eof(); }
  bool has_error() const override {
    return error_ || (in_ != nullptr && in_->bad()) || (out_ != nullptr && out_->bad());
  }
  int error_number() const override { return errno_; }
  // The iostreams belong to whoever made the server: closing the stream only frees its id.
  bool close() override { return flush(); }

 private:
  // Records a failure; returns 0 so callers can return it as "nothing transferred".
  std::size_t fail(int number) {
    error_ = true;
    errno_ = number;
    return 0;
  }

  std::istream* in_;
  std::ostream* out_;
  bool error_ = false;
  int errno_ = 0;
};

Bytes reply(SpResult result) {
  return SpReplyWriter(result).finish();
}
Bytes malformed() {
  return reply(SpResult::kBadParameters);
}

// A reply carrying one slice, clipped to what a reply can carry.
Bytes slice_reply(SpResult result, std::string_view data) {
  SpReplyWriter writer(result);
  writer.put_slice(data.substr(0, kSpMaxReplyData));
  return std::move(writer).finish();
}

// The iserver's quoting of one argument on a command line (parsecl.c QuotedArg).
std::string quoted(const std::string& argument) {
  if (argument.find_first_of(" \t") == std::string::npos) return argument;
  return "\"" + argument + "\"";
}

std::string join_command_line(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) {
    if (!line.empty()) line += ' ';
    line += quoted(word);
  }
  return line;
}

// Whether path is root or below it, component by component ("/a/bc" is not below "/a/b").
}  // namespace

SpServer::SpServer(SpServerOptions options, SpHost host)
    : options_(std::move(options)),
      host_(std::move(host)),
      sandbox_(std::make_unique<Sandbox>(options_.root)) {
  streams_.resize(kSpMaxStreams);
  // iserver files.c DupStdStreams: ids 0, 1, 2 are stdin, stdout, stderr.
  streams_[kSpStdin] = std::make_unique<StandardStream>(host_.in, nullptr);
  streams_[kSpStdout] = std::make_unique<StandardStream>(nullptr, host_.out);
  streams_[kSpStderr] = std::make_unique<StandardStream>(nullptr, host_.err);
}

SpServer::~SpServer() = default;

const fs::path& SpServer::root() const {
  return sandbox_->root();
}

detail::SpStream* SpServer::stream(std::int32_t id) {
  if (id < 0 || id >= kSpMaxStreams) return nullptr;
  return streams_[static_cast<std::size_t>(id)].get();
}

Bytes SpServer::handle(const Bytes& request) {
  if (request.empty()) return malformed();
  SpRequestReader fields(request.data() + 1, request.size() - 1);
  switch (static_cast<SpTag>(request[0])) {
    case SpTag::kOpen:
      return open(fields);
    case SpTag::kClose:
      return close(fields);
    case SpTag::kRead:
      return read(fields);
    case SpTag::kWrite:
      return write(fields);
    case SpTag::kGets:
      return gets(fields);
    case SpTag::kPuts:
      return puts(fields);
    case SpTag::kFlush:
      return flush(fields);
    case SpTag::kSeek:
      return seek(fields);
    case SpTag::kTell:
      return tell(fields);
    case SpTag::kEof:
      return eof(fields);
    case SpTag::kFerror:
      return ferror(fields);
    case SpTag::kRemove:
      return remove(fields);
    case SpTag::kRename:
      return rename(fields);
    case SpTag::kGetKey:
      return getkey();
    case SpTag::kPollKey:
      return pollkey();
    case SpTag::kGetEnv:
      return getenv(fields);
    case SpTag::kTime:
      return time();
    case SpTag::kSystem:
      return system(fields);
    case SpTag::kExit:
      return exit(fields);
    case SpTag::kCommandLine:
      return commandline(fields);
    case SpTag::kCore:
      return core(fields);
    case SpTag::kVersion:
      return version();
    default:
      return reply(SpResult::kNotImplemented);  // serverc.c SpUnknown
  }
}

// SP.OPEN: slice name, BYTE type, BYTE mode -> result, INT32 stream id.
Bytes SpServer::open(SpRequestReader& fields) {
  std::string name;
  std::uint8_t type = 0;
  std::uint8_t mode = 0;
  if (!fields.read_slice(name) || !fields.read_u8(type) || !fields.read_u8(mode)) {
    return malformed();
  }
  if (type != static_cast<std::uint8_t>(SpOpenType::kBinary) &&
      type != static_cast<std::uint8_t>(SpOpenType::kText)) {
    return reply(SpResult::kError);
  }
  // bsd.h: the same fopen modes for text and binary (a POSIX host does not translate).
  static constexpr const char* kModes[] = {"r", "w", "a", "r+", "w+", "a+"};
  if (mode < 1 || mode > 6) return reply(SpResult::kError);
  const auto free_id = std::find(streams_.begin(), streams_.end(), nullptr);
  if (free_id == streams_.end()) return reply(SpResult::kNoResource);
  const Sandbox::Opened opened_file = sandbox_->open(name, kModes[mode - 1]);
  if (opened_file.result != SpResult::kOk) return reply(opened_file.result);
  std::FILE* file = opened_file.file;
  // filec.c: append modes start at the end ("the ANSI spec says the initial position is
  // implementation specific").
  const auto opened = static_cast<SpOpenMode>(mode);
  if (opened == SpOpenMode::kAppend || opened == SpOpenMode::kAppendUpdate) {
    std::fseek(file, 0, SEEK_END);
  }
  *free_id = std::make_unique<FileStream>(file);
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u32(static_cast<std::uint32_t>(free_id - streams_.begin()));
  return std::move(writer).finish();
}

// SP.CLOSE: INT32 id -> result.
Bytes SpServer::close(SpRequestReader& fields) {
  std::int32_t id = 0;
  if (!fields.read_i32(id)) return malformed();
  SpStream* target = stream(id);
  if (target == nullptr) return reply(SpResult::kBadId);
  const bool ok = target->close();
  streams_[static_cast<std::size_t>(id)].reset();
  return reply(ok ? SpResult::kOk : SpResult::kError);
}

// SP.READ: INT32 id, INT16 count -> result, slice data. OK even when fewer bytes (or none) come:
// end of file shows as a short read.
Bytes SpServer::read(SpRequestReader& fields) {
  std::int32_t id = 0;
  std::uint16_t count = 0;
  if (!fields.read_i32(id) || !fields.read_u16(count)) return malformed();
  SpStream* source = stream(id);
  if (source == nullptr) return reply(SpResult::kBadId);
  if (source->last_op == SpStream::LastOp::kWrite) return reply(SpResult::kNoPosition);
  std::string data(std::min<std::size_t>(count, kSpMaxReplyData), '\0');
  data.resize(source->read(data.data(), data.size()));
  source->last_op = SpStream::LastOp::kRead;
  return slice_reply(SpResult::kOk, data);
}

// SP.WRITE: INT32 id, slice data -> result, INT16 bytes written.
Bytes SpServer::write(SpRequestReader& fields) {
  std::int32_t id = 0;
  std::string data;
  if (!fields.read_i32(id) || !fields.read_slice(data)) return malformed();
  SpStream* sink = stream(id);
  if (sink == nullptr) return reply(SpResult::kBadId);
  if (sink->last_op == SpStream::LastOp::kRead) return reply(SpResult::kNoPosition);
  const std::size_t written = sink->write(data.data(), data.size());
  sink->last_op = SpStream::LastOp::kWrite;
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u16(static_cast<std::uint16_t>(written));
  return std::move(writer).finish();
}

// SP.GETS: INT32 id, INT16 limit -> result, slice line. As fgets(buffer, limit + 1): at most limit
// bytes, up to and including a newline, which is not returned; an error if end of file (or an
// error) comes before any byte.
Bytes SpServer::gets(SpRequestReader& fields) {
  std::int32_t id = 0;
  std::uint16_t limit = 0;
  if (!fields.read_i32(id) || !fields.read_u16(limit)) return malformed();
  SpStream* source = stream(id);
  if (source == nullptr) return reply(SpResult::kBadId);
  if (source->last_op == SpStream::LastOp::kWrite) return reply(SpResult::kNoPosition);
  source->last_op = SpStream::LastOp::kRead;
  const std::size_t most = std::min<std::size_t>(limit, kSpMaxReplyData);
  std::string line;
  bool newline = false;
  bool ended = false;
  while (line.size() < most) {
    const int c = source->get_byte();
    if (c == EOF) {
      ended = true;
      break;
    }
    if (c == '\n') {
      newline = true;
      break;
    }
    line.push_back(static_cast<char>(c));
  }
  if (ended && line.empty() && !newline) return reply(SpResult::kError);
  return slice_reply(SpResult::kOk, line);
}

// SP.PUTS: INT32 id, slice line -> result; the line is written with a newline after it.
Bytes SpServer::puts(SpRequestReader& fields) {
  std::int32_t id = 0;
  std::string line;
  if (!fields.read_i32(id) || !fields.read_slice(line)) return malformed();
  SpStream* sink = stream(id);
  if (sink == nullptr) return reply(SpResult::kBadId);
  if (sink->last_op == SpStream::LastOp::kRead) return reply(SpResult::kNoPosition);
  line.push_back('\n');
  const bool ok = sink->write(line.data(), line.size()) == line.size();
  sink->last_op = SpStream::LastOp::kWrite;
  return reply(ok ? SpResult::kOk : SpResult::kError);
}

// SP.FLUSH: INT32 id -> result.
Bytes SpServer::flush(SpRequestReader& fields) {
  std::int32_t id = 0;
  if (!fields.read_i32(id)) return malformed();
  SpStream* target = stream(id);
  if (target == nullptr) return reply(SpResult::kBadId);
  return reply(target->flush() ? SpResult::kOk : SpResult::kError);
}

// SP.SEEK: INT32 id, INT32 offset, INT32 origin (1 start, 2 current, 3 end) -> result.
Bytes SpServer::seek(SpRequestReader& fields) {
  std::int32_t id = 0;
  std::int32_t offset = 0;
  std::int32_t origin = 0;
  if (!fields.read_i32(id) || !fields.read_i32(offset) || !fields.read_i32(origin)) {
    return malformed();
  }
  SpStream* target = stream(id);
  if (target == nullptr) return reply(SpResult::kBadId);
  int whence = 0;
  switch (static_cast<SpSeekOrigin>(origin)) {
    case SpSeekOrigin::kStart:
      whence = SEEK_SET;
      break;
    case SpSeekOrigin::kCurrent:
      whence = SEEK_CUR;
      break;
    case SpSeekOrigin::kEnd:
      whence = SEEK_END;
      break;
    default:
      return reply(SpResult::kError);  // iserver leaves the origin undefined here
  }
  if (!target->seek(offset, whence)) return reply(SpResult::kError);
  target->last_op = SpStream::LastOp::kNone;
  return reply(SpResult::kOk);
}

// SP.TELL: INT32 id -> result, INT32 position.
Bytes SpServer::tell(SpRequestReader& fields) {
  std::int32_t id = 0;
  if (!fields.read_i32(id)) return malformed();
  SpStream* target = stream(id);
  if (target == nullptr) return reply(SpResult::kBadId);
  const long position = target->tell();
  // A position past INT32's range cannot be told in the reply's INT32: an error, not a wrapped
  // number the program would seek back to.
  if (position < 0 || position > std::numeric_limits<std::int32_t>::max()) {
    return reply(SpResult::kError);
  }
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u32(static_cast<std::uint32_t>(position));
  return std::move(writer).finish();
}

// SP.EOF: INT32 id -> OK if the end-of-file indicator is set, an error if not.
Bytes SpServer::eof(SpRequestReader& fields) {
  std::int32_t id = 0;
  if (!fields.read_i32(id)) return malformed();
  SpStream* target = stream(id);
  if (target == nullptr) return reply(SpResult::kBadId);
  return reply(target->at_eof() ? SpResult::kOk : SpResult::kError);
}

// SP.FERROR: INT32 id -> OK, INT32 error number, slice message if the error indicator is set; an
// error if not. The number is the errno of the stream's own last failure (the iserver sends
// whatever errno holds when asked) and the message its strerror.
Bytes SpServer::ferror(SpRequestReader& fields) {
  std::int32_t id = 0;
  if (!fields.read_i32(id)) return malformed();
  SpStream* target = stream(id);
  if (target == nullptr) return reply(SpResult::kBadId);
  if (!target->has_error()) return reply(SpResult::kError);
  const int number = target->error_number();
  const std::string message = number != 0 ? std::strerror(number) : "";
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u32(static_cast<std::uint32_t>(number));
  writer.put_slice(std::string_view(message).substr(0, kSpMaxReplyData - 4));
  return std::move(writer).finish();
}

// SP.REMOVE: slice name -> result (ER_NOFILE if there is no such file).
Bytes SpServer::remove(SpRequestReader& fields) {
  std::string name;
  if (!fields.read_slice(name)) return malformed();
  return reply(sandbox_->remove(name));
}

// SP.RENAME: slice old name, slice new name -> result.
Bytes SpServer::rename(SpRequestReader& fields) {
  std::string from;
  std::string to;
  if (!fields.read_slice(from) || !fields.read_slice(to)) return malformed();
  return reply(sandbox_->rename(from, to));
}

// SP.GETKEY: -> result, BYTE key; waits for one (here: the next byte of the input stream).
Bytes SpServer::getkey() {
  if (host_.in == nullptr) return reply(SpResult::kError);
  const auto c = host_.in->get();
  if (c == std::istream::traits_type::eof()) return reply(SpResult::kError);
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u8(key(c));
  return std::move(writer).finish();
}

// SP.POLLKEY: -> OK, BYTE key if one is waiting, else the error result (hostc.c SpPollkey). A key
// is waiting when the input stream's buffer holds a byte (std::cin's usually does not: a terminal's
// keys reach POLLKEY only through GETKEY).
Bytes SpServer::pollkey() {
  if (host_.in == nullptr || host_.in->rdbuf() == nullptr || host_.in->rdbuf()->in_avail() <= 0) {
    return reply(SpResult::kError);
  }
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u8(key(host_.in->get()));
  return std::move(writer).finish();
}

std::uint8_t SpServer::key(int c) const {
  if (options_.newline_is_return && c == '\n') return '\r';
  return static_cast<std::uint8_t>(c);
}

// SP.GETENV: slice name -> result, slice value. The error result for an empty or unknown name; a
// value too long for the packet is clipped and answered with the error result, as hostc.c does.
Bytes SpServer::getenv(SpRequestReader& fields) {
  std::string name;
  if (!fields.read_slice(name)) return malformed();
  if (name.empty() || name.find('\0') != std::string::npos) return reply(SpResult::kError);
  const SpEnvironmentPolicy& policy = options_.environment;
  std::optional<std::string> value;
  if (const auto fixed = policy.fixed.find(name); fixed != policy.fixed.end()) {
    value = fixed->second;
  } else if (policy.mode == SpEnvironmentPolicy::Mode::kAll ||
             (policy.mode == SpEnvironmentPolicy::Mode::kListed &&
              std::find(policy.listed.begin(), policy.listed.end(), name) != policy.listed.end())) {
    if (host_.getenv) value = host_.getenv(name);
  }
  if (!value) return reply(SpResult::kError);
  return slice_reply(value->size() > kSpMaxReplyData ? SpResult::kError : SpResult::kOk, *value);
}

// SP.TIME: -> result, INT32 local time, INT32 UTC time.
Bytes SpServer::time() {
  const HostTime now = host_.clock ? host_.clock() : HostTime{};
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u32(static_cast<std::uint32_t>(now.local_seconds));
  writer.put_u32(static_cast<std::uint32_t>(now.utc_seconds));
  return std::move(writer).finish();
}

// SP.SYSTEM: slice command -> result, INT32 status (the raw status system() returns). The empty
// command asks whether there is a shell: OK if running it succeeds (hostc.c, Unix hosts).
Bytes SpServer::system(SpRequestReader& fields) {
  std::string command;
  if (!fields.read_slice(command)) return malformed();
  if (!options_.allow_system || !host_.system) return reply(SpResult::kNoPrivilege);
  if (command.find('\0') != std::string::npos) return reply(SpResult::kError);
  const int status = host_.system(command);
  SpReplyWriter writer(command.empty() && status != 0 ? SpResult::kError : SpResult::kOk);
  writer.put_u32(static_cast<std::uint32_t>(status));
  return std::move(writer).finish();
}

// SP.EXIT: INT32 status -> result. The server is to stop after replying.
Bytes SpServer::exit(SpRequestReader& fields) {
  std::int32_t status = 0;
  if (!fields.read_i32(status)) return malformed();
  exited_ = true;
  exit_status_ = status;
  return reply(SpResult::kOk);
}

// SP.COMMANDLINE: BYTE all -> result, slice line. A line longer than a reply can carry is clipped
// and answered kTruncated (the iserver's 4096-byte buffer never had to).
Bytes SpServer::commandline(SpRequestReader& fields) {
  std::uint8_t all = 0;
  if (!fields.read_u8(all)) return malformed();
  std::vector<std::string> words;
  if (all != kSpShortCommandLine && !options_.program_name.empty()) {
    words.push_back(options_.program_name);
  }
  words.insert(words.end(), options_.program_args.begin(), options_.program_args.end());
  const std::string line = join_command_line(words);
  return slice_reply(line.size() > kSpMaxReplyData ? SpResult::kTruncated : SpResult::kOk, line);
}

// SP.CORE: INT32 offset, INT16 length -> result, slice bytes of the core image from offset. The
// error result without an image or with an offset outside it; the length is clipped to the image
// and to the packet.
Bytes SpServer::core(SpRequestReader& fields) {
  if (!options_.core) return reply(SpResult::kError);  // serverc.c: "not peeked"
  std::int32_t offset = 0;
  std::uint16_t length = 0;
  if (!fields.read_i32(offset) || !fields.read_u16(length)) return malformed();
  const std::vector<std::uint8_t>& image = *options_.core;
  if (offset < 0 || static_cast<std::size_t>(offset) >= image.size()) {
    return reply(SpResult::kError);
  }
  const std::size_t start = static_cast<std::size_t>(offset);
  const std::size_t count =
      std::min({static_cast<std::size_t>(length), image.size() - start, kSpMaxReplyData});
  const std::string bytes(image.begin() + static_cast<std::ptrdiff_t>(start),
                          image.begin() + static_cast<std::ptrdiff_t>(start + count));
  return slice_reply(SpResult::kOk, bytes);
}

// SP.VERSION: -> result, BYTE version, BYTE host, BYTE OS, BYTE board.
Bytes SpServer::version() {
  SpReplyWriter writer(SpResult::kOk);
  writer.put_u8(options_.identity.version);
  writer.put_u8(options_.identity.host);
  writer.put_u8(options_.identity.os);
  writer.put_u8(options_.identity.board);
  return std::move(writer).finish();
}

}  // namespace t800::host
