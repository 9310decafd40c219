#include "extract/observe/ThetaFormErrors.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"

namespace grainbridge::extract::observe {

namespace {

double meanOf(std::span<const double> x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

// Means of consecutive blocks of `size` samples (the blocking transformation's blocks at that level).
std::vector<double> blockMeans(const std::vector<double>& x, std::size_t size) {
  std::vector<double> out(x.size() / size, 0.0);
  for (std::size_t b = 0; b < out.size(); ++b) {
    for (std::size_t k = 0; k < size; ++k) out[b] += x[b * size + k];
    out[b] /= static_cast<double>(size);
  }
  return out;
}

std::optional<double> pearson(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() < 3) return std::nullopt;
  const double ma = meanOf(a), mb = meanOf(b);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    sab += (a[k] - ma) * (b[k] - mb);
    saa += (a[k] - ma) * (a[k] - ma);
    sbb += (b[k] - mb) * (b[k] - mb);
  }
  if (saa == 0.0 || sbb == 0.0) return std::nullopt;
  return std::clamp(sab / std::sqrt(saa * sbb), -1.0, 1.0);
}

}  // namespace

std::string correlationColumn(const std::string& first, const std::string& second) {
  return first + "_" + second + "_corr";
}

ThetaFormErrors thetaFormErrors(std::span<const ThetaFormSeries> forms, std::span<const double> temperature,
                                const core::ClosureFormState& state) {
  if (temperature.empty()) throw Error("theta-form errors: no frames");
  const double meanT = meanOf(temperature);
  if (!(meanT > 0.0)) throw Error("theta-form errors: the mean granular temperature is not positive");
  core::ClosureFormState atMean = state;
  atMean.granularTemperature = meanT;  // the forms of these series' means
  ThetaFormErrors out;
  std::vector<std::vector<double>> linearised;  // empty for a form of zero mean
  std::vector<std::size_t> blockSizes;
  for (const auto& f : forms) {
    if (f.values.size() != temperature.size()) {
      throw Error("theta-form errors: " + std::string(core::closureFormInfo(f.form).name) + " has " +
                  std::to_string(f.values.size()) + " frames, the temperature " + std::to_string(temperature.size()));
    }
    const auto& info = core::closureFormInfo(f.form);
    const double meanX = meanOf(f.values);
    ThetaFormError e{std::string(info.name), core::toClosureForm(f.form, meanX, atMean), 0.0, true};
    std::vector<double> d;
    std::size_t blockSize = 1;
    if (meanX != 0.0) {
      d.resize(temperature.size());
      for (std::size_t k = 0; k < d.size(); ++k) {
        d[k] = e.value * (f.values[k] / meanX - info.temperaturePower * temperature[k] / meanT);
      }
      const auto b = core::averaging::blockAverage(d);
      e.error = b.standardError;
      e.plateauReached = b.plateauReached;
      blockSize = b.blockSize;
    }
    out.forms.push_back(std::move(e));
    linearised.push_back(std::move(d));
    blockSizes.push_back(blockSize);
  }
  for (std::size_t i = 0; i < forms.size(); ++i) {
    for (std::size_t j = i + 1; j < forms.size(); ++j) {
      if (linearised[i].empty() || linearised[j].empty()) continue;
      // The correlation of the two series' block means at the longer of their two blocking
      // levels, where the blocks are about independent: the correlation of the two means.
      const auto a = blockMeans(linearised[i], std::max(blockSizes[i], blockSizes[j]));
      const auto b = blockMeans(linearised[j], std::max(blockSizes[i], blockSizes[j]));
      if (const auto r = pearson(a, b)) out.correlations.push_back({out.forms[i].name, out.forms[j].name, *r});
    }
  }
  return out;
}

std::vector<std::string> addThetaFormErrors(nlohmann::json& row, const core::ClosureFormState& state,
                                            const std::vector<double>& temperature, const std::vector<double>& pressure,
                                            const std::vector<double>& shearStress,
                                            const std::vector<double>& dissipation) {
  const double shearRate = state.shearRate;
  std::vector<double> viscosity, work;
  std::vector<ThetaFormSeries> forms{{core::ClosureForm::PTheta, pressure}};
  if (shearRate != 0.0) {
    // Under shear J is the shear work tau gammadot (ClosurePointObserver::finish says why), so eta_theta and j_theta
    // share tau's fluctuations.
    for (double tau : shearStress) {
      viscosity.push_back(tau / shearRate);
      work.push_back(tau * shearRate);
    }
    forms.push_back({core::ClosureForm::EtaTheta, viscosity});
    forms.push_back({core::ClosureForm::JTheta, work});
  } else if (!dissipation.empty()) {
    forms.push_back({core::ClosureForm::JTheta, dissipation});
  }
  std::vector<std::string> noPlateau;
  const auto errors = thetaFormErrors(forms, temperature, state);
  for (const auto& f : errors.forms) {
    row[f.name + "_err"] = f.error;
    if (!f.plateauReached) noPlateau.push_back(f.name);
  }
  for (const auto& c : errors.correlations) row[correlationColumn(c.first, c.second)] = c.coefficient;
  return noPlateau;
}

std::optional<std::string> errorWarning(std::size_t frames, const std::vector<std::string>& quantities) {
  if (quantities.empty()) return std::nullopt;
  if (frames < core::averaging::BlockAverage::kMinSamplesForBlocking) {
    return "only " + std::to_string(frames) +
           " frames, too few to block: the errors take the frames as independent "
           "and may be far too small (average over a longer run)";
  }
  std::string list;
  for (const auto& q : quantities) list += (list.empty() ? "" : ", ") + q;
  return "the blocking curve reached no plateau in " + std::to_string(frames) + " frames for " + list +
         ": those errors are lower bounds (the averaged window is short for the correlation time; average over a "
         "longer run)";
}

}  // namespace grainbridge::extract::observe
