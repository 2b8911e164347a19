#include "sculpt/display_settings.h"

namespace sculpt::app {

std::string_view fieldName(FieldKind field) {
  switch (field) {
    case FieldKind::None: return "none";
    case FieldKind::YoungsModulus: return "youngs";
    case FieldKind::Density: return "density";
    case FieldKind::Displacement: return "displacement";
    case FieldKind::StrainEnergy: return "strain";
    case FieldKind::Damping: return "damping";
  }
  return "none";
}

std::string_view fieldLabel(FieldKind field) {
  switch (field) {
    case FieldKind::None: return "None";
    case FieldKind::YoungsModulus: return "Young's modulus";
    case FieldKind::Density: return "Density";
    case FieldKind::Displacement: return "Displacement";
    case FieldKind::StrainEnergy: return "Strain energy density";
    case FieldKind::Damping: return "Damping";
  }
  return "None";
}

std::string_view fieldUnit(FieldKind field) {
  switch (field) {
    case FieldKind::None: return "";
    case FieldKind::YoungsModulus: return "Pa";
    case FieldKind::Density: return "kg/m^3";
    case FieldKind::Displacement: return "m";
    case FieldKind::StrainEnergy: return "J/m^3";
    case FieldKind::Damping: return "kg/(m^3 s)";
  }
  return "";
}

std::optional<FieldKind> parseField(std::string_view name) {
  for (FieldKind field : kFieldKinds)
    if (fieldName(field) == name) return field;
  return std::nullopt;
}

}  // namespace sculpt::app
