// arnoldweb: map.fits, the velocity map as a HEALPix FITS file (output.formats
// = ["hdf5", "fits"]; docs/outputs.md): an empty primary HDU and a binary
// table of one 64-bit integer column COUNTS, one pixel per row in RING order,
// with the keywords of the HEALPix FITS convention (PIXTYPE, ORDERING, NSIDE,
// INDXSCHM, FIRSTPIX, LASTPIX, OBJECT) that healpy.read_map and other HEALPix
// tools read. Written by CFITSIO into memory (no file name is parsed as
// CFITSIO's extended syntax), then put in place atomically like every output.
#include <fitsio.h>

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/atomic_file.hpp"

namespace arnoldweb {
namespace {

// An in-memory FITS file (CFITSIO's memory driver); its bytes once closed.
class MemoryFits {
 public:
  explicit MemoryFits(const std::string& path) : path_(path) {
    fits_create_memfile(&f_, &buffer_, &size_, 2880 * 16, std::realloc, &status_);
    check("create it");
  }
  ~MemoryFits() {
    int ignored = 0;
    if (f_) fits_close_file(f_, &ignored);
    std::free(buffer_);
  }
  MemoryFits(const MemoryFits&) = delete;
  MemoryFits& operator=(const MemoryFits&) = delete;

  fitsfile* get() { return f_; }

  // Throws OutputError naming the file and CFITSIO's message when the last call failed.
  void check(const char* what) {
    if (!status_) return;
    char text[FLEN_STATUS] = {};
    fits_get_errstatus(status_, text);
    throw OutputError(path_, std::string("writing the FITS map failed (") + what + "): CFITSIO: " + text);
  }
  int* status() { return &status_; }

  std::string close() {
    fits_close_file(f_, &status_);
    f_ = nullptr;
    check("close it");
    return std::string(static_cast<const char*>(buffer_), size_);
  }

 private:
  std::string path_;
  fitsfile* f_ = nullptr;
  void* buffer_ = nullptr;
  std::size_t size_ = 0;
  int status_ = 0;
};

template <class T>
void key(MemoryFits& f, const char* name, T value, const char* comment) {
  if constexpr (std::is_same_v<T, const char*>) {
    fits_write_key(f.get(), TSTRING, name, const_cast<char*>(value), comment, f.status());
  } else if constexpr (std::is_same_v<T, double>) {
    fits_write_key(f.get(), TDOUBLE, name, &value, comment, f.status());
  } else {
    long long v = value;
    fits_write_key(f.get(), TLONGLONG, name, &v, comment, f.status());
  }
  f.check(name);
}

}  // namespace

void write_map_fits(const std::string& path, const Plan& plan, const Result& r) {
  const std::size_t npix = r.map.size();
  std::vector<long long> counts(npix);
  for (std::size_t i = 0; i < npix; ++i) {
    if (r.map[i] > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
      throw OutputError(path, "a count of the map does not fit FITS's 64-bit integers (pixel " + std::to_string(i) + ")");
    counts[i] = static_cast<long long>(r.map[i]);
  }
  MemoryFits f(path);
  fits_create_img(f.get(), BYTE_IMG, 0, nullptr, f.status());  // the primary HDU: no image
  f.check("the primary HDU");
  char* names[] = {const_cast<char*>("COUNTS")};
  char* forms[] = {const_cast<char*>("K")};
  char* units[] = {const_cast<char*>("windows")};
  fits_create_tbl(f.get(), BINARY_TBL, static_cast<LONGLONG>(npix), 1, names, forms, units, "VELOCITY_MAP",
                  f.status());
  f.check("the table");
  key(f, "PIXTYPE", "HEALPIX", "HEALPix pixelisation");
  key(f, "ORDERING", "RING", "pixel ordering scheme");
  key(f, "NSIDE", static_cast<long long>(plan.scene.nside), "resolution parameter of the map");
  key(f, "FIRSTPIX", 0LL, "first pixel (0 based)");
  key(f, "LASTPIX", static_cast<long long>(npix) - 1, "last pixel (0 based)");
  key(f, "INDXSCHM", "IMPLICIT", "the row is the pixel index");
  key(f, "OBJECT", "FULLSKY", "every pixel of the sphere");
  key(f, "ENERGY", plan.scene.energy, "model.energy");
  key(f, "AVERAGE", plan.scene.average, "run.average: averaging window in T");
  key(f, "WINDOWS", static_cast<long long>(plan.windows), "windows per trajectory");
  const std::string digest = digest_map(r);
  key(f, "MAPDIGST", digest.c_str(), "XXH3-128 of the counts (summary.json: digests.map)");
  fits_write_comment(f.get(), "Counts of averaged velocity directions V = (X(t + dt) - X(t)) / dt "
                              "per HEALPix pixel, written by arnoldweb (map.h5 holds the same counts).",
                     f.status());
  f.check("a comment");
  fits_write_col(f.get(), TLONGLONG, 1, 1, 1, static_cast<LONGLONG>(npix), counts.data(), f.status());
  f.check("the counts");
  detail::write_file_atomically(path, f.close());
}

}  // namespace arnoldweb
