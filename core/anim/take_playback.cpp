#include "anim/take_playback.h"

#include "embed/deformation_gradients.h"

namespace sculpt {

void playbackFrame(const Take& take, uint32_t frame, SceneFrame& out) {
  const SceneSurfaceMap& surface = *take.segments()[take.segmentOf(frame)].surface;
  const SceneGeometry& g = surface.geometry();
  take.controlPoints(frame, out.control);
  surface.cellNodes(out.control, out.nodes);
  applyNodeGradientStencil(g.gradientStencil(kDefaultGradientScheme), out.nodes, out.gradients);
  out.sceneId = g.sceneId;
  const size_t cells = g.cellMesh.numCells();
  if (const CellFields* fields = take.fieldsAt(frame)) {
    out.cellYoungs = fields->youngs;
    out.cellDensity = fields->density;
    out.cellDamping = fields->damping;
  } else {
    out.cellYoungs.assign(cells, 0.0f);
    out.cellDensity.assign(cells, 0.0f);
    out.cellDamping.assign(cells, 0.0f);
  }
  out.cellStrainEnergy.assign(cells, 0.0f);
  out.simulatedTime = frame / take.fps();
  out.stepMs = 0.0;
  out.lastStep = StepReport{};
  out.physicsReady = true;
  out.springs.clear();
}

}  // namespace sculpt
