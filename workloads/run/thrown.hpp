// What was thrown, in words, for messages about code t800sim did not write -- a plugin's static
// initialiser, a program's build(), a process's body -- which may throw anything, not only a
// std::exception.
#pragma once

#include <exception>
#include <string>

namespace workloads {

// "std::runtime_error: the message"; for what is not a std::exception, its type alone: "int (not
// a std::exception)".
std::string describe_thrown(const std::exception_ptr& thrown);

}  // namespace workloads
