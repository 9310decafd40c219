#include "core/Sha256.hpp"

#include <openssl/evp.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "core/Error.hpp"

namespace grainbridge::core {

namespace {
struct MdCtxDeleter {
  void operator()(EVP_MD_CTX* c) const { EVP_MD_CTX_free(c); }
};

class Hasher {
 public:
  Hasher() : ctx_(EVP_MD_CTX_new()) {
    GB_ASSERT(ctx_ && EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) == 1, "EVP sha256 init failed");
  }
  void update(const void* data, std::size_t n) { EVP_DigestUpdate(ctx_.get(), data, n); }
  std::string hex() {
    std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
    unsigned int len = 0;
    EVP_DigestFinal_ex(ctx_.get(), digest.data(), &len);
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out(2 * len, '0');
    for (unsigned int i = 0; i < len; ++i) {
      out[2 * i] = kHex[digest[i] >> 4];
      out[2 * i + 1] = kHex[digest[i] & 0xF];
    }
    return out;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, MdCtxDeleter> ctx_;
};
}  // namespace

std::string sha256Hex(std::string_view data) {
  Hasher h;
  h.update(data.data(), data.size());
  return h.hex();
}

std::string sha256File(const std::filesystem::path& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw Error("cannot read '" + path.string() + "' to hash it: " + std::strerror(errno));
  Hasher h;
  std::array<char, 1 << 16> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), f.get())) > 0) h.update(buf.data(), n);
  if (std::ferror(f.get())) throw Error("error reading '" + path.string() + "' to hash it");
  return h.hex();
}

std::string sha256FileOncePerVersion(const std::filesystem::path& path) {
  using Version = std::tuple<std::string, std::uintmax_t, std::filesystem::file_time_type::rep>;
  static std::mutex mutex;
  static std::map<Version, std::string> digests;
  // Any error reading the version: hash without the memo and let the reader name the problem.
  std::error_code pathError, sizeError, timeError;
  const auto canonical = std::filesystem::canonical(path, pathError);
  if (pathError) return sha256File(path);
  const auto size = std::filesystem::file_size(canonical, sizeError);
  const auto written = std::filesystem::last_write_time(canonical, timeError);
  if (sizeError || timeError) return sha256File(path);
  const Version version{canonical.string(), size, written.time_since_epoch().count()};
  {
    const std::lock_guard lock(mutex);
    if (const auto it = digests.find(version); it != digests.end()) return it->second;
  }
  std::string digest = sha256File(canonical);
  const std::lock_guard lock(mutex);
  return digests.emplace(version, std::move(digest)).first->second;
}

}  // namespace grainbridge::core
