// The program's commands and options as plain data: what is generated from the command
// line itself (bash completion, completion.cpp) reads this, not CLI11.
#pragma once
#include <string>
#include <vector>

namespace softraster::cli {

struct OptionInfo {
    std::vector<std::string> names;    // "-o", "--output"
    bool takes_value = false;
    bool numeric = false;               // its value is a number (nothing to complete)
    std::vector<std::string> choices;   // the values it accepts, where they are a list
};
struct CommandInfo {
    std::string name;
    std::vector<OptionInfo> options;
    bool takes_files = false;                   // has positional arguments (files)
    std::vector<std::string> positional_choices;  // ... or one that takes one of these words
};

// A bash completion script for the program with these commands and top-level options:
// commands, each command's options, an option's choices, and file names elsewhere.
std::string bash_completion(const std::vector<CommandInfo>& commands, const std::vector<OptionInfo>& global);

}  // namespace softraster::cli
