// A kernel's code can load what the kernel declares, compute what it computes, and hold constants;
// a value made in another kernel's recording, or before any, is none of these, so reading it or
// storing it there is an error naming the kernels, the value's C++ type and the array stored into,
// never a silent constant (issue 25, item 3). A body that throws is reported with its kernel's name
// and the exception's message.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "t800sim/kernel.hpp"

namespace {

using t800::codegen::KernelError;
using t800sim::Real32;
using t800sim::Real64;

template <class S>
S product_recorded_in(const std::string& kernel) {
  S carried;
  t800sim::record_kernel<S>(kernel, [&] {
    std::vector<S> x(2, S(3));
    t800sim::declare(x, "x");
    carried = x[0] * x[1];
  });
  return carried;
}

std::string kernel_error_of(const std::function<void()>& record) {
  try {
    record();
  } catch (const KernelError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(KernelErrors, AValueOfAnotherKernelReadIsAnErrorNamingBothKernelsAndItsType) {
  const Real64 carried = product_recorded_in<Real64>("producer");
  const std::string message = kernel_error_of([&] {
    t800sim::record_kernel<Real64>("consumer", [&] {
      Real64 y = 2.0;
      t800sim::declare_variable(y, "y");
      y = y + carried;
    });
  });
  EXPECT_NE(message.find("kernel \"consumer\" reads"), std::string::npos) << message;
  EXPECT_NE(message.find("kernel \"producer\""), std::string::npos) << message;
  EXPECT_NE(message.find("Real64"), std::string::npos) << message;
  EXPECT_NE(message.find("declare"), std::string::npos) << message;  // what would be valid
}

TEST(KernelErrors, AValueOfAnotherKernelStoredNamesTheArray) {
  const Real32 carried = product_recorded_in<Real32>("producer32");
  const std::string message = kernel_error_of([&] {
    t800sim::record_kernel<Real32>("storer", [&] {
      std::vector<Real32> out(1);
      t800sim::declare(out, "out");
      out[0] = carried;
    });
  });
  EXPECT_NE(message.find("kernel \"storer\" stores into out"), std::string::npos) << message;
  EXPECT_NE(message.find("kernel \"producer32\""), std::string::npos) << message;
  EXPECT_NE(message.find("Real32"), std::string::npos) << message;
}

TEST(KernelErrors, AValueMadeBeforeTheKernelIsAnErrorUntilDeclared) {
  std::vector<Real64> x(4, Real64(1.0));  // made before any recording
  const std::string message = kernel_error_of([&] {
    t800sim::record_kernel<Real64>("undeclared", [&] {
      Real64 s = 0.0;
      t800sim::declare_variable(s, "s");
      s = s + x[2];
    });
  });
  EXPECT_NE(message.find("kernel \"undeclared\" reads"), std::string::npos) << message;
  EXPECT_NE(message.find("made before the kernel was recorded"), std::string::npos) << message;
  // Declared, the same array is data the PROC is given.
  EXPECT_NO_THROW(t800sim::record_kernel<Real64>("declared", [&] {
    t800sim::declare(x, "x");
    Real64 s = 0.0;
    t800sim::declare_variable(s, "s");
    s = s + x[2];
  }));
}

TEST(KernelErrors, ItsOwnValuesAndConstantsAreNoError) {
  EXPECT_NO_THROW(t800sim::record_kernel<Real64>("own", [] {
    std::vector<Real64> x(2, Real64(1.5));
    t800sim::declare(x, "x");
    const Real64 sum = x[0] + x[1];
    x[1] = sum * 2.0;  // a literal is a constant of the code
  }));
}

TEST(KernelErrors, ABodyThatThrowsIsReportedWithTheKernelsNameAndMessage) {
  const std::string message = kernel_error_of([] {
    t800sim::record_kernel<Real32>("daxpy", [] { throw std::runtime_error("n must be even"); });
  });
  EXPECT_EQ(message, "kernel \"daxpy\" failed while it was recorded: n must be even");
}

}  // namespace
