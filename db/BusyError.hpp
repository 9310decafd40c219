#pragma once
// SQLITE_BUSY gets its own error type because callers treat it differently from every other
// database failure: it means "another process holds the write lock longer than our busy
// timeout", which a periodic writer (the lease heartbeat) simply retries on its next beat,
// whereas a constraint violation or an I/O error is a real failure.
#include <string>

#include "core/Error.hpp"

namespace grainbridge::db {

class BusyError : public grainbridge::Error {
 public:
  explicit BusyError(const std::string& what);
};

}  // namespace grainbridge::db
