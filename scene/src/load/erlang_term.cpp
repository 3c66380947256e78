// Decoding Erlang's external term format (erts User's Guide, "External Term Format").
#include "glass/scene/erlang_term.h"

#include <zlib.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace glass::scene {

namespace {

// Tags of the external term format.
enum Tag : std::uint8_t {
  kVersion = 131,
  kCompressed = 80,
  kNewFloat = 70,
  kSmallInteger = 97,
  kInteger = 98,
  kFloat = 99,
  kAtom = 100,
  kSmallTuple = 104,
  kLargeTuple = 105,
  kNil = 106,
  kString = 107,
  kList = 108,
  kBinary = 109,
  kSmallBig = 110,
  kLargeBig = 111,
  kSmallAtom = 115,
  kMap = 116,
  kAtomUtf8 = 118,
  kSmallAtomUtf8 = 119,
};

void appendUtf8(std::string &out, std::int64_t code) {
  const auto c = static_cast<std::uint32_t>(code);
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// Nesting deeper than this is refused, so that a hostile file cannot exhaust the stack. Wings
// files nest about ten deep.
constexpr int kMaxDepth = 256;

class Decoder {
public:
  explicit Decoder(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  ErlangTerm term(int depth) {
    if (depth > kMaxDepth) fail("terms nest more than " + std::to_string(kMaxDepth) + " deep");
    const std::size_t start = at_;
    const std::uint8_t tag = byte();
    ErlangTerm t;
    switch (tag) {
    case kSmallInteger: t.integer = byte(); break;
    case kInteger: t.integer = static_cast<std::int32_t>(unsigned32()); break;
    case kSmallBig: bigInteger(t, byte(), start); break;
    case kLargeBig: bigInteger(t, unsigned32(), start); break;
    case kNewFloat:
      t.kind = ErlangTerm::Kind::Float;
      t.number = std::bit_cast<double>(unsigned64());
      break;
    case kFloat: {
      t.kind = ErlangTerm::Kind::Float;
      const std::string digits(reinterpret_cast<const char *>(take(31).data()), 31);
      const std::string text = digits.substr(0, digits.find('\0'));
      char *end = nullptr;
      t.number = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size()) fail("float '" + text + "' is not a number", start);
      break;
    }
    case kAtom: latin1Atom(t, unsigned16()); break;
    case kAtomUtf8: atom(t, unsigned16()); break;
    case kSmallAtom: latin1Atom(t, byte()); break;
    case kSmallAtomUtf8: atom(t, byte()); break;
    case kSmallTuple: elements(t, ErlangTerm::Kind::Tuple, byte(), depth); break;
    case kLargeTuple: elements(t, ErlangTerm::Kind::Tuple, unsigned32(), depth); break;
    case kNil: t.kind = ErlangTerm::Kind::List; break;
    case kString: {
      t.kind = ErlangTerm::Kind::String;
      const std::size_t length = unsigned16();
      const auto chars = take(length);
      t.text.assign(chars.begin(), chars.end());
      break;
    }
    case kList: {
      elements(t, ErlangTerm::Kind::List, unsigned32(), depth);
      const std::size_t tailAt = at_;
      const ErlangTerm tail = term(depth + 1);
      if (!(tail.kind == ErlangTerm::Kind::List && tail.items.empty())) fail("an improper list (its tail is not [])", tailAt);
      break;
    }
    case kBinary: {
      t.kind = ErlangTerm::Kind::Binary;
      const auto data = take(unsigned32());
      t.text.assign(data.begin(), data.end());
      break;
    }
    case kMap: {
      const std::uint32_t pairs = unsigned32();
      if (pairs > remaining() / 2) fail("a map claims " + std::to_string(pairs) + " pairs, more than the bytes left", start);
      elements(t, ErlangTerm::Kind::Map, std::size_t{pairs} * 2, depth);
      break;
    }
    case kCompressed: fail("a compressed term inside a term", start); break;
    default: fail("tag " + std::to_string(tag) + " is not a term Wings files use (supported: integers, floats, atoms, tuples, lists, strings, binaries, maps)", start);
    }
    return t;
  }

  std::size_t at() const { return at_; }
  std::size_t remaining() const { return bytes_.size() - at_; }

  [[noreturn]] void fail(const std::string &what, std::size_t where) const {
    throw ErlangTermError("at byte " + std::to_string(where) + ": " + what);
  }
  [[noreturn]] void fail(const std::string &what) const { fail(what, at_); }

  std::uint8_t byte() { return take(1)[0]; }
  std::uint32_t unsigned32() {
    const auto b = take(4);
    return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) | b[3];
  }

private:
  std::span<const std::uint8_t> take(std::size_t count) {
    if (count > remaining())
      fail("the data ends early: " + std::to_string(count) + " bytes needed, " + std::to_string(remaining()) + " left");
    auto piece = bytes_.subspan(at_, count);
    at_ += count;
    return piece;
  }
  std::uint16_t unsigned16() {
    const auto b = take(2);
    return static_cast<std::uint16_t>((b[0] << 8) | b[1]);
  }
  std::uint64_t unsigned64() {
    const std::uint64_t high = unsigned32();
    return (high << 32) | unsigned32();
  }

  void atom(ErlangTerm &t, std::size_t length) {
    t.kind = ErlangTerm::Kind::Atom;
    const auto chars = take(length);
    t.text.assign(chars.begin(), chars.end());
  }

  // ATOM_EXT and SMALL_ATOM_EXT hold Latin-1; names are kept in UTF-8.
  void latin1Atom(ErlangTerm &t, std::size_t length) {
    t.kind = ErlangTerm::Kind::Atom;
    for (std::uint8_t c : take(length)) appendUtf8(t.text, c);
  }

  void elements(ErlangTerm &t, ErlangTerm::Kind kind, std::size_t count, int depth) {
    t.kind = kind;
    // Every element takes at least one byte: a count beyond the bytes left is a broken file, and
    // must not reserve memory for it.
    if (count > remaining()) fail("a term claims " + std::to_string(count) + " elements, more than the bytes left");
    t.items.reserve(count);
    for (std::size_t i = 0; i < count; ++i) t.items.push_back(term(depth + 1));
  }

  // Bignums: little-endian base-256 digits after a sign byte; only those that fit in 63 bits.
  void bigInteger(ErlangTerm &t, std::size_t digits, std::size_t start) {
    const bool negative = byte() != 0;
    const auto d = take(digits);
    std::uint64_t value = 0;
    for (std::size_t i = digits; i-- > 0;) {
      if (value >> 55 != 0) fail("an integer too large for 64 bits", start);
      value = (value << 8) | d[i];
    }
    if (value > static_cast<std::uint64_t>(INT64_MAX)) fail("an integer too large for 64 bits", start);
    t.integer = negative ? -static_cast<std::int64_t>(value) : static_cast<std::int64_t>(value);
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

// zlib's inflate into a buffer that grows with the output, so that a size claimed by a broken
// file allocates nothing until the data backs it.
std::vector<std::uint8_t> inflateExactly(std::span<const std::uint8_t> packed, std::uint32_t size) {
  std::vector<std::uint8_t> out;
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) throw ErlangTermError("zlib cannot start inflating");
  stream.next_in = const_cast<Bytef *>(packed.data());
  stream.avail_in = static_cast<uInt>(packed.size());
  int status = Z_OK;
  std::size_t produced = 0;
  while (status == Z_OK) {
    const std::size_t chunk = std::min<std::size_t>(std::size_t{size} + 1 - produced, std::size_t{1} << 20);
    if (chunk == 0) break;
    out.resize(produced + chunk);
    stream.next_out = out.data() + produced;
    stream.avail_out = static_cast<uInt>(chunk);
    status = inflate(&stream, Z_NO_FLUSH);
    produced = out.size() - stream.avail_out;
    if (status == Z_BUF_ERROR && stream.avail_in == 0) break;
  }
  const std::string message = stream.msg != nullptr ? stream.msg : "";
  inflateEnd(&stream);
  if (status != Z_STREAM_END) {
    if (produced > size) throw ErlangTermError("the compressed term inflates to more than the " + std::to_string(size) + " bytes it claims");
    throw ErlangTermError("the compressed term is corrupt or cut short" + (message.empty() ? std::string() : " (zlib: " + message + ")"));
  }
  if (produced != size)
    throw ErlangTermError("the compressed term inflates to " + std::to_string(produced) + " bytes, not the " + std::to_string(size) + " it claims");
  out.resize(produced);
  return out;
}

} // namespace

bool ErlangTerm::asText(std::string &out) const {
  switch (kind) {
  case Kind::Atom:
  case Kind::String:
  case Kind::Binary: out = text; return true;
  case Kind::List:
    out.clear();
    for (const ErlangTerm &item : items) {
      if (item.kind != Kind::Integer || item.integer < 0 || item.integer > 0x10FFFF) return false;
      appendUtf8(out, item.integer);
    }
    return true;
  default: return false;
  }
}

bool ErlangTerm::asNumber(double &out) const {
  if (kind == Kind::Float) out = number;
  else if (kind == Kind::Integer) out = static_cast<double>(integer);
  else return false;
  return true;
}

std::string ErlangTerm::describe(std::size_t limit) const {
  std::ostringstream text;
  switch (kind) {
  case Kind::Integer: text << integer; break;
  case Kind::Float: text << number; break;
  case Kind::Atom: text << this->text; break;
  case Kind::String: text << '"' << this->text << '"'; break;
  case Kind::Binary: text << "<<" << this->text.size() << " bytes>>"; break;
  case Kind::Tuple:
  case Kind::List:
  case Kind::Map: {
    text << (kind == Kind::Tuple ? "{" : kind == Kind::List ? "[" : "#{");
    for (std::size_t i = 0; i < items.size() && text.tellp() < static_cast<std::streamoff>(limit); ++i)
      text << (i > 0 ? "," : "") << items[i].describe(limit);
    text << (kind == Kind::Tuple ? "}" : kind == Kind::List ? "]" : "}");
    break;
  }
  }
  std::string result = text.str();
  if (result.size() > limit) result = result.substr(0, limit) + "...";
  return result;
}

ErlangTerm decodeErlangTerm(std::span<const std::uint8_t> bytes) {
  Decoder outer(bytes);
  if (outer.byte() != kVersion) outer.fail("not an Erlang term (the first byte is not 131)", 0);
  if (outer.remaining() > 0 && bytes[1] == kCompressed) {
    outer.byte();
    const std::uint32_t size = outer.unsigned32();
    const std::vector<std::uint8_t> inflated = inflateExactly(bytes.subspan(outer.at()), size);
    Decoder inner(inflated);
    ErlangTerm t = inner.term(0);
    if (inner.remaining() != 0) inner.fail(std::to_string(inner.remaining()) + " bytes after the term");
    return t;
  }
  ErlangTerm t = outer.term(0);
  if (outer.remaining() != 0) outer.fail(std::to_string(outer.remaining()) + " bytes after the term");
  return t;
}

} // namespace glass::scene
