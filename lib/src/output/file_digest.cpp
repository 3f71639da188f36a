// arnoldweb: digests of the files of an output directory (file_digest.hpp).
#include "output/file_digest.hpp"

#include <xxhash.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "os/regular_file.hpp"

namespace arnoldweb::detail {
namespace {

thread_local DigestLedger* t_ledger = nullptr;

std::string key_of(const std::string& path) { return std::filesystem::path(path).lexically_normal().string(); }

}  // namespace

FileDigest digest_bytes(const std::string& bytes) {
  const XXH128_hash_t h = XXH3_128bits(bytes.data(), bytes.size());
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return {bytes.size(), hex};
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
