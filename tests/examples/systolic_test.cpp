// The systolic matrix product (programs/systolic, configs/scenes/systolic-matmul.toml): C is the
// product a plain sequential loop computes, on any network; the overlap of links and FPU shows in
// the time as the link protocol and the grid's schedule say it must.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "../cli/cli_fixtures.hpp"
#include "programs/systolic/block_product.hpp"
#include "tests/test_paths.hpp"

namespace {

nlohmann::json product(const std::string& sets = "") {
  const auto o = cli_test::run("run configs/scenes/systolic-matmul.toml --json" + sets);
  EXPECT_EQ(o.exit_code, 0) << o.out.substr(0, 2000);
  return nlohmann::json::parse(o.out);
}

// C = A.B by the textbook loop in float, each element summed over k in order, hashed (FNV-1a, 64
// bit) over its bytes row by row.
std::string sequential_product_checksum(std::size_t n) {
  const std::vector<float> a = systolic::matrix(n, 1), b = systolic::matrix(n, 2);
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      float c = 0;
      for (std::size_t k = 0; k < n; ++k) c = c + a[i * n + k] * b[k * n + j];
      unsigned char bytes[4];
      std::memcpy(bytes, &c, 4);
      for (unsigned char byte : bytes) h = (h ^ byte) * 1099511628211ull;
    }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

TEST(SystolicMatmul, CIsTheSequentialProductOnAnyNetwork) {
  const std::string expected = sequential_product_checksum(32);
  const nlohmann::json mesh = product()["workload"];
  EXPECT_EQ(mesh["c_checksum"], expected);
  EXPECT_LT(mesh["max_abs_error"].get<double>(), 1e-5);       // against double precision (Eigen)
  EXPECT_EQ(mesh["channels_on_one_link"], mesh["channels"]);  // the mesh is the grid
  // On a chain most grid neighbours are not linked: routed, slower, the same C.
  const nlohmann::json chain = product(" --set network.family=chain")["workload"];
  EXPECT_EQ(chain["c_checksum"], expected);
  EXPECT_LT(chain["channels_on_one_link"].get<int>(), chain["channels"].get<int>());
  EXPECT_GT(chain["tp_us"].get<double>(), mesh["tp_us"].get<double>());
}

// Every cell multiplies `grid` blocks on one CPU, so no schedule beats grid block steps. Without
// the overlap an interior cell also takes in two blocks per step, one after the other, and a byte
// crosses a link in at least 11 bit times (a data packet; 0.55 us at 20 Mbit/s), so each step costs
// at least the multiply plus 2 x 256 bytes x 0.55 us.
TEST(SystolicMatmul, OverlapHidesTheLinksAndTheBoundsHold) {
  const nlohmann::json on = product(), off = product(" --set workload.overlap=false");
  const int grid = on["workload"]["grid"];
  const double cycle_us = 0.05;  // T800-20
  const double step_us = on["workload"]["block_step_cycles"].get<double>() * cycle_us;
  const double transfer_us = on["workload"]["block_bytes"].get<double>() * 11 / 20.0;
  const double t_on = on["workload"]["tp_us"], t_off = off["workload"]["tp_us"];
  EXPECT_GE(t_on, grid * step_us);
  EXPECT_GE(t_off, grid * (step_us + 2 * transfer_us));
  EXPECT_LT(t_on, t_off);
  EXPECT_EQ(on["workload"]["c_checksum"], off["workload"]["c_checksum"]);
}

// workload.output_csv: C as the program's table, written by t800sim -- every element the textbook
// loop's float, read back exactly.
TEST(SystolicMatmul, TheCsvHoldsC) {
  const std::size_t n = 32;
  const std::string path = test_paths::binary_dir() + "/systolic-c.csv";
  std::remove(path.c_str());
  product(" --set workload.output_csv=" + path);
  std::ifstream csv(path);
  std::string line;
  ASSERT_TRUE(std::getline(csv, line)) << path;
  EXPECT_EQ(line.rfind("c1,c2,", 0), 0u) << line;
  const std::vector<float> a = systolic::matrix(n, 1), b = systolic::matrix(n, 2);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_TRUE(std::getline(csv, line)) << "row " << i;
    std::stringstream cells(line);
    std::string cell;
    for (std::size_t j = 0; j < n; ++j) {
      ASSERT_TRUE(std::getline(cells, cell, ',')) << "row " << i << " column " << j;
      float c = 0;
      for (std::size_t k = 0; k < n; ++k) c = c + a[i * n + k] * b[k * n + j];
      EXPECT_EQ(std::stod(cell), double(c)) << "C(" << i << ", " << j << ")";
    }
    EXPECT_FALSE(std::getline(cells, cell)) << "row " << i << " has more than " << n << " columns";
  }
  EXPECT_FALSE(std::getline(csv, line)) << "more than " << n << " rows";
}

TEST(SystolicMatmul, AGridLargerThanTheNetworkIsAnError) {
  const auto o =
      cli_test::run("run configs/scenes/systolic-matmul.toml --set workload.grid=5 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("--set workload.grid=5"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("needs 25 processors"), std::string::npos) << o.out;
}

}  // namespace
