# glass's GLUT installed under glass's prefix for programs written for freeglut: libglass holds
# GLUT (window/), so libglut.so.3 (the name freeglut programs are linked against) and libglut.so
# (for -lglut) are names of libglass, and glut.pc gives the same flags as glass.pc with -lglut.
# Only inside glass's prefix: the system's libglut is never replaced, a program picks glass's by
# -L (or PKG_CONFIG_PATH) and finds it at run time by the rpath.
get_target_property(glass_gl_soversion glass_gl SOVERSION)
set(glass_gl_soname "${CMAKE_SHARED_LIBRARY_PREFIX}glass${CMAKE_SHARED_LIBRARY_SUFFIX}.${glass_gl_soversion}")
set(glut_names_dir ${PROJECT_BINARY_DIR}/glut_names)
file(MAKE_DIRECTORY ${glut_names_dir})
foreach(name libglut.so.3 libglut.so)
  file(CREATE_LINK ${glass_gl_soname} ${glut_names_dir}/${name} SYMBOLIC)
  install(FILES ${glut_names_dir}/${name} DESTINATION ${CMAKE_INSTALL_LIBDIR})
endforeach()

configure_file(${PROJECT_SOURCE_DIR}/cmake/glut.pc.in ${PROJECT_BINARY_DIR}/glut.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/glut.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
