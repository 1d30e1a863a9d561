// Reading robot files: the Stanford arm's values, and errors that name file:line:column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include "dynamics_fixtures.hpp"
#include "network/config_error.hpp"
#include "tests/test_paths.hpp"

namespace dynamics {
namespace {

using testing::stanford;

TEST(RobotFile, LoadsTheStanfordArm) {
  const RobotModel& model = stanford();
  EXPECT_EQ(model.name, "Stanford arm");
  EXPECT_EQ(model.gravity, Eigen::Vector3d(0, 0, -9.81));
  EXPECT_EQ(model.joints[2].type, JointType::prismatic);
  EXPECT_DOUBLE_EQ(model.joints[0].dh.d, 0.412);
  EXPECT_DOUBLE_EQ(model.joints[0].dh.alpha, -M_PI / 2);
  EXPECT_DOUBLE_EQ(model.joints[2].dh.theta, -M_PI / 2);
  EXPECT_DOUBLE_EQ(model.joints[2].limits.min, 0.3048);
  EXPECT_DOUBLE_EQ(model.joints[4].limits.max, M_PI / 2);
  EXPECT_DOUBLE_EQ(model.joints[1].link.com.y(), -1.054);
  EXPECT_DOUBLE_EQ(model.joints[5].link.inertia.z(), 0.0003);
  EXPECT_DOUBLE_EQ(model.joints[0].link.mass, 9.29);
}

// A valid file with one joint entry's line replaced, for the error cases.
std::string robot_text(const std::string& from, const std::string& to) {
  std::ifstream in(testing::stanford_path());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

int line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

// Parses and expects a ConfigError at `line` whose message contains `words`.
void expect_error(const std::string& text, int line, const std::string& words) {
  try {
    tools::parse_robot(text, "robot.toml");
    ADD_FAILURE() << "no error; expected: " << words;
  } catch (const network::ConfigError& error) {
    EXPECT_EQ(error.where().file, "robot.toml");
    EXPECT_EQ(error.where().line, line) << error.what();
    EXPECT_GT(error.where().column, 0) << error.what();
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()).rfind("robot.toml:" + std::to_string(line) + ":", 0), 0u)
        << error.what();
  }
}

TEST(RobotFile, RejectsAnUnknownKey) {
  const std::string text = robot_text("mass = 5.01", "masss = 5.01");
  expect_error(text, line_of(text, "masss"), "unknown key 'masss' in joints[2]");
}

TEST(RobotFile, RejectsAWrongType) {
  const std::string text = robot_text("d = 0.154", "d = \"0.154\"");
  expect_error(text, line_of(text, "d = \"0.154\""), "joints[2].d must be a number");
}

TEST(RobotFile, RejectsANegativeMass) {
  const std::string text = robot_text("mass = 4.25", "mass = -4.25");
  expect_error(text, line_of(text, "mass = -4.25"), "joints[3].mass must not be negative");
}

TEST(RobotFile, RejectsLimitsWithMinAboveMax) {
  const std::string text = robot_text("limits = [0.3048, 1.270]", "limits = [1.270, 0.3048]");
  expect_error(text, line_of(text, "limits = [1.270, 0.3048]"),
               "min 1.27 is greater than max 0.3048");
}

TEST(RobotFile, RejectsTheWrongNumberOfJoints) {
  const std::string full = robot_text("", "");
  const std::string text = full.substr(0, full.rfind("[[joints]]"));  // five joints
  try {
    tools::parse_robot(text, "robot.toml");
    ADD_FAILURE() << "five joints accepted";
  } catch (const network::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("exactly 6 [[joints]] entries, found 5"),
              std::string::npos)
        << error.what();
    EXPECT_GT(error.where().line, 0) << error.what();
  }
}

TEST(RobotFile, RejectsAMissingKeyAndABadJointType) {
  const std::string missing = robot_text("inertia = [0.108, 0.018, 0.100]\n", "");
  // Reported at the [[joints]] header of the second joint.
  const std::size_t header = missing.rfind("[[joints]]", missing.find("mass = 5.01"));
  const int header_line =
      1 + static_cast<int>(
              std::count(missing.begin(), missing.begin() + static_cast<long>(header), '\n'));
  expect_error(missing, header_line, "joints[2] is missing the key 'inertia'");
  const std::string bad_type = robot_text("type = \"prismatic\"", "type = \"sliding\"");
  expect_error(bad_type, line_of(bad_type, "sliding"), "\"revolute\" or \"prismatic\"");
}

TEST(RobotFile, RejectsSyntaxErrorsAndUnopenableFiles) {
  const std::string text = robot_text("mass = 0.63", "mass = = 0.63");
  expect_error(text, line_of(text, "mass = = 0.63"), "");
  EXPECT_THROW(tools::load_robot("/nonexistent/robot.toml"), network::ConfigError);
}

// No rigid body has a principal moment above the sum of the other two: the error says how to fix
// the file, and how to keep a published data set that has such values.
TEST(RobotFile, TriangleInequalityErrorSaysHowToFixIt) {
  const std::string text =
      robot_text("inertia = [0.276, 0.255, 0.071]", "inertia = [0.0, 0.35, 0.0]");
  expect_error(text, line_of(text, "inertia = [0.0, 0.35, 0.0]"),
               "joints[1].inertia: Iy = 0.35 exceeds the sum of the other two moments");
  expect_error(text, line_of(text, "inertia = [0.0, 0.35, 0.0]"), "(Ixx, Iyy, Izz");
  expect_error(text, line_of(text, "inertia = [0.0, 0.35, 0.0]"), "triangle_inequality = false");
}

TEST(RobotFile, TheTriangleInequalityOptOutNeedsANoteAndKeepsTheData) {
  const std::string broken =
      robot_text("inertia = [0.276, 0.255, 0.071]", "inertia = [0.0, 0.35, 0.0]");
  // Without a note the opt-out itself is the error, at its line.
  const std::string opt_out = "triangle_inequality = false\n" + broken;
  expect_error(opt_out, 1, "needs triangle_inequality_note");
  const std::string noted =
      "triangle_inequality = false\ntriangle_inequality_note = \"published data\"\n" + broken;
  const RobotModel model = tools::parse_robot(noted, "robot.toml");
  EXPECT_DOUBLE_EQ(model.joints[0].link.inertia.y(), 0.35);
  // A note without the opt-out is a mistake too.
  expect_error("triangle_inequality_note = \"x\"\n" + robot_text("", ""), 1,
               "without triangle_inequality = false");
}

// The shipped PUMA 560 file is Corke's published data set, kept with the opt-out: link 1's moments
// as the toolbox gives them (0, 0.35, 0).
TEST(RobotFile, LoadsThePublishedPuma560) {
  const RobotModel model =
      tools::load_robot(test_paths::source_dir() + "/configs/robots/puma560.toml");
  EXPECT_EQ(model.name, "Puma 560");
  EXPECT_EQ(model.joints[0].link.inertia, Eigen::Vector3d(0, 0.35, 0));
  EXPECT_DOUBLE_EQ(model.joints[1].dh.a, 0.4318);
  EXPECT_DOUBLE_EQ(model.joints[2].dh.d, 0.15005);
}

}  // namespace
}  // namespace dynamics
