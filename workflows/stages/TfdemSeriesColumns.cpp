#include "workflows/stages/TfdemSeriesColumns.hpp"

#include "engines/tfdem/ParticleBedMeasures.hpp"

namespace grainbridge::workflows::stages {

TfdemSeriesColumns::TfdemSeriesColumns(tfdem::TfdemEngine& engine, const TfdemStageSetup& setup)
    : engine_(engine), setup_(setup) {
  for (const auto& tap : setup.taps) names_.push_back("dp_" + tap.name);
  for (const char* n :
       {"mean_height", "mean_height_fields", "contacts", "coordination", "multi_contact_ratio", "gas_iterations"})
    names_.push_back(n);
}

void TfdemSeriesColumns::sample(driver::SeriesRow& row) {
  const auto& flow = engine_.flow();
  std::vector<double> values;
  for (const auto& tap : setup_.taps) {
    values.push_back(fluid::pressureAtHeight(flow, setup_.vertical, tap.low) -
                     fluid::pressureAtHeight(flow, setup_.vertical, tap.high));
  }
  const auto& particles = engine_.simulation().particles();
  values.push_back(tfdem::meanParticleHeight(particles, setup_.vertical, setup_.bottom));
  values.push_back(fluid::meanParticleHeight(flow, setup_.vertical, 1));  // Eq. 5.22, the deposited phase
  const auto& contacts = engine_.particleFrame().contacts;
  const auto numbers = tfdem::contactNumbers(contacts, static_cast<std::int64_t>(particles.nOwned));
  values.push_back(static_cast<double>(contacts.size()));
  values.push_back(numbers.coordination);
  values.push_back(numbers.multiContactRatio);
  values.push_back(engine_.gasIterations());
  for (double v : values) row.add(v);
}

}  // namespace grainbridge::workflows::stages
