#include "network/icollect_map.hpp"

#include <map>
#include <sstream>
#include <vector>

namespace network {

namespace {

constexpr const char* kConnectivity = "Connectivity for network";
constexpr const char* kMemoryMap = "Memory map for '";

// A word of a line and the 1-based column it starts at.
struct Word {
  std::string text;
  int column;
};

std::vector<Word> words_of(const std::string& line) {
  std::vector<Word> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back({line.substr(start, i - start), int(start) + 1});
  }
  return words;
}

std::string trimmed(const std::string& line) {
  const std::size_t first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

// Reads the map file line by line; every error names the line and column it is about.
class MapReader {
 public:
  MapReader(const std::string& path, std::optional<t800::ProcessorType> each)
      : path_(path), each_(each) {}

  void line(const std::string& text, int number);
  Topology topology();

 private:
  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw ConfigError(SourcePos{path_, line, column}, message);
  }
  void processor(const std::string& text, int line);
  void connect(const std::vector<Word>& words, int line);
  int number(const Word& word, int line, const char* what) const;
  t800::ProcessorType type_of(const Word& word, int line) const;
  int index_of(const Word& number_word, int line) const;
  LinkEnd end(const std::vector<Word>& words, std::size_t at, int line) const;

  std::string path_;
  std::optional<t800::ProcessorType> each_;
  std::map<int, ProcessorSpec> processors_;  // by the map's processor number
  struct Wire {
    std::vector<Word> words;
    int line;
  };
  std::vector<Wire> wires_;  // read once every processor is known
  Topology topology_;
  bool in_connectivity_ = false;
  bool saw_connectivity_ = false;
};

int MapReader::number(const Word& word, int line, const char* what) const {
  int value = -1;
  std::istringstream in(word.text);
  if (!(in >> value) || !in.eof() || value < 0 || value > 1'000'000)
    fail(line, word.column, std::string("expected ") + what + ", got '" + word.text + "'");
  return value;
}

t800::ProcessorType MapReader::type_of(const Word& word, int line) const {
  std::optional<t800::ProcessorType> family;
  if (word.text == "T800") family = t800::ProcessorType::T800_20;
  if (word.text == "T805") family = t800::ProcessorType::T805_20;
  if (word.text == "T414") family = t800::ProcessorType::T414_20;
  if (!family)
    fail(line, word.column,
         "processor type '" + word.text + "': t800sim models the T800, T805 and T414");
  if (!each_) return *family;
  if (t800::processor_model(*each_).has_fpu != t800::processor_model(*family).has_fpu)
    fail(line, word.column,
         "the map's processor is a " + word.text + ", which --processor " +
             std::string(t800::to_string(*each_)) + " is not: give a type " +
             (t800::processor_model(*family).has_fpu ? "with" : "without") +
             " a floating-point unit");
  return *each_;
}

// "Memory map for 'System[1]' processor 1 T800"
void MapReader::processor(const std::string& text, int line) {
  const std::size_t open = text.find(kMemoryMap);
  const std::size_t close = text.find('\'', open + std::string(kMemoryMap).size());
  if (close == std::string::npos)
    fail(line, int(open) + 1, "the processor's name has no closing quote");
  const std::vector<Word> rest = words_of(text.substr(close + 1));
  const int offset = int(close) + 1;
  if (rest.size() != 3 || rest[0].text != "processor")
    fail(line, offset + 1, "expected \"processor NUMBER TYPE\" after the name");
  const Word number_word{rest[1].text, offset + rest[1].column};
  const Word type_word{rest[2].text, offset + rest[2].column};
  const int n = number(number_word, line, "a processor number");
  if (processors_.count(n))
    fail(line, number_word.column, "processor " + std::to_string(n) + " has a memory map already");
  ProcessorSpec spec;
  spec.name = "P" + std::to_string(n);
  spec.config.type = type_of(type_word, line);
  spec.where = SourcePos{path_, line, int(open) + 1};
  processors_[n] = spec;
}

void MapReader::line(const std::string& text, int number) {
  const std::string t = trimmed(text);
  if (t.rfind(kMemoryMap, 0) == 0) return processor(text, number);
  if (t == kConnectivity) {
    in_connectivity_ = saw_connectivity_ = true;
    return;
  }
  if (!in_connectivity_ || t.empty()) return;
  std::vector<Word> words = words_of(text);
  if (words[0].text != "Connect") {
    in_connectivity_ = false;  // a later section
    return;
  }
  wires_.push_back({std::move(words), number});
}

int MapReader::index_of(const Word& number_word, int line) const {
  const int n = number(number_word, line, "a processor number");
  const auto found = processors_.find(n);
  if (found == processors_.end())
    fail(line, number_word.column,
         "processor " + std::to_string(n) + " has no memory map in this file");
  return int(std::distance(processors_.begin(), found));
}

// "processor N link L" starting at words[at].
LinkEnd MapReader::end(const std::vector<Word>& words, std::size_t at, int line) const {
  if (words.size() < at + 4 || words[at].text != "processor" || words[at + 2].text != "link")
    fail(line, at < words.size() ? words[at].column : 1,
         "expected \"processor NUMBER link NUMBER\"");
  const int link = number(words[at + 3], line, "a link number");
  if (link >= kLinksPerProcessor)
    fail(line, words[at + 3].column,
         "link " + std::to_string(link) + ": a transputer has links 0 to 3");
  return LinkEnd{index_of(words[at + 1], line), link};
}

// "Connect HOST to processor 0 link 0", "Connect processor 1 link 1 to processor 0 link 2" (and
// the host named second).
void MapReader::connect(const std::vector<Word>& w, int line) {
  const bool host_first = w.size() > 1 && w[1].text == "HOST";
  const bool host_last = w.back().text == "HOST";
  const std::size_t to = host_first ? 2 : 5;
  if (w.size() != (host_first || host_last ? 7u : 10u) || w[to].text != "to")
    fail(line, w[0].column,
         "expected \"Connect processor N link L to processor M link K\" or \"Connect HOST to "
         "processor N link L\"");
  const SourcePos where{path_, line, w[0].column};
  Topology& t = topology_;
  if (host_first || host_last) {
    if (t.host) fail(line, w[0].column, "a second connection to the host");
    t.host = end(w, host_first ? 3 : 1, line);
    return;
  }
  Connection c;
  c.a = end(w, 1, line);
  c.b = end(w, 6, line);
  c.where = where;
  t.connections.push_back(c);
}

Topology MapReader::topology() {
  if (!saw_connectivity_)
    fail(0, 0, std::string("no \"") + kConnectivity + "\" section: not an icollect map file");
  if (processors_.empty())
    fail(0, 0, "no \"Memory map for\" line names a processor: not an icollect map file");
  for (auto& [n, spec] : processors_) topology_.processors.push_back(spec);
  for (const Wire& wire : wires_) connect(wire.words, wire.line);
  if (!topology_.host)
    fail(0, 0, "no \"Connect HOST to processor N link L\": nothing says where the file boots");
  topology_.name = "icollect map";
  topology_.source = path_;
  topology_.description = "the network of the configuration that " + path_ + " maps";
  validate(topology_);
  return topology_;
}

}  // namespace

bool is_icollect_map(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (trimmed(line) == kConnectivity) return true;
  return false;
}

Topology parse_icollect_map(const std::string& text, const std::string& path,
                            std::optional<t800::ProcessorType> each) {
  MapReader reader(path, each);
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) reader.line(line, number);
  return reader.topology();
}

}  // namespace network
