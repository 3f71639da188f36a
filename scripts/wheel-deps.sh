#!/usr/bin/env bash
# The two C libraries of the binary wheel that Debian links with network and
# crypto libraries, built for the wheel without them (docs/python.md, "What
# the wheel carries"): Debian's HDF5 links libcurl for its ROS3 driver (reading
# HDF5 from S3), which drags OpenSSL, GnuTLS, Kerberos, LDAP, SSH, RTMP and
# more into the wheel; Debian's CFITSIO links libcurl-gnutls for remote FITS
# files. arnoldweb reads and writes local files only, and nobody would update
# those libraries inside a wheel.
#
# Each is built from the upstream source Debian ships for the version of this
# machine's -dev package (its .orig tarball, fetched by apt from Debian's
# source index, whose signature and checksums apt checks), configured as
# Debian's debian/rules configures it, minus what arnoldweb does not use:
#   HDF5 1.10:   threadsafe, zlib, v18 API, as Debian; without ROS3 (libcurl),
#                szip, Fortran, C++, Java, the high-level library, tools, tests.
#   CFITSIO 4.2: reentrant; without curl and bzip2.
# Debian's patches (other architectures, the Hurd, packaging, Java) are not
# applied. The result goes to build-wheel-deps/prefix (kept; rebuilt only when
# a version or this script changes; ccache serves a rebuild). Prints the prefix last.
#
#   scripts/wheel-deps.sh                 build (or reuse) them
#   WHEEL_DEPS_DIR=dir scripts/wheel-deps.sh
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
deps=${WHEEL_DEPS_DIR:-$root/build-wheel-deps}
prefix=$deps/prefix
version() { dpkg-query -W -f='${source:Version}' "$1" 2>/dev/null || { echo "wheel-deps: $1 is not installed (scripts/bootstrap.sh)" >&2; exit 2; }; }
hdf5=$(version libhdf5-dev)
cfitsio=$(version libcfitsio-dev)
stamp="hdf5 $hdf5, cfitsio $cfitsio, $(sha256sum "$0" | cut -c1-16)"
if [ -f "$prefix/.built" ] && [ "$(cat "$prefix/.built")" = "$stamp" ]; then
  echo "$prefix"
  exit 0
fi

# the sources: apt with its own lists (the system's configuration is left as it is)
suite=$(. /etc/os-release && echo "$VERSION_CODENAME")
mkdir -p "$deps/apt/lists/partial" "$deps/apt/cache/archives/partial" "$deps/src"
echo "deb-src http://deb.debian.org/debian $suite main" >"$deps/apt/sources.list"
apt=(-o Dir::Etc::SourceList="$deps/apt/sources.list" -o Dir::Etc::SourceParts=/nonexistent
     -o Dir::State::Lists="$deps/apt/lists" -o Dir::Cache="$deps/apt/cache" -o Debug::NoLocking=1
     -o APT::Sandbox::User="$(id -un)")
start=$SECONDS
apt-get "${apt[@]}" -qq update >"$deps/apt.log" 2>&1 \
  || { cat "$deps/apt.log"; echo "wheel-deps: apt could not read Debian's source index ($suite)" >&2; exit 3; }
(cd "$deps/src" && apt-get "${apt[@]}" -qq source --download-only --tar-only "hdf5=$hdf5" "cfitsio=$cfitsio") \
  >>"$deps/apt.log" 2>&1 || { cat "$deps/apt.log"; echo "wheel-deps: apt could not fetch the sources" >&2; exit 3; }

compiler=cc
command -v ccache >/dev/null 2>&1 && compiler="ccache cc"
jobs=$(nproc)
rm -rf "$prefix" "$deps/build"
mkdir -p "$deps/build"
unpack() {  # the .orig tarball of source package $1 into build/$1
  mkdir -p "$deps/build/$1"
  tar xf "$(ls "$deps/src/$1"_*.orig.tar.* | head -n 1)" -C "$deps/build/$1" --strip-components=1
}
build() {  # name, configure arguments...
  local name=$1
  shift
  (cd "$deps/build/$name" && CC="$compiler" CFLAGS="-O2 -g0" ./configure --prefix="$prefix" "$@" &&
     make -j"$jobs" && make install) >"$deps/$name.log" 2>&1 \
    || { tail -n 40 "$deps/$name.log"; echo "wheel-deps: building $name failed ($deps/$name.log)" >&2; exit 1; }
}
unpack hdf5
build hdf5 --enable-shared --disable-static --enable-build-mode=production --disable-sharedlib-rpath \
  --with-zlib --with-default-api-version=v18 --with-pthread --enable-linux-lfs \
  --enable-threadsafe --enable-unsupported --disable-hl --disable-fortran --disable-cxx --disable-java \
  --disable-tests --disable-tools --without-szlib --disable-ros3-vfd --disable-hdfs
unpack cfitsio
build cfitsio --enable-reentrant --disable-curl --without-bzip2
rm -f "$prefix"/lib/*.la "$prefix"/lib/*.a
echo "$stamp" >"$prefix/.built"
echo "wheel-deps: HDF5 $hdf5 and CFITSIO $cfitsio built in $((SECONDS - start)) s" >&2
echo "$prefix"
