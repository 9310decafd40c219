#include "extract/observe/ForceStatisticsObserver.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <sstream>
#include <string>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/text/NumberText.hpp"
#include "extract/statistics/ContactSubset.hpp"
#include "extract/statistics/CorrelationLength.hpp"
#include "extract/statistics/DensityHistogram.hpp"
#include "extract/statistics/ForceCorrelation.hpp"
#include "extract/statistics/ForcePdfFit.hpp"
#include "extract/statistics/NormalForces.hpp"
#include "extract/statistics/VelocityCorrelation.hpp"
#include "extract/statistics/VelocityMoments.hpp"

namespace grainbridge::extract::observe {

using nlohmann::json;
namespace st = extract::statistics;

namespace {

// What the helpers below report through, and with which parameters.
struct Ctx {
  OutputSink& out;
  const ForceStatisticsOptions& options;
};

json fitRow(const json& family, const std::string& source, const char* model, const st::ForcePdfFit& fit,
            double meanForce) {
  json row = {{"family", family},
              {"source", source},
              {"forces", fit.samples},
              {"mean_force", meanForce},
              {"model", model},
              {"a", fit.params.a},
              {"a_err", fit.error.a},
              {"b", fit.params.b},
              {"b_err", fit.error.b},
              {"beta", fit.params.beta},
              {"beta_err", fit.error.beta},
              {"chi2_dof", fit.chi2PerDof},
              {"density_integral", fit.integral},
              {"extra_json",
               {{"normalised_a", fit.normalisedA},
                {"normalised_a_err", fit.normalisedAError},
                {"gamma_rule", fit.gammaRule},
                {"fit_range", {fit.fitMin, fit.fitMax}}}}};
  if (std::string(model) == "eq6.13") {
    row["alpha"] = fit.params.alpha;
    row["alpha_err"] = fit.error.alpha;
    row["gamma"] = fit.params.gamma;
    row["gamma_err"] = fit.error.gamma;
  }
  return row;
}

// The density histogram of the normalised forces f and its Eq. 6.11 and 6.13 fits. A fit the
// data cannot constrain (few contacts, a narrow range) is recorded with its reason, not fatal:
// the histogram and the other statistics still stand.
struct PdfWithFits {
  st::DensityHistogram histogram;
  std::optional<st::ForcePdfFit> eq611, eq613;

  std::string csvRows(const std::string& prefix) const {
    auto curve = [](const std::optional<st::ForcePdfFit>& fit, double x) {
      return fit ? core::roundTripText(st::forcePdf(fit->params, x)) : std::string();
    };
    std::ostringstream out;
    for (std::size_t k = 0; k + 1 < histogram.edges.size(); ++k) {
      const double c = histogram.centre[k];
      out << prefix << core::roundTripText(histogram.edges[k]) << ',' << core::roundTripText(histogram.edges[k + 1])
          << ',' << core::roundTripText(histogram.density[k]) << ',' << core::roundTripText(histogram.error[k]) << ','
          << curve(eq611, c) << ',' << curve(eq613, c) << '\n';
    }
    return out.str();
  }
};

PdfWithFits pdfWithFits(const Ctx& ctx, const std::vector<double>& f, double meanForce, const std::string& source) {
  const json& family = ctx.options.family;
  PdfWithFits out{st::densityHistogram(f, st::BinOptions{}, "normalised contact forces (" + source + ")"), {}, {}};
  auto fitted = [&](const char* model, auto&& fit) -> std::optional<st::ForcePdfFit> {
    try {
      return fit(out.histogram, st::ForcePdfFitOptions{});
    } catch (const Error& e) {
      spdlog::warn("{}: force PDF fit {} of {} forces ({}) failed: {}", ctx.out.label(), model, f.size(), source,
                   e.what());
      ctx.out.addRecord("force_statistics", {{"family", family},
                                             {"source", source},
                                             {"forces", f.size()},
                                             {"mean_force", meanForce},
                                             {"model", model},
                                             {"extra_json", {{"fit_error", e.what()}}}});
      return std::nullopt;
    }
  };
  out.eq611 = fitted("eq6.11", [](const auto& h, const auto& o) { return st::fitEq611(h, o); });
  out.eq613 = fitted("eq6.13", [](const auto& h, const auto& o) { return st::fitEq613(h, o); });
  return out;
}

// Records the successful fits of `pdf`, with the force correlation length when there is one.
void recordFits(const Ctx& ctx, const PdfWithFits& pdf, const std::string& source, double meanForce,
                const std::optional<st::CorrelationLength>& xi) {
  for (const auto& [model, fit] : {std::pair{"eq6.11", &pdf.eq611}, std::pair{"eq6.13", &pdf.eq613}}) {
    if (!*fit) continue;
    json row = fitRow(ctx.options.family, source, model, **fit, meanForce);
    if (xi) {
      row["correlation_length"] = xi->length;
      row["correlation_length_err"] = xi->error;
    }
    ctx.out.addRecord("force_statistics", row);
  }
}

// Correlations up to correlation_range diameters, or half the shortest periodic edge.
st::CorrelationOptions correlationOptions(const Ctx& ctx, const core::data::Domain& domain, double diameter) {
  double rMax = ctx.options.correlationRange * diameter;
  for (int a = 0; a < 3; ++a) {
    if (domain.periodic[static_cast<std::size_t>(a)]) rMax = std::min(rMax, 0.5 * (domain.hi[a] - domain.lo[a]));
  }
  return {0.1 * diameter, rMax, 16};
}

// A correlation that does not decay within the range has no length: say so, keep the rest.
std::optional<st::CorrelationLength> lengthOf(const Ctx& ctx, const st::CorrelationFunction& c,
                                              const std::string& what) {
  try {
    return st::decayLength(c);
  } catch (const Error& e) {
    spdlog::warn("{}: no {} correlation length: {}", ctx.out.label(), what, e.what());
    return std::nullopt;
  }
}

// Frames without a repulsive contact (a dilute gas between collisions) have no <F_n>.
bool hasRepulsiveContact(const core::data::ParticleFrame& frame) {
  for (std::size_t k = 0; k < frame.contacts.size(); ++k) {
    if (frame.contacts.forceNormal[k].dot(frame.contacts.branch[k]) > 0.0) return true;
  }
  return false;
}

void addForceStatistics(const Ctx& ctx, const std::vector<core::data::ParticleFrame>& allFrames, double diameter,
                        json& point) {
  // Velocity statistics take every frame; force statistics only the frames with a repulsive
  // contact. A dilute gas (solid fraction 0.05 sheared at k* = 1e5) can go 400 frames without
  // one: its closure point is still worth having, so say why it has no force statistics.
  std::vector<core::data::ParticleFrame> frames;
  for (const auto& frame : allFrames) {
    if (hasRepulsiveContact(frame)) frames.push_back(frame);
  }
  const auto options = correlationOptions(ctx, allFrames.front().domain, diameter);
  const auto velocities = st::velocityCorrelation(allFrames, options);
  if (const auto xi = lengthOf(ctx, velocities, "velocity")) {
    point["velocity_correlation_length"] = xi->length;
    point["velocity_correlation_length_err"] = xi->error;
  }
  const auto moments = st::velocityMoments(allFrames);
  point["extra_json"]["velocity_kurtosis"] = {moments.component[0].kurtosis, moments.component[1].kurtosis,
                                              moments.component[2].kurtosis};
  std::optional<st::CorrelationFunction> forces;
  if (frames.empty()) {
    const std::string why =
        "none of the " + std::to_string(allFrames.size()) + " averaged frames has a contact with F_n > 0";
    spdlog::warn("{}: no force PDF or force correlation: {}", ctx.out.label(), why);
    point["extra_json"]["force_statistics_skipped"] = why;
  } else {
    const auto f = st::normalisedForces(frames);
    double meanForce = 0.0;
    for (const auto& frame : frames) meanForce += st::repulsiveForces(frame).meanForce;
    meanForce /= static_cast<double>(frames.size());
    const PdfWithFits pdf = pdfWithFits(ctx, f, meanForce, "contacts");
    ctx.out.writeFile("force_pdf.csv", "f_lo,f_hi,density,error,eq6.11,eq6.13\n" + pdf.csvRows(""), "csv");
    forces = st::forceCorrelation(frames, options);
    const auto forceLength = lengthOf(ctx, *forces, "force");
    if (forceLength) {
      point["force_correlation_length"] = forceLength->length;
      point["force_correlation_length_err"] = forceLength->error;
    }
    recordFits(ctx, pdf, "contacts", meanForce, forceLength);
    if (pdf.eq611) {
      point["extra_json"]["force_pdf_eq611"] = {
          {"a", pdf.eq611->params.a}, {"b", pdf.eq611->params.b}, {"beta", pdf.eq611->params.beta}};
    }
  }
  std::ostringstream corr;
  corr << "r,force_pairs,force_correlation,force_correlation_err,velocity_correlation,velocity_correlation_err\n";
  for (std::size_t k = 0; k < velocities.r.size(); ++k) {
    corr << core::roundTripText(velocities.r[k]) << ',' << core::roundTripText(forces ? forces->pairs[k] : 0.0) << ','
         << core::roundTripText(forces ? forces->normalised[k] : NAN) << ','
         << core::roundTripText(forces ? forces->normalisedError[k] : NAN) << ','
         << core::roundTripText(velocities.normalised[k]) << ',' << core::roundTripText(velocities.normalisedError[k])
         << '\n';
  }
  ctx.out.writeFile("correlations.csv", corr.str(), "csv");
}

void addMstForceStatistics(const Ctx& ctx, const std::vector<core::data::ParticleFrame>& frames,
                           const std::vector<std::vector<std::vector<std::size_t>>>& treeContacts, double diameter) {
  std::ostringstream pdfCsv, corrCsv;
  pdfCsv << "pass,f_lo,f_hi,density,error,eq6.11,eq6.13\n";
  corrCsv << "pass,r,force_pairs,force_correlation,force_correlation_err\n";
  const std::size_t passes = treeContacts.empty() ? 0 : treeContacts.front().size();
  // <F_n> of all repulsive contacts of each frame (0: none), not of the MST's own.
  std::vector<double> frameMean(frames.size(), 0.0);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (hasRepulsiveContact(frames[k])) frameMean[k] = st::repulsiveForces(frames[k]).meanForce;
  }
  for (std::size_t p = 0; p < passes; ++p) {
    const std::string source = "mst_pass" + std::to_string(p + 1);
    std::vector<double> f;
    std::vector<core::data::ParticleFrame> subsets;
    double meanForce = 0.0;
    for (std::size_t k = 0; k < frames.size(); ++k) {
      const double mean = frameMean[k];
      if (mean == 0.0) continue;
      meanForce += mean;
      auto subset = st::withContacts(frames[k], treeContacts[k][p]);
      const auto& c = subset.contacts;
      for (std::size_t e = 0; e < c.size(); ++e) {
        const double fn = c.forceNormal[e].dot(c.branch[e].normalized());
        if (fn > 0.0) f.push_back(fn / mean);
      }
      if (hasRepulsiveContact(subset)) subsets.push_back(std::move(subset));
    }
    if (subsets.empty()) continue;
    meanForce /= static_cast<double>(subsets.size());
    const PdfWithFits pdf = pdfWithFits(ctx, f, meanForce, source);
    pdfCsv << pdf.csvRows(std::to_string(p + 1) + ",");
    const auto forces = st::forceCorrelation(subsets, correlationOptions(ctx, subsets.front().domain, diameter));
    for (std::size_t k = 0; k < forces.r.size(); ++k) {
      corrCsv << p + 1 << ',' << core::roundTripText(forces.r[k]) << ',' << core::roundTripText(forces.pairs[k]) << ','
              << core::roundTripText(forces.normalised[k]) << ',' << core::roundTripText(forces.normalisedError[k])
              << '\n';
    }
    recordFits(ctx, pdf, source, meanForce, lengthOf(ctx, forces, source + " force"));
  }
  ctx.out.writeFile("mst_force_pdf.csv", pdfCsv.str(), "csv");
  ctx.out.writeFile("mst_correlations.csv", corrCsv.str(), "csv");
}

}  // namespace

void ForceStatisticsObserver::observe(ObservedFrame& observed) {
  frames_.push_back(std::move(observed.frame));  // registered last: no observer reads it after
}

void ForceStatisticsObserver::finish(OutputSink& out, ExtractResult& result) {
  const Ctx ctx{out, options_};
  const double diameter = closurePoint_.diameter();
  addForceStatistics(ctx, frames_, diameter, result.point);
  if (structure_ != nullptr && !structure_->treeContacts().empty()) {
    addMstForceStatistics(ctx, frames_, structure_->treeContacts(), diameter);
  }
}

}  // namespace grainbridge::extract::observe
