# Included by install.cmake: glass under the names that programs written for Mesa look for, in
# glass's own prefix (never over the system's Mesa):
#   libOSMesa.so.8 and libOSMesa.so  (Mesa's OSMesa: <GL/osmesa.h> and every gl* entry point)
#   libGLU.so.1 and libGLU.so        (GLU)
#   osmesa.pc                        (pkg-config osmesa)
# Each name is a symbolic link to libglass, which holds GL, GLU and OSMesa together: a process
# that loads several of the names gets one library, so GLU's GL calls reach the context that
# OSMesaMakeCurrent made current. Programs linked against Mesa's libOSMesa.so.8 run on glass with
# the prefix's library directory first on LD_LIBRARY_PATH (docs/osmesa.md).

set(GLASS_LIBRARY_ALIASES
  libOSMesa.so.8 $<TARGET_SONAME_FILE_NAME:glass_gl>
  libOSMesa.so libOSMesa.so.8
  libGLU.so.1 $<TARGET_SONAME_FILE_NAME:glass_gl>
  libGLU.so libGLU.so.1)
install(CODE "
  set(aliases \"${GLASS_LIBRARY_ALIASES}\")
  set(libdir \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}\")
  while(aliases)
    list(POP_FRONT aliases name target)
    message(STATUS \"Installing: \${libdir}/\${name} -> \${target}\")
    file(CREATE_LINK \${target} \${libdir}/\${name} SYMBOLIC)
  endwhile()
")

configure_file(${PROJECT_SOURCE_DIR}/cmake/osmesa.pc.in ${PROJECT_BINARY_DIR}/osmesa.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/osmesa.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
