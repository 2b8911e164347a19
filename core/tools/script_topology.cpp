#include "tools/script_topology.h"

#include <stdexcept>

namespace sculpt {

CellComplex applyTopologyEvents(const CellComplex& mesh, SessionScript& script) {
  CellComplex edited = mesh;
  std::vector<ScriptEvent> remaining;
  for (const ScriptEvent& event : script.events) {
    const auto* topology = std::get_if<TopologyEvent>(&event.action);
    if (!topology) {
      remaining.push_back(event);
      continue;
    }
    try {
      edited = applyTopologyOperation(edited, *topology).mesh;
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("events[" + std::to_string(event.index) + "] (topology " +
                                  topologyOpName(topology->op) + "): " + e.what());
    }
  }
  script.events = std::move(remaining);
  return edited;
}

}  // namespace sculpt
