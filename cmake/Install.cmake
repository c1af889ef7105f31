# `cmake --install`: the CLI, the video module it loads, the libraries with
# their public headers, the CMake package (find_package(tofsim CONFIG) then
# tofsim::tofsim) and, when built, the Python package. Two components, which
# are also the two Debian packages (cmake/Packaging.cmake): `runtime` (what
# runs) and `dev` (what builds against tofsim). Layout: cmake/InstallLayout.cmake.
include(CMakePackageConfigHelpers)

# Every library a consumer links, in layer order. A library that one of them
# links and that is missing here fails at configure time (install(EXPORT)
# names it).
set(TOFSIM_EXPORTED_LIBRARIES util volume optics physics io compare scene capture rays ir gl
    render reference cpu lidar_spec lidar sensors config imaging pipeline)

# The libraries' include folders are absolute source (and build) paths, right
# for this build tree only: in the export they become <prefix>/include, where
# every library's headers go (tofsim/<library>/...).
function(tofsim_install_interface target)
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  if(NOT dirs)
    return()
  endif()
  set(wrapped "")
  foreach(dir IN LISTS dirs)
    if(dir MATCHES "^\\$<")
      list(APPEND wrapped "${dir}")
    else()
      list(APPEND wrapped "$<BUILD_INTERFACE:${dir}>")
    endif()
  endforeach()
  list(APPEND wrapped "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${wrapped}")
endfunction()

# What the exported libraries link besides each other, and what provides it
# to a consumer: cmake/tofsimConfig.cmake.in finds (find_dependency) or
# defines each. A library linking something else fails the configure here,
# not a consumer's build.
set(TOFSIM_CONSUMER_DEPENDENCIES Threads::Threads glm::glm OpenGL::OpenGL OpenGL::EGL embree
    OpenEXR::OpenEXR ZLIB::ZLIB HDF5::HDF5 TinyGLTF::TinyGLTF nlohmann_json::nlohmann_json
    yaml-cpp opencv_core opencv_imgproc PNG::PNG ${CMAKE_DL_LIBS})
function(tofsim_check_dependencies target)
  get_target_property(items ${target} INTERFACE_LINK_LIBRARIES)
  foreach(item IN LISTS items)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
    if(item MATCHES "^tofsim" OR item IN_LIST TOFSIM_CONSUMER_DEPENDENCIES)
      continue()
    endif()
    message(FATAL_ERROR "${target} links ${item}, which tofsim's CMake package does not provide: "
                        "add it to cmake/tofsimConfig.cmake.in and TOFSIM_CONSUMER_DEPENDENCIES "
                        "(cmake/Install.cmake), and its -dev package to cmake/Packaging.cmake")
  endforeach()
endfunction()

set(exported_targets tofsim_warnings)
set_target_properties(tofsim_warnings PROPERTIES EXPORT_NAME warnings)
foreach(name IN LISTS TOFSIM_EXPORTED_LIBRARIES)
  set(target tofsim_${name})
  if(NOT TARGET ${target})
    message(FATAL_ERROR "cmake/Install.cmake: no library ${target}")
  endif()
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  tofsim_install_interface(${target})
  tofsim_check_dependencies(${target})
  list(APPEND exported_targets ${target})
  get_target_property(source_dir ${target} SOURCE_DIR)
  install(DIRECTORY ${source_dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          COMPONENT dev FILES_MATCHING PATTERN "*.h")
endforeach()
# What the physics headers include beside them: the shaders' shared math
# (tofsim/physics/TransientPhysics.h includes "transient_physics.glsl").
file(GLOB physics_glsl ${PROJECT_SOURCE_DIR}/shaders/*.glsl)
install(FILES ${physics_glsl} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tofsim/physics COMPONENT dev)
install(FILES ${PROJECT_BINARY_DIR}/apps/pipeline/generated/tofsim/pipeline/Version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tofsim/pipeline COMPONENT dev)

# tofsim::tofsim: everything a program needs to load a config, render it and
# run its sensors (the pipeline links every layer below it).
add_library(tofsim_umbrella INTERFACE)
add_library(tofsim::tofsim ALIAS tofsim_umbrella)
target_link_libraries(tofsim_umbrella INTERFACE tofsim::pipeline)
set_target_properties(tofsim_umbrella PROPERTIES EXPORT_NAME tofsim)
list(APPEND exported_targets tofsim_umbrella)

install(TARGETS ${exported_targets} EXPORT tofsimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT tofsimTargets NAMESPACE tofsim:: DESTINATION ${TOFSIM_INSTALL_CMAKEDIR}
        COMPONENT dev)
# HDF5 (tofsim::io's, private) as this build found it: the consumer's config
# defines HDF5::HDF5 from it, since CMake's FindHDF5 test-compiles a C program
# and a C++ project has no C enabled. Debian's libhdf5-dev has these paths on
# every machine.
set(HDF5_PREFER_PARALLEL OFF)
find_package(HDF5 REQUIRED COMPONENTS C HL)
foreach(property LINK_LIBRARIES INCLUDE_DIRECTORIES COMPILE_DEFINITIONS)
  get_target_property(value HDF5::HDF5 INTERFACE_${property})
  set(TOFSIM_HDF5_${property} "${value}")
  if(NOT value)
    set(TOFSIM_HDF5_${property} "")
  endif()
endforeach()
# The high-level library (H5DS dimension scales) that core/io adds to HDF5::HDF5.
list(APPEND TOFSIM_HDF5_LINK_LIBRARIES ${HDF5_HL_LIBRARIES})
configure_package_config_file(cmake/tofsimConfig.cmake.in
  ${PROJECT_BINARY_DIR}/tofsimConfig.cmake
  INSTALL_DESTINATION ${TOFSIM_INSTALL_CMAKEDIR}
  PATH_VARS TOFSIM_INSTALL_MODULEDIR)
# 0.x: a minor version may change the API, so only the same 0.x matches.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tofsimConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tofsimConfig.cmake ${PROJECT_BINARY_DIR}/tofsimConfigVersion.cmake
        DESTINATION ${TOFSIM_INSTALL_CMAKEDIR} COMPONENT dev)

install(TARGETS tofsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(TARGETS tofsim_video_module LIBRARY DESTINATION ${TOFSIM_INSTALL_MODULEDIR}
        COMPONENT runtime)
# The Python package: python/CMakeLists.txt (when the module is built).
