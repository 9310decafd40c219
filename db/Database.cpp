#include "db/Database.hpp"

#include <sqlite3.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <random>
#include <thread>

#include "core/FailPoint.hpp"
#include "core/Log.hpp"
#include "db/BusyError.hpp"
#include "db/FileSystemKind.hpp"
#include "db/Migrations.hpp"

namespace grainbridge::db {

namespace {

constexpr std::chrono::milliseconds kDefaultBusyTimeout{30000};

// Error messages quote the SQL, but a whole migration script would drown the actual problem.
std::string abbreviated(const std::string& sql) {
  constexpr std::size_t kMax = 200;
  return sql.size() <= kMax ? sql : sql.substr(0, kMax) + "...";
}

bool isBusy(int rc) { return (rc & 0xFF) == SQLITE_BUSY; }

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Backoff between BEGIN IMMEDIATE attempts once a full busy timeout has already expired:
// doubling, capped, with jitter so processes that gave up together do not retry in lockstep.
std::chrono::milliseconds backoff(int attempt) {
  thread_local std::minstd_rand random(
      static_cast<unsigned>(::getpid()) ^
      static_cast<unsigned>(std::chrono::steady_clock::now().time_since_epoch().count()));
  const long base = std::min(50L << std::min(attempt, 10), 2000L);
  return std::chrono::milliseconds(base + static_cast<long>(random() % static_cast<unsigned long>(base / 2 + 1)));
}

}  // namespace

std::string sqliteVersion() { return sqlite3_libversion(); }

Database::Database(sqlite3* connection, std::filesystem::path path) : connection_(connection), path_(std::move(path)) {}

Database::~Database() { close(); }

Database::Database(Database&& other) noexcept
    : connection_(std::exchange(other.connection_, nullptr)),
      path_(std::move(other.path_)),
      inTransaction_(std::exchange(other.inTransaction_, false)),
      busyRetries_(other.busyRetries_) {}

Database& Database::operator=(Database&& other) noexcept {
  if (this != &other) {
    close();
    connection_ = std::exchange(other.connection_, nullptr);
    path_ = std::move(other.path_);
    inTransaction_ = std::exchange(other.inTransaction_, false);
    busyRetries_ = other.busyRetries_;
  }
  return *this;
}

void Database::close() noexcept {
  // close_v2 defers the close until Statements still alive are finalized, so a Statement
  // outliving its Database is harmless instead of leaking the connection.
  if (connection_ != nullptr) sqlite3_close_v2(connection_);
  connection_ = nullptr;
}

void Database::throwError(int rc, const std::string& what) const {
  const std::string detail = connection_ != nullptr ? sqlite3_errmsg(connection_) : sqlite3_errstr(rc);
  const std::string message = "database " + path_.string() + ": " + what + ": " + detail;
  if (isBusy(rc)) throw BusyError(message);
  throw Error(message);
}

Database Database::open(const std::filesystem::path& path) {
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  std::error_code ec;
  std::filesystem::create_directories(absolute.parent_path(), ec);
  if (ec)
    throw Error("cannot create folder " + absolute.parent_path().string() + " for database " + absolute.string() +
                ": " + ec.message());
  sqlite3* raw = nullptr;
  const int rc = sqlite3_open_v2(absolute.c_str(), &raw, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  Database db(raw, absolute);  // owns the handle even on failure: SQLite allocates one to report the error
  if (rc != SQLITE_OK) db.throwError(rc, "cannot open or create the file");
  db.configureForWriting();
  db.checkSchemaNotNewer();
  db.migrate();
  return db;
}

Database Database::openReadOnly(const std::filesystem::path& path) {
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  if (!std::filesystem::is_regular_file(absolute))
    throw Error("database " + absolute.string() + " does not exist (or is not a file)");
  sqlite3* raw = nullptr;
  const int rc = sqlite3_open_v2(absolute.c_str(), &raw, SQLITE_OPEN_READONLY, nullptr);
  Database db(raw, absolute);
  if (rc != SQLITE_OK) db.throwError(rc, "cannot open the file read-only");
  sqlite3_extended_result_codes(db.connection_, 1);
  db.setBusyTimeout(kDefaultBusyTimeout);
  db.checkSchemaNotNewer();
  return db;
}

void Database::configureForWriting() {
  sqlite3_extended_result_codes(connection_, 1);
  setBusyTimeout(kDefaultBusyTimeout);
  // Off by default in SQLite for backwards compatibility; we want a dangling run_id to fail.
  exec("PRAGMA foreign_keys=ON");
  // WAL lets readers (status, reports) run while a writer commits, but it coordinates through
  // shared memory (the -shm file) that network file systems do not provide between nodes:
  // there, a rollback journal is the only safe mode (see FileSystemKind.hpp).
  const bool network = isOnNetworkFileSystem(path_.parent_path());
  Statement pragma = prepare(network ? "PRAGMA journal_mode=DELETE" : "PRAGMA journal_mode=WAL");
  const std::string mode = pragma.step() ? lowerCase(pragma.columnText(0)) : std::string();
  if (mode != (network ? "delete" : "wal"))
    spdlog::warn("database {}: journal mode is '{}' ({} wanted); another process may hold it open", path_.string(),
                 mode, network ? "delete" : "wal");
  // In WAL, NORMAL never corrupts (a power cut can only lose the last commits) and saves an
  // fsync per commit; with a rollback journal, only FULL is safe against power loss.
  exec(mode == "wal" ? "PRAGMA synchronous=NORMAL" : "PRAGMA synchronous=FULL");
}

void Database::checkSchemaNotNewer() {
  const int version = schemaVersion();
  if (version > latestSchemaVersion())
    throw Error("database " + path_.string() + " has schema version " + std::to_string(version) +
                ", newer than version " + std::to_string(latestSchemaVersion()) +
                " that this build of grainbridge knows; use the newer grainbridge that wrote it");
}

void Database::migrate() {
  // Checked without a lock first: an up-to-date database (the common case) must not need
  // the write lock just to be opened, e.g. by the heartbeat while a writer commits.
  if (schemaVersion() == latestSchemaVersion()) return;
  transaction([](Database& db) {
    // Re-read under the write lock: another process may have migrated meanwhile.
    const int from = db.schemaVersion();
    db.checkSchemaNotNewer();
    const auto& scripts = migrations();
    for (int version = from; version < latestSchemaVersion(); ++version) {
      try {
        db.exec(scripts[static_cast<std::size_t>(version)]);
      } catch (const Error& e) {
        throw e.withContext("while migrating database " + db.path_.string() + " from schema version " +
                            std::to_string(version) + " to " + std::to_string(version + 1));
      }
    }
    // user_version is part of the database header, so it commits or rolls back with the DDL.
    db.exec("PRAGMA user_version=" + std::to_string(latestSchemaVersion()));
  });
}

int Database::latestSchemaVersion() { return static_cast<int>(migrations().size()); }

int Database::schemaVersion() {
  Statement pragma = prepare("PRAGMA user_version");
  return pragma.step() ? static_cast<int>(pragma.columnInt64(0)) : 0;
}

void Database::exec(const std::string& sql) {
  GB_ASSERT(connection_ != nullptr, "use of a moved-from Database");
  char* message = nullptr;
  const int rc = sqlite3_exec(connection_, sql.c_str(), nullptr, nullptr, &message);
  if (rc == SQLITE_OK) return;
  const std::string text = message != nullptr ? message : sqlite3_errstr(rc);
  sqlite3_free(message);
  const std::string full = "database " + path_.string() + ": SQL \"" + abbreviated(sql) + "\" failed: " + text;
  if (isBusy(rc)) throw BusyError(full);
  throw Error(full);
}

Statement Database::prepare(const std::string& sql) {
  GB_ASSERT(connection_ != nullptr, "use of a moved-from Database");
  sqlite3_stmt* stmt = nullptr;
  const char* tail = nullptr;
  const int rc = sqlite3_prepare_v2(connection_, sql.data(), static_cast<int>(sql.size()), &stmt, &tail);
  if (rc != SQLITE_OK) {
    sqlite3_finalize(stmt);
    throwError(rc, "cannot prepare SQL \"" + abbreviated(sql) + "\"");
  }
  // A second statement after the first would be silently ignored: that is a bug in our SQL.
  const bool onlyWhitespaceLeft =
      std::all_of(tail, sql.data() + sql.size(), [](unsigned char c) { return std::isspace(c) != 0; });
  if (stmt == nullptr || !onlyWhitespaceLeft) sqlite3_finalize(stmt);
  GB_ASSERT(stmt != nullptr, "prepare() of empty SQL");
  GB_ASSERT(onlyWhitespaceLeft, "prepare() takes one statement (use exec for several): " + sql);
  return Statement(connection_, stmt, sql, path_);
}

std::string Database::integrityCheck() {
  Statement pragma = prepare("PRAGMA integrity_check");
  std::string result;
  while (pragma.step()) {
    if (!result.empty()) result += '\n';
    result += pragma.columnText(0);
  }
  return result;
}

std::int64_t Database::lastInsertRowId() { return sqlite3_last_insert_rowid(connection_); }

int Database::changes() { return sqlite3_changes(connection_); }

std::string Database::journalMode() {
  Statement pragma = prepare("PRAGMA journal_mode");
  return pragma.step() ? lowerCase(pragma.columnText(0)) : std::string();
}

void Database::setBusyTimeout(std::chrono::milliseconds timeout) {
  sqlite3_busy_timeout(connection_, static_cast<int>(timeout.count()));
}

void Database::setBusyRetries(int retries) {
  GB_ASSERT(retries >= 0, "busy retries must be >= 0");
  busyRetries_ = retries;
}

void Database::beginTransaction() {
  GB_ASSERT(connection_ != nullptr, "use of a moved-from Database");
  for (int attempt = 0;; ++attempt) {
    const int rc = sqlite3_exec(connection_, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK) {
      inTransaction_ = true;
      return;
    }
    if (!isBusy(rc)) throwError(rc, "BEGIN IMMEDIATE failed");
    if (attempt >= busyRetries_)
      throwError(rc, "another process holds the write lock: BEGIN IMMEDIATE still busy after " +
                         std::to_string(attempt + 1) + " attempt(s), each waiting the full busy timeout");
    // The busy handler has already waited a full timeout; a pause lets a writer that was
    // starved by others get through before we queue up again.
    std::this_thread::sleep_for(backoff(attempt));
  }
}

void Database::commitTransaction() {
  // Tests SIGKILL here to prove a commit interrupted at the worst moment leaves no trace.
  core::failPoint("db.commit");
  const int rc = sqlite3_exec(connection_, "COMMIT", nullptr, nullptr, nullptr);
  if (rc != SQLITE_OK) throwError(rc, "COMMIT failed");
  inTransaction_ = false;
}

void Database::rollbackTransaction() noexcept {
  inTransaction_ = false;
  // SQLite may already have rolled back by itself (e.g. after SQLITE_FULL or an interrupt);
  // a second ROLLBACK would then fail with "no transaction is active".
  if (connection_ == nullptr || sqlite3_get_autocommit(connection_) != 0) return;
  const int rc = sqlite3_exec(connection_, "ROLLBACK", nullptr, nullptr, nullptr);
  if (rc != SQLITE_OK) spdlog::error("database {}: ROLLBACK failed: {}", path_.string(), sqlite3_errmsg(connection_));
}

}  // namespace grainbridge::db
