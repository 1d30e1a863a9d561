// Variables shared by the PAR branches of one process, and a branch waiting until they say it may
// go on. occam has no such thing (its branches share nothing they write) -- a program would put a
// buffer process between them and pay for its communications. Where a model keeps the data in
// place and the wait itself should cost nothing, a Shared stands for that buffer:
//
//   t800sim::Shared rows;   // owned by the process, outliving its PAR
//   std::size_t stored = 0;
//   p.par({[&](Process& q) { ...; ++stored; rows.notify(); },                 // the producer
//          [&](Process& q) { rows.wait_until(q, [&] { return stored > 0; }); ... }});
//
// A waiting branch gives up its processor (other processes run meanwhile) and takes it back, behind
// whatever is ready, once a notify() finds its condition true. Waiting and notifying take no
// simulated time of their own.
#pragma once

#include <functional>
#include <memory>

namespace t800sim {

class Process;

class Shared {
 public:
  Shared();
  ~Shared();
  Shared(const Shared&) = delete;
  Shared& operator=(const Shared&) = delete;

  // Returns at once when ready() holds; otherwise gives up the processor, looks again, and waits
  // for notify()s until it holds (looking once after each: no polling).
  void wait_until(Process& p, const std::function<bool()>& ready);
  // The shared variables changed: the waiting branches look at their conditions again (in the same
  // instant of simulated time, once the notifying branch lets them).
  void notify();

 private:
  struct Event;
  std::unique_ptr<Event> changed_;
};

}  // namespace t800sim
