// arnoldweb: starting other programs (ffmpeg for movies, python3 for bench
// plots) without a shell. The arguments go to the program as they are, so no
// file name, however odd, is ever interpreted as a command.
#pragma once

#include <string>
#include <vector>

namespace arnoldweb::detail {

// The path of an executable `name` found on $PATH (as execvp would find it),
// or "" if there is none. A name with a slash is checked as given.
std::string find_program(const std::string& name);

struct ProgramRun {
  int exit_code = -1;   // the program's exit status; -1 if it could not start or was killed
  int signal = 0;       // the signal that ended it, if any
  std::string output;   // stdout and stderr together, when captured (at most 64 KiB kept)
};

// Runs argv[0] (searched on $PATH) with argv[1...] and waits for it. stdin is
// /dev/null; stdout and stderr are captured into ProgramRun::output (or
// discarded when !capture). The program runs in its own process group, so a
// Ctrl-C at the terminal reaches arnoldweb, not it (arnoldweb then finishes
// what it is writing). Never starts a shell.
ProgramRun run_program(const std::vector<std::string>& argv, bool capture = true);

}  // namespace arnoldweb::detail
