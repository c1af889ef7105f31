# Where `cmake --install` and the Debian package put things (GNU layout under
# CMAKE_INSTALL_PREFIX). Included before the targets: the imaging library
# compiles in where the installed video module lies relative to the CLI and to
# the Python module (apps/imaging/src/VideoModule.cpp). The rules themselves
# are in cmake/Install.cmake.
include(GNUInstallDirs)

# Debian's own folder for Python 3 packages: with CMAKE_INSTALL_PREFIX /usr (the
# .deb) `import tofsim` works as is; under another prefix
# PYTHONPATH=<prefix>/lib/python3/dist-packages.
set(TOFSIM_INSTALL_PYTHONDIR "lib/python3/dist-packages" CACHE STRING
    "Where the Python package tofsim is installed, relative to the prefix")
# The MP4 encoder module (dlopen'ed by the imaging library), private to tofsim.
set(TOFSIM_INSTALL_MODULEDIR "${CMAKE_INSTALL_LIBDIR}/tofsim")
# `pip install .` (pyproject.toml: scikit-build-core, which defines SKBUILD):
# the prefix is the wheel's site-packages, so everything goes inside the
# package folder tofsim/: the module, the CLI in tofsim/bin (the `tofsim`
# command and `python -m tofsim` run it: python/tofsim/__main__.py), the
# video module in tofsim/lib. Only the runtime component is installed.
if(SKBUILD)
  set(TOFSIM_INSTALL_PYTHONDIR ".")
  set(CMAKE_INSTALL_BINDIR "tofsim/bin")
  set(TOFSIM_INSTALL_MODULEDIR "tofsim/lib")
endif()
set(TOFSIM_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/tofsim")
# The prefix of the Debian package (cmake/Packaging.cmake): CPack's default.
set(TOFSIM_PACKAGE_PREFIX "/usr" CACHE PATH "Install prefix inside the .deb")
