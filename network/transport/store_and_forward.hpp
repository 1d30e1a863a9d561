// A routed channel: any pair of ends that is not internal or direct (not neighbours, or a link
// direction shared by several channels). The writer sends the message, with the routers' header
// ahead of it (t800::RouteHeader), to the first transputer on the channel's path; a software
// router on every transputer the message enters takes it off the link and sends it on, or, at the
// reader's transputer, leaves it in the channel's mailbox.
//
// OutputOrFail gives up if the first hop has not taken the message by the deadline, and the
// routers forward it with the same deadline (network/reliable.hpp); InputOrFail gives up if no
// message is in the mailbox by its deadline.
#pragma once

#include <cstdint>
#include <list>
#include <vector>

#include "network/channel.hpp"
#include "network/lazy_event.hpp"
#include "t800/link.hpp"

namespace network {

// The routers' header on every routed message: destination channel and length, two words (U).
constexpr std::int64_t kRouteHeaderBytes = 8;

class StoreAndForward final : public Transport {
 public:
  // A link and the end a message leaves by.
  struct Hop {
    t800::Link* link = nullptr;
    int end = 0;
  };
  // hops[i]: from the channel's path[i] to path[i + 1].
  StoreAndForward(Channel& channel, std::vector<Hop> hops)
      : channel_(channel), hops_(std::move(hops)) {}

  void send(Process& writer, t800::Message m) override;
  t800::Message receive(Process& reader) override;
  bool send_or_fail(Process& writer, t800::Message m, double deadline_us) override;
  std::optional<t800::Message> receive_or_fail(Process& reader, double deadline_us) override;
  bool input_ready() const override { return !mailbox_.empty(); }
  void watch(Process& alter, sc_core::sc_event_or_list& events) override;
  void unwatch(Process&) override {}
  const char* kind_name() const override { return "routed"; }

  // What the router on `node` does with a message of this channel it took off a link.
  void pass_on(Process& router, int node, t800::Message m);

 private:
  t800::Message with_header(t800::Message m, double deadline_us) const;
  void deliver(Process& router, t800::Message m);
  t800::Message take_mail();
  std::optional<t800::Message> mail_by(const sc_core::sc_time& deadline);  // nullopt: none came

  Channel& channel_;
  std::vector<Hop> hops_;
  // Messages delivered by the reader's router, waiting for the reader (a list: an empty one
  // allocates nothing, t800/link.hpp).
  std::list<t800::Message> mailbox_;
  LazyEvent mail_;
};

}  // namespace network
