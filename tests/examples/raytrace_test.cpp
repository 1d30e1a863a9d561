// The ray-tracer farm (programs/raytrace, configs/scenes/raytrace-farm.toml): whatever the network
// and the number of workers, the image is the one a plain sequential trace computes and every line
// is traced once; the on-demand master gives more lines to faster workers; the farm's time is
// bounded by its own compute as a farm's must be.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "programs/raytrace/scene.hpp"
#include "tests/test_paths.hpp"

namespace {

nlohmann::json run_json(const std::string& args) {
  const auto o = cli_test::run("run " + args + " --json");
  EXPECT_EQ(o.exit_code, 0) << o.out.substr(0, 2000);
  return nlohmann::json::parse(o.out);
}

nlohmann::json farm(const std::string& family, int workers, const std::string& extra = "") {
  return run_json("configs/scenes/raytrace-farm.toml --set network.family=" + family +
                  " --set network.workers=" + std::to_string(workers) + extra);
}

// FNV-1a (64 bit) over the bytes of the image's floats, red plane, green plane, then blue, line by
// line: the checksum the program reports, computed here from a sequential trace in plain float (or
// double, its colours rounded to float as they travel).
template <class Scalar = float>
std::string sequential_image_checksum(int width, int height, int reflections) {
  std::vector<float> image(std::size_t(3 * width * height));
  for (int line = 0; line < height; ++line) {
    const std::vector<float> rgb = raytrace::trace_line<Scalar>(line, width, height, reflections);
    for (int colour = 0; colour < 3; ++colour)
      for (int x = 0; x < width; ++x)
        image[std::size_t((colour * height + line) * width + x)] =
            rgb[std::size_t(colour * width + x)];
  }
  std::uint64_t h = 14695981039346656037ull;
  for (float v : image) {
    unsigned char bytes[4];
    std::memcpy(bytes, &v, 4);  // little-endian host: the bytes in the order the program hashes
    for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

int lines_traced(const nlohmann::json& workload) {
  int lines = 0;
  for (const auto& worker : workload["per_worker"]) lines += worker["lines"].get<int>();
  return lines;
}

// Every worker count the issue asks for, on a tree and on a chain: a smaller image (40 lines of
// 16 pixels) keeps the 32 runs short; at 16 workers some take 2 lines and some 3.
TEST(RaytraceFarm, TheImageIsTheSequentialTraceAtEveryWorkerCountOnATreeAndAChain) {
  const std::string expected = sequential_image_checksum(16, 40, 2);
  for (const std::string family : {"tree", "chain"})
    for (int workers = 1; workers <= 16; ++workers) {
      const nlohmann::json w =
          farm(family, workers, " --set workload.width=16 --set workload.height=40")["workload"];
      EXPECT_EQ(w["image_checksum"], expected) << family << " " << workers;
      EXPECT_EQ(lines_traced(w), 40) << family << " " << workers;
    }
}

// The full image, and fewer lines than workers (some workers get none).
TEST(RaytraceFarm, TheImageIsTheSequentialTraceAtFullSizeAndWithIdleWorkers) {
  const nlohmann::json full = farm("tree", 5)["workload"];
  EXPECT_EQ(full["image_checksum"], sequential_image_checksum(64, 64, 2));
  EXPECT_EQ(lines_traced(full), 64);
  const nlohmann::json few = farm("chain", 12, " --set workload.height=5")["workload"];
  EXPECT_EQ(few["image_checksum"], sequential_image_checksum(64, 5, 2));
  EXPECT_EQ(lines_traced(few), 5);
}

// Three workers on the master's links, one of them a T800-20 among T800-30s: on demand, lines go
// to whoever asks, so the slower worker traces fewer than either faster one (an equal share would
// give each 21 or 22 of the 64; by clock speed alone the T800-20 would take about 16 and the others
// 24 each).
TEST(RaytraceFarm, OnDemandASlowerWorkerTracesFewerLines) {
  const std::string path = testing::TempDir() + "raytrace-slow-worker.toml";
  std::ofstream(path) << R"(name = "raytrace-slow-worker"
[workload]
kind = "raytrace-farm"
[topology]
host = "P0.link0"
[[topology.processor]]
name = "P0"
type = "T800-30"
[[topology.processor]]
name = "P1"
type = "T800-30"
[[topology.processor]]
name = "P2"
type = "T800-20"
[[topology.processor]]
name = "P3"
type = "T800-30"
[[topology.link]]
from = "P0.link1"
to = "P1.link0"
[[topology.link]]
from = "P0.link2"
to = "P2.link0"
[[topology.link]]
from = "P0.link3"
to = "P3.link0"
)";
  const nlohmann::json w = run_json(path)["workload"];
  EXPECT_EQ(w["image_checksum"], sequential_image_checksum(64, 64, 2));
  std::map<std::string, int> lines;
  for (const auto& worker : w["per_worker"])
    lines[worker["processor"].get<std::string>()] = worker["lines"].get<int>();
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_LT(lines["P2"], lines["P1"]);
  EXPECT_LT(lines["P2"], lines["P3"]);
  EXPECT_EQ(lines["P1"] + lines["P2"] + lines["P3"], 64);
}

// A farm cannot beat its work shared out evenly, and one worker cannot finish before its own work;
// adding workers must help while lines outnumber them, on a tree and on a chain.
TEST(RaytraceFarm, TimeIsBoundedByTheWorkAndFallsWithWorkers) {
  for (const std::string family : {"tree", "chain"}) {
    double previous = 0;
    for (int workers : {1, 4, 16}) {
      const nlohmann::json w = farm(family, workers)["workload"];
      const double tp = w["tp_us"].get<double>(), compute = w["compute_us"].get<double>();
      EXPECT_GE(tp, compute / workers) << family << " " << workers;
      if (workers == 1) {
        EXPECT_GT(tp, compute);
      }
      if (previous > 0) {
        EXPECT_LT(tp, previous) << family << " " << workers;
      }
      previous = tp;
      for (const auto& worker : w["per_worker"]) EXPECT_GT(worker["lines"].get<int>(), 0);
    }
  }
}

// Variable work per line is what makes an on-demand master worth having.
TEST(RaytraceFarm, LinesCostDifferentAmounts) {
  const nlohmann::json w = farm("tree", 1)["workload"];
  EXPECT_GT(w["line_cycles_max"].get<double>(), 1.5 * w["line_cycles_min"].get<double>());
}

// Through the chain most lines and results cross more links than through the tree.
TEST(RaytraceFarm, AChainIsSlowerThanATreeOfTheSameWorkers) {
  EXPECT_GT(farm("chain", 16)["workload"]["tp_us"].get<double>(),
            farm("tree", 16)["workload"]["tp_us"].get<double>());
}

TEST(RaytraceFarm, PrecisionIsStatedAndUsed) {
  const nlohmann::json r32 = farm("tree", 3),
                       r64 = farm("tree", 3, " --set workload.precision=real64");
  EXPECT_EQ(r32["setting"]["precision"]["value"], "real32");
  EXPECT_EQ(r64["setting"]["precision"]["value"], "real64");
  EXPECT_EQ(r64["workload"]["image_checksum"], sequential_image_checksum<double>(64, 64, 2));
  EXPECT_NE(r64["workload"]["image_checksum"], r32["workload"]["image_checksum"]);
  // REAL64 arithmetic takes the FPU longer (datasheet: fpmul 18 vs 11 cycles, fpdiv 31 vs 16).
  EXPECT_GT(r64["workload"]["line_cycles_max"].get<double>(),
            r32["workload"]["line_cycles_max"].get<double>());
}

TEST(RaytraceFarm, ANetworkWithoutAWorkerIsAnErrorNamingTheNetwork) {
  const std::string path = testing::TempDir() + "raytrace-single.toml";
  std::ofstream(path)
      << std::string("[network]\ntopology = \"") + test_paths::source_dir() +
             "/configs/topologies/single.toml\"\n[workload]\nkind = \"raytrace-farm\"\n";
  const auto o = cli_test::run("run " + path + " 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(
      o.out.find(path +
                 ":2:12: error: workload raytrace-farm: the farm needs a worker processor beside "
                 "the master's P0"),
      std::string::npos)
      << o.out;
}

}  // namespace
