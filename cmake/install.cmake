# cmake --install: libglass, its headers (GL/gl.h, GL/glu.h, GL/glut.h, glass/*.h), the glass
# command line, a pkg-config file and a CMake package giving glass::gl.
include(CMakePackageConfigHelpers)

install(TARGETS glass_gl EXPORT glassTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/pipeline/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

install(EXPORT glassTargets NAMESPACE glass:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/glass)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/glassConfig.cmake.in
  ${PROJECT_BINARY_DIR}/glassConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/glass)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/glassConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/glassConfig.cmake ${PROJECT_BINARY_DIR}/glassConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/glass)

# The prefix in glass.pc is found from the file's own place (${pcfiledir}), so that the package
# works wherever it is installed, including `cmake --install --prefix` into another directory.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(GLASS_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH pc_to_prefix "/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/")
  string(REGEX REPLACE "/$" "" pc_to_prefix "${pc_to_prefix}")
  set(GLASS_PC_PREFIX "\${pcfiledir}/${pc_to_prefix}")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/glass.pc.in ${PROJECT_BINARY_DIR}/glass.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/glass.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# GLUT's names (libglut.so.3, glut.pc) under the same prefix.
include(${PROJECT_SOURCE_DIR}/cmake/glut_install.cmake)

# Installed programs and libraries find glass's libraries relative to their own place ($ORIGIN),
# so that an installed glass runs from any prefix without LD_LIBRARY_PATH.
file(RELATIVE_PATH bin_to_lib "/${CMAKE_INSTALL_BINDIR}" "/${CMAKE_INSTALL_LIBDIR}")
set_target_properties(glass PROPERTIES INSTALL_RPATH "$ORIGIN/${bin_to_lib}")
set_target_properties(glass_gl PROPERTIES INSTALL_RPATH "$ORIGIN")

include(${PROJECT_SOURCE_DIR}/cmake/osmesa.cmake)  # the libOSMesa.so.8 and libGLU.so.1 names
