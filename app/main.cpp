// grainbridge: the command-line front end. Argument parsing (CLI11) and dispatch only; every
// piece of behaviour lives in the modules. Exit codes: 0 success, 1 a stage failed or was
// interrupted, 2 usage or config error.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/json/Diagnostics.hpp"
#include "core/parallel/Communicator.hpp"
#include "workflows/commands/Commands.hpp"
#include "workflows/report/BuildDescription.hpp"

namespace gb = grainbridge;

namespace {

// CLI11 answers a mistyped command ("grainbridge runn") with "A subcommand is required": name the
// word it did not know, the closest command and the list. Walks down known subcommands first, so
// "db quer" is answered at the db level. Empty when every word names a command.
std::string unknownCommandMessage(const CLI::App& app, int argc, char** argv) {
  const CLI::App* level = &app;
  std::string path = "grainbridge";
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') continue;
    std::vector<std::string> names;
    const CLI::App* next = nullptr;
    for (const auto* sub : level->get_subcommands([](const CLI::App*) { return true; })) {
      names.push_back(sub->get_name());
      if (sub->get_name() == word) next = sub;
    }
    if (names.empty()) return "";
    if (next == nullptr) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      const auto hint = gb::core::json::closestMatch(word, names);
      return path + ": unknown command \"" + word + "\"" + (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)") +
             "; commands: " + list;
    }
    level = next;
    path += " " + word;
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  gb::core::parallel::initialize(&argc, &argv);
  const int rank = gb::core::parallel::worldRank();

  CLI::App app{"grainbridge: multiscale workflows for granular and gas-solid flows (DEM -> closures -> continuum)"};
  app.require_subcommand(1);
  app.fallthrough();  // -v and -q also work after the subcommand: grainbridge run cfg.json -q
  bool verbose = false;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbose, "more log output (debug level)");
  app.add_flag("-q,--quiet", quiet, "warnings and errors only");
  // What this binary is and what it was built with: the code version, each library, the engines.
  app.set_version_flag("--version", [] {
    return gb::workflows::report::codeDescription() + "\n" + gb::workflows::report::librariesDescription() + "\n" +
           gb::workflows::report::enginesDescription();
  });
  gb::workflows::commands::CommandOptions opt;

  auto* run = app.add_subcommand(
      "run", "run a workflow: every stage instance not already done (under mpirun, spread over ranks)");
  run->add_option("config", opt.config, "workflow config (JSON)")->required();
  run->add_flag("--force", opt.force, "rerun stage instances even when a valid cached result exists");
  run->add_flag("--keep-going", opt.keepGoing, "after a failure, still run every instance that does not depend on it");
  run->add_option("--workdir", opt.workDir, "folder holding results/ (default: current folder)");

  auto* status = app.add_subcommand("status", "show which stage instances are done, running, failed or pending");
  status->add_option("config", opt.config, "workflow config (JSON)")->required();
  status->add_option("--why", opt.why, "explain what changed since STAGE last ran");
  status->add_option("--workdir", opt.workDir, "folder holding results/ (default: current folder)");

  auto* check = app.add_subcommand("check", "validate a workflow config without running anything");
  check->add_option("config", opt.config, "workflow config (JSON)")->required();

  auto* stages = app.add_subcommand("stages", "list stage types and their parameters");
  stages->add_option("type", opt.stageType, "only this stage type (e.g. mfm)");
  stages->add_flag("--markdown", opt.markdown, "print the reference as Markdown (docs/stages.md)");

  auto* report =
      app.add_subcommand("report", "write the HTML report of a workflow's completed stages (or `report validation`)");
  report->add_option("config", opt.config, "workflow config (JSON)");
  report->add_option("--workdir", opt.workDir, "folder holding results/ (default: current folder)");
  report->add_flag("--open", opt.open, "open the page in the system's browser ($BROWSER, xdg-open)");
  auto* validation = report->add_subcommand(
      "validation", "every VALIDATION.md figure reached so far (physics-test records and workflow databases)");
  validation->add_option("--records", opt.records, "folder of physics-test records (default: build/validation)");
  validation->add_option("--db", opt.databases, "closure database of a workflow run (repeatable)");
  validation->add_option("--output,-o", opt.output, "HTML file to write (default: validation.html)");

  auto* dbCmd = app.add_subcommand("db", "inspect the database (runs, provenance, integrity)");
  dbCmd->require_subcommand(1);
  auto addDbSource = [&opt](CLI::App* c) {
    c->add_option("--db", opt.database, "database file");
    c->add_option("--config", opt.config, "workflow config whose database to use");
    c->add_option("--workdir", opt.workDir, "folder holding results/ (default: current folder)");
  };
  auto* dbRuns = dbCmd->add_subcommand("runs", "list stage runs");
  addDbSource(dbRuns);
  dbRuns->add_option("--workflow", opt.workflowFilter, "only runs of this workflow");
  dbRuns->add_option("--format", opt.format, "table | csv | json")->check(CLI::IsMember({"table", "csv", "json"}));
  auto* dbShow = dbCmd->add_subcommand(
      "show", "the full provenance of one run: config, parameters, code, artifacts, upstream runs");
  addDbSource(dbShow);
  dbShow->add_option("run", opt.runId, "run id (from db runs)")->required();
  dbShow->add_flag("--files", opt.files, "list every artifact with its sha256 (default: one line per kind)");
  auto* dbIntegrity = dbCmd->add_subcommand("integrity", "run SQLite's integrity check");
  addDbSource(dbIntegrity);
  auto* dbQuery = dbCmd->add_subcommand(
      "query", "closure points (or force / structure statistics, rheology rows, closure table nodes with their "
               "standard errors) filtered by family, state ranges and run");
  addDbSource(dbQuery);
  dbQuery
      ->add_option("--table", opt.table,
                   "closure_points | force_statistics | structure_statistics | rheology | closure_tables (one row "
                   "per node: value and uncertainty)")
      ->check(CLI::IsMember({"closure_points", "force_statistics", "structure_statistics", "rheology",
                             "closure_tables"}));
  dbQuery->add_option("--family", opt.family, "only this family (simple_shear, fluidized_cell, bnp, ...)");
  dbQuery->add_option("--where", opt.where,
                      "COLUMN=LO:HI, COLUMN=VALUE, COLUMN=LO: or COLUMN=:HI, or COLUMN=TEXT for a text column such as "
                      "species (repeatable)");
  dbQuery->add_option("--run", opt.runId, "only rows of this run");
  dbQuery->add_option("--workflow", opt.workflowFilter, "only rows of this workflow's runs");
  dbQuery->add_option("--columns", opt.columns, "comma-separated columns to show (default: every column set)");
  dbQuery->add_option("--format", opt.format, "table | csv | json")->check(CLI::IsMember({"table", "csv", "json"}));
  auto* dbExport = dbCmd->add_subcommand(
      "export", "write the closure database (points, statistics, tables, runs) to FILE.json or to a folder of CSVs");
  addDbSource(dbExport);
  dbExport->add_option("--output,-o", opt.output, "FILE.json, or a folder")->required();
  dbExport->add_option("--workflow", opt.workflowFilter, "only this workflow");

  auto* closuresCmd =
      app.add_subcommand("closures", "list the continuum closures (drag, g0, kinetic theory, walls, ...)");
  closuresCmd->add_flag("--markdown", opt.markdown, "print the catalog as Markdown (docs/closures.md)");
  auto* closuresEval =
      closuresCmd->add_subcommand("eval", "evaluate one closure at a state: closures eval NAME key=value ...");
  closuresEval->add_option("name", opt.closureName, "closure name (from `grainbridge closures`)")->required();
  closuresEval->add_option("values", opt.closureArgs, "parameters and inputs as key=value (units allowed)");
  closuresEval->add_option("--format", opt.format, "table or json")->check(CLI::IsMember({"table", "json"}));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const bool noCommand = std::string(e.what()).find("subcommand") != std::string::npos ||
                           dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr;
    if (const auto unknown = noCommand ? unknownCommandMessage(app, argc, argv) : ""; !unknown.empty()) {
      if (rank == 0) std::fprintf(stderr, "%s\n", unknown.c_str());
      gb::core::parallel::finalize();
      return 2;
    }
    const int code = app.exit(e);  // prints help or the usage error
    gb::core::parallel::finalize();
    return code == 0 ? 0 : 2;
  }
  gb::core::initLogging(quiet     ? gb::core::Verbosity::Quiet
                        : verbose ? gb::core::Verbosity::Verbose
                                  : gb::core::Verbosity::Normal,
                        rank);

  int code = 0;
  try {
    if (*run)
      code = gb::workflows::commands::commandRun(opt);
    else if (rank != 0)
      code = 0;  // only `run` uses worker ranks
    else if (*status)
      code = gb::workflows::commands::commandStatus(opt);
    else if (*check)
      code = gb::workflows::commands::commandCheck(opt);
    else if (*stages)
      code = gb::workflows::commands::commandStages(opt);
    else if (*validation)
      code = gb::workflows::commands::commandReportValidation(opt);
    else if (*report)
      code = gb::workflows::commands::commandReport(opt);
    else if (*dbRuns)
      code = gb::workflows::commands::commandDbRuns(opt);
    else if (*dbShow)
      code = gb::workflows::commands::commandDbShow(opt);
    else if (*dbIntegrity)
      code = gb::workflows::commands::commandDbIntegrity(opt);
    else if (*dbQuery)
      code = gb::workflows::commands::commandDbQuery(opt);
    else if (*dbExport)
      code = gb::workflows::commands::commandDbExport(opt);
    else if (*closuresEval)
      code = gb::workflows::commands::commandClosuresEval(opt);
    else if (*closuresCmd)
      code = gb::workflows::commands::commandClosures(opt);
  } catch (const gb::core::json::InputError& e) {
    if (rank == 0) std::fprintf(stderr, "%s\n", e.what());
    code = 2;
  } catch (const gb::workflows::commands::UsageError& e) {
    if (rank == 0) std::fprintf(stderr, "grainbridge: %s\n", e.what());
    code = 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "grainbridge: error: %s\n", e.what());
    code = 1;
  }
  gb::core::parallel::finalize();
  return code;
}
