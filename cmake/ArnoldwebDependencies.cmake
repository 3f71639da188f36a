# Every dependency comes from Debian's packages (see README.md, .ci/run).
find_package(OpenCL REQUIRED)
find_package(Boost 1.74 REQUIRED)            # Boost.Compute (header-only)
find_package(tomlplusplus REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(PkgConfig REQUIRED)
# cairo renders the PNG pictures; without it (e.g. on a bare GPU node) the
# library still runs and writes data, and `arnoldweb render` can draw the
# pictures later on a machine that has it.
pkg_check_modules(CAIRO IMPORTED_TARGET cairo)
# CFITSIO writes map.fits, the HEALPix FITS map (output.formats; Debian: libcfitsio-dev); without
# it (e.g. a bare GPU node) output.formats = ["hdf5", "fits"] is refused when the scene is read.
pkg_check_modules(CFITSIO IMPORTED_TARGET cfitsio)
if(NOT CFITSIO_FOUND)
  message(STATUS "CFITSIO not found: this build refuses output.formats \"fits\" (Debian: libcfitsio-dev)")
endif()
find_path(XXHASH_INCLUDE_DIR xxhash.h DOC "xxHash (Debian: libxxhash-dev)" REQUIRED)
find_library(XXHASH_LIBRARY xxhash DOC "xxHash (Debian: libxxhash-dev)" REQUIRED)
add_library(arnoldweb_xxhash INTERFACE IMPORTED)
target_include_directories(arnoldweb_xxhash INTERFACE ${XXHASH_INCLUDE_DIR})
target_link_libraries(arnoldweb_xxhash INTERFACE ${XXHASH_LIBRARY})
find_path(RANDOM123_INCLUDE_DIR Random123/philox.h
          DOC "Random123 headers (Debian: librandom123-dev)" REQUIRED)
if(NOT EXISTS "${Boost_INCLUDE_DIRS}/boost/compute.hpp")
  message(FATAL_ERROR "Boost.Compute not found under ${Boost_INCLUDE_DIRS} (Debian: libboost-dev)")
endif()

set(ARNOLDWEB_HAVE_CUDA OFF)
if(ARNOLDWEB_CUDA)
  find_package(CUDAToolkit QUIET)
  if(CUDAToolkit_FOUND AND TARGET CUDA::nvrtc AND TARGET CUDA::cudart_static)
    set(ARNOLDWEB_HAVE_CUDA ON)
    message(STATUS "arnoldweb: CUDA backend enabled (CUDA ${CUDAToolkit_VERSION}, NVRTC)")
  else()
    message(STATUS "arnoldweb: CUDA toolkit not found, CUDA backend disabled")
  endif()
endif()
