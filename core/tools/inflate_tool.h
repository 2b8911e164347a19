#pragma once
// Inflate / deflate (docs/design/ux.md "Brushes", McDonnell-Qin section 4.1): a pressure on the
// boundary faces inside the brush sphere while the button is held. Positive pressure inflates,
// negative deflates (Ctrl in the window negates it). The sphere is in rest coordinates (the window
// maps its hit to the rest position through the material point), so the pressed faces stay the same
// while the solid moves. The tool keeps a reference to its simulator, which must outlive it.

#include <Eigen/Core>
#include <limits>

#include "sim/load_forms.h"
#include "sim/simulator.h"

namespace sculpt {

class InflateTool {
 public:
  explicit InflateTool(Simulator& simulator);
  ~InflateTool();
  InflateTool(const InflateTool&) = delete;
  InflateTool& operator=(const InflateTool&) = delete;

  /// Starts (or moves) the pressure: the faces whose rest centroid lies within `radius` of
  /// `centre` (infinity: the whole boundary), `pressure` in Pa (negative deflates). Throws
  /// std::invalid_argument for non-finite values or a negative radius.
  void press(const Eigen::Vector3d& centre, double radius, double pressure);
  /// Changes the pressure of the held brush (stylus pressure). Nothing when not pressing.
  void setPressure(double pressure);
  /// Removes the pressure.
  void release();

  bool active() const { return form_ != nullptr; }
  double pressure() const { return form_ ? form_->pressure() : 0.0; }
  /// Triangles under the brush (0 when not pressing).
  size_t numTriangles() const { return form_ ? form_->numTriangles() : 0; }

 private:
  Simulator& simulator_;
  PressureForm* form_ = nullptr;  // owned by the simulator
};

}  // namespace sculpt
