// arnoldweb: digests of the files of an output directory (file_digest.hpp).
#include "output/file_digest.hpp"

#include <unistd.h>
#include <xxhash.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "os/regular_file.hpp"

namespace arnoldweb::detail {
namespace {

thread_local DigestLedger* t_ledger = nullptr;

std::string key_of(const std::string& path) { return std::filesystem::path(path).lexically_normal().string(); }

FileDigest digest_of(const XXH128_hash_t& h, std::uint64_t bytes) {
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return {bytes, hex};
}

}  // namespace

FileDigest digest_bytes(const std::string& bytes) { return digest_of(XXH3_128bits(bytes.data(), bytes.size()), bytes.size()); }

FileDigest digest_file(int fd, const std::string& path) {
  const std::unique_ptr<XXH3_state_t, XXH_errorcode (*)(XXH3_state_t*)> state(XXH3_createState(), XXH3_freeState);
  if (!state || XXH3_128bits_reset(state.get()) != XXH_OK) throw OutputError(path, "cannot digest it (out of memory)");
  std::vector<char> buf(1 << 20);
  std::uint64_t total = 0;
  for (;;) {
    const ssize_t n = ::pread(fd, buf.data(), buf.size(), static_cast<off_t>(total));
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw OutputError(path, std::string("cannot read it for its digest: ") + std::strerror(errno));
    }
    XXH3_128bits_update(state.get(), buf.data(), static_cast<std::size_t>(n));
    total += static_cast<std::uint64_t>(n);
  }
  return digest_of(XXH3_128bits_digest(state.get()), total);
}

nlohmann::ordered_json file_digest_json(const FileDigest& d) { return {{"bytes", d.bytes}, {"xxh3_128", d.xxh3_128}}; }

nlohmann::ordered_json file_digests_json(const FileDigests& digests) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [name, d] : digests) j[name] = file_digest_json(d);
  return j;
}

DigestLedger::DigestLedger() : previous_(t_ledger) { t_ledger = this; }
DigestLedger::~DigestLedger() { t_ledger = previous_; }

void DigestLedger::record(const std::string& path, const FileDigest& digest) {
  if (t_ledger) t_ledger->by_path_[key_of(path)] = digest;
}

FileDigests DigestLedger::of(const std::string& dir, const std::vector<std::string>& names) const {
  FileDigests out;
  for (const std::string& name : names) {
    const std::string path = (std::filesystem::path(dir) / name).string();
    const auto it = by_path_.find(key_of(path));
    if (it != by_path_.end()) {
      out[name] = it->second;
      continue;
    }
    // not written through the atomic writers: its bytes as they are now
    const RegularFile f = read_regular_file(path, UINT64_MAX);
    if (!f.why.empty()) throw OutputError(path, "cannot read it back for its digest: " + f.why);
    out[name] = digest_bytes(f.bytes);
  }
  return out;
}

}  // namespace arnoldweb::detail
