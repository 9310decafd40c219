#pragma once
// One SQLite connection to a grainbridge database. The file is shared by every process of a
// workflow (and by anyone with the sqlite3 shell or pandas), so the connection is configured
// for multi-process safety: a busy timeout instead of instant SQLITE_BUSY, every write
// transaction taking the write lock up front (BEGIN IMMEDIATE), WAL only where the file
// system supports it (see FileSystemKind.hpp), and the schema migrated on open.
// One connection per thread: a Database is movable (to hand it to a thread) but not copyable.
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <type_traits>
#include <utility>

#include "core/Error.hpp"
#include "db/Statement.hpp"

struct sqlite3;

namespace grainbridge::db {

// The SQLite library this binary uses ("3.40.1"), for `grainbridge --version`.
[[nodiscard]] std::string sqliteVersion();

class Database {
 public:
  // Opens or creates the file (creating missing parent folders), configures the connection
  // and migrates the schema to latestSchemaVersion() in one transaction. Throws Error if the
  // file cannot be opened or its schema is newer than this build knows.
  static Database open(const std::filesystem::path& path);
  // For readers (reports, queries): the file must exist; nothing is created or migrated.
  // A schema newer than this build is refused as in open().
  static Database openReadOnly(const std::filesystem::path& path);

  ~Database();
  Database(Database&& other) noexcept;
  Database& operator=(Database&& other) noexcept;
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  // Runs fn(*this) inside BEGIN IMMEDIATE ... COMMIT and returns what fn returns. Taking the
  // write lock at BEGIN means two writers never both hold read locks and then deadlock trying
  // to upgrade; a busy lock is waited for (busy timeout), then retried with backoff, then
  // reported as BusyError. If fn throws, everything it wrote is rolled back and the exception
  // propagates. Not reentrant: nesting is a programmer error.
  template <class Fn>
  decltype(auto) transaction(Fn&& fn);

  void exec(const std::string& sql);  // several ';'-separated statements allowed, no results
  Statement prepare(const std::string& sql);

  int schemaVersion();
  static int latestSchemaVersion();
  std::string integrityCheck();  // PRAGMA integrity_check: "ok" or the problems, one per line
  std::int64_t lastInsertRowId();
  int changes();              // rows changed by the last INSERT/UPDATE/DELETE
  std::string journalMode();  // "wal" or "delete" (lower case, as SQLite reports it)
  bool inTransaction() const { return inTransaction_; }
  const std::filesystem::path& path() const { return path_; }  // absolute

  // How long one attempt waits for a lock (default 30 s), and how many more times
  // transaction() retries BEGIN IMMEDIATE after that before throwing BusyError (default 4).
  void setBusyTimeout(std::chrono::milliseconds timeout);
  void setBusyRetries(int retries);

 private:
  Database(sqlite3* connection, std::filesystem::path path);
  void configureForWriting();
  void checkSchemaNotNewer();
  void migrate();
  void beginTransaction();
  void commitTransaction();
  void rollbackTransaction() noexcept;
  [[noreturn]] void throwError(int rc, const std::string& what) const;
  void close() noexcept;

  sqlite3* connection_ = nullptr;
  std::filesystem::path path_;
  bool inTransaction_ = false;
  int busyRetries_ = 4;
};

template <class Fn>
decltype(auto) Database::transaction(Fn&& fn) {
  GB_ASSERT(!inTransaction_, "Database::transaction is not reentrant (database " + path_.string() + ")");
  beginTransaction();
  try {
    if constexpr (std::is_void_v<std::invoke_result_t<Fn, Database&>>) {
      std::forward<Fn>(fn)(*this);
      commitTransaction();
    } else {
      decltype(auto) result = std::forward<Fn>(fn)(*this);
      commitTransaction();
      return result;
    }
  } catch (...) {
    rollbackTransaction();
    throw;
  }
}

}  // namespace grainbridge::db
