// Bad input: a scene, mesh, image or argument that cannot be used. what() is one line that
// names the file (and the JSON path or line number where there is one) and what is wrong.
#pragma once
#include <stdexcept>
#include <string>

namespace softraster {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace softraster
