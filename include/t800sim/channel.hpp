// Channels as a program declares them (t800sim/program.hpp): typed by their protocol, resolved to
// the simulator's channels when the program is placed on a network. A process outputs on an
// Out<P> and inputs from an In<P>; a Chan<P> is both ends of one channel, the way occam's CHAN is
// passed to the two processes it connects.
#pragma once

#include <string>
#include <vector>

#include "t800sim/protocol.hpp"

namespace network {
struct Channel;
}

namespace t800sim {

namespace detail {
// A declared channel: its name and protocol, the processes at its ends, and (once the program is
// placed) the simulator's channel. Owned by the program's Builder.
struct ChannelSlot {
  std::string name, protocol;
  std::string writer, reader;  // process names; empty while only one end is declared
  // Channel i of an array of `array` channels: an end named after a group of `array` processes is
  // joined to its member i (resolved when the program is placed: groups may be declared later).
  int index = -1, array = 0;
  network::Channel* impl = nullptr;
};
}  // namespace detail

template <class P>
class Out {
 public:
  using protocol_type = P;
  Out() = default;
  explicit Out(detail::ChannelSlot* slot) : slot_(slot) {}
  const std::string& name() const { return slot_->name; }
  detail::ChannelSlot* slot() const { return slot_; }

 private:
  detail::ChannelSlot* slot_ = nullptr;
};

template <class P>
class In {
 public:
  using protocol_type = P;
  In() = default;
  explicit In(detail::ChannelSlot* slot) : slot_(slot) {}
  const std::string& name() const { return slot_->name; }
  detail::ChannelSlot* slot() const { return slot_; }

 private:
  detail::ChannelSlot* slot_ = nullptr;
};

template <class P>
class Chan {
 public:
  using protocol_type = P;
  Chan() = default;
  explicit Chan(detail::ChannelSlot* slot) : slot_(slot) {}
  operator Out<P>() const { return Out<P>(slot_); }  // NOLINT(google-explicit-constructor)
  operator In<P>() const { return In<P>(slot_); }    // NOLINT(google-explicit-constructor)
  Out<P> out() const { return Out<P>(slot_); }
  In<P> in() const { return In<P>(slot_); }
  const std::string& name() const { return slot_->name; }
  detail::ChannelSlot* slot() const { return slot_; }

 private:
  detail::ChannelSlot* slot_ = nullptr;
};

// occam's channel arrays ([n]CHAN OF P).
template <class P>
using Chans = std::vector<Chan<P>>;

}  // namespace t800sim
