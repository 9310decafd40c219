#include "db/FileSystemKind.hpp"

#include <sys/vfs.h>
#include <array>

namespace grainbridge::db {

bool isNetworkFileSystemMagic(std::uint64_t fsType) {
  // From linux/magic.h and the vendors' documentation. FUSE (0x65735546) is left out on
  // purpose: it is as often a local overlay (rootless containers) as sshfs, and mis-flagging
  // a local disk only costs WAL, while sshfs users can put the database elsewhere.
  static constexpr std::array<std::uint64_t, 14> kNetwork = {
      0x6969,      // NFS
      0x517B,      // SMB (smbfs)
      0xFF534D42,  // CIFS
      0xFE534D42,  // SMB2
      0x0BD00BD0,  // Lustre
      0x47504653,  // GPFS / IBM Spectrum Scale
      0x19830326,  // BeeGFS
      0x00C36400,  // CephFS
      0x5346414F,  // AFS
      0x6B414653,  // kAFS
      0x01021997,  // 9P (v9fs)
      0x01161970,  // GFS2
      0x7461636F,  // OCFS2
      0xAAD7AAEA,  // PanFS
  };
  for (std::uint64_t magic : kNetwork)
    if (fsType == magic) return true;
  return false;
}

bool isOnNetworkFileSystem(const std::filesystem::path& dir) {
  struct statfs info {};
  if (::statfs(dir.c_str(), &info) != 0) return false;
  // f_type is a signed word on some ABIs; the magic numbers are 32-bit patterns.
  return isNetworkFileSystemMagic(static_cast<std::uint64_t>(info.f_type) & 0xFFFFFFFFu);
}

}  // namespace grainbridge::db
