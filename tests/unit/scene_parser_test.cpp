// The scene language's parser: every error message over the broken scenes in tests/scenes/broken
// (each NAME.scene has its expected messages in NAME.expected), and the pieces behind them.
#include <doctest/doctest.h>

#include <glass/scene/frame_values.h>
#include <glass/scene/lexer.h>
#include <glass/scene/parser.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace glass::scene;

namespace {

std::string readFile(const fs::path &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Messages name files by the path they were opened with; the expected files use bare names.
std::string withoutDirectory(std::string text, const std::string &directory) {
  for (std::size_t at = text.find(directory); at != std::string::npos; at = text.find(directory, at)) {
    text.erase(at, directory.size());
  }
  return text;
}

std::string parseMessages(const std::string &text, ParseOptions options = {}) {
  Diagnostics diagnostics;
  parseSceneText("test.scene", text, diagnostics, options);
  return diagnostics.format();
}

} // namespace

TEST_CASE("scene parser: every broken scene gives its expected messages, with file:line:col") {
  const fs::path directory = fs::path(GLASS_SOURCE_DIR) / "tests" / "scenes" / "broken";
  std::vector<fs::path> scenes;
  for (const fs::directory_entry &entry : fs::directory_iterator(directory)) {
    if (entry.path().extension() == ".scene") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  REQUIRE(scenes.size() >= 10);
  const bool update = std::getenv("GLASS_UPDATE_EXPECTED") != nullptr;
  for (const fs::path &scene : scenes) {
    CAPTURE(scene.filename().string());
    Diagnostics diagnostics;
    Program program = parseSceneFile(scene.string(), diagnostics);
    CHECK(diagnostics.hasErrors());
    std::string messages = withoutDirectory(diagnostics.format(), directory.string() + "/");
    fs::path expectedPath = fs::path(scene).replace_extension(".expected");
    if (update) {
      std::ofstream(expectedPath, std::ios::binary) << messages;
      continue;
    }
    REQUIRE_MESSAGE(fs::exists(expectedPath), "no " << expectedPath.filename().string()
                                                    << " (run with GLASS_UPDATE_EXPECTED=1 to write it, then review it)");
    CHECK(messages == readFile(expectedPath));
  }
}

TEST_CASE("scene parser: a missing scene file is one error without a place") {
  Diagnostics diagnostics;
  parseSceneFile("/nonexistent/dir/none.scene", diagnostics);
  REQUIRE(diagnostics.errorCount() == 1);
  CHECK(diagnostics.format() == "error: cannot read scene '/nonexistent/dir/none.scene': No such file or directory\n1 error\n");
}

TEST_CASE("scene lexer: tokens, positions, comments, lists and continuations") {
  Diagnostics diagnostics;
  SourceFile file("t.scene", "translate 1 -2.5e1 .5 # comment\nmesh points positions [ 1\n 2 3 ] \\\n  size 2\n\"a\\\"b\" $p\n");
  std::vector<Token> tokens = tokenize(file, diagnostics);
  CHECK_FALSE(diagnostics.hasErrors());
  std::vector<TokenKind> kinds;
  for (const Token &t : tokens) kinds.push_back(t.kind);
  using K = TokenKind;
  std::vector<TokenKind> expected = {K::Word,     K::Number,    K::Number, K::Number, K::EndOfLine, K::Word,
                                     K::Word,     K::Word,      K::ListOpen, K::Number, K::Number, K::Number,
                                     K::ListClose, K::Word,     K::Number, K::EndOfLine, K::String, K::Reference,
                                     K::EndOfLine, K::EndOfLine, K::EndOfFile};
  CHECK(kinds == expected);
  CHECK(tokens[2].number == -25.0);
  CHECK(tokens[3].number == 0.5);
  CHECK(tokens[3].where.line == 1);
  CHECK(tokens[3].where.column == 20);
  CHECK(tokens[10].where.line == 3); // the list runs over the line end
  CHECK(tokens[13].text == "size");  // the backslash joined line 4 to the statement
  CHECK(tokens[16].text == "a\"b");
  CHECK(tokens[17].text == "p");
}

TEST_CASE("scene lexer: a byte order mark before the first line is not part of the text") {
  Diagnostics diagnostics;
  SourceFile file("t.scene", "\xEF\xBB\xBFtranslate 1 2 3\n");
  std::vector<Token> tokens = tokenize(file, diagnostics);
  CHECK_FALSE(diagnostics.hasErrors());
  REQUIRE(tokens.size() >= 1);
  CHECK(tokens[0].text == "translate");
  CHECK(tokens[0].where.column == 1);
  CHECK(file.line(1) == "translate 1 2 3");
  // Elsewhere it is a bad character, as any other.
  SourceFile later("u.scene", "translate 1 2 3\n\xEF\xBB\xBF\n");
  tokenize(later, diagnostics);
  CHECK(diagnostics.hasErrors());
}

TEST_CASE("scene diagnostics: the caret lines up under tabs and underlines the token") {
  std::string messages = parseMessages("\ttranlate 1 0 0\n");
  CHECK(messages == "test.scene:1:2: error: unknown statement 'tranlate'; did you mean 'translate'?\n"
                    "    1 | \ttranlate 1 0 0\n"
                    "      | \t^~~~~~~~\n"
                    "1 error\n");
}

TEST_CASE("scene diagnostics: the parser stops at 20 errors and says so") {
  std::string text;
  for (int i = 0; i < 30; ++i) text += "bogus\n";
  Diagnostics diagnostics;
  parseSceneText("many.scene", text, diagnostics);
  CHECK(diagnostics.errorCount() == 20);
  CHECK(diagnostics.format().find("20 errors (stopped at the limit of 20)") != std::string::npos);
}

TEST_CASE("scene diagnostics: errors past the limit are neither counted nor shown") {
  // Lexer errors (moved over in source order) and several errors of one statement can arrive
  // after the limit is reached; the count and the list must still stop at it.
  std::string text;
  for (int i = 0; i < 30; ++i) text += "bogus \"unterminated\n";
  for (int i = 0; i < 30; ++i) text += "translate x y z\n";
  Diagnostics diagnostics;
  parseSceneText("many.scene", text, diagnostics);
  CHECK(diagnostics.errorCount() == 20);
  const std::string messages = diagnostics.format();
  std::size_t shown = 0;
  for (std::size_t at = messages.find(": error: "); at != std::string::npos;
       at = messages.find(": error: ", at + 1))
    ++shown;
  CHECK(shown == 20);
  CHECK(messages.find("20 errors (stopped at the limit of 20)") != std::string::npos);
}

TEST_CASE("scene diagnostics: bytes a terminal would act on are shown escaped") {
  // An ESC sequence (set the colour red), a C1 control (U+009B, CSI) and a stray byte that is not
  // UTF-8; valid UTF-8 stays as it is, and the caret still lines up under the escaped bytes.
  const std::string messages =
      parseMessages("\x1b[31mred 1\n# caf\xc3\xa9\nbad\xc2\x9b\xff 2\n");
  CHECK(messages.find('\x1b') == std::string::npos);
  CHECK(messages.find("\xc2\x9b") == std::string::npos);
  CHECK(messages.find('\xff') == std::string::npos);
  // The ESC byte is underlined by 4 columns, and what follows it moves 3 columns on.
  CHECK(messages.find("test.scene:1:1: error: unexpected character byte 27\n    1 | \\x1b[31mred 1\n"
                      "      | ^~~~\n") != std::string::npos);
  CHECK(messages.find("test.scene:1:3: error: malformed number '31mred'\n    1 | \\x1b[31mred 1\n"
                      "      |      ^~~~~~\n") != std::string::npos);
  CHECK(messages.find("bad\\xc2\\x9b\\xff 2") != std::string::npos);
  CHECK(printable("caf\xc3\xa9\t\x7f\n") == "caf\xc3\xa9\t\\x7f\\x0a");
}

TEST_CASE("scene parser: includes nested too deep are reported") {
  const fs::path directory = fs::temp_directory_path() / "glass_scene_include_depth";
  fs::create_directories(directory);
  for (int i = 0; i < 5; ++i) {
    std::ofstream(directory / ("level" + std::to_string(i) + ".scene"))
        << "include \"level" << i + 1 << ".scene\"\n";
  }
  std::ofstream(directory / "level5.scene") << "translate 1 0 0\n";
  ParseOptions options;
  options.maxIncludeDepth = 3;
  Diagnostics diagnostics;
  parseSceneFile((directory / "level0.scene").string(), diagnostics, options);
  std::string messages = withoutDirectory(diagnostics.format(), directory.string() + "/");
  CHECK(messages.find("level2.scene:1:9: error: includes nested more than 3 deep") != std::string::npos);
  CHECK(messages.find("level0.scene:1:1: note: which was included from here") != std::string::npos);
  fs::remove_all(directory);
}

TEST_CASE("scene parser: --set replaces a declared value and is checked") {
  ParseOptions options;
  options.overrides = {{"angle", "45"}, {"light", "1,2,3"}};
  Diagnostics diagnostics;
  Program program = parseSceneText("set.scene", "param angle 30\nparam light 0 0 1\nrotate $angle 0 1 0\n", diagnostics, options);
  REQUIRE_FALSE(diagnostics.hasErrors());
  CHECK(program.parameters[0].value == std::vector<double>{45.0});
  CHECK(program.parameters[1].value == std::vector<double>{1.0, 2.0, 3.0});

  options.overrides = {{"light", "1,2"}, {"angle", "x"}};
  std::string messages = parseMessages("param angle 30\nparam light 0 0 1\n", options);
  CHECK(messages.find("test.scene:1:7: error: --set angle=x: the value must be numbers separated by commas") != std::string::npos);
  CHECK(messages.find("test.scene:2:7: error: --set light=1,2: 'light' holds 3 numbers, the value gives 2") != std::string::npos);

  options.overrides = {{"angel", "3"}};
  messages = parseMessages("param angle 30\nparam light 0 0 1\n", options);
  CHECK(messages == "error: --set angel: the scene 'test.scene' declares no parameter 'angel' (it declares angle, light)\n1 error\n");
}

TEST_CASE("scene parser: warnings do not stop a scene") {
  Diagnostics diagnostics;
  Program program = parseSceneText("w.scene", "clear_color 1 0 0\nbegin lines\nvertex 0 0\nend\n", diagnostics);
  CHECK_FALSE(diagnostics.hasErrors());
  std::string messages = diagnostics.format();
  CHECK(messages.find("w.scene:1:1: warning: 'clear_color' only sets the colour") != std::string::npos);
  CHECK(messages.find("w.scene:2:1: warning: 'begin lines' has 1 vertex: GL draws 0 lines and ignores the last 1") != std::string::npos);
  CHECK(program.statements.size() == 2);
}

TEST_CASE("scene parser: a mesh whose vertices (or indices) do not make whole primitives is a warning") {
  Diagnostics diagnostics;
  Program program = parseSceneText("m.scene",
                                    "mesh triangles positions [ 0 0 0  1 0 0 ]\n"
                                    "mesh quads positions [ 0 0  1 0  1 1  0 1 ] position_size 2 indices [ 0 1 2 3 0 1 ]\n"
                                    "mesh quads positions [ 0 0  1 0  1 1  0 1 ] position_size 2\n",
                                    diagnostics);
  CHECK_FALSE(diagnostics.hasErrors());
  std::string messages = diagnostics.format();
  std::size_t warnings = 0;
  for (std::size_t at = messages.find("warning:"); at != std::string::npos; at = messages.find("warning:", at + 1)) ++warnings;
  CHECK(warnings == 2);
  CHECK(messages.find("m.scene:1:1: warning: 'mesh triangles' sends 2 vertices: GL draws 0 triangles and ignores the last 2") != std::string::npos);
  CHECK(messages.find("m.scene:2:1: warning: 'mesh quads' sends 6 vertices: GL draws 1 quad and ignores the last 2") != std::string::npos);
  CHECK(program.statements.size() == 3);
}

TEST_CASE("scene animation: numbers interpolate linearly, rotations by slerp") {
  Diagnostics diagnostics;
  Program program = parseSceneText(
      "a.scene", "frames 11\nparam x 0 10\nanimate x key 0 0 10 key 10 10 20\nparam r rotation 0 0 1 0\n"
                 "animate r key 0 0 0 1 0 key 10 90 0 1 0\nrotate $r\ntranslate $x 0\n",
      diagnostics);
  REQUIRE_FALSE(diagnostics.hasErrors());
  FrameValues values = evaluateParameters(program, 5);
  CHECK(values.values[0] == std::vector<double>{5.0, 15.0});
  // Halfway between 0 and 90 degrees about y by slerp is 45 degrees about y.
  CHECK(values.values[1][0] == doctest::Approx(45.0));
  CHECK(values.values[1][2] == doctest::Approx(1.0));
  // Before the first key and after the last, the value holds.
  Parameter &x = program.parameters[0];
  CHECK(parameterAt(x, -3.0) == std::vector<double>{0.0, 10.0});
  CHECK(parameterAt(x, 40.0) == std::vector<double>{10.0, 20.0});
}

TEST_CASE("scene parser: every example in docs/scene-format.md parses") {
  // Examples are the fenced blocks marked ```scene; each is parsed on its own.
  std::string docs = readFile(fs::path(GLASS_SOURCE_DIR) / "docs" / "scene-format.md");
  REQUIRE_FALSE(docs.empty());
  int examples = 0;
  for (std::size_t at = docs.find("```scene\n"); at != std::string::npos; at = docs.find("```scene\n", at)) {
    at += 9;
    std::size_t end = docs.find("```", at);
    REQUIRE(end != std::string::npos);
    std::string example = docs.substr(at, end - at);
    Diagnostics diagnostics;
    parseSceneText((fs::path(GLASS_SOURCE_DIR) / "docs" / "example.scene").string(), example, diagnostics);
    CAPTURE(example);
    CHECK_MESSAGE(!diagnostics.hasErrors(), diagnostics.format());
    ++examples;
    at = end + 3;
  }
  CHECK(examples >= 40);
}

TEST_CASE("scene parser: every scene in scenes/ parses without errors or warnings") {
  int count = 0;
  for (const fs::directory_entry &entry : fs::directory_iterator(fs::path(GLASS_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".scene") continue;
    Diagnostics diagnostics;
    parseSceneFile(entry.path().string(), diagnostics);
    CAPTURE(entry.path().filename().string());
    CHECK_MESSAGE(diagnostics.all().empty(), diagnostics.format());
    ++count;
  }
  CHECK(count >= 8);
}
