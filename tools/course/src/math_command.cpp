// glass math: the study guide's test and exam computations as a command.
#include <cmath>

#include "command_arguments.h"
#include "glass/course/commands.h"
#include "glass/course/exact_number.h"
#include "glass/course/math_reports.h"
#include "glass/course/sphere_view_picture.h"
#include "glass/geometry/affine_decomposition.h"

namespace glass::course {

namespace g = glass::geometry;

std::string mathHelp() {
  return R"(usage: glass math COMPUTATION [ARGUMENTS]

The computations of the study guide's test (section 3) and exam (section 4), worked step by step
as the guide's answers are. Without arguments each one solves the guide's own example. Numbers
may be fractions, like 2/3.

  rotate-compose [ANGLE X Y Z]...
        the composite of rotations by ANGLE degrees about (X, Y, Z), in the order given, by
        matrices (equation 9) and by quaternions (equation 7); the angle and axis of the result
        (test question 4: -90 0 1 0  180 1 0 0)
  decompose [A11 A12 A13 A21 A22 A23 [0 0 1]]
        a plane affine matrix as translation x rotation x scaling, or with a shear when the
        columns are not orthogonal (test question 2: -2 -1 2 -2 1 -1)
  view [--eye X Y Z] [--center X Y Z] [--radius R] [--height H] [--width W] [--visible F]
       [--up X Y Z] [-o CHECK.png [--pixels N]]
        gluLookAt and gluPerspective so that a sphere fills the share H of the window's height
        and W of its width with the part F of it visible (the exam's viewing question: eye
        (0, 2, -1), centre (1, 4, 1), radius 1, H = 2/3, W = 1/2, F = 1/2); -o draws the answer
        with glass, N pixels high (default 360), and measures the shares from the pixels
  normal [X0 Y0 Z0 X1 Y1 Z1 X2 Y2 Z2]
        a triangle's normal and what its direction says about the orientation (the exam's
        A0 = (3, 1, 2), A1 = (3, -1, 3), A2 = (4, -1, 4))
  arc [--from DEG] [--to DEG] [--radius R]
        a circular arc as rational quadratic Bezier curves, control points and weights (the exam's
        arc from 0 to 120 degrees)
  torus-patch [--major R] [--minor r] [--inner]
        control points and weights of the exam's 1/16 torus patch x >= 0, y <= 0, z >= 0
        (default R = 2, r = 1; --inner for the inner half of that eighth)

Examples:
  glass math rotate-compose
  glass math rotate-compose 90 0 0 1  90 1 0 0
  glass math decompose -2 -1 2 -2 1 -1
  glass math view -o view.png
  glass math normal 3 1 2  3 -1 3  4 -1 4
  glass math arc --from 0 --to 120
  glass math torus-patch --major 3 --minor 1
)";
}

namespace {

std::vector<double> allNumbers(ArgumentList& list, const std::string& what) {
  std::vector<double> values;
  while (!list.empty()) {
    const std::string arg = list.take();
    if (!looksLikeNumber(arg)) throw UsageError(std::string("unexpected '") + arg + "' (" + what + " takes numbers)");
    values.push_back(parseNumber(arg, what));
  }
  return values;
}

int rotateCompose(ArgumentList& list, std::ostream& out) {
  const std::vector<double> numbers = allNumbers(list, "rotate-compose");
  std::vector<RotationStep> steps;
  if (numbers.empty()) {
    out << "The study guide's test question 4: first -90 degrees about the y axis, then 180 degrees about x.\n\n";
    steps = {{-90, {0, 1, 0}}, {180, {1, 0, 0}}};
  } else {
    if (numbers.size() % 4 != 0) throw UsageError("rotate-compose takes groups of four numbers: ANGLE X Y Z");
    for (std::size_t i = 0; i < numbers.size(); i += 4) {
      const glm::dvec3 axis{numbers[i + 1], numbers[i + 2], numbers[i + 3]};
      if (axis == glm::dvec3(0.0)) throw UsageError("the axis (0, 0, 0) has no direction");
      steps.push_back({numbers[i], axis});
    }
  }
  out << rotateComposeReport(steps);
  return 0;
}

int decompose(ArgumentList& list, std::ostream& out) {
  std::vector<double> v = allNumbers(list, "decompose");
  if (v.empty()) {
    out << "The study guide's test question 2.\n\n";
    v = {-2, -1, 2, -2, 1, -1};
  }
  if (v.size() == 9) {
    if (v[6] != 0 || v[7] != 0 || v[8] != 1) throw UsageError("an affine matrix has the last row 0 0 1");
    v.resize(6);
  }
  if (v.size() != 6) throw UsageError("decompose takes the six entries A11 A12 A13 A21 A22 A23 (or nine, ending 0 0 1)");
  const g::Affine2 a = g::Affine2::fromRows(v[0], v[1], v[2], v[3], v[4], v[5]);
  out << decomposeReport(a);
  return g::decomposeAffine(a) ? 0 : 1;
}

int view(ArgumentList& list, std::ostream& out, std::ostream& err) {
  g::SphereViewProblem problem;
  std::string output;
  int pixels = 360;
  auto vector3 = [&list](const std::string& option) {
    const std::vector<double> v = list.numbers(option, 3);
    return glm::dvec3{v[0], v[1], v[2]};
  };
  while (!list.empty()) {
    const std::string arg = list.take();
    if (arg == "--eye") {
      problem.eye = vector3(arg);
    } else if (arg == "--center" || arg == "--centre") {
      problem.center = vector3(arg);
    } else if (arg == "--up") {
      problem.up = vector3(arg);
    } else if (arg == "--radius") {
      problem.radius = list.number(arg);
    } else if (arg == "--height") {
      problem.heightShare = list.number(arg);
    } else if (arg == "--width") {
      problem.widthShare = list.number(arg);
    } else if (arg == "--visible") {
      problem.visibleFraction = list.number(arg);
    } else if (arg == "-o" || arg == "--output") {
      output = list.value(arg);
    } else if (arg == "--pixels") {
      pixels = static_cast<int>(parseInteger(list.value(arg), arg, 16, 8192));
    } else {
      throw UsageError(std::string("unexpected '") + arg + "' (see glass math --help)");
    }
  }
  out << viewReport(problem);
  const g::SphereViewResult result = g::solveSphereView(problem);
  if (!result.solution) return 1;
  if (!output.empty()) {
    const SphereViewMeasurement m = renderSphereView(*result.solution, problem.radius, pixels, output.c_str());
    if (!m.drawn) {
      err << "glass math view: cannot draw or write " << output << "\n";
      return 1;
    }
    out << "\nWrote " << output << " (" << m.width << " x " << m.height << "), drawn with these calls: the sphere covers "
        << m.rows << " of " << m.height << " rows (" << decimal(m.heightShare()) << ") and " << m.columns << " of "
        << m.width << " columns (" << decimal(m.widthShare()) << ").\n";
  }
  return 0;
}

int normal(ArgumentList& list, std::ostream& out) {
  std::vector<double> v = allNumbers(list, "normal");
  if (v.empty()) {
    out << "The study guide's exam, question 2.\n\n";
    v = {3, 1, 2, 3, -1, 3, 4, -1, 4};
  }
  if (v.size() != 9) throw UsageError("normal takes the nine coordinates X0 Y0 Z0 X1 Y1 Z1 X2 Y2 Z2");
  out << normalReport({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]});
  return 0;
}

int arc(ArgumentList& list, std::ostream& out) {
  double from = 0.0, to = 120.0, radius = 1.0;
  while (!list.empty()) {
    const std::string arg = list.take();
    if (arg == "--from") {
      from = list.number(arg);
    } else if (arg == "--to") {
      to = list.number(arg);
    } else if (arg == "--radius") {
      radius = list.number(arg);
    } else {
      throw UsageError(std::string("unexpected '") + arg + "' (arc takes --from, --to and --radius)");
    }
  }
  if (!(to > from) || to - from > 360.0 || !(radius > 0.0)) {
    throw UsageError("the arc needs --from < --to <= --from + 360 and a positive --radius");
  }
  out << arcReport(from, to, radius);
  return 0;
}

int torusPatch(ArgumentList& list, std::ostream& out) {
  double major = 2.0, minor = 1.0;
  bool inner = false;
  while (!list.empty()) {
    const std::string arg = list.take();
    if (arg == "--major" || arg == "--R") {
      major = list.number(arg);
    } else if (arg == "--minor" || arg == "--r") {
      minor = list.number(arg);
    } else if (arg == "--inner") {
      inner = true;
    } else {
      throw UsageError(std::string("unexpected '") + arg + "' (torus-patch takes --major, --minor and --inner)");
    }
  }
  if (!(major > 0.0) || !(minor > 0.0)) throw UsageError("the radii must be positive");
  out << torusPatchReport(major, minor, inner);
  return 0;
}

}  // namespace

int runMathCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty()) throw UsageError("which computation? rotate-compose, decompose, view, normal, arc, torus-patch");
    const std::string what = args.front();
    if (what == "-h" || what == "--help" || what == "help") {
      out << mathHelp();
      return 0;
    }
    ArgumentList list({args.begin() + 1, args.end()});
    for (const std::string& arg : args) {
      if (arg == "-h" || arg == "--help") {
        out << mathHelp();
        return 0;
      }
    }
    if (what == "rotate-compose") return rotateCompose(list, out);
    if (what == "decompose") return decompose(list, out);
    if (what == "view") return view(list, out, err);
    if (what == "normal") return normal(list, out);
    if (what == "arc") return arc(list, out);
    if (what == "torus-patch") return torusPatch(list, out);
    throw UsageError(std::string("unknown computation '") + what +
                     "' (rotate-compose, decompose, view, normal, arc, torus-patch)");
  } catch (const UsageError& e) {
    err << "glass math: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace glass::course
