/* glGetString(GL_EXTENSIONS) lists exactly the extensions glass's headers declare, and each one
 * the system's <GL/glext.h> knows comes with all its names (extension_names.h, written by
 * extension_names.cmake: it does not compile if an enumerant is missing or has another value, and
 * the program does not link if a function is missing). */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <glass/context.h>

#include <stdio.h>
#include <string.h>

typedef void (*EntryPoint)(void);

struct Entry {
  const char *name;
  EntryPoint address;
};

#define ENTRY(function) {#function, (EntryPoint)function}

#include "extension_names.h"

#define COUNT(array) (sizeof(array) / sizeof((array)[0]))

/* Whether the space-separated list has the name as a whole word. */
static int listed(const char *list, const char *name) {
  const size_t length = strlen(name);
  for (const char *at = strstr(list, name); at; at = strstr(at + 1, name)) {
    if ((at == list || at[-1] == ' ') && (at[length] == ' ' || at[length] == '\0')) return 1;
  }
  return 0;
}

static int declared(const char *name, size_t length) {
  for (size_t i = 0; i < COUNT(declared_extensions); ++i) {
    if (strlen(declared_extensions[i]) == length && strncmp(declared_extensions[i], name, length) == 0)
      return 1;
  }
  return 0;
}

int main(void) {
  GlassContext *context = glassCreateContext(4, 4);
  if (!context || !glassMakeCurrent(context)) {
    fprintf(stderr, "no context\n");
    return 1;
  }
  const char *extensions = (const char *)glGetString(GL_EXTENSIONS);
  int failures = 0;
  for (size_t i = 0; i < COUNT(declared_extensions); ++i) {
    const char *name = declared_extensions[i];
    if (!listed(extensions, name)) {
      fprintf(stderr, "declared but not in GL_EXTENSIONS: %s\n", name);
      ++failures;
    }
  }
  for (const char *word = extensions; *word;) {
    const size_t length = strcspn(word, " ");
    if (length > 0 && !declared(word, length)) {
      fprintf(stderr, "in GL_EXTENSIONS but not declared: %.*s\n", (int)length, word);
      ++failures;
    }
    word += length;
    while (*word == ' ') ++word;
  }
  for (size_t i = 0; i < COUNT(extension_functions); ++i) {
    if (!extension_functions[i].address) {
      fprintf(stderr, "missing: %s\n", extension_functions[i].name);
      ++failures;
    }
  }
  printf("%zu extensions declared (%zu in the system's headers), %zu functions, %d failures\n",
         COUNT(declared_extensions), COUNT(system_known_extensions), COUNT(extension_functions),
         failures);
  glassDestroyContext(context);
  return failures == 0 ? 0 : 1;
}
