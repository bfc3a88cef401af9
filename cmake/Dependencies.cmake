# Every dependency comes from a Debian 12 package (scripts/install-deps.sh installs them all).
find_package(PkgConfig REQUIRED)
find_package(LibXml2 REQUIRED)                       # SVG parsing (under svgpp)
find_package(Boost 1.74 REQUIRED)                    # svgpp is built on Boost headers
find_path(SVGPP_INCLUDE_DIR svgpp/svgpp.hpp REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)            # scene files, --json output
find_package(Eigen3 3.4 REQUIRED NO_MODULE)          # ARAP sparse Cholesky
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL 5.5 REQUIRED)                      # constrained Delaunay triangulation
pkg_check_modules(POLYCLIPPING REQUIRED IMPORTED_TARGET polyclipping)   # union and offset
add_library(animpak::polyclipping ALIAS PkgConfig::POLYCLIPPING)
find_package(CLI11 2.1 REQUIRED)                     # command line
find_package(OpenCL 1.2 REQUIRED)                    # the OpenCL backend (ICD loader; headers incl. CL/opencl.hpp)

if(ANIMPAK_RENDERING)
  pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)    # anti-aliased vector rasterisation
  add_library(animpak::cairo ALIAS PkgConfig::CAIRO)
  # Through pkg-config: Debian 12's OpenImageIO CMake config names tools from another package.
  pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO>=2.4)   # PNG output, image comparison
  add_library(animpak::oiio ALIAS PkgConfig::OIIO)
endif()

if(ANIMPAK_BUILD_TESTS)
  find_package(Catch2 2.13 REQUIRED)
  include(Catch)
endif()
