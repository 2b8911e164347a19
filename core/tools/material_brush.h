#pragma once
// Material painting (docs/design/ux.md "Brushes" and "Material painting", McDonnell-Qin section 4.1
// stiffness and mass painting): Young's modulus, density and damping in physical units, painted
// into the Gauss samples of the volume by a sphere brush with a falloff, a strength and mirror
// symmetry; an eyedropper reads the material back.
//
// Falloff presets (Blender's, with p = 1 - r/R for a sample at distance r from the centre of a
// brush of radius R; weight 0 for r > R):
//   smooth   3p^2 - 2p^3      r = 0: 1, r = R/2: 0.5,        r = R: 0
//   sphere   sqrt(2p - p^2)   r = 0: 1, r = R/2: sqrt(3)/2,  r = R: 0
//   linear   p                r = 0: 1, r = R/2: 0.5,        r = R: 0
//   sharp    p^2              r = 0: 1, r = R/2: 0.25,       r = R: 0
//   constant 1                r = 0: 1, r = R/2: 1,          r = R: 1
// A dab blends each painted field of a sample towards the target by w = strength x falloff
// (FemModel::paintMaterial with a weight): strength 1 and weight 1 set the target exactly.
//
// Symmetry: with mirror x (on by default), y, z, the dab is repeated at the centre's reflections
// through the planes x = c.x, y = c.y, z = c.z of the symmetry centre c (up to 8 images with all
// three), all in the same call; a sample's weight is the largest over the images, so a dab on
// the plane does not paint twice.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "fem/fem_model.h"
#include "fem/material.h"

namespace sculpt {

enum class Falloff { Smooth = 0, Sphere = 1, Linear = 2, Sharp = 3, Constant = 4 };

const char* falloffName(Falloff falloff);
/// "smooth", "sphere", "linear", "sharp", "constant"; nullopt otherwise.
std::optional<Falloff> parseFalloff(const std::string& name);
/// The weight at distance r from the centre of a brush of radius `radius` (table above); 0 for
/// r > radius or a radius <= 0.
double falloffWeight(Falloff falloff, double r, double radius);

struct MirrorSymmetry {
  bool x = true;
  bool y = false;
  bool z = false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< a point on every mirror plane (m)
};

struct MaterialBrushSettings {
  double radius = 0.5;    ///< m, in rest coordinates
  double strength = 1.0;  ///< in [0, 1]
  Falloff falloff = Falloff::Smooth;
  Material target;                                  ///< the values painted
  FemModel::MaterialFields fields{true, true, true, false};  ///< which of them (not nu by default)
  MirrorSymmetry mirror;
};

/// Empty when usable; otherwise a sentence naming the bad setting (radius <= 0 or not finite,
/// strength outside [0, 1], invalid target material, non-finite mirror centre).
std::string brushProblem(const MaterialBrushSettings& settings);

/// One dab at rest position `centre` and its mirror images. Returns the number of Gauss samples
/// touched (weight > 0). Throws std::invalid_argument when brushProblem is not empty or the
/// centre is not finite.
long paintDab(FemModel& model, const Eigen::Vector3d& centre,
              const MaterialBrushSettings& settings);

/// The eyedropper: the material of the Gauss sample nearest to rest position `rest` (the lowest
/// index on ties). Throws std::invalid_argument for a non-finite position or a model without
/// samples.
Material pickMaterial(const FemModel& model, const Eigen::Vector3d& rest);

}  // namespace sculpt
