// The command line of the softraster program (command_line.cpp): parses argv and runs the
// command it names; returns the process exit code.
#pragma once

namespace softraster::cli {

int run_command_line(int argc, char** argv);

}  // namespace softraster::cli
