#include "engines/closures/KineticModel.hpp"

#include <string>

#include "core/Error.hpp"
#include "engines/closures/Lun1984.hpp"
#include "engines/closures/SyamlalAlgebraic.hpp"

namespace grainbridge::closures {

namespace {

SyamlalAlgebraic syamlal(SyamlalViscosityForm form) {
  SyamlalAlgebraic model;
  model.params.viscosityForm = form;
  return model;
}

}  // namespace

std::string_view toString(KineticModelName model) {
  // The models own their names; this only picks the model.
  switch (model) {
    case KineticModelName::Lun1984:
      return Lun1984{}.name();
    case KineticModelName::Lun1984Mfix:
      return Lun1984{Lun1984ViscosityForm::Mfix}.name();
    case KineticModelName::SyamlalAlgebraicPrinted:
      return syamlal(SyamlalViscosityForm::Printed).name();
    case KineticModelName::SyamlalAlgebraicMfix:
      return syamlal(SyamlalViscosityForm::Mfix).name();
  }
  GB_ASSERT(false, "unknown KineticModelName " + std::to_string(static_cast<int>(model)));
}

KineticModelName kineticModelFromString(std::string_view name) {
  for (const KineticModelName model : kAllKineticModels) {
    if (toString(model) == name) return model;
  }
  std::string valid;
  for (const KineticModelName model : kAllKineticModels) {
    if (!valid.empty()) valid += ", ";
    valid += '"';
    valid += toString(model);
    valid += '"';
  }
  throw Error("unknown kinetic theory model \"" + std::string(name) + "\"; valid names are " + valid);
}

KineticTransport evaluate(KineticModelName model, const KineticState& state) {
  switch (model) {
    case KineticModelName::Lun1984:
      return Lun1984{}.evaluate(state);
    case KineticModelName::Lun1984Mfix:
      return Lun1984{Lun1984ViscosityForm::Mfix}.evaluate(state);
    case KineticModelName::SyamlalAlgebraicPrinted:
      return syamlal(SyamlalViscosityForm::Printed).evaluate(state);
    case KineticModelName::SyamlalAlgebraicMfix:
      return syamlal(SyamlalViscosityForm::Mfix).evaluate(state);
  }
  GB_ASSERT(false, "unknown KineticModelName " + std::to_string(static_cast<int>(model)));
}

}  // namespace grainbridge::closures
