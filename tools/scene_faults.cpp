#include "tools/scene_faults.hpp"

#include <cmath>
#include <stdexcept>

#include "network/toml_util.hpp"

namespace tools {

namespace {

using network::ConfigError;
using network::FaultSpec;
using network::SourcePos;

const char* kForms =
    "kind = \"corrupt\" or \"drop\" with link = \"A->B\", kind = \"dead-link\" with link = "
    "\"A-B\", kind = \"halt\" with processor = \"P\"; at_us = a time >= 0; xor = 1..255 (corrupt)";

class FaultReader {
 public:
  FaultReader(std::string file, const network::Topology& topology)
      : file_(std::move(file)), topology_(topology) {}

  FaultSpec read(const toml::table& t, const SourcePos& table_pos) const {
    for (auto&& [key, value] : t) {
      const std::string k(key.str());
      if (k != "kind" && k != "link" && k != "processor" && k != "at_us" && k != "xor")
        throw ConfigError(pos(key.source()), "unknown key '" + k +
                                                 "' in a fault; valid keys are kind, link, "
                                                 "processor, at_us, xor");
    }
    FaultSpec f;
    f.origin = table_pos;
    const toml::node* kind = t.get("kind");
    if (!kind) throw ConfigError(table_pos, std::string("a fault needs a kind: ") + kForms);
    const std::string name = text(*kind, "kind");
    if (name == "corrupt")
      f.kind = FaultSpec::Kind::corrupt;
    else if (name == "drop")
      f.kind = FaultSpec::Kind::drop;
    else if (name == "dead-link")
      f.kind = FaultSpec::Kind::dead_link;
    else if (name == "halt")
      f.kind = FaultSpec::Kind::halt;
    else
      fail(*kind,
           "unknown fault kind '" + name + "'; valid kinds are corrupt, drop, dead-link, halt");
    where(t, f, table_pos);
    const toml::node* at = t.get("at_us");
    if (!at)
      throw ConfigError(table_pos, "a fault needs at_us, the simulated time (us) it acts from");
    if (!at->is_number()) fail(*at, "'at_us': expected a number, got " + network::type_name(*at));
    f.at_us = network::number(*at);
    if (!std::isfinite(f.at_us) || f.at_us < 0 || f.at_us > 1e12)
      fail(*at, "'at_us' = " + network::number_text(f.at_us) +
                    ": give a simulated time in us, 0 to 1e12");
    if (const toml::node* x = t.get("xor")) {
      if (f.kind != FaultSpec::Kind::corrupt) fail(*x, "'xor' is for kind = \"corrupt\" only");
      if (!x->is_integer())
        fail(*x, "'xor': expected an integer 1..255, got " + network::type_name(*x));
      const std::int64_t mask = *x->value<std::int64_t>();
      if (mask < 1 || mask > 255) fail(*x, "'xor' = " + std::to_string(mask) + ": give 1..255");
      f.xor_mask = int(mask);
    }
    return f;
  }

  SourcePos pos(const toml::source_region& s) const { return network::pos_of(s, file_); }

 private:
  [[noreturn]] void fail(const toml::node& n, const std::string& message) const {
    throw ConfigError(pos(n.source()), message);
  }
  std::string text(const toml::node& n, const std::string& key) const {
    if (!n.is_string()) fail(n, "'" + key + "': expected a string, got " + network::type_name(n));
    return *n.value<std::string>();
  }
  void processor(const toml::node& n, const std::string& name) const {
    if (topology_.find(name) < 0)
      fail(n, "no processor '" + name + "' in the network " + topology_.name);
  }
  bool neighbours(int a, int b) const {
    for (const network::Connection& c : topology_.connections)
      if ((c.a.processor == a && c.b.processor == b) || (c.a.processor == b && c.b.processor == a))
        return true;
    return false;
  }
  void where(const toml::table& t, FaultSpec& f, const SourcePos& table_pos) const {
    const toml::node* link = t.get("link");
    const toml::node* proc = t.get("processor");
    if (f.kind == FaultSpec::Kind::halt) {
      if (link) fail(*link, "a halt names a processor, not a link");
      if (!proc) throw ConfigError(table_pos, "kind = \"halt\" needs processor = \"NAME\"");
      f.processor = text(*proc, "processor");
      processor(*proc, f.processor);
      return;
    }
    if (proc)
      fail(*proc,
           "a " + std::string(network::to_string(f.kind)) + " fault names a link, not a processor");
    const bool both = f.kind == FaultSpec::Kind::dead_link;
    const std::string form = both ? "\"A-B\" (both directions)" : "\"A->B\" (one direction)";
    if (!link) throw ConfigError(table_pos, std::string("this fault needs link = ") + form);
    const std::string value = text(*link, "link");
    const std::string separator = both ? "-" : "->";
    const auto cut = value.find(separator);
    if (cut == std::string::npos || cut == 0 || cut + separator.size() >= value.size() ||
        (both && value.find("->") != std::string::npos))
      fail(*link, "link = \"" + value + "\": write " + form);
    f.from = value.substr(0, cut);
    f.to = value.substr(cut + separator.size());
    processor(*link, f.from);
    processor(*link, f.to);
    if (!neighbours(topology_.find(f.from), topology_.find(f.to)))
      fail(*link, f.from + " and " + f.to + " are not neighbours: no link joins them");
  }

  std::string file_;
  const network::Topology& topology_;
};

}  // namespace

std::vector<FaultSpec> read_faults(const toml::node* faults, const std::string& file,
                                   const network::Topology& topology) {
  std::vector<FaultSpec> out;
  if (!faults) return out;
  const FaultReader reader(file, topology);
  const toml::array* list = faults->as_array();
  if (!list)
    throw ConfigError(
        reader.pos(faults->source()),
        "'fault': expected an array of tables ([[fault]]), got " + network::type_name(*faults));
  for (const toml::node& entry : *list) {
    if (!entry.is_table())
      throw ConfigError(reader.pos(entry.source()),
                        "a fault: expected a table ([[fault]]), got " + network::type_name(entry));
    out.push_back(reader.read(*entry.as_table(), reader.pos(entry.source())));
  }
  return out;
}

// The flag's KEY=VALUE,... list as a TOML inline table: numbers stay numbers, anything else is a
// string.
FaultSpec parse_fault_flag(const std::string& text, const network::Topology& topology) {
  const std::string flag = "--fault " + text;
  std::string table = "fault = {";
  std::size_t start = 0;
  bool first = true;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw ConfigError({flag, 0, 0}, "'" + item + "' is not KEY=VALUE; write e.g. " +
                                          "--fault kind=drop,link=L1->E2,at_us=150 (" + kForms +
                                          ")");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    for (char c : key)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        throw ConfigError({flag, 0, 0}, "'" + key +
                                            "' is not a key; valid keys are kind, link, "
                                            "processor, at_us, xor");
    // A number starts with a digit, a sign or a point and is one whole (processor names, "E3",
    // are strings).
    bool number = !value.empty() && (std::isdigit(static_cast<unsigned char>(value[0])) ||
                                     value[0] == '+' || value[0] == '-' || value[0] == '.');
    if (number) {
      std::size_t used = 0;
      try {
        std::stod(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      number = used == value.size() || value.rfind("0x", 0) == 0;
    }
    std::string quoted = "\"";
    for (char c : value) {
      if (c == '"' || c == '\\') quoted += '\\';
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) continue;
      quoted += c;
    }
    quoted += "\"";
    table += std::string(first ? "" : ", ") + key + " = " + (number ? value : quoted);
    first = false;
    start = comma + 1;
  }
  table += "}";
  toml::table root;
  try {
    root = network::parse_toml_text(table, flag);
  } catch (const ConfigError& e) {
    throw ConfigError({flag, 0, 0}, "not a list of KEY=VALUE: " + e.message());
  }
  try {
    return FaultReader(flag, topology).read(*root["fault"].as_table(), {flag, 0, 0});
  } catch (const ConfigError& e) {  // a flag has no lines: name it alone
    throw ConfigError({flag, 0, 0}, e.message());
  }
}

}  // namespace tools
