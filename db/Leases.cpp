#include "db/Leases.hpp"

#include <unistd.h>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "db/Clock.hpp"
#include "db/Database.hpp"

namespace grainbridge::db {

namespace {
// Statements below compare all three identity columns: pid alone may have been reused.
constexpr const char* kIsMine = "key=? AND host=? AND pid=? AND pid_start=?";

void bindIdentity(Statement& statement, int first, const std::string& key, const LeaseHolder& me) {
  statement.bind(first, key).bind(first + 1, me.host).bind(first + 2, me.pid).bind(first + 3, me.pidStart);
}

void bindRunId(Statement& statement, int index, std::int64_t runId) {
  if (runId == 0)
    statement.bindNull(index);
  else
    statement.bind(index, runId);
}
}  // namespace

std::string hostName() {
  char buffer[256] = {};
  if (::gethostname(buffer, sizeof buffer - 1) != 0) return "localhost";
  return buffer;
}

std::optional<std::string> liveProcessStartTime(std::int64_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!in || !std::getline(in, stat)) return std::nullopt;
  // Field 2 (comm) is parenthesised and may itself contain spaces and ')': parse after the
  // LAST ')'. What follows is field 3 (state), so field 22 is the 20th token.
  const std::size_t close = stat.rfind(')');
  if (close == std::string::npos) return std::nullopt;
  std::istringstream fields(stat.substr(close + 1));
  std::string state, token;
  fields >> state;
  for (int field = 4; field <= 22; ++field)
    if (!(fields >> token)) return std::nullopt;
  // A zombie keeps its /proc entry until reaped but will never touch its lease again.
  if (state == "Z" || state == "X" || state == "x") return std::nullopt;
  return token;
}

LeaseHolder currentProcessHolder(std::int64_t runId) {
  const std::int64_t pid = ::getpid();
  const std::optional<std::string> start = liveProcessStartTime(pid);
  if (!start) throw Error("cannot read /proc/" + std::to_string(pid) + "/stat (is /proc mounted?): leases need it");
  return LeaseHolder{hostName(), pid, *start, runId};
}

bool isHolderAlive(const LeaseHolder& holder, const std::string& heartbeatAt, std::chrono::seconds staleAfter) {
  if (holder.host == hostName()) {
    const std::optional<std::string> start = liveProcessStartTime(holder.pid);
    return start && *start == holder.pidStart;
  }
  // An unreadable heartbeat cannot prove the holder alive, and a lease nobody can judge
  // would block its stage forever.
  const auto beat = parseUtc(heartbeatAt);
  return beat && std::chrono::system_clock::now() - *beat < staleAfter;
}

Leases::Leases(Database& db) : db_(db) {}

Leases::ClaimResult Leases::claim(const std::string& key, const LeaseHolder& me, std::chrono::seconds staleAfter) {
  // Each step is one atomic statement, so this is safe even outside a transaction; the loop
  // only repeats if another process changed the row between our read and our write.
  constexpr int kAttempts = 8;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const std::string now = nowUtc();
    Statement insert = db_.prepare(
        "INSERT INTO leases(key, run_id, host, pid, pid_start, claimed_at, heartbeat_at) VALUES(?,?,?,?,?,?,?) "
        "ON CONFLICT(key) DO NOTHING");
    insert.bind(1, key).bind(3, me.host).bind(4, me.pid).bind(5, me.pidStart).bind(6, now).bind(7, now);
    bindRunId(insert, 2, me.runId);
    insert.step();
    if (db_.changes() == 1) return {true, std::nullopt};

    Statement read = db_.prepare("SELECT host, pid, pid_start, run_id, heartbeat_at FROM leases WHERE key=?");
    read.bind(1, key);
    if (!read.step()) continue;  // released meanwhile: try inserting again
    const LeaseHolder current{read.columnText(0), read.columnInt64(1), read.columnText(2), read.columnInt64(3)};
    const std::string heartbeatAt = read.columnText(4);

    if (current.sameProcess(me)) {
      // Claiming again what we hold (e.g. to attach the run id) just refreshes it.
      Statement refresh =
          db_.prepare(std::string("UPDATE leases SET heartbeat_at=?, run_id=COALESCE(?, run_id) WHERE ") + kIsMine);
      refresh.bind(1, now);
      bindRunId(refresh, 2, me.runId);
      bindIdentity(refresh, 3, key, me);
      refresh.step();
      if (db_.changes() == 1) return {true, std::nullopt};
      continue;
    }
    if (isHolderAlive(current, heartbeatAt, staleAfter)) return {false, current};

    // Take over only if the row is still exactly the dead holder's (compare-and-swap), so
    // two processes that both saw it dead cannot both win.
    Statement takeOver = db_.prepare(
        "UPDATE leases SET run_id=?, host=?, pid=?, pid_start=?, claimed_at=?, heartbeat_at=? "
        "WHERE key=? AND host=? AND pid=? AND pid_start=? AND heartbeat_at=?");
    bindRunId(takeOver, 1, me.runId);
    takeOver.bind(2, me.host).bind(3, me.pid).bind(4, me.pidStart).bind(5, now).bind(6, now);
    bindIdentity(takeOver, 7, key, current);
    takeOver.bind(11, heartbeatAt);
    takeOver.step();
    if (db_.changes() == 1) {
      spdlog::info("lease {}: took over from {}:{}, which is no longer running", key, current.host, current.pid);
      return {true, std::nullopt};
    }
  }
  throw Error("database " + db_.path().string() + ": lease " + key + " kept changing hands during " +
              std::to_string(kAttempts) + " claim attempts");
}

void Leases::heartbeat(const std::string& key, const LeaseHolder& me) {
  Statement update = db_.prepare(std::string("UPDATE leases SET heartbeat_at=? WHERE ") + kIsMine);
  update.bind(1, nowUtc());
  bindIdentity(update, 2, key, me);
  update.step();
}

void Leases::release(const std::string& key, const LeaseHolder& me) {
  Statement remove = db_.prepare(std::string("DELETE FROM leases WHERE ") + kIsMine);
  bindIdentity(remove, 1, key, me);
  remove.step();
}

bool Leases::setRun(const std::string& key, const LeaseHolder& me, std::int64_t runId) {
  Statement update = db_.prepare(std::string("UPDATE leases SET run_id=? WHERE ") + kIsMine);
  bindRunId(update, 1, runId);
  bindIdentity(update, 2, key, me);
  update.step();
  return db_.changes() == 1;
}

std::optional<LeaseHolder> Leases::holder(const std::string& key) {
  Statement read = db_.prepare("SELECT host, pid, pid_start, run_id FROM leases WHERE key=?");
  read.bind(1, key);
  if (!read.step()) return std::nullopt;
  return LeaseHolder{read.columnText(0), read.columnInt64(1), read.columnText(2), read.columnInt64(3)};
}

std::vector<std::pair<std::string, LeaseHolder>> Leases::deadLeases(std::chrono::seconds staleAfter) {
  Statement read = db_.prepare("SELECT key, host, pid, pid_start, run_id, heartbeat_at FROM leases ORDER BY key");
  std::vector<std::pair<std::string, LeaseHolder>> dead;
  while (read.step()) {
    LeaseHolder holder{read.columnText(1), read.columnInt64(2), read.columnText(3), read.columnInt64(4)};
    if (!isHolderAlive(holder, read.columnText(5), staleAfter))
      dead.emplace_back(read.columnText(0), std::move(holder));
  }
  return dead;
}

}  // namespace grainbridge::db
