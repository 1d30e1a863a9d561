#include "workloads/integration/integrators.hpp"

namespace integration {

const char* to_string(Method method) {
  return method == Method::rk4 ? "rk4" : "semi-implicit-euler";
}

std::optional<Method> parse_method(std::string_view text) {
  if (text == "rk4") return Method::rk4;
  if (text == "semi-implicit-euler") return Method::semi_implicit_euler;
  return std::nullopt;
}

int evaluations_per_step(Method method) {
  return method == Method::rk4 ? 4 : 1;
}

}  // namespace integration
