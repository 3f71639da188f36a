// arnoldweb: checkpoint images (checkpoint_image.hpp, checkpoint.hpp).
#include "run/checkpoint_image.hpp"

#include <xxhash.h>

#include <cstdio>
#include <map>
#include <sstream>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/run.hpp"
#include "arnoldweb/version.hpp"
#include "run/byte_stream.hpp"

namespace arnoldweb {
namespace detail {
namespace {

constexpr char kMagic[8] = {'A', 'W', 'C', 'K', 'P', 'T', '\n', '\0'};
constexpr std::uint64_t kFormat = 1;

}  // namespace

std::string write_checkpoint(const CheckpointInfo& info, const std::vector<std::string>& parts) {
  ByteWriter w;
  w.bytes().append(kMagic, 8);
  w.u64(kFormat);
  w.text(info.version);
  w.text(info.identity);
  w.text(info.scene_file);
  w.text(info.scene_text);
  w.u64(info.overrides.size());
  for (std::size_t k = 0; k < info.overrides.size(); ++k) {
    w.text(info.overrides[k]);
    w.text(k < info.override_labels.size() ? info.override_labels[k] : std::string());
  }
  w.u64(info.parts);
  w.u64(info.completed);
  w.u64(info.trajectories);
  w.u64(parts.size());
  for (const auto& p : parts) w.text(p);
  const std::uint64_t h = XXH64(w.bytes().data(), w.bytes().size(), 0);
  w.u64(h);
  return std::move(w.bytes());
}

void read_checkpoint(const std::string& image, const std::string& path, CheckpointInfo& info,
                     std::vector<std::string>& parts) {
  if (image.size() < 8 + 8 + 8 || image.compare(0, 8, std::string(kMagic, 8)) != 0)
    throw CheckpointError(path, "not an arnoldweb checkpoint (it does not start with the checkpoint signature)");
  std::uint64_t stored = 0;
  for (int b = 0; b < 8; ++b)
    stored |= static_cast<std::uint64_t>(static_cast<unsigned char>(image[image.size() - 8 + b])) << (8 * b);
  if (XXH64(image.data(), image.size() - 8, 0) != stored)
    throw CheckpointError(path, "the checkpoint is damaged (its checksum does not match: truncated or altered); "
                                "remove it to start the run afresh");
  try {
    const std::string body = image.substr(8, image.size() - 16);
    ByteReader in(body);
    const std::uint64_t format = in.u64();
    if (format != kFormat)
      throw CheckpointError(path, "checkpoint format " + std::to_string(format) + " is not the format " +
                                      std::to_string(kFormat) + " of arnoldweb " ARNOLDWEB_VERSION);
    info.version = in.text();
    info.identity = in.text();
    info.scene_file = in.text();
    info.scene_text = in.text();
    const std::uint64_t n = in.u64();
    info.overrides.clear();
    info.override_labels.clear();
    for (std::uint64_t k = 0; k < n; ++k) {
      info.overrides.push_back(in.text());
      info.override_labels.push_back(in.text());
    }
    info.parts = in.u64();
    info.completed = in.u64();
    info.trajectories = in.u64();
    const std::uint64_t begun = in.u64();
    parts.clear();
    for (std::uint64_t k = 0; k < begun; ++k) parts.push_back(in.text());
    info.parts_begun = begun;
    if (!in.at_end()) throw std::runtime_error("data after the end");
    if (begun == 0 || begun > info.parts) throw std::runtime_error("a count of parts that cannot be");
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const CheckpointError*>(&e)) throw;
    throw CheckpointError(path, std::string("the checkpoint is damaged (") + e.what() + ")");
  }
}

}  // namespace detail

CheckpointInfo read_checkpoint_info(const std::string& image, const std::string& path) {
  CheckpointInfo info;
  std::vector<std::string> parts;
  detail::read_checkpoint(image, path, info, parts);
  return info;
}

namespace detail {
namespace {

// A scene's TOML as "[table] key" -> value ("not set" for a key without one).
std::map<std::string, std::string> toml_values(const std::string& toml) {
  std::map<std::string, std::string> values;
  std::istringstream in(toml);
  std::string line, table;
  const std::string not_set = " is not set";
  int arrays = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '[') {
      table = line;
      if (line.compare(0, 2, "[[") == 0) table += " " + std::to_string(arrays++);  // each [[panel]] its own
    } else if (line[0] == '#') {
      if (table.empty() || line.size() < 2 + not_set.size() ||
          line.compare(line.size() - not_set.size(), not_set.size(), not_set) != 0)
        continue;  // the header's comments
      values[table + " " + line.substr(2, line.size() - 2 - not_set.size())] = "not set";
    } else if (const std::size_t eq = line.find(" = "); eq != std::string::npos) {
      values[table + " " + line.substr(0, eq)] = line.substr(eq + 3);
    }
  }
  return values;
}

}  // namespace

std::string values_apart_from_defaults(const Scene& scene) {
  const Scene defaults;
  Scene s = scene;
  s.device = defaults.device;
  s.output_dir = defaults.output_dir;
  s.checkpoint_every = defaults.checkpoint_every;
  s.file.clear();  // comments of to_toml(): how the values were given, not what they are
  s.overrides.clear();
  s.override_labels.clear();
  const auto values = toml_values(s.to_toml()), default_values = toml_values(defaults.to_toml());
  std::string text;
  for (const auto& [key, value] : values) {
    const auto d = default_values.find(key);
    if (d == default_values.end() || d->second != value) text += key + " = " + value + "\n";
  }
  return text;
}

}  // namespace detail

std::string job_identity(const Job& job) {
  XXH3_state_t* st = XXH3_createState();
  XXH3_128bits_reset(st);
  for (const JobPart& part : job.parts) {
    const std::string text = part.name + "\n" + detail::values_apart_from_defaults(part.plan.scene);
    XXH3_128bits_update(st, text.data(), text.size());
  }
  const XXH128_hash_t h = XXH3_128bits_digest(st);
  XXH3_freeState(st);
  char buf[33];
  std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return buf;
}

}  // namespace arnoldweb
