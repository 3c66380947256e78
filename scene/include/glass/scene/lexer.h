// Turns scene text into tokens. A statement is one line: a newline ends it, except inside a
// bracketed list `[ ... ]` or after a backslash at the end of the line. `#` starts a comment.
#pragma once

#include "glass/scene/diagnostics.h"
#include "glass/scene/source.h"

#include <string>
#include <vector>

namespace glass::scene {

enum class TokenKind {
  Word,         // a statement name, parameter name or keyword value: [A-Za-z_][A-Za-z0-9_]*
  Number,       // 12, -0.5, 1e-3, .25
  String,       // "path/to/file.png" (escapes: \" \\ \n \t)
  Reference,    // $name: the value of a declared parameter
  ListOpen,     // [
  ListClose,    // ]
  EndOfLine,    // the end of a statement
  EndOfFile,
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  std::string text; // the word, the string's contents, or the reference's name (without '$')
  double number = 0.0;
  SourceLocation where;
  int length = 1; // columns the token spans in the source line
};

// What a token is called in messages: "number", "word 'foo'", "end of line", ...
std::string describeToken(const Token &token);

// Reads the whole file. Errors (an unterminated string, a stray character, a malformed number)
// go to the diagnostics and the lexer carries on after them; the token list always ends with
// EndOfLine then EndOfFile.
std::vector<Token> tokenize(const SourceFile &file, Diagnostics &diagnostics);

} // namespace glass::scene
