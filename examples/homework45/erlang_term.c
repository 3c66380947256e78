/* Erlang's external term format, decoded (Erlang/OTP's "External Term Format" chapter of the ERTS
 * user's guide: a version byte 131, then tagged terms, big-endian). */
#include "erlang_term.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

/* Deeper nesting than any .wings file has is refused rather than recursed into. */
#define MAX_DEPTH 100

struct decoded {
  struct term root; /* first, so that the root's address is the block's */
  unsigned char *inflated;
};

struct reader {
  const unsigned char *at, *end;
  char *error;
  size_t error_size;
  int failed;
};

static void fail(struct reader *r, const char *format, ...)
{
  if (r->failed) return;
  r->failed = 1;
  va_list args;
  va_start(args, format);
  vsnprintf(r->error, r->error_size, format, args);
  va_end(args);
}

static int need(struct reader *r, size_t count)
{
  if ((size_t)(r->end - r->at) >= count) return 1;
  fail(r, "the term ends %zu bytes early", count - (size_t)(r->end - r->at));
  return 0;
}

static unsigned long long big_endian(struct reader *r, int bytes)
{
  unsigned long long value = 0;
  for (int i = 0; i < bytes; ++i) value = value << 8 | r->at[i];
  r->at += bytes;
  return value;
}

static void free_items(struct term *t)
{
  if (t->kind != TERM_TUPLE && t->kind != TERM_LIST && t->kind != TERM_MAP) return;
  for (size_t i = 0; i < t->length; ++i) free_items(&t->items[i]);
  free(t->items);
  t->items = NULL;
}

static int decode(struct reader *r, struct term *out, int depth);

/* count items, each at least one byte long (so a count beyond the data is refused before any
 * allocation). */
static int decode_items(struct reader *r, struct term *out, enum term_kind kind, size_t count, int depth)
{
  out->kind = kind;
  out->length = 0;
  out->items = NULL;
  if (count > (size_t)(r->end - r->at)) {
    fail(r, "a term claims %zu items with %zu bytes left", count, (size_t)(r->end - r->at));
    return 0;
  }
  if (count == 0) return 1;
  out->items = calloc(count, sizeof *out->items);
  if (!out->items) {
    fail(r, "out of memory");
    return 0;
  }
  for (size_t i = 0; i < count; ++i) {
    out->length = i + 1; /* counted before decoding, so that a failed item is freed too */
    if (!decode(r, &out->items[i], depth + 1)) return 0;
  }
  return 1;
}

static int decode(struct reader *r, struct term *out, int depth)
{
  memset(out, 0, sizeof *out);
  if (depth > MAX_DEPTH) {
    fail(r, "terms nested deeper than %d", MAX_DEPTH);
    return 0;
  }
  if (!need(r, 1)) return 0;
  const int tag = *r->at++;
  switch (tag) {
  case 97: /* SMALL_INTEGER_EXT */
    if (!need(r, 1)) return 0;
    out->kind = TERM_INTEGER;
    out->integer = (long long)big_endian(r, 1);
    return 1;
  case 98: /* INTEGER_EXT: 32-bit signed */
    if (!need(r, 4)) return 0;
    out->kind = TERM_INTEGER;
    out->integer = (long long)(int)(unsigned)big_endian(r, 4);
    return 1;
  case 110: case 111: { /* SMALL_BIG_EXT, LARGE_BIG_EXT: little-endian digits and a sign */
    if (!need(r, tag == 110 ? 2 : 5)) return 0;
    const size_t digits = (size_t)big_endian(r, tag == 110 ? 1 : 4);
    const int negative = *r->at++;
    if (digits > 7) {
      fail(r, "an integer of %zu bytes is too large", digits);
      return 0;
    }
    if (!need(r, digits)) return 0;
    long long value = 0;
    for (size_t i = digits; i > 0; --i) value = value * 256 + r->at[i - 1];
    r->at += digits;
    out->kind = TERM_INTEGER;
    out->integer = negative ? -value : value;
    return 1;
  }
  case 70: { /* NEW_FLOAT_EXT: IEEE 754 double, big-endian */
    if (!need(r, 8)) return 0;
    const unsigned long long bits = big_endian(r, 8);
    out->kind = TERM_FLOAT;
    memcpy(&out->number, &bits, sizeof out->number);
    return 1;
  }
  case 99: { /* FLOAT_EXT: the number as 31 bytes of text */
    if (!need(r, 31)) return 0;
    char text[32];
    memcpy(text, r->at, 31);
    text[31] = '\0';
    r->at += 31;
    char *end = NULL;
    out->kind = TERM_FLOAT;
    out->number = strtod(text, &end);
    if (end == text) {
      fail(r, "a float in text form is not a number");
      return 0;
    }
    return 1;
  }
  case 100: case 118: case 115: case 119: { /* ATOM_EXT, ATOM_UTF8_EXT (16-bit length), SMALL_ forms (8-bit) */
    const int width = tag == 100 || tag == 118 ? 2 : 1;
    if (!need(r, (size_t)width)) return 0;
    const size_t length = (size_t)big_endian(r, width);
    if (!need(r, length)) return 0;
    out->kind = TERM_ATOM;
    out->bytes = r->at;
    out->length = length;
    r->at += length;
    return 1;
  }
  case 109: case 77: { /* BINARY_EXT, BIT_BINARY_EXT (its last byte partly used) */
    if (!need(r, tag == 109 ? 4 : 5)) return 0;
    const size_t length = (size_t)big_endian(r, 4);
    if (tag == 77) r->at++;
    if (!need(r, length)) return 0;
    out->kind = TERM_BINARY;
    out->bytes = r->at;
    out->length = length;
    r->at += length;
    return 1;
  }
  case 104: /* SMALL_TUPLE_EXT */
    if (!need(r, 1)) return 0;
    return decode_items(r, out, TERM_TUPLE, (size_t)big_endian(r, 1), depth);
  case 105: /* LARGE_TUPLE_EXT */
    if (!need(r, 4)) return 0;
    return decode_items(r, out, TERM_TUPLE, (size_t)big_endian(r, 4), depth);
  case 106: /* NIL_EXT */
    out->kind = TERM_LIST;
    return 1;
  case 107: { /* STRING_EXT: a list of bytes */
    if (!need(r, 2)) return 0;
    const size_t length = (size_t)big_endian(r, 2);
    if (!need(r, length)) return 0;
    out->kind = TERM_LIST;
    out->items = length ? calloc(length, sizeof *out->items) : NULL;
    if (length && !out->items) {
      fail(r, "out of memory");
      return 0;
    }
    for (size_t i = 0; i < length; ++i) {
      out->items[i].kind = TERM_INTEGER;
      out->items[i].integer = r->at[i];
    }
    out->length = length;
    r->at += length;
    return 1;
  }
  case 108: { /* LIST_EXT: elements, then the tail (NIL for a proper list) */
    if (!need(r, 4)) return 0;
    if (!decode_items(r, out, TERM_LIST, (size_t)big_endian(r, 4), depth)) return 0;
    struct term tail;
    if (!decode(r, &tail, depth + 1)) {
      free_items(&tail);
      return 0;
    }
    const int proper = tail.kind == TERM_LIST && tail.length == 0;
    free_items(&tail);
    if (!proper) fail(r, "an improper list");
    return proper;
  }
  case 116: { /* MAP_EXT: key, value pairs */
    if (!need(r, 4)) return 0;
    const size_t pairs = (size_t)big_endian(r, 4);
    if (pairs > (size_t)(r->end - r->at) / 2) {
      fail(r, "a map claims %zu pairs with %zu bytes left", pairs, (size_t)(r->end - r->at));
      return 0;
    }
    return decode_items(r, out, TERM_MAP, 2 * pairs, depth);
  }
  default:
    fail(r, "unsupported term tag %d", tag);
    return 0;
  }
}

struct term *erlang_term_decode(const unsigned char *data, size_t size, char *error, size_t error_size)
{
  struct reader r = {data, data + size, error, error_size, 0};
  struct decoded *result = calloc(1, sizeof *result);
  if (!result) {
    snprintf(error, error_size, "out of memory");
    return NULL;
  }
  if (!need(&r, 1) || *r.at++ != 131) {
    fail(&r, "not an Erlang term (no version byte 131)");
    free(result);
    return NULL;
  }
  if (r.at < r.end && *r.at == 80) { /* compressed: the inflated size, then a zlib stream */
    ++r.at;
    if (!need(&r, 4)) {
      free(result);
      return NULL;
    }
    uLongf inflated_size = (uLongf)big_endian(&r, 4);
    /* Deflate expands at most about 1032 times: a larger claim is a broken file. */
    if (inflated_size == 0 || inflated_size / 1032 > (uLongf)(r.end - r.at) + 1) {
      fail(&r, "the compressed term claims %lu bytes", (unsigned long)inflated_size);
      free(result);
      return NULL;
    }
    result->inflated = malloc(inflated_size);
    const uLongf expected = inflated_size;
    if (!result->inflated ||
        uncompress(result->inflated, &inflated_size, r.at, (uLong)(r.end - r.at)) != Z_OK ||
        inflated_size != expected) {
      fail(&r, "the compressed term does not inflate to its stated size");
      free(result->inflated);
      free(result);
      return NULL;
    }
    r.at = result->inflated;
    r.end = result->inflated + inflated_size;
  }
  if (!decode(&r, &result->root, 0) || (r.at != r.end && (fail(&r, "%zu bytes after the term", (size_t)(r.end - r.at)), 1))) {
    erlang_term_free(&result->root);
    return NULL;
  }
  return &result->root;
}

void erlang_term_free(struct term *root)
{
  if (!root) return;
  struct decoded *block = (struct decoded *)root;
  free_items(&block->root);
  free(block->inflated);
  free(block);
}

int term_is_atom(const struct term *t, const char *name)
{
  return t->kind == TERM_ATOM && t->length == strlen(name) && memcmp(t->bytes, name, t->length) == 0;
}
