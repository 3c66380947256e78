// One image test: run a GL program built against glass, then compare its PNG with the reference
// image Mesa made of the same program.
//
//   glass_image_test PROGRAM OUTPUT.png REFERENCE.png DIFF.png [--fail-psnr DB] [--fail-percent P]
//
// Fails (exit 1) when the program fails, or the picture is beyond the limits; then DIFF.png shows
// where the pictures differ (see glass/image_compare.h).
#include "glass/image_compare.h"

#include <cstdio>
#include <iostream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

// Runs `program output` without a shell; returns its exit status, or -1 if it did not exit.
int runProgram(const std::string& program, const std::string& output) {
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    char* const argv[] = {const_cast<char*>(program.c_str()), const_cast<char*>(output.c_str()),
                          nullptr};
    execv(program.c_str(), argv);
    std::perror(program.c_str());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -1;
  if (WIFSIGNALED(status))
    std::cerr << program << ": killed by signal " << WTERMSIG(status) << "\n";
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: " << argv[0]
              << " PROGRAM OUTPUT.png REFERENCE.png DIFF.png [--fail-psnr DB] [--fail-percent P]\n";
    return 2;
  }
  const std::string program = argv[1], output = argv[2], reference = argv[3], diff = argv[4];

  // The comparison options, with the two images in front: `glass compare` parses the same way.
  std::vector<std::string> compareArgs = {output, reference};
  for (int i = 5; i < argc; ++i) compareArgs.emplace_back(argv[i]);
  std::string error;
  std::optional<glass::ImageCompareRequest> request =
      glass::parseImageCompareArguments(compareArgs, error);
  if (!request) {
    std::cerr << argv[0] << ": " << error << "\n";
    return 2;
  }
  request->diffPath = diff;
  request->diffOnlyOnFailure = true;

  if (access(reference.c_str(), R_OK) != 0) {
    std::cerr << "no reference image " << reference << " (tools/make-references.sh makes it)\n";
    return 1;
  }

  // A stale picture from an earlier run must not stand in for this one, nor a stale diff.
  std::remove(output.c_str());
  std::remove(diff.c_str());
  const int status = runProgram(program, output);
  if (status != 0) std::cerr << program << " exited with status " << status << "\n";
  if (access(output.c_str(), R_OK) != 0) {
    std::cerr << program << " wrote no picture to " << output << "\n";
    return 1;
  }

  std::cout << "glass:     " << output << "\nreference: " << reference << "\n";
  const int compared = glass::runImageCompare(*request, std::cout, std::cerr);
  return status == 0 && compared == 0 ? 0 : 1;
}
