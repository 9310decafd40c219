#include "engines/fluid/FlowStateIo.hpp"

#include "core/io/H5Path.hpp"

namespace grainbridge::fluid {

namespace {
std::string phaseArray(const std::string& group, std::size_t m, const std::string& what) {
  return core::io::memberPath(group, "phase_" + std::to_string(m) + "_" + what);
}
std::string velocityArray(const std::string& group, std::size_t m, std::size_t axis) {
  return phaseArray(group, m, "velocity_" + std::to_string(axis));
}
}  // namespace

void writeFlowState(core::io::H5OutputFile& f, const std::string& group, const FlowState& st) {
  if (group != "/") f.createGroup(group);
  f.writeAttribute(group, "time", st.time);
  f.writeDataset(core::io::memberPath(group, "pressure"), st.pressure.values());
  for (std::size_t m = 0; m < st.phases.size(); ++m) {
    f.writeDataset(phaseArray(group, m, "fraction"), st.phases[m].fraction.values());
    f.writeDataset(phaseArray(group, m, "granular_temperature"), st.phases[m].granularTemperature.values());
    for (std::size_t a = 0; a < 3; ++a) f.writeDataset(velocityArray(group, m, a), st.phases[m].velocity[a].values());
  }
}

void readFlowState(const core::io::H5InputFile& f, const std::string& group, FlowState& st) {
  // Every array has the padded size of the state's grid: a state of another grid fails the
  // shape check of its first array.
  const hsize_t n = st.pressure.values().size();
  if (f.exists(phaseArray(group, st.phases.size(), "fraction"))) {
    throw f.error("group", group,
                  "holds more than the " + std::to_string(st.phases.size()) + " phases of this flow state");
  }
  st.time = f.readDoubleAttribute(group, "time");
  st.pressure.values() = f.readDoubles(core::io::memberPath(group, "pressure"), {n});
  for (std::size_t m = 0; m < st.phases.size(); ++m) {
    st.phases[m].fraction.values() = f.readDoubles(phaseArray(group, m, "fraction"), {n});
    st.phases[m].granularTemperature.values() = f.readDoubles(phaseArray(group, m, "granular_temperature"), {n});
    for (std::size_t a = 0; a < 3; ++a)
      st.phases[m].velocity[a].values() = f.readDoubles(velocityArray(group, m, a), {n});
  }
}

}  // namespace grainbridge::fluid
