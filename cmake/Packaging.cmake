# `cpack -G DEB` in the build folder: two Debian packages from the install
# components (cmake/Install.cmake), prefix /usr (TOFSIM_PACKAGE_PREFIX):
#   tofsim      the CLI, its video module and the Python package. Depends:
#               what dpkg-shlibdeps (dpkg-dev) finds the binaries link.
#   tofsim-dev  headers, static libraries, the CMake package. Depends: tofsim
#               of the same version and the -dev packages find_package(tofsim)
#               looks for (the libraries are static: a consumer links their
#               dependencies itself).
set(CPACK_PACKAGE_NAME tofsim)
set(CPACK_PACKAGE_VENDOR "tofsim")
set(CPACK_PACKAGE_CONTACT "tofsim maintainers <tofsim@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "time-of-flight sensor simulator (transient rendering)")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX ${TOFSIM_PACKAGE_PREFIX})
set(CPACK_STRIP_FILES ON)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME tofsim)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# Mesa's EGL driver (the GL backend on machines without a GPU driver of their
# own) is loaded by libglvnd, not linked; the Python package imports NumPy.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "libegl-mesa0, libgl1-mesa-dri, python3, python3-numpy")
# Each package's description follows CPACK_PACKAGE_DESCRIPTION_SUMMARY (its first line).
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION
    "tofsim renders the transient impulse response of a glTF scene and\nsimulates streak cameras, SPADs and CW-ToF sensors on it: the CLI\nand the Python package.")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME tofsim-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
    "tofsim (= ${PROJECT_VERSION}), libglm-dev, libegl-dev, libgl-dev, libembree-dev, libopenexr-dev, libhdf5-dev, zlib1g-dev, libtinygltf-dev, nlohmann-json3-dev, libyaml-cpp-dev, libopencv-dev, libpng-dev")
set(CPACK_DEBIAN_DEV_DESCRIPTION
    "The C++ libraries of tofsim: static libraries, headers and the CMake\npackage (find_package(tofsim CONFIG REQUIRED), then link tofsim::tofsim).")
# gzip: quick on two cores (xz takes several times longer for a few MB less).
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)
include(CPack)
