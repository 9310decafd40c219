#pragma once
// One function per CLI subcommand: app/main.cpp only parses arguments and dispatches here.
#include <cstdint>
#include <string>
#include <vector>

#include "core/Error.hpp"

namespace grainbridge::workflows::commands {

struct CommandOptions {
  std::string config;
  std::string workDir = ".";
  bool force = false;
  bool keepGoing = false;
  std::string why;
  bool markdown = false;
  std::string stageType;  // `stages TYPE`: only that type
  bool files = false;     // `db show --files`: every artifact with its sha256
  bool open = false;  // report --open
  std::string database;
  std::string workflowFilter;
  std::string format = "table";
  std::int64_t runId = 0;
  // db query / db export
  std::string table = "closure_points";
  std::string family;
  std::vector<std::string> where;  // COLUMN=LO:HI
  std::string columns;             // comma-separated; "" = every column that is set
  std::string output;
  // report validation
  std::string records = "build/validation";
  std::vector<std::string> databases;
  // closures eval
  std::string closureName;
  std::vector<std::string> closureArgs;  // key=value
};

// A usage problem the parser could not catch (e.g. neither --db nor --config): exit code 2.
class UsageError : public Error {
 public:
  using Error::Error;
};

int commandRun(const CommandOptions& opt);
int commandStatus(const CommandOptions& opt);
int commandCheck(const CommandOptions& opt);
int commandStages(const CommandOptions& opt);
int commandReport(const CommandOptions& opt);
int commandReportValidation(const CommandOptions& opt);
int commandDbRuns(const CommandOptions& opt);
int commandDbShow(const CommandOptions& opt);
int commandDbIntegrity(const CommandOptions& opt);
int commandDbQuery(const CommandOptions& opt);
int commandDbExport(const CommandOptions& opt);
int commandClosures(const CommandOptions& opt);
int commandClosuresEval(const CommandOptions& opt);

}  // namespace grainbridge::workflows::commands
