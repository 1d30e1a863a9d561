// An sc_event made on first use. Every event made while the network is elaborated costs SystemC a
// generated unique name and an entry in its registry of objects -- a fifth of a 1023-worker farm's
// set-up -- and most of a process's or a channel's events are never used: a direct channel waits on
// its link, not on its own events, and a process nobody joins is never waited for.
//
// Every wait on such an event is in a loop that tests its condition first, and every notification
// follows the change it announces, so a notification before the event is made -- nobody can be
// waiting on it -- is dropped without changing what anyone does.
#pragma once

#include <memory>

#include <systemc>

namespace network {

class LazyEvent {
 public:
  sc_core::sc_event& get() {
    if (!event_) event_ = std::make_unique<sc_core::sc_event>();
    return *event_;
  }
  // notify(SC_ZERO_TIME), where anyone could be waiting.
  void notify_delta() {
    if (event_) event_->notify(sc_core::SC_ZERO_TIME);
  }

 private:
  std::unique_ptr<sc_core::sc_event> event_;
};

}  // namespace network
