// Subscripts a kernel computes (t800sim::at): the values are those of plain C++ indexing, the
// recording keeps each subscript as the INT expression it was, a subscript out of range or into
// an array the kernel did not declare is an error naming the kernel, and a constant subscript is
// the element itself.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "t800sim/kernel.hpp"

namespace {

using t800::codegen::KernelError;
using t800::codegen::NodeKind;
using t800sim::Int;
using t800sim::Real64;

std::string subscript_error(const std::function<void()>& body) {
  try {
    t800sim::record_kernel<Real64>("SUBSCRIPTS", body);
  } catch (const KernelError& e) {
    return e.what();
  }
  return "(no error)";
}

// The reference is the same loop on doubles and ints, indexed by C++.
TEST(ComputedSubscripts, GiveThePlainIndexingsNumbers) {
  const std::vector<int> perm{4, 2, 0, 3, 1};
  const std::vector<double> x0{1.5, -2.0, 0.25, 8.0, -0.5};
  std::vector<double> expect(5, 1.0);
  for (std::size_t i = 0; i < 5; ++i)
    expect[std::size_t(perm[i])] += 3.0 * x0[std::size_t(perm[(i + 2) % 5])];

  std::vector<Real64> x(x0.begin(), x0.end()), y(5, Real64(1.0));
  std::vector<Int> p;
  for (int v : perm) p.push_back(Int(v));
  Real64 a = 3.0;
  const t800sim::Kernel k = t800sim::record_kernel<Real64>("GATHER", [&] {
    t800sim::declare(x, "x");
    t800sim::declare(y, "y");
    t800sim::declare(p, "p");
    t800sim::declare_variable(a, "a");
    for (std::size_t i : t800sim::seq<Real64>(5)) {
      const Int next = (Int(std::int32_t(i)) + Int(2)) % Int(5);
      t800sim::at(y, p[i]) = t800sim::at(y, p[i]) + a * t800sim::at(x, t800sim::at(p, next));
    }
  });
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(y[i].value(), expect[i]) << i;

  // Every load and store of x and y carries its subscript: an INT node (a load of p's, for y).
  const auto& r = *k.work().code;
  std::vector<int> used;
  for (const auto& node : r.nodes())
    if (node.kind == NodeKind::load) used.push_back(node.access);
  for (const auto& event : r.events())
    if (event.kind == t800::codegen::EventKind::store) used.push_back(event.access);
  int subscripted = 0;
  for (int id : used) {
    const auto& access = r.accesses()[std::size_t(id)];
    const std::string& array = r.arrays()[std::size_t(access.array)].name;
    if (array == "x" || array == "y") {
      ASSERT_GE(access.subscript, 0) << array << "[" << access.index << "]";
      EXPECT_TRUE(r.nodes()[std::size_t(access.subscript)].integer);
      if (array == "y") EXPECT_EQ(r.nodes()[std::size_t(access.subscript)].kind, NodeKind::load);
      ++subscripted;
    }
  }
  EXPECT_EQ(subscripted, 5 * 3);  // y read, y written, x read in each of 5 iterations
}

TEST(ComputedSubscripts, WorkOnArraysAndOutsideARecording) {
  std::array<Int, 4> v{Int(7), Int(8), Int(9), Int(10)};
  Int k = 2;
  EXPECT_EQ(Int(t800sim::at(v, k)).value(), 9);  // no recording: plain indexing
  t800sim::at(v, k + Int(1)) = Int(-1);
  EXPECT_EQ(v[3].value(), -1);
}

TEST(ComputedSubscripts, OutOfRangeIsAnErrorNamingTheKernelAndTheArray) {
  const std::string e = subscript_error([] {
    std::vector<Real64> x(4, Real64(0.0));
    Int k = 3;
    t800sim::declare(x, "x");
    t800sim::declare_variable(k, "k");
    t800sim::at(x, k + Int(1)) = Real64(1.0);
  });
  EXPECT_NE(e.find("SUBSCRIPTS"), std::string::npos) << e;
  EXPECT_NE(e.find("subscript 4 of x is out of its range 0..3"), std::string::npos) << e;
}

TEST(ComputedSubscripts, IntoAnArrayTheKernelDidNotDeclareIsAnError) {
  const std::string e = subscript_error([] {
    std::vector<Real64> x(4, Real64(0.0));
    Int k = 1;
    t800sim::declare_variable(k, "k");
    t800sim::at(x, k) = Real64(1.0);
  });
  EXPECT_NE(e.find("SUBSCRIPTS"), std::string::npos) << e;
  EXPECT_NE(e.find("needs x declared whole"), std::string::npos) << e;
}

TEST(ComputedSubscripts, AConstantSubscriptIsTheElementItself) {
  std::vector<Real64> x(4, Real64(2.0));
  const t800sim::Kernel k = t800sim::record_kernel<Real64>("CONSTANT", [&] {
    t800sim::declare(x, "x");
    t800sim::at(x, Int(1)) = t800sim::at(x, Int(3)) * Real64(2.0);
  });
  EXPECT_EQ(x[1].value(), 4.0);
  for (const auto& access : k.work().code->accesses()) EXPECT_LT(access.subscript, 0);
  int loads = 0;
  for (const auto& node : k.work().code->nodes()) loads += node.kind == NodeKind::load;
  EXPECT_EQ(loads, 1);  // x[3], as the element itself
}

}  // namespace
