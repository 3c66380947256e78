/* Erlang's external term format (the format of term_to_binary, which Wings3D's .wings files
 * hold), decoded into a tree: just the term shapes a .wings file uses. */
#ifndef HOMEWORK45_ERLANG_TERM_H
#define HOMEWORK45_ERLANG_TERM_H

#include <stddef.h>

enum term_kind { TERM_INTEGER, TERM_FLOAT, TERM_ATOM, TERM_BINARY, TERM_TUPLE, TERM_LIST, TERM_MAP };

struct term {
  enum term_kind kind;
  long long integer;     /* TERM_INTEGER */
  double number;         /* TERM_FLOAT */
  const unsigned char *bytes; /* TERM_ATOM (name, not terminated), TERM_BINARY */
  size_t length;         /* bytes of an atom or binary; items of a tuple, list or map (2 per pair) */
  struct term *items;    /* TERM_TUPLE, TERM_LIST (proper part only), TERM_MAP */
};

/* Decodes one term that starts with the version byte 131, inflating it when compressed (tag 80).
 * Returns the root, or NULL with a message in `error` (of `error_size` bytes). The tree and the
 * bytes it points into stay valid until erlang_term_free. */
struct term *erlang_term_decode(const unsigned char *data, size_t size, char *error, size_t error_size);
void erlang_term_free(struct term *root);

/* Whether the term is the atom `name`. */
int term_is_atom(const struct term *t, const char *name);

#endif
