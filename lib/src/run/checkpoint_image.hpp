// arnoldweb: the byte layout of a checkpoint (checkpoint.hpp): magic, format
// number, header fields, the parts' reduction images, XXH64 of all of it.
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/checkpoint.hpp"

namespace arnoldweb::detail {

std::string write_checkpoint(const CheckpointInfo& info, const std::vector<std::string>& part_images);
// Checks integrity (CheckpointError naming `path`); fills info and the part images.
void read_checkpoint(const std::string& image, const std::string& path, CheckpointInfo& info,
                     std::vector<std::string>& part_images);

}  // namespace arnoldweb::detail
