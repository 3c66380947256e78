// `glass render`: a scene file to a picture (or a numbered picture per frame).
#include "command_registry.h"

#include <glass/scene/parser.h>
#include <glass/scene/render.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <tuple>
#include <unistd.h>

namespace glass::cli {

namespace {

constexpr const char *kHelp = R"(usage: glass render SCENE -o OUTPUT [options]

Renders a scene file (docs/scene-format.md) to a picture. The format follows OUTPUT's
extension: .png, .jpg/.jpeg, .bmp or .tga. The file is written whole or not at all.

options:
  -o, --output FILE     the picture to write (required)
  --size WxH            image size in pixels (default: the scene's `size`, else 640x480)
  --ssaa N              supersampling: draw at N times the size in x and y and average each
                        N x N block (a box filter) into one pixel; N from 1 to 16
  --frames A:B          render frames A to B (counted from 0) of an animated scene, one file
                        each: OUTPUT's name gets the frame number (out.png -> out_0007.png),
                        or give a printf pattern such as frame%03d.png. --frames N: one frame
  --set NAME=VALUE      replace the value of a parameter the scene declares with `param`
                        (numbers separated by commas: --set light=1,2,3); may be repeated
  --view VIEW           what to show: color (the picture, default), depth (the depth buffer
                        as grey), overdraw (fragments per pixel as a heat map), wireframe
  --trace-vertex N      print the N-th vertex the scene sends (from 0) through every stage:
                        object, eye, clip, normalized device and window coordinates, lit colour
  -h, --help            this help

exit status: 0 written, 1 bad scene (messages on stderr, nothing written), 2 bad usage

examples:
  glass render scenes/showcase.scene -o out/showcase.png
  glass render scenes/lighting.scene -o lit.png --size 800x600 --ssaa 4
  glass render scenes/animation.scene -o frames/spin.png --frames 0:119
  glass render scenes/lighting.scene -o spot.png --set spot_angle=25
  glass render scenes/room.scene -o depth.png --view depth
  glass render scenes/matrix_stack.scene -o q1.png --trace-vertex 0
)";

struct RenderRequest {
  std::string scene;
  std::string output;
  scene::RenderOptions options;
  std::optional<std::pair<int, int>> frames;
  std::vector<std::pair<std::string, std::string>> sets;
};

bool parseInteger(const std::string &text, long long min, long long max, long long &value) {
  if (text.empty()) return false;
  std::size_t used = 0;
  try {
    value = std::stoll(text, &used);
  } catch (...) {
    return false;
  }
  return used == text.size() && value >= min && value <= max;
}

// A printf pattern must hold exactly one integer conversion, or nothing else may use '%'.
bool validPattern(const std::string &output) {
  std::size_t percent = output.find('%');
  if (percent == std::string::npos) return true;
  std::size_t i = percent + 1;
  while (i < output.size() && (output[i] == '0' || (output[i] >= '1' && output[i] <= '9'))) ++i;
  return i < output.size() && output[i] == 'd' && output.find('%', i) == std::string::npos;
}

// Reads the command line; on a mistake returns false and says what in `error`.
bool parseArguments(const std::vector<std::string> &args, RenderRequest &request, std::string &error) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    std::string inlineValue;
    bool hasInline = false;
    if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos && arg.rfind("--set", 0) != 0) {
      inlineValue = arg.substr(arg.find('=') + 1);
      arg = arg.substr(0, arg.find('='));
      hasInline = true;
    }
    auto value = [&](std::string &out) {
      if (hasInline) {
        out = inlineValue;
        return true;
      }
      if (i + 1 >= args.size()) {
        error = arg + " needs a value";
        return false;
      }
      out = args[++i];
      return true;
    };
    std::string v;
    if (arg == "-o" || arg == "--output") {
      if (!value(request.output)) return false;
    } else if (arg == "--size") {
      if (!value(v)) return false;
      std::size_t x = v.find('x');
      long long w = 0, h = 0;
      if (x == std::string::npos || !parseInteger(v.substr(0, x), 1, scene::kMaxFramebufferSide, w) ||
          !parseInteger(v.substr(x + 1), 1, scene::kMaxFramebufferSide, h)) {
        error = "--size wants WIDTHxHEIGHT with each from 1 to " + std::to_string(scene::kMaxFramebufferSide) +
                ", as in --size 800x600, not '" + v + "'";
        return false;
      }
      request.options.width = static_cast<int>(w);
      request.options.height = static_cast<int>(h);
    } else if (arg == "--ssaa") {
      long long n = 0;
      if (!value(v)) return false;
      if (!parseInteger(v, 1, 16, n)) {
        error = "--ssaa wants a whole number from 1 to 16, not '" + v + "'";
        return false;
      }
      request.options.supersample = static_cast<int>(n);
    } else if (arg == "--frames") {
      if (!value(v)) return false;
      std::size_t colon = v.find(':');
      long long a = 0, b = 0;
      bool ok = colon == std::string::npos
                    ? parseInteger(v, 0, 1000000, a) && (b = a, true)
                    : parseInteger(v.substr(0, colon), 0, 1000000, a) && parseInteger(v.substr(colon + 1), 0, 1000000, b);
      if (!ok || b < a) {
        error = "--frames wants FIRST:LAST (counted from 0, FIRST <= LAST) or one frame number, not '" + v + "'";
        return false;
      }
      request.frames = std::make_pair(static_cast<int>(a), static_cast<int>(b));
    } else if (arg == "--set") {
      if (i + 1 >= args.size()) {
        error = "--set needs NAME=VALUE";
        return false;
      }
      v = args[++i];
      std::size_t equals = v.find('=');
      if (equals == std::string::npos || equals == 0) {
        error = "--set wants NAME=VALUE, as in --set angle=30, not '" + v + "'";
        return false;
      }
      request.sets.emplace_back(v.substr(0, equals), v.substr(equals + 1));
    } else if (arg.rfind("--set=", 0) == 0) {
      v = arg.substr(6);
      std::size_t equals = v.find('=');
      if (equals == std::string::npos || equals == 0) {
        error = "--set wants NAME=VALUE, as in --set angle=30, not '" + v + "'";
        return false;
      }
      request.sets.emplace_back(v.substr(0, equals), v.substr(equals + 1));
    } else if (arg == "--view") {
      if (!value(v)) return false;
      if (v == "color" || v == "colour") {
        request.options.view = scene::View::Color;
      } else if (v == "depth") {
        request.options.view = scene::View::Depth;
      } else if (v == "overdraw") {
        request.options.view = scene::View::Overdraw;
      } else if (v == "wireframe") {
        request.options.view = scene::View::Wireframe;
      } else {
        error = "--view wants color, depth, overdraw or wireframe, not '" + v + "'";
        return false;
      }
    } else if (arg == "--trace-vertex") {
      long long n = 0;
      if (!value(v)) return false;
      if (!parseInteger(v, 0, 1LL << 40, n)) {
        error = "--trace-vertex wants a vertex number from 0, not '" + v + "'";
        return false;
      }
      request.options.traceVertex = static_cast<long>(n);
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      error = "unknown option '" + arg + "'";
      return false;
    } else if (request.scene.empty()) {
      request.scene = arg;
    } else {
      error = "one scene at a time: '" + request.scene + "' and '" + arg + "' given";
      return false;
    }
  }
  if (request.scene.empty()) {
    error = "no scene file given";
    return false;
  }
  if (request.output.empty()) {
    error = "no output given: add -o OUTPUT.png";
    return false;
  }
  if (!scene::isSupportedImagePath(request.output)) {
    error = "cannot tell the picture format of '" + request.output + "': use .png, .jpg, .jpeg, .bmp or .tga";
    return false;
  }
  if (!validPattern(request.output)) {
    error = "the output name '" + request.output + "' has a '%' that is not one %d (or %04d) frame number";
    return false;
  }
  if (!request.frames && request.output.find('%') != std::string::npos) {
    error = "the output name has a frame number pattern; give --frames";
    return false;
  }
  return true;
}

// out.png -> out_0007.png; a printf pattern (frame%03d.png) is filled in instead.
std::string frameFileName(const std::string &output, int frame) {
  if (output.find('%') != std::string::npos) {
    std::vector<char> buffer(output.size() + 32);
    std::snprintf(buffer.data(), buffer.size(), output.c_str(), frame);
    return buffer.data();
  }
  std::filesystem::path path(output);
  char number[16];
  std::snprintf(number, sizeof number, "_%04d", frame);
  return (path.parent_path() / (path.stem().string() + number + path.extension().string())).string();
}

int runRender(const std::vector<std::string> &args) {
  if (wantsHelp(args)) {
    std::cout << kHelp;
    return kExitOk;
  }
  std::string error;
  RenderRequest parsed;
  if (!parseArguments(args, parsed, error)) {
    std::cerr << "glass render: " << error << "\n(see glass render --help)\n";
    return kExitUsage;
  }
  const RenderRequest *request = &parsed;

  scene::Diagnostics diagnostics;
  scene::ParseOptions parseOptions;
  parseOptions.overrides = request->sets;
  scene::Program program = scene::parseSceneFile(request->scene, diagnostics, parseOptions);
  if (diagnostics.hasErrors()) {
    diagnostics.print(std::cerr);
    return kExitBadInput;
  }

  int first = 0, last = 0;
  if (request->frames) {
    std::tie(first, last) = *request->frames;
    if (last >= program.frames) {
      diagnostics.print(std::cerr);
      std::cerr << "glass render: --frames " << first << ":" << last << " goes past the scene's last frame, "
                << program.frames - 1 << " (it declares " << (program.frames == 1 ? "no animation" : "'frames " + std::to_string(program.frames) + "'")
                << ")\n";
      return kExitUsage;
    }
  }

  // Each frame goes to a temporary file next to its target; only when every frame is done are
  // they renamed into place, so a failure leaves no pictures behind. On a terminal a status line
  // says which frame is being drawn (and at what size), for long renders and frame ranges; it is
  // erased when done, and never written when standard error is a file or a pipe.
  const bool progress = isatty(STDERR_FILENO) == 1;
  std::vector<std::pair<std::string, std::string>> written; // temporary, final
  auto discard = [&] {
    for (const auto &[temporary, final] : written) std::filesystem::remove(temporary);
  };
  scene::FrameRenderer renderer(program);  // one context for all the frames
  for (int frame = first; frame <= last; ++frame) {
    if (progress) {
      std::cerr << "\rglass render: drawing frame " << frame;
      if (last > first) std::cerr << " (" << frame - first + 1 << " of " << last - first + 1 << ")";
      if (request->options.supersample > 1) std::cerr << " with " << request->options.supersample << " x " << request->options.supersample << " samples a pixel";
      std::cerr << "..." << std::flush;
    }
    scene::RenderedFrame rendered;
    if (!renderer.render(frame, request->options, rendered, diagnostics)) {
      if (progress) std::cerr << "\n";
      diagnostics.print(std::cerr);
      discard();
      return kExitBadInput;
    }
    if (!rendered.notes.empty()) std::cout << rendered.notes << "\n";
    if (!rendered.trace.empty()) std::cout << rendered.trace;
    std::string target = request->frames ? frameFileName(request->output, frame) : request->output;
    std::string temporary = target + ".partial-" + std::to_string(getpid()) + std::filesystem::path(target).extension().string();
    std::string reason;
    if (!scene::writeImage(temporary, rendered.image, reason)) {
      if (progress) std::cerr << "\n";
      std::cerr << "glass render: cannot write '" << target << "': " << reason << "\n";
      discard();
      return kExitBadInput;
    }
    written.emplace_back(temporary, target);
  }
  if (progress) std::cerr << "\r\033[K" << std::flush;
  for (const auto &[temporary, final] : written) {
    std::error_code ec;
    std::filesystem::rename(temporary, final, ec);
    if (ec) {
      std::cerr << "glass render: cannot write '" << final << "': " << ec.message() << "\n";
      discard();
      return kExitBadInput;
    }
  }
  diagnostics.print(std::cerr); // warnings, if any
  return kExitOk;
}

const bool registered = registerCommand({"render", "render a scene file to a picture (PNG, JPEG, BMP, TGA)", runRender});

} // namespace

} // namespace glass::cli
