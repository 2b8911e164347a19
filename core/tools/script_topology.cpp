#include "tools/script_topology.h"

#include <algorithm>
#include <stdexcept>
#include <variant>

#include "mesh/topology.h"
#include "subdiv/refinement_cost.h"

namespace sculpt {

bool hasTopologyEvents(const SessionScript& script) {
  return std::any_of(script.events.begin(), script.events.end(), [](const ScriptEvent& event) {
    return std::holds_alternative<TopologyEvent>(event.action);
  });
}

CellComplex applyTopologyEvents(const CellComplex& mesh, SessionScript& script,
                                int simulationLevel) {
  CellComplex edited = mesh;
  std::vector<ScriptEvent> remaining;
  for (const ScriptEvent& event : script.events) {
    const auto* topology = std::get_if<TopologyEvent>(&event.action);
    if (!topology) {
      remaining.push_back(event);
      continue;
    }
    const std::string name = "events[" + std::to_string(event.index) + "] (topology " +
                             topologyOpName(topology->op) + "): ";
    try {
      edited = applyTopologyOperation(edited, *topology).mesh;
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + e.what());
    }
    if (simulationLevel < 0) continue;
    const std::string editedName =
        "the edited mesh (" + std::to_string(edited.numCells()) + " cells)";
    const std::string refusal =
        refinementRefusal(buildTopology(edited), simulationLevel, editedName, kSimulation);
    if (!refusal.empty()) throw std::invalid_argument(name + refusal);
  }
  script.events = std::move(remaining);
  return edited;
}

}  // namespace sculpt
