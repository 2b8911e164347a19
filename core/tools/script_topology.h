#pragma once
// The topology events of a session script (session_script.h) edit the control mesh, so they
// cannot run on a simulation that already exists: they all have t = 0 and are applied, in file
// order, to the control mesh the model is then built from. The simulation therefore starts from
// the edited rest shape, and paint and pin events later in the script act on the edited solid.

#include "mesh/cell_complex.h"
#include "tools/session_script.h"

namespace sculpt {

/// Whether the script edits the control mesh (has topology events).
bool hasTopologyEvents(const SessionScript& script);

/// Applies the script's topology events to `mesh` in file order and removes them from the script
/// (what remains can be given to ScriptPlayer). Throws std::invalid_argument naming the event,
/// e.g. "events[0] (topology extrude): face 0 of cell 13 is not on the boundary.", leaving the
/// script unchanged. With simulationLevel >= 0 (0: trilinear elements on the edited mesh), each
/// event is also refused, the same way, once the mesh it leaves could not be simulated at that
/// level in the memory available (subdiv/refinement_cost.h): a few whole-mesh subdivisions
/// multiply the cells by 8 each, and the next event never runs.
CellComplex applyTopologyEvents(const CellComplex& mesh, SessionScript& script,
                                int simulationLevel = -1);

}  // namespace sculpt
