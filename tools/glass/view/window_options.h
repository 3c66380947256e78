// The options every window of the `glass` program takes (glass view, glass ifs3d view): the
// window's size, and the headless run's snapshot and event script (docs/glut.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace glass::cli::view {

enum class WindowOption { NotOne, Taken, Bad };

// When args[i] is --snapshot FILE or --events FILE (set as GLASS_GLUT_SNAPSHOT or
// GLASS_GLUT_EVENTS for glass's GLUT) or --size WxH (into width and height), takes it and its
// value, leaving i on the value: Taken. Bad, with `problem` said, for a size that is not one;
// NotOne for anything else.
WindowOption takeWindowOption(const std::vector<std::string> &args, std::size_t &i, int &width, int &height,
                              std::string &problem);

} // namespace glass::cli::view
