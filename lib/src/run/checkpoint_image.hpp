// arnoldweb: the byte layout of a checkpoint (checkpoint.hpp): magic, format
// number, header fields, the parts' reduction images, XXH64 of all of it.
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/checkpoint.hpp"
#include "arnoldweb/scene.hpp"

namespace arnoldweb::detail {

// The identity's text of one scene: its values that differ from the defaults
// (Scene{}), one "[table] key = value" line each (a panel's too); the keys that do not change results (run.device, output.dir,
// run.checkpoint_every) left out. A key that a later arnoldweb adds, at its
// default, leaves it unchanged: a long campaign's checkpoint resumes across
// such versions.
std::string values_apart_from_defaults(const Scene& scene);

std::string write_checkpoint(const CheckpointInfo& info, const std::vector<std::string>& part_images);
// Checks integrity (CheckpointError naming `path`); fills info and the part images.
void read_checkpoint(const std::string& image, const std::string& path, CheckpointInfo& info,
                     std::vector<std::string>& part_images);

}  // namespace arnoldweb::detail
