// The ray-tracer farm (programs/raytrace, configs/scenes/raytrace-farm.toml): whatever the network
// and the number of workers, the image is the one a plain sequential trace computes, every line is
// traced once, and the farm's time is bounded by its own compute as a farm's must be.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "programs/raytrace/scene.hpp"

namespace {

nlohmann::json farm(const std::string& family, int workers, const std::string& extra = "") {
  const auto o =
      cli_test::run("run configs/scenes/raytrace-farm.toml --json --set network.family=" + family +
                    " --set network.workers=" + std::to_string(workers) + extra);
  EXPECT_EQ(o.exit_code, 0) << o.out.substr(0, 2000);
  return nlohmann::json::parse(o.out);
}

// FNV-1a (64 bit) over the bytes of the image's floats, red plane, green plane, then blue, line by
// line: the checksum the program reports, computed here from a sequential trace in plain float.
std::string sequential_checksum(int width, int height, int reflections) {
  std::vector<float> image(std::size_t(3 * width * height));
  for (int line = 0; line < height; ++line) {
    const std::vector<float> rgb = raytrace::trace_line<float>(line, width, height, reflections);
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

TEST(RaytraceFarm, TheImageIsTheSequentialTraceOnAnyNetwork) {
  const std::string expected = sequential_checksum(64, 64, 2);
  for (const auto& [family, workers] :
       std::vector<std::pair<std::string, int>>{{"tree", 1}, {"tree", 5}, {"chain", 7}}) {
    const nlohmann::json w = farm(family, workers)["workload"];
    EXPECT_EQ(w["image_checksum"], expected) << family << " " << workers;
    int lines = 0;
    for (const auto& worker : w["per_worker"]) lines += worker["lines"].get<int>();
    EXPECT_EQ(lines, 64) << family << " " << workers;
  }
}

// A farm cannot beat its work shared out evenly, and one worker cannot finish before its own work;
// adding workers to a tree must help while lines outnumber them.
TEST(RaytraceFarm, TimeIsBoundedByTheWorkAndFallsWithWorkers) {
  double previous = 0;
  for (int workers : {1, 4, 16}) {
    const nlohmann::json w = farm("tree", workers)["workload"];
    const double tp = w["tp_us"].get<double>(), compute = w["compute_us"].get<double>();
    EXPECT_GE(tp, compute / workers) << workers;
    if (workers == 1) EXPECT_GT(tp, compute);
    if (previous > 0) EXPECT_LT(tp, previous) << workers;
    previous = tp;
    for (const auto& worker : w["per_worker"]) EXPECT_GT(worker["lines"].get<int>(), 0);
  }
}

// Variable work per line is what makes an on-demand master worth having.
TEST(RaytraceFarm, LinesCostDifferentAmounts) {
  const nlohmann::json w = farm("tree", 1)["workload"];
  EXPECT_GT(w["line_cycles_max"].get<double>(), 1.5 * w["line_cycles_min"].get<double>());
}

// Through the chain every line and result crosses more links than through the tree.
TEST(RaytraceFarm, AChainIsSlowerThanATreeOfTheSameWorkers) {
  EXPECT_GT(farm("chain", 16)["workload"]["tp_us"].get<double>(),
            farm("tree", 16)["workload"]["tp_us"].get<double>());
}

TEST(RaytraceFarm, PrecisionIsStatedAndUsed) {
  const nlohmann::json r32 = farm("tree", 3),
                       r64 = farm("tree", 3, " --set workload.precision=real64");
  EXPECT_EQ(r32["setting"]["precision"]["value"], "real32");
  EXPECT_EQ(r64["setting"]["precision"]["value"], "real64");
  // REAL64 arithmetic takes the FPU longer (datasheet: fpmul 18 vs 11 cycles, fpdiv 31 vs 16).
  EXPECT_GT(r64["workload"]["line_cycles_max"].get<double>(),
            r32["workload"]["line_cycles_max"].get<double>());
}

}  // namespace
