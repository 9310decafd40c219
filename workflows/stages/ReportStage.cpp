#include "workflows/stages/ReportStage.hpp"

#include "core/Error.hpp"
#include "workflows/report/HtmlReport.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::stages {

ReportStage::ReportStage() {
  schema_.add(
      params::ParamSpec::string("title").defaultValue("grainbridge report").doesNotAffectResults().doc("page title"));
}

void ReportStage::run(StageContext& ctx) const {
  if (ctx.inputs().empty()) throw Error("report: no upstream stages; give it \"from\"");
  const auto files = report::writeHtmlReport(
      {ctx.params().at("title"), ctx.databasePath(), StageRegistry::builtin().reportView()}, ctx.inputs(),
                                             ctx.outputDir(), ctx.publishedDir());
  for (const auto& f : files.files) ctx.addArtifact(f.path, f.kind);
  ctx.setSummary({{"instances", ctx.inputs().size()}});
}

}  // namespace grainbridge::workflows::stages
