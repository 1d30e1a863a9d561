// Level 4 (L4): takes the rows of U from L3, one per step, back-substitutes and has q̈ -- the end
// of Tp; serving until finish, it sends q̈ to the client. A process of the SDK (t800sim::Process):
// its channels are typed, each message a header word and a row in one communication
// (Messages::Packet), a stop told by the header word's flags.
#pragma once

#include "workloads/pipeline/levels/context.hpp"

namespace workloads::levels {

template <class T>
class Level4 {
 public:
  explicit Level4(const Context<T>& context) : c_(context) {}
  // One system; false when the pipeline stops (finish, or a failure).
  bool round(t800sim::Process& p);
  // Its channels, given when its process starts.
  void attach(Ends ends) { ends_ = std::move(ends); }

 private:
  using M = Messages<T>;
  Context<T> c_;
  Ends ends_;  // from L3; to the client when serving until finish
};

extern template class Level4<float>;
extern template class Level4<double>;

}  // namespace workloads::levels
