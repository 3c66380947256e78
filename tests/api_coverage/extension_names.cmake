# api_coverage.extension_names: glass's extension names against the system's <GL/glext.h>.
#
# The extensions glass declares are the `#define GL_<VENDOR>_<name> 1` lines of its gl.h and
# glext.h. For each of them that the system's glext.h (or gl.h) also has, extension_names.h gets
#  - an #error for each enumerant of the system's block that glass does not define, or defines
#    with another value;
#  - the address of each function of the block, so that the test does not link if glass does not
#    export it;
# and system_extension_guards.h undefines the extension's guard, so that system_headers.c reads the
# system's block after glass's and a prototype or typedef that differs is an error there.
# extension_names.c then checks that glGetString(GL_EXTENSIONS) lists exactly the declared ones.

set(glass_headers ${PROJECT_SOURCE_DIR}/pipeline/include/GL/gl.h
                  ${PROJECT_SOURCE_DIR}/pipeline/include/GL/glext.h
                  ${PROJECT_SOURCE_DIR}/pipeline/include/GL/glass_statistics.h)
set(declared "")
foreach(header IN LISTS glass_headers)
  file(STRINGS ${header} lines REGEX "^#define[ \t]+GL_[A-Z0-9]+_[A-Za-z0-9_]*[a-z][A-Za-z0-9_]*[ \t]+1$")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#define[ \t]+([A-Za-z0-9_]+).*$" "\\1" name "${line}")
    list(APPEND declared ${name})
  endforeach()
endforeach()
list(REMOVE_DUPLICATES declared)
file(READ ${GLASS_SYSTEM_GLEXT_HEADER} system_glext)
file(READ ${GLASS_SYSTEM_GL_HEADER} system_gl)
# The core versions glass's gl.h declares beyond those the system's gl.h declares (whose blocks
# system_headers.c compares already) get the same checks as the extensions, from their blocks in
# glext.h, but are not extension names.
set(versions "")
foreach(header IN LISTS glass_headers)
  file(STRINGS ${header} lines REGEX "^#define[ \t]+GL_VERSION_1_[0-9][ \t]+1$")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#define[ \t]+([A-Za-z0-9_]+).*$" "\\1" name "${line}")
    if(NOT system_gl MATCHES "#define[ \t]+${name}[ \t]")
      list(APPEND versions ${name})
    endif()
  endforeach()
endforeach()

set(checks "/* Written by tests/api_coverage/extension_names.cmake from glass's and the system's headers. */\n")
set(guards "/* Written by tests/api_coverage/extension_names.cmake. */\n")
set(declared_list "")
set(known_list "")
set(functions "")
foreach(extension IN LISTS declared versions)
  if(NOT extension MATCHES "^GL_VERSION_")
    string(APPEND declared_list "  \"${extension}\",\n")
  endif()
  set(block "")
  foreach(text IN ITEMS system_glext system_gl)
    string(FIND "${${text}}" "#ifndef ${extension}\n" begin)
    if(begin GREATER_EQUAL 0)
      string(SUBSTRING "${${text}}" ${begin} -1 rest)
      string(FIND "${rest}" "#endif /* ${extension} */" end)
      if(end LESS 0)
        string(FIND "${rest}" "#endif\n" end)  # gl.h closes its blocks without a comment
      endif()
      string(SUBSTRING "${rest}" 0 ${end} block)
      break()
    endif()
  endforeach()
  if(block STREQUAL "")
    continue()  # glass's own extension (GL_WIN_phong_shading, GL_GLASS_bump_map, ...)
  endif()
  if(NOT extension MATCHES "^GL_VERSION_")
    string(APPEND known_list "  \"${extension}\",\n")
  endif()
  string(APPEND guards "#undef ${extension}\n")
  string(REGEX MATCHALL "#define[ \t]+GL_[A-Za-z0-9_]+[ \t]+0x[0-9A-Fa-f]+|#define[ \t]+GL_[A-Za-z0-9_]+[ \t]+[0-9]+"
         defines "${block}")
  foreach(define IN LISTS defines)
    string(REGEX REPLACE "^#define[ \t]+([A-Za-z0-9_]+)[ \t]+([0-9A-Fa-fx]+)$" "\\1;\\2" pair "${define}")
    list(GET pair 0 name)
    list(GET pair 1 value)
    if(name STREQUAL extension)
      continue()
    endif()
    string(APPEND checks "#if !defined(${name})\n#error \"${name} (${extension}) is not defined by glass's headers\"\n"
                         "#elif ${name} != ${value}\n#error \"${name} is not ${value} in glass's headers\"\n#endif\n")
  endforeach()
  string(REGEX MATCHALL "GLAPI[^;]*APIENTRY[ \t]+gl[A-Za-z0-9_]+" prototypes "${block}")
  foreach(prototype IN LISTS prototypes)
    string(REGEX REPLACE "^.*[ \t](gl[A-Za-z0-9_]+)$" "\\1" function "${prototype}")
    string(APPEND functions "  ENTRY(${function}),\n")
  endforeach()
endforeach()
string(APPEND checks "\nstatic const char *const declared_extensions[] = {\n${declared_list}};\n")
string(APPEND checks "\nstatic const char *const system_known_extensions[] = {\n${known_list}};\n")
string(APPEND checks "\nstatic const struct Entry extension_functions[] = {\n${functions}};\n")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/extension_names.h.new "${checks}")
configure_file(${CMAKE_CURRENT_BINARY_DIR}/extension_names.h.new
               ${CMAKE_CURRENT_BINARY_DIR}/extension_names.h COPYONLY)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/system_extension_guards.h.new "${guards}")
configure_file(${CMAKE_CURRENT_BINARY_DIR}/system_extension_guards.h.new
               ${CMAKE_CURRENT_BINARY_DIR}/system_extension_guards.h COPYONLY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${glass_headers}
             ${GLASS_SYSTEM_GLEXT_HEADER})

add_executable(glass_extension_names extension_names.c)
target_link_libraries(glass_extension_names PRIVATE glass::gl)
target_include_directories(glass_extension_names PRIVATE ${CMAKE_CURRENT_BINARY_DIR})
set_target_properties(glass_extension_names PROPERTIES C_STANDARD 11 C_STANDARD_REQUIRED ON)
add_test(NAME api_coverage.extension_names COMMAND glass_extension_names)
