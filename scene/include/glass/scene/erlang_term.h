// Erlang's external term format (the bytes of term_to_binary), as far as Wings3D files use it:
// integers, floats, atoms, tuples, lists, strings, binaries and maps, optionally zlib-compressed.
// The format is specified in the Erlang/OTP documentation, "External Term Format" (erts
// User's Guide); each tag below is named as there.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace glass::scene {

struct ErlangTerm {
  enum class Kind { Integer, Float, Atom, Tuple, List, String, Binary, Map };
  Kind kind = Kind::Integer;
  std::int64_t integer = 0;
  double number = 0.0;
  std::string text;                // atom name, or the bytes of a string or binary
  std::vector<ErlangTerm> items;   // tuple elements, list elements, or map keys and values in turn

  bool isAtom(std::string_view name) const { return kind == Kind::Atom && text == name; }
  // A tuple whose first element is the atom `tag` and which has `size` elements.
  bool isTagged(std::string_view tag, std::size_t size) const {
    return kind == Kind::Tuple && items.size() == size && items[0].isAtom(tag);
  }
  // Lists written as strings (STRING_EXT) are lists of small integers: both count as lists.
  bool isList() const { return kind == Kind::List || kind == Kind::String; }
  std::size_t listSize() const { return kind == Kind::String ? text.size() : items.size(); }
  // A name: an atom, a string, a binary, or a list of character codes (UTF-8 encoded here).
  bool asText(std::string &out) const;
  // An integer or a float.
  bool asNumber(double &out) const;
  // How the term looks in Erlang, cut short after `limit` characters, for messages.
  std::string describe(std::size_t limit = 40) const;
};

class ErlangTermError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Decodes a whole term_to_binary result (version byte 131, then a term or a compressed term).
// Throws ErlangTermError saying what is wrong and at which byte.
ErlangTerm decodeErlangTerm(std::span<const std::uint8_t> bytes);

} // namespace glass::scene
