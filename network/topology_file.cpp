#include "network/topology_file.hpp"

#include <toml++/toml.h>

#include "network/toml_util.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>

namespace network {

namespace {

// Reads one topology table; every error carries the position of the node it is about.
class Reader {
 public:
  Reader(const toml::table& root, std::string file) : root_(root), file_(std::move(file)) {}
  Topology read();

 private:
  SourcePos pos(const toml::node& node) const { return pos_of(node.source(), file_); }
  [[noreturn]] void fail(const toml::node& node, const std::string& message) const {
    throw ConfigError(pos(node), message);
  }
  void check_keys(const toml::table& table, std::initializer_list<const char*> valid,
                  const std::string& where) const;
  const toml::node& expect(const toml::node& node, toml::node_type type, const std::string& key,
                           const char* type_text) const;
  std::string text(const toml::table& table, const std::string& key, std::string fallback) const;
  const toml::array* tables(const std::string& key) const;

  ProcessorSpec processor(const toml::table& table) const;
  t800::MemoryConfig memory(const toml::node& node) const;
  LinkEnd end(const toml::node& node, const Topology& t) const;
  Connection link(const toml::table& table, const Topology& t) const;

  const toml::table& root_;
  std::string file_;
};

void Reader::check_keys(const toml::table& table, std::initializer_list<const char*> valid,
                        const std::string& where) const {
  std::vector<std::string> names(valid.begin(), valid.end());
  for (auto&& [key, value] : table) {
    bool known = false;
    for (const std::string& name : names) known = known || key.str() == name;
    if (!known)
      throw ConfigError(pos_of(key.source(), file_), "unknown key '" + std::string(key.str()) +
                                                         "' in " + where + "; valid keys are " +
                                                         join(names));
  }
}

const toml::node& Reader::expect(const toml::node& node, toml::node_type type,
                                 const std::string& key, const char* type_text) const {
  if (node.type() != type)
    fail(node, "'" + key + "': expected " + type_text + ", got " + type_name(node));
  return node;
}

std::string Reader::text(const toml::table& table, const std::string& key,
                         std::string fallback) const {
  const toml::node* node = table.get(key);
  if (!node) return fallback;
  return *expect(*node, toml::node_type::string, key, "a string").value<std::string>();
}

// [[processor]] and [[link]]: an array whose elements are tables; nullptr when absent.
const toml::array* Reader::tables(const std::string& key) const {
  const toml::node* node = root_.get(key);
  if (!node) return nullptr;
  const std::string hint =
      "'" + key + "' must be written [[" + key + "]]: expected an array of tables";
  if (!node->is_array()) fail(*node, hint + ", got " + type_name(*node));
  for (const toml::node& element : *node->as_array())
    if (!element.is_table()) fail(element, hint + ", got an element of type " + type_name(element));
  return node->as_array();
}

// Names appear in link ends ("NAME.linkN"), so they stay plain words.
bool valid_name(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

ProcessorSpec Reader::processor(const toml::table& table) const {
  check_keys(table, {"name", "type", "memory"}, "[[processor]]");
  const toml::node* name = table.get("name");
  if (!name) fail(table, "[[processor]] has no name: add name = \"P1\" (any unique name)");
  ProcessorSpec spec;
  spec.name = *expect(*name, toml::node_type::string, "name", "a string").value<std::string>();
  spec.where = pos(*name);
  if (!valid_name(spec.name))
    fail(*name, "processor name '" + spec.name +
                    "' is not valid: use letters, digits, '_' and '-' only (e.g. \"P1\")");
  if (const toml::node* type = table.get("type")) {
    const std::string text =
        *expect(*type, toml::node_type::string, "type", "a string").value<std::string>();
    auto parsed = t800::parse_processor_type(text);
    if (!parsed)
      fail(*type, "unknown processor type '" + text + "'; valid types are " +
                      t800::processor_type_names());
    spec.config.type = *parsed;
  }
  if (const toml::node* mem = table.get("memory")) spec.config.memory = memory(*mem);
  return spec;
}

// memory = "auto" | "onchip" | "external" (code and data alike), or a table
// { data = ..., code = ..., wait_states = n }.
t800::MemoryConfig Reader::memory(const toml::node& node) const {
  t800::MemoryConfig config;
  if (node.is_string()) {
    const std::string text = *node.value<std::string>();
    auto placement = t800::parse_placement(text);
    if (!placement)
      fail(node, "unknown memory placement '" + text +
                     "'; valid placements are auto, onchip, external (or a table "
                     "{ data = ..., code = ..., wait_states = n })");
    config.data = config.code = *placement;
    return config;
  }
  const toml::table& table =
      *expect(node, toml::node_type::table, "memory", "a placement or a table").as_table();
  check_keys(table, {"data", "code", "wait_states"}, "memory");
  for (const char* key : {"data", "code"}) {
    const toml::node* value = table.get(key);
    if (!value) continue;
    const std::string text =
        *expect(*value, toml::node_type::string, key, "a string").value<std::string>();
    auto placement = t800::parse_placement(text);
    if (!placement)
      fail(*value, "unknown memory placement '" + text + "' for " + key +
                       "; valid placements are auto, onchip, external");
    (std::string(key) == "data" ? config.data : config.code) = *placement;
  }
  if (const toml::node* ws = table.get("wait_states")) {
    const auto n =
        *expect(*ws, toml::node_type::integer, "wait_states", "an integer").value<std::int64_t>();
    if (n < 0)
      fail(*ws, "wait_states = " + std::to_string(n) +
                    " is negative: give the wait states per external memory access, 0 or more");
    // A sanity bound: real boards used a handful; this only keeps the int conversion safe.
    if (n > 1000) fail(*ws, "wait_states = " + std::to_string(n) + " is too large: at most 1000");
    config.wait_states = static_cast<int>(n);
  }
  return config;
}

LinkEnd Reader::end(const toml::node& node, const Topology& t) const {
  const std::string text =
      *expect(node, toml::node_type::string, "link end", "a string").value<std::string>();
  const auto dot = text.rfind('.');
  const std::string link = dot == std::string::npos ? "" : text.substr(dot + 1);
  // One digit: "link01" is no link of a T800 and is not read as link1.
  const bool digits = link.size() == 5 && link.compare(0, 4, "link") == 0 &&
                      std::isdigit(static_cast<unsigned char>(link[4]));
  if (!digits || dot == 0)
    fail(node, "malformed link end '" + text +
                   "': expected NAME.linkN with N one of 0-3, e.g. \"P0.link1\"");
  const std::string name = text.substr(0, dot);
  const int index = std::stoi(link.substr(4));
  const int p = t.find(name);
  if (p < 0) {
    std::vector<std::string> names;
    for (const ProcessorSpec& spec : t.processors) names.push_back(spec.name);
    fail(node, "unknown processor '" + name + "' in link end '" + text + "'; processors are " +
                   join(names));
  }
  if (index >= kLinksPerProcessor)
    fail(node, "link index " + std::to_string(index) + " in '" + text +
                   "' is outside 0-3: a T800 has four links, link0 to link3");
  return {p, index};
}

Connection Reader::link(const toml::table& table, const Topology& t) const {
  check_keys(table, {"from", "to", "speed_mbps"}, "[[link]]");
  Connection c;
  c.where = pos(table);
  for (const char* key : {"from", "to"}) {
    const toml::node* node = table.get(key);
    if (!node)
      fail(table, std::string("[[link]] has no '") + key +
                      "': give both ends, e.g. from = " + "\"P0.link1\" and to = \"P1.link0\"");
    (std::string(key) == "from" ? c.a : c.b) = end(*node, t);
  }
  if (const toml::node* speed = table.get("speed_mbps")) {
    if (!speed->is_number())
      fail(*speed, "'speed_mbps': expected a number, got " + type_name(*speed));
    const double mbps = number(*speed);
    if (!t800::is_valid_link_speed(mbps))
      fail(*speed, "link speed " + number_text(*speed) +
                       " Mbit/s is not supported: a T800 link runs at 5, 10 or 20 Mbit/s");
    c.speed_mbps = mbps;
  }
  return c;
}

Topology Reader::read() {
  check_keys(root_, {"name", "description", "host", "processor", "link"}, "a topology");
  Topology t;
  t.source = file_;
  t.name = text(root_, "name", std::filesystem::path(file_).stem().string());
  t.description = text(root_, "description", "");
  const toml::array* processors = tables("processor");
  if (!processors || processors->empty())
    fail(root_, "the topology has no processors: add at least one [[processor]] with a name");
  if (processors->size() > std::size_t(kMaxProcessors))  // before reading them all
    fail(*processors->get(std::size_t(kMaxProcessors)),
         "the topology has " + std::to_string(processors->size()) + " processors; at most " +
             std::to_string(kMaxProcessors) + " are simulated");
  for (const toml::node& p : *processors) t.processors.push_back(processor(*p.as_table()));
  const toml::node* host = root_.get("host");
  if (!host)
    fail(root_,
         "no host connection: name the processor link wired to the host PC, e.g. host = "
         "\"" +
             t.processors.front().name + ".link0\"");
  t.host = end(*host, t);
  if (const toml::array* links = tables("link"))
    for (const toml::node& l : *links) t.connections.push_back(link(*l.as_table(), t));
  validate(t);
  return t;
}

}  // namespace

Topology parse_topology(const toml::table& table, const std::string& file) {
  return Reader(table, file).read();
}

Topology load_topology(const std::string& path) {
  return parse_topology(parse_toml_file(path, "topology file"), path);
}

}  // namespace network
