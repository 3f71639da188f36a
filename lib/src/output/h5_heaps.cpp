// arnoldweb: global heap collections and local heaps walked as HDF5 1.10.8 walks them (h5_heaps.hpp).
#include "output/h5_heaps.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_set>

namespace arnoldweb::detail {
namespace {

constexpr char kSignature[] = "\x89HDF\r\n\x1a\n";
constexpr std::size_t kPiece = 1 << 20;
constexpr std::uint64_t kFreeNull = 1;  // H5HL_FREE_NULL: the end of a local heap's free list

std::uint64_t little_endian(const std::string& b, std::size_t at, std::size_t bytes) {
  std::uint64_t v = 0;
  for (std::size_t k = bytes; k-- > 0;) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
  return v;
}

// What the superblock (at 0, 512, 1024, ...) says of the file's addresses: where they count
// from and the sizes of offsets and lengths (8 and 8 from 0 without one).
struct Addressing {
  std::uint64_t base = 0;
  std::size_t offsets = 8, lengths = 8;
};

std::size_t size_field(const std::string& b, std::size_t at) {
  const std::size_t n = static_cast<unsigned char>(b[at]);
  return n == 2 || n == 4 || n == 8 ? n : 8;
}

Addressing addressing(const ReadAt& read, std::uint64_t size) {
  for (std::uint64_t at = 0; at + 16 <= size; at = at ? 2 * at : 512) {
    const std::string b = read(at, 16);
    if (b.size() < 16 || b.compare(0, 8, kSignature, 8) != 0) continue;
    const bool v2 = b[8] >= 2;
    return {at, size_field(b, v2 ? 9 : 13), size_field(b, v2 ? 10 : 14)};
  }
  return {};
}

// The collection at `at`, walked as H5HG__cache_heap_deserialize walks it.
std::string collection_problem(const ReadAt& read, std::uint64_t at, std::uint64_t size, const Addressing& a) {
  const std::size_t header = 8 + a.lengths, object_header = 8 + a.lengths;
  const std::string head = read(at, header);
  if (head.size() < header) return "";
  const std::uint64_t collection = little_endian(head, 8, a.lengths);
  // HDF5 reads the collection whole: one that does not fit the file is an error there, not a walk
  if (collection <= header || collection > size - at) return "";
  const std::string c = read(at, static_cast<std::size_t>(collection));
  for (std::uint64_t p = header; p + object_header <= c.size();) {
    const std::uint64_t index = little_endian(c, p, 2), object = little_endian(c, p + 8, a.lengths);
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

// The local heap at `at`: its free list followed as H5HL__fl_deserialize follows it, which
// stops with an error at a block outside the data, a next offset of 0 or a block that overruns
// the data, and otherwise allocates a node per block until the list ends.
std::string local_heap_problem(const ReadAt& read, std::uint64_t at, std::uint64_t size, const Addressing& a) {
  const std::size_t L = a.lengths, prefix = 8 + 2 * L + a.offsets;
  const std::string head = read(at, prefix);
  if (head.size() < prefix || head[4] != 0) return "";  // version 0 only, as HDF5
  const std::uint64_t data_size = little_endian(head, 8, L), first = little_endian(head, 8 + L, L);
  const std::uint64_t data = a.base + little_endian(head, 8 + 2 * L, a.offsets);
  if (data < a.base || data > size || data_size > size - data) return "";  // HDF5 cannot read it: an error
  std::unordered_set<std::uint64_t> passed;
  for (std::uint64_t block = first; block != kFreeNull;) {
    if (block >= data_size || data_size - block < 2 * L) return "";
    if (!passed.insert(block).second)
      return "holds a local heap at byte " + std::to_string(at) + " whose free list returns to its block at offset " +
             std::to_string(block) + ": HDF5 1.10.8 would take memory for ever reading it (a damaged file)";
    const std::string b = read(data + block, 2 * L);
    if (b.size() < 2 * L) return "";
    const std::uint64_t next = little_endian(b, 0, L), bytes = little_endian(b, L, L);
    if (next == 0 || bytes > data_size - block) return "";
    block = next;
  }
  return "";
}

}  // namespace

std::string heap_problem(const ReadAt& read, std::uint64_t size) {
  const Addressing a = addressing(read, size);
  struct Kind {
    const char* signature;
    std::string (*problem)(const ReadAt&, std::uint64_t, std::uint64_t, const Addressing&);
  };
  const Kind kinds[] = {{"GCOL", collection_problem}, {"HEAP", local_heap_problem}};
  for (std::uint64_t at = 0; at < size; at += kPiece) {
    const std::string piece = read(at, kPiece + 3);  // 3 more: a signature across two pieces
    const std::size_t end = std::min(piece.size(), kPiece);
    for (const Kind& kind : kinds)
      for (std::size_t k = 0; k < end; ++k) {
        const void* hit = std::memchr(piece.data() + k, kind.signature[0], end - k);
        if (!hit) break;
        k = static_cast<std::size_t>(static_cast<const char*>(hit) - piece.data());
        if (k + 4 <= piece.size() && piece.compare(k, 4, kind.signature) == 0)
          if (std::string why = kind.problem(read, at + k, size, a); !why.empty()) return why;
      }
  }
  return "";
}

}  // namespace arnoldweb::detail
