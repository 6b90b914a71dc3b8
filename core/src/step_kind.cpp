#include "styk/core/step_kind.hpp"

namespace styk {

const char* procedure_keyword(StepKind kind) {
  switch (kind) {
    case StepKind::Static:
      return "*STATIC";
    case StepKind::HeatTransfer:
      return "*HEAT TRANSFER";
    case StepKind::ElectricConduction:
      return "*COUPLED THERMAL-ELECTRICAL";
  }
  return "";
}

int scalar_dof(StepKind kind) {
  return kind == StepKind::HeatTransfer ? 11 : kind == StepKind::ElectricConduction ? 9 : 0;
}

}  // namespace styk
