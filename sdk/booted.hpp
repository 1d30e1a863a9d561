// A program's booted processors (Builder::booted) and byte links (Builder::byte_link): checked
// against where the program's processes went, joined to their links, and run by the
// instruction-set simulator beside the program's processes (docs/iss.md, "Mixed networks").
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sdk/placement.hpp"
#include "t800sim/program.hpp"
#include "workloads/run/result_value.hpp"

namespace workloads::boot {
class BootSession;
class IssNode;
}  // namespace workloads::boot

namespace t800sim::detail {

class BootedProcessors {
 public:
  // Throws std::invalid_argument naming a processor the network does not have, or one booted twice.
  BootedProcessors(const std::string& kind, const Builder& builder,
                   const network::Topology& topology);
  ~BootedProcessors();
  BootedProcessors(BootedProcessors&&) noexcept;
  BootedProcessors& operator=(BootedProcessors&&) noexcept;

  // Throws std::invalid_argument for a process placed on a booted processor, a channel routed
  // through one, or a byte link that is not between its process and a booted neighbour.
  void join(network::Machine& machine, const std::vector<PlacedProcess>& placed);
  // An instruction-set simulator on each booted processor, waiting at reset.
  void spawn(network::Machine& machine);
  // Each booted processor: whether it was booted, its instructions and cycles, its state.
  workloads::ResultValue results() const;
  bool empty() const { return nodes_.empty(); }

 private:
  std::string kind_;
  const Builder* builder_;
  std::vector<int> nodes_;
  std::unique_ptr<workloads::boot::BootSession> session_;
  std::vector<std::unique_ptr<workloads::boot::IssNode>> iss_;
};

}  // namespace t800sim::detail
