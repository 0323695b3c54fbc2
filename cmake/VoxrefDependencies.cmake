# Every third-party dependency, found on the system (Debian 12 packages; nothing vendored).
# cmake/setup-debian.sh installs them.

find_package(glm REQUIRED)                      # libglm-dev
find_package(PkgConfig REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)  # libosmesa6-dev
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)        # libegl-dev (headers; loaded at run time)
find_package(OpenEXR 3 REQUIRED)                # libopenexr-dev
# libopenimageio-dev. Through pkg-config: Debian 12's OpenImageIOConfig.cmake fails unless the
# command-line tools (openimageio-tools, which pulls in Qt) are installed too.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
find_package(embree 3 REQUIRED)                 # libembree-dev (fixtures, issue 5)
find_package(CLI11 REQUIRED)                    # libcli11-dev
find_package(nlohmann_json 3 REQUIRED)          # nlohmann-json3-dev
find_package(tomlplusplus 3 REQUIRED)           # libtomlplusplus-dev: suite files (docs/ci.md)
find_package(ZLIB REQUIRED)                     # zlib1g-dev (gzip-compressed raw volumes)
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)  # libzstd-dev: a general-purpose baseline of the benchmarks
pkg_check_modules(LZMA REQUIRED IMPORTED_TARGET liblzma)  # liblzma-dev: xz, another baseline
find_package(OpenSSL REQUIRED)                  # libssl-dev: SHA-256 of the fixture manifest (libcrypto)
find_package(Threads REQUIRED)
find_package(GTest REQUIRED)                    # libgtest-dev
