#include "tools/robot_file.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "network/config_error.hpp"
#include "network/toml_util.hpp"

namespace tools {

namespace {

using network::ConfigError;
using network::SourcePos;

const std::vector<std::string_view> kRobotKeys = {
    "name", "gravity", "joints", "triangle_inequality", "triangle_inequality_note"};
const std::vector<std::string_view> kJointKeys = {
    "type", "a", "alpha_deg", "d", "theta_deg", "limits", "mass", "com", "inertia"};

double radians(double degrees) {
  return degrees * M_PI / 180.0;
}

// Reads typed values out of one file, turning every problem into a ConfigError at the offending
// node.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  SourcePos where(const toml::source_region& region) const {
    return {file_, static_cast<int>(region.begin.line), static_cast<int>(region.begin.column)};
  }

  [[noreturn]] void fail(const toml::source_region& region, const std::string& message) const {
    throw ConfigError(where(region), message);
  }

  void reject_unknown_keys(const toml::table& table, const std::vector<std::string_view>& allowed,
                           const std::string& context) const {
    for (const auto& [key, node] : table) {
      bool known = false;
      for (std::string_view name : allowed) known = known || key.str() == name;
      if (known) continue;
      std::string names;
      for (std::string_view name : allowed)
        names += fmt::format("{}{}", names.empty() ? "" : ", ", name);
      fail(key.source(),
           fmt::format("unknown key '{}' in {} (expected one of: {})", key.str(), context, names));
    }
  }

  const toml::node& require(const toml::table& table, std::string_view key,
                            const std::string& context) const {
    const toml::node* node = table.get(key);
    if (!node) fail(table.source(), fmt::format("{} is missing the key '{}'", context, key));
    return *node;
  }

  double number(const toml::node& node, const std::string& what) const {
    if (auto value = node.value<double>(); value && node.is_number()) {
      if (!std::isfinite(*value)) fail(node.source(), fmt::format("{} must be finite", what));
      return *value;
    }
    fail(node.source(), fmt::format("{} must be a number, not {}", what, type_name(node)));
  }

  template <std::size_t N>
  std::array<double, N> numbers(const toml::node& node, const std::string& what) const {
    const toml::array* array = node.as_array();
    if (!array || array->size() != N) {
      fail(node.source(), fmt::format("{} must be an array of {} numbers", what, N));
    }
    std::array<double, N> values{};
    for (std::size_t i = 0; i < N; ++i)
      values[i] = number(*array->get(i), fmt::format("{}[{}]", what, i));
    return values;
  }

  std::string text(const toml::node& node, const std::string& what) const {
    if (const auto* value = node.as_string()) return value->get();
    fail(node.source(), fmt::format("{} must be a string, not {}", what, type_name(node)));
  }

 private:
  static std::string type_name(const toml::node& node) {
    std::ostringstream out;
    out << node.type();
    return out.str();
  }
  std::string file_;
};

Eigen::Vector3d vector3(const std::array<double, 3>& v) {
  return {v[0], v[1], v[2]};
}

dynamics::JointType joint_type(const Reader& reader, const toml::node& node,
                               const std::string& what) {
  const std::string type = reader.text(node, what);
  if (type == "revolute") return dynamics::JointType::revolute;
  if (type == "prismatic") return dynamics::JointType::prismatic;
  reader.fail(node.source(),
              fmt::format("{} must be \"revolute\" or \"prismatic\", not \"{}\"", what, type));
}

// Physical sanity of the inertial data: m >= 0, principal moments >= 0 and each at most the sum of
// the other two (a real body's moments obey the triangle inequality: Ixx + Iyy = 2 * sum of m z^2
// + ... >= Izz). Published data sets sometimes break the last rule (Corke's PUMA 560 has Iyy =
// 0.35, Ixx = Izz = 0 for link 1, where only the moment about the joint axis was identified); a
// file may keep such data with `triangle_inequality = false` and a `triangle_inequality_note`
// saying why.
void check_inertia(const Reader& reader, const toml::table& table,
                   const dynamics::LinkInertia& link, const std::string& context,
                   bool triangle_inequality) {
  if (link.mass < 0) {
    reader.fail(table.get("mass")->source(),
                fmt::format("{}.mass must not be negative (got {})", context, link.mass));
  }
  const Eigen::Vector3d& i = link.inertia;
  const toml::source_region& where = table.get("inertia")->source();
  if (i.minCoeff() < 0) reader.fail(where, fmt::format("{}.inertia must not be negative", context));
  if (!triangle_inequality) return;
  const double slack = 1e-12 * i.sum();
  for (int axis = 0; axis < 3; ++axis) {
    if (i(axis) > i.sum() - i(axis) + slack) {
      reader.fail(
          where,
          fmt::format("{}.inertia: I{} = {} exceeds the sum of the other two moments ({}), which "
                      "no rigid body does. Check the order (Ixx, Iyy, Izz: principal moments "
                      "about the centre of mass, in the link's DH frame) and the units (kg m^2). "
                      "To keep a published data set as it is, put triangle_inequality = false "
                      "and triangle_inequality_note = \"why\" at the top of the file",
                      context, "xyz"[axis], i(axis), i.sum() - i(axis)));
    }
  }
}

// `triangle_inequality = false` switches the check off, but only with a note saying why: data that
// no rigid body could have are kept on purpose, never by accident.
bool triangle_inequality_checked(const Reader& reader, const toml::table& root) {
  const toml::node* flag = root.get("triangle_inequality");
  const toml::node* note = root.get("triangle_inequality_note");
  if (!flag) {
    if (note)
      reader.fail(note->source(),
                  "triangle_inequality_note without triangle_inequality = false: the note "
                  "explains switching the check off");
    return true;
  }
  if (!flag->is_boolean()) reader.fail(flag->source(), "triangle_inequality must be true or false");
  if (*flag->value<bool>()) return true;
  if (!note || reader.text(*note, "triangle_inequality_note").empty())
    reader.fail(flag->source(),
                "triangle_inequality = false needs triangle_inequality_note = \"...\" saying why "
                "these inertias are kept (e.g. the published data set they come from)");
  return false;
}

dynamics::Joint parse_joint(const Reader& reader, const toml::table& table,
                            const std::string& context, bool triangle_inequality) {
  reader.reject_unknown_keys(table, kJointKeys, context);
  auto field = [&](std::string_view key) -> const toml::node& {
    return reader.require(table, key, context);
  };
  auto name = [&context](std::string_view key) { return fmt::format("{}.{}", context, key); };
  dynamics::Joint joint;
  joint.type = joint_type(reader, field("type"), name("type"));
  joint.dh.a = reader.number(field("a"), name("a"));
  joint.dh.alpha = radians(reader.number(field("alpha_deg"), name("alpha_deg")));
  joint.dh.d = reader.number(field("d"), name("d"));
  joint.dh.theta = radians(reader.number(field("theta_deg"), name("theta_deg")));
  const auto limits = reader.numbers<2>(field("limits"), name("limits"));
  if (limits[0] > limits[1]) {
    reader.fail(field("limits").source(), fmt::format("{}: min {} is greater than max {}",
                                                      name("limits"), limits[0], limits[1]));
  }
  // Revolute limits are written in degrees, prismatic ones in metres.
  const double unit = joint.type == dynamics::JointType::revolute ? M_PI / 180.0 : 1.0;
  joint.limits = {limits[0] * unit, limits[1] * unit};
  joint.link.mass = reader.number(field("mass"), name("mass"));
  joint.link.com = vector3(reader.numbers<3>(field("com"), name("com")));
  joint.link.inertia = vector3(reader.numbers<3>(field("inertia"), name("inertia")));
  check_inertia(reader, table, joint.link, context, triangle_inequality);
  return joint;
}

dynamics::RobotModel parse_table(const Reader& reader, const toml::table& root) {
  reader.reject_unknown_keys(root, kRobotKeys, "the robot file");
  dynamics::RobotModel model;
  if (const toml::node* name = root.get("name")) model.name = reader.text(*name, "name");
  if (const toml::node* gravity = root.get("gravity")) {
    model.gravity = vector3(reader.numbers<3>(*gravity, "gravity"));
  }
  const toml::node& joints_node = reader.require(root, "joints", "the robot file");
  const toml::array* joints = joints_node.as_array();
  if (!joints || !joints->is_array_of_tables()) {
    reader.fail(joints_node.source(), "joints must be an array of tables ([[joints]])");
  }
  if (joints->size() != static_cast<std::size_t>(dynamics::kJoints)) {
    reader.fail(joints_node.source(),
                fmt::format("the robot needs exactly {} [[joints]] entries, found {}",
                            dynamics::kJoints, joints->size()));
  }
  const bool triangle_inequality = triangle_inequality_checked(reader, root);
  for (std::size_t i = 0; i < joints->size(); ++i) {
    model.joints[i] = parse_joint(reader, *joints->get(i)->as_table(),
                                  fmt::format("joints[{}]", i + 1), triangle_inequality);
  }
  return model;
}

}  // namespace

dynamics::RobotModel parse_robot(const std::string& text, const std::string& file) {
  return parse_table(Reader(file), network::parse_toml_text(text, file));
}

dynamics::RobotModel load_robot(const std::string& path) {
  return parse_table(Reader(path), network::parse_toml_file(path, "robot file"));
}

}  // namespace tools
