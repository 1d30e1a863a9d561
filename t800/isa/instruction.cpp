#include "t800/isa/instruction.hpp"

namespace t800::isa {

std::string assembly(const Instruction& instruction) {
  std::string text(mnemonic(instruction.op));
  if (info(instruction.op).encoding == Encoding::direct)
    text += " " + std::to_string(instruction.operand);
  return text;
}

}  // namespace t800::isa
