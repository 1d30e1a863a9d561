#include "network/channel.hpp"

#include "network/process.hpp"

namespace network {

void LastUser::set(Process& p) {
  process = &p;
  incarnation = p.incarnation();
}

bool LastUser::is(const Process& p) const {
  return process == &p && incarnation == p.incarnation();
}

bool LastUser::ended() const {
  return process->incarnation() != incarnation || process->ended();
}

}  // namespace network
