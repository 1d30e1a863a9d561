#include "workloads/run/thrown.hpp"

#include <cxxabi.h>

#include <cstdlib>
#include <memory>
#include <typeinfo>

namespace workloads {

namespace {

std::string demangled(const std::type_info* type) {
  if (!type) return "an exception of unknown type";
  int status = 0;
  const std::unique_ptr<char, void (*)(void*)> name(
      abi::__cxa_demangle(type->name(), nullptr, nullptr, &status), std::free);
  return status == 0 && name ? name.get() : type->name();
}

}  // namespace

std::string describe_thrown(const std::exception_ptr& thrown) {
  try {
    std::rethrow_exception(thrown);
  } catch (const std::exception& e) {
    return demangled(&typeid(e)) + ": " + e.what();
  } catch (...) {
    // The type of the exception being handled: C++ itself has no way to name it (libstdc++'s ABI).
    return demangled(abi::__cxa_current_exception_type()) + " (not a std::exception)";
  }
}

}  // namespace workloads
