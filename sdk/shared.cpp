#include "t800sim/shared.hpp"

#include <systemc>

#include "network/process.hpp"
#include "t800sim/process.hpp"

namespace t800sim {

struct Shared::Event {
  sc_core::sc_event event;
};

Shared::Shared() : changed_(std::make_unique<Event>()) {}
Shared::~Shared() = default;

void Shared::wait_until(Process& p, const std::function<bool()>& ready) {
  if (ready()) return;
  network::Process& impl = p.impl();
  impl.deschedule();
  while (!ready()) sc_core::wait(changed_->event);
  impl.reschedule();
}

void Shared::notify() {
  changed_->event.notify(sc_core::SC_ZERO_TIME);
}

}  // namespace t800sim
