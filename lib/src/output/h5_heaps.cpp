// arnoldweb: global heap collections walked as HDF5 1.10.8 walks them (h5_global_heaps.hpp).
#include "output/h5_global_heaps.hpp"

#include <algorithm>
#include <cstring>

namespace arnoldweb::detail {
namespace {

constexpr char kSignature[] = "\x89HDF\r\n\x1a\n";
constexpr std::size_t kPiece = 1 << 20;

std::uint64_t little_endian(const std::string& b, std::size_t at, std::size_t bytes) {
  std::uint64_t v = 0;
  for (std::size_t k = bytes; k-- > 0;) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
  return v;
}

// The size of lengths in the superblock (at 0, 512, 1024, ...), 8 without one.
std::size_t size_of_lengths(const ReadAt& read, std::uint64_t size) {
  for (std::uint64_t at = 0; at + 16 <= size; at = at ? 2 * at : 512) {
    const std::string b = read(at, 16);
    if (b.size() < 16 || b.compare(0, 8, kSignature, 8) != 0) continue;
    const std::size_t n = static_cast<unsigned char>(b[b[8] >= 2 ? 10 : 14]);
    return n == 2 || n == 4 || n == 8 ? n : 8;
  }
  return 8;
}

// The collection at `at`, walked as H5HG__cache_heap_deserialize walks it.
std::string collection_problem(const ReadAt& read, std::uint64_t at, std::uint64_t size, std::size_t lengths) {
  const std::size_t header = 8 + lengths, object_header = 8 + lengths;
  const std::string head = read(at, header);
  if (head.size() < header) return "";
  const std::uint64_t collection = little_endian(head, 8, lengths);
  // HDF5 reads the collection whole: one that does not fit the file is an error there, not a walk
  if (collection <= header || collection > size - at) return "";
  const std::string c = read(at, static_cast<std::size_t>(collection));
  for (std::uint64_t p = header; p + object_header <= c.size();) {
    const std::uint64_t index = little_endian(c, p, 2), object = little_endian(c, p + 8, lengths);
    const std::uint64_t begin = p;
    // as HDF5: the free space (index 0) takes its size, another object its header and aligned data
    const std::uint64_t step = index == 0 ? object : object_header + ((object + 7) & ~std::uint64_t{7});
    if (step == 0 || step > ~std::uint64_t{0} - (std::uint64_t{1} << 48))
      return "holds a global heap collection at byte " + std::to_string(at) + " whose object " +
             std::to_string(index) + " has a size (" + std::to_string(object) +
             ") on which HDF5 1.10.8 loops for ever (a damaged file)";
    p = begin + step;
  }
  return "";
}

}  // namespace

std::string global_heap_problem(const ReadAt& read, std::uint64_t size) {
  const std::size_t lengths = size_of_lengths(read, size);
  for (std::uint64_t at = 0; at < size; at += kPiece) {
    const std::string piece = read(at, kPiece + 3);  // 3 more: a signature across two pieces
    for (std::size_t k = 0; k + 4 <= piece.size() && k < kPiece; ++k) {
      const void* hit = std::memchr(piece.data() + k, 'G', std::min(piece.size(), kPiece) - k);
      if (!hit) break;
      k = static_cast<std::size_t>(static_cast<const char*>(hit) - piece.data());
      if (k + 4 <= piece.size() && piece.compare(k, 4, "GCOL") == 0)
        if (std::string why = collection_problem(read, at + k, size, lengths); !why.empty()) return why;
    }
  }
  return "";
}

}  // namespace arnoldweb::detail
