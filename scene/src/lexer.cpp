#include "glass/scene/lexer.h"

#include <charconv>

namespace glass::scene {

namespace {

bool isWordStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordChar(char c) { return isWordStart(c) || isDigit(c); }
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
// Characters that may follow a number or word directly.
bool isDelimiter(char c) { return isSpace(c) || c == '\n' || c == '#' || c == '[' || c == ']'; }

class Lexer {
public:
  Lexer(const SourceFile &file, Diagnostics &diagnostics)
      : file_(file), text_(file.text()), diagnostics_(diagnostics) {}

  std::vector<Token> run() {
    // Past the error limit nothing more would be shown: stop reading (a file of random bytes is
    // an error every few bytes, and lexing all of a large one would only cost time and memory).
    while (pos_ < text_.size() && !diagnostics_.full()) {
      char c = text_[pos_];
      if (isSpace(c)) {
        advance();
      } else if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') advance();
      } else if (c == '\n') {
        if (listDepth_ == 0) push(TokenKind::EndOfLine, here(), 1);
        advance();
      } else if (c == '\\') {
        continuation();
      } else if (c == '[') {
        if (listDepth_ == 0) listOpen_ = here();
        ++listDepth_;
        push(TokenKind::ListOpen, here(), 1);
        advance();
      } else if (c == ']') {
        if (listDepth_ == 0) {
          diagnostics_.error(here(), "']' without a matching '['");
        } else {
          --listDepth_;
          push(TokenKind::ListClose, here(), 1);
        }
        advance();
      } else if (c == '"') {
        string();
      } else if (c == '$') {
        reference();
      } else if (isDigit(c) || c == '-' || c == '+' || c == '.') {
        number();
      } else if (isWordStart(c)) {
        word();
      } else {
        SourceLocation at = here();
        std::string shown = (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
                                ? "byte " + std::to_string(static_cast<unsigned char>(c))
                                : std::string("'") + c + "'";
        diagnostics_.error(at, "unexpected character " + shown);
        advance();
      }
    }
    if (listDepth_ > 0) {
      diagnostics_.error(here(), "end of file inside a list: ']' expected")
          .note(listOpen_, "the list was opened here");
      listDepth_ = 0;
    }
    push(TokenKind::EndOfLine, here(), 1);
    push(TokenKind::EndOfFile, here(), 1);
    return std::move(tokens_);
  }

private:
  SourceLocation here() const { return {&file_, line_, column_}; }

  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }

  Token &push(TokenKind kind, SourceLocation at, int length) {
    Token t;
    t.kind = kind;
    t.where = at;
    t.length = length;
    tokens_.push_back(std::move(t));
    return tokens_.back();
  }

  // A backslash joins the next line to this statement; only blanks or a comment may follow it.
  void continuation() {
    SourceLocation at = here();
    advance();
    while (pos_ < text_.size() && isSpace(text_[pos_])) advance();
    if (pos_ < text_.size() && text_[pos_] == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') advance();
    }
    if (pos_ < text_.size() && text_[pos_] != '\n') {
      diagnostics_.error(at, "'\\' continues a statement on the next line and must end its line");
      return;
    }
    if (pos_ < text_.size()) advance(); // the newline, which no longer ends the statement
  }

  void string() {
    SourceLocation at = here();
    std::size_t start = pos_;
    advance();
    std::string value;
    while (true) {
      if (pos_ >= text_.size() || text_[pos_] == '\n') {
        diagnostics_.error(at, "string is not closed: '\"' expected before the end of the line",
                           static_cast<int>(pos_ - start));
        break;
      }
      char c = text_[pos_];
      if (c == '"') {
        advance();
        break;
      }
      if (c == '\\' && pos_ + 1 < text_.size() && text_[pos_ + 1] != '\n') {
        SourceLocation escapeAt = here();
        advance();
        char e = text_[pos_];
        switch (e) {
        case '"': value += '"'; break;
        case '\\': value += '\\'; break;
        case 'n': value += '\n'; break;
        case 't': value += '\t'; break;
        default:
          diagnostics_.error(escapeAt, std::string("unknown escape '\\") + e +
                                           "' in string (known: \\\" \\\\ \\n \\t)", 2);
          value += e;
        }
        advance();
        continue;
      }
      value += c;
      advance();
    }
    Token &t = push(TokenKind::String, at, static_cast<int>(pos_ - start));
    t.text = std::move(value);
  }

  void reference() {
    SourceLocation at = here();
    std::size_t start = pos_;
    advance();
    if (pos_ >= text_.size() || !isWordStart(text_[pos_])) {
      diagnostics_.error(at, "'$' must be followed by the name of a parameter");
      return;
    }
    while (pos_ < text_.size() && isWordChar(text_[pos_])) advance();
    Token &t = push(TokenKind::Reference, at, static_cast<int>(pos_ - start));
    t.text = text_.substr(start + 1, pos_ - start - 1);
  }

  void word() {
    SourceLocation at = here();
    std::size_t start = pos_;
    while (pos_ < text_.size() && isWordChar(text_[pos_])) advance();
    if (pos_ < text_.size() && !isDelimiter(text_[pos_])) {
      badToken(at, start, "unexpected character in name");
      return;
    }
    Token &t = push(TokenKind::Word, at, static_cast<int>(pos_ - start));
    t.text = text_.substr(start, pos_ - start);
  }

  // [+-]? (digits [. digits*] | . digits) ([eE] [+-]? digits)?
  void number() {
    SourceLocation at = here();
    std::size_t start = pos_;
    std::size_t p = pos_;
    if (text_[p] == '+' || text_[p] == '-') ++p;
    std::size_t digitsBefore = 0, digitsAfter = 0;
    while (p < text_.size() && isDigit(text_[p])) ++p, ++digitsBefore;
    if (p < text_.size() && text_[p] == '.') {
      ++p;
      while (p < text_.size() && isDigit(text_[p])) ++p, ++digitsAfter;
    }
    bool ok = digitsBefore + digitsAfter > 0;
    if (ok && p < text_.size() && (text_[p] == 'e' || text_[p] == 'E')) {
      std::size_t q = p + 1;
      if (q < text_.size() && (text_[q] == '+' || text_[q] == '-')) ++q;
      std::size_t exponentDigits = 0;
      while (q < text_.size() && isDigit(text_[q])) ++q, ++exponentDigits;
      if (exponentDigits == 0) ok = false;
      p = q;
    }
    if (!ok || (p < text_.size() && !isDelimiter(text_[p]))) {
      while (pos_ < p) advance();
      badToken(at, start, "malformed number");
      return;
    }
    // from_chars does not take a leading '+'.
    std::size_t parseFrom = text_[start] == '+' ? start + 1 : start;
    double value = 0.0;
    auto result = std::from_chars(text_.data() + parseFrom, text_.data() + p, value);
    while (pos_ < p) advance();
    if (result.ec != std::errc()) {
      diagnostics_.error(at, "number '" + text_.substr(start, p - start) + "' is out of range",
                         static_cast<int>(p - start));
      return;
    }
    Token &t = push(TokenKind::Number, at, static_cast<int>(p - start));
    t.number = value;
    t.text = text_.substr(start, p - start);
  }

  // Skips the rest of a run of non-blank characters and reports it as one bad token.
  void badToken(SourceLocation at, std::size_t start, const char *what) {
    while (pos_ < text_.size() && !isDelimiter(text_[pos_])) advance();
    std::string shown = text_.substr(start, pos_ - start);
    diagnostics_.error(at, std::string(what) + " '" + shown + "'", static_cast<int>(shown.size()));
  }

  const SourceFile &file_;
  const std::string &text_;
  Diagnostics &diagnostics_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
  int listDepth_ = 0;
  SourceLocation listOpen_;
  std::vector<Token> tokens_;
};

} // namespace

std::string describeToken(const Token &token) {
  switch (token.kind) {
  case TokenKind::Word: return "'" + token.text + "'";
  case TokenKind::Number: return "number " + token.text;
  case TokenKind::String: return "string \"" + token.text + "\"";
  case TokenKind::Reference: return "'$" + token.text + "'";
  case TokenKind::ListOpen: return "'['";
  case TokenKind::ListClose: return "']'";
  case TokenKind::EndOfLine: return "end of line";
  case TokenKind::EndOfFile: return "end of file";
  }
  return "token";
}

std::vector<Token> tokenize(const SourceFile &file, Diagnostics &diagnostics) {
  return Lexer(file, diagnostics).run();
}

} // namespace glass::scene
