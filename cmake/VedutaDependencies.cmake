# Every dependency comes from Debian 12. When one is missing, say which package brings it,
# so that `./setup.sh` or the reader knows what to install.

include(FindPkgConfig)

macro(veduta_require found package)
  if(NOT ${found})
    message(FATAL_ERROR "veduta: missing dependency; install the Debian package '${package}' "
                        "(apt-get install ${package}), or run ./setup.sh which installs all of them.")
  endif()
endmacro()

find_package(Threads REQUIRED)

find_package(embree 3 QUIET)
veduta_require(embree_FOUND libembree-dev)

# OpenImageIO's CMake config needs OpenCV headers on Debian 12 and OpenColorIO's computes a
# wrong prefix; their pkg-config files are correct.
pkg_check_modules(OIIO QUIET IMPORTED_TARGET OpenImageIO)
veduta_require(OIIO_FOUND libopenimageio-dev)
pkg_check_modules(OCIO QUIET IMPORTED_TARGET OpenColorIO)
veduta_require(OCIO_FOUND libopencolorio-dev)

find_package(OpenEXR QUIET CONFIG)
veduta_require(OpenEXR_FOUND libopenexr-dev)
find_package(PNG QUIET)
veduta_require(PNG_FOUND libpng-dev)
find_package(ZLIB QUIET)  # CRC-32 of checkpoints
veduta_require(ZLIB_FOUND zlib1g-dev)
find_package(GeographicLib QUIET)
veduta_require(GeographicLib_FOUND libgeographiclib-dev)
# DHDN ↔ ETRS89 through the BeTA2007 grid (geodesy/datum_grid.h); proj-data brings the grid.
find_package(PROJ QUIET CONFIG)
veduta_require(PROJ_FOUND libproj-dev)
set(CGAL_DATA_DIR "unused")  # silences CGAL's note about its data directory
find_package(CGAL QUIET CONFIG)
veduta_require(CGAL_FOUND libcgal-dev)
find_package(GDAL QUIET CONFIG)
veduta_require(GDAL_FOUND libgdal-dev)
find_package(citygml QUIET CONFIG)  # CityGML building models (city/citygml_file.h)
veduta_require(citygml_FOUND libcitygml-dev)
find_package(TBB QUIET CONFIG)
veduta_require(TBB_FOUND libtbb-dev)
find_package(pugixml QUIET CONFIG)
veduta_require(pugixml_FOUND libpugixml-dev)
find_package(CLI11 QUIET CONFIG)
veduta_require(CLI11_FOUND libcli11-dev)
find_package(fmt QUIET CONFIG)
veduta_require(fmt_FOUND libfmt-dev)
find_package(assimp QUIET CONFIG)
veduta_require(assimp_FOUND libassimp-dev)
# Georeferenced OBJ in double: src/io/georeferenced_mesh.cpp compiles the header-only reader.
find_package(tinyobjloader QUIET CONFIG)
veduta_require(tinyobjloader_FOUND libtinyobjloader-dev)
if(VEDUTA_BUILD_TESTS)
  find_package(GTest QUIET CONFIG)
  veduta_require(GTest_FOUND libgtest-dev)
  # glTF read back in the export tests (tests/io/gltf_writer_test.cpp). Debian ships tinygltf as
  # a shared library with a CMake config; its header alone needs no JSON library.
  find_package(TinyGLTF QUIET CONFIG)
  veduta_require(TinyGLTF_FOUND libtinygltf-dev)
endif()
if(VEDUTA_BUILD_BENCH)
  find_package(benchmark QUIET CONFIG)
  veduta_require(benchmark_FOUND libbenchmark-dev)
endif()
