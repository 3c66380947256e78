// `glass ifs3d view`: homework 3's cloud of points and the fractal rebuilt from its maps in a
// GLUT window. `glass ifs3d` itself is the course library's command (course_commands.cpp hands
// `view` to this one, the part that needs a window).
#pragma once

#include <string>
#include <vector>

namespace glass::cli {

int runIfs3dView(const std::vector<std::string> &args);

} // namespace glass::cli
