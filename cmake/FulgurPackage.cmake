# What a program that links fulgur finds once it is installed
# (docs/linking.md): fulgur.pc and fulgur-gpu.pc for pkg-config, and the
# CMake package fulgur (fulgurConfig.cmake, its version file and the
# exported targets fulgur::fulgur, fulgur::fulgur_static, fulgur::gpu).
include(CMakePackageConfigHelpers)

set(FULGUR_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fulgur)

# The pkg-config files are written when installing, so that they name the
# prefix installed to (cmake --install --prefix DIR), not the configured one.
set(FULGUR_GPU_BUILT FALSE)
set(pc_files fulgur)
if(TARGET fulgur_gpu_shared)
  set(FULGUR_GPU_BUILT TRUE)
  list(APPEND pc_files fulgur-gpu) # with FULGUR_GPU_REQUIRES_PRIVATE from gpu/
endif()
# the project's variables now; the three paths stay @...@ until install time
set(prefix @prefix@)
set(libdir @libdir@)
set(includedir @includedir@)
foreach(pc IN LISTS pc_files)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc.in.install @ONLY)
  install(CODE "
    set(prefix \"\${CMAKE_INSTALL_PREFIX}\")
    set(libdir \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}\")
    set(includedir \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_INCLUDEDIR}\")
    configure_file(\"${PROJECT_BINARY_DIR}/${pc}.pc.in.install\" \"${PROJECT_BINARY_DIR}/${pc}.pc\" @ONLY)
    file(INSTALL \"${PROJECT_BINARY_DIR}/${pc}.pc\"
         DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig\")")
endforeach()

install(EXPORT fulgurTargets NAMESPACE fulgur:: DESTINATION ${FULGUR_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/fulgurConfig.cmake.in
  ${PROJECT_BINARY_DIR}/fulgurConfig.cmake INSTALL_DESTINATION ${FULGUR_CMAKE_DIR})
# Before 1.0 a minor release may break the ABI (docs/linking.md): a request
# for 0.1 is met by 0.1.x only.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(compatibility SameMinorVersion)
else()
  set(compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/fulgurConfigVersion.cmake
  COMPATIBILITY ${compatibility})
install(FILES ${PROJECT_BINARY_DIR}/fulgurConfig.cmake ${PROJECT_BINARY_DIR}/fulgurConfigVersion.cmake
        DESTINATION ${FULGUR_CMAKE_DIR})
