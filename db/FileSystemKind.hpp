#pragma once
// Which journal mode a database file can safely use depends on the file system under it.
// WAL coordinates readers and writers through a memory-mapped "-shm" file, i.e. shared memory
// between processes of ONE machine; network and cluster file systems (NFS, SMB, Lustre, GPFS,
// BeeGFS, ...) neither share that memory between nodes nor keep mmap coherent, so WAL there
// can corrupt the database. They get a rollback journal (DELETE) instead, which needs only
// POSIX byte-range locks.
#include <cstdint>
#include <filesystem>

namespace grainbridge::db {

// True for statfs f_type magic numbers of network / cluster file systems.
bool isNetworkFileSystemMagic(std::uint64_t fsType);
// statfs of `dir` (which must exist); false if statfs fails, since a local disk is the
// common case and an unknown FS should not silently cost the WAL concurrency.
bool isOnNetworkFileSystem(const std::filesystem::path& dir);

}  // namespace grainbridge::db
