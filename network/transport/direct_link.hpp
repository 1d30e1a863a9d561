// A direct channel: its ends on neighbouring transputers, alone on that link direction. The bytes
// move by DMA while the CPUs do other work; OutputOrFail and InputOrFail can give up either way.
#pragma once

#include "network/channel.hpp"
#include "t800/link.hpp"

namespace network {

class DirectLink final : public Transport {
 public:
  // `writer_end`: the writer's end of `link`.
  DirectLink(Channel& channel, t800::Link& link, int writer_end)
      : channel_(channel), link_(link), writer_end_(writer_end) {}

  void send(Process& writer, t800::Message m) override;
  t800::Message receive(Process& reader) override;
  bool send_or_fail(Process& writer, t800::Message m, double deadline_us) override;
  std::optional<t800::Message> receive_or_fail(Process& reader, double deadline_us) override;
  bool input_ready() const override { return link_.input_pending(reader_end()); }
  void watch(Process& alter, sc_core::sc_event_or_list& events) override;
  void unwatch(Process&) override {}
  const char* kind_name() const override { return "direct"; }

 private:
  int reader_end() const { return 1 - writer_end_; }

  Channel& channel_;
  t800::Link& link_;
  int writer_end_;
};

}  // namespace network
