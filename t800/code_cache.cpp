#include "t800/code_cache.hpp"

namespace t800 {

const codegen::CodeUnit& CodeCache::unit(const std::shared_ptr<const codegen::Recording>& kernel,
                                         const codegen::Target& target) {
  const auto key = std::make_tuple(kernel.get(), target.fpu, target.checked, target.notes);
  auto found = units_.find(key);
  if (found == units_.end())
    found = units_.emplace(key, Compiled{kernel, codegen::generate(*kernel, target)}).first;
  return found->second.unit;
}

}  // namespace t800
