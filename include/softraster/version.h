// The version of the installed shared library a program runs with (CMake's softraster_VERSION
// and pkg-config's --modversion tell the one it was built against). Defined in the shared
// library only (src/version.cpp): the in-tree programs link the static archive.
#pragma once

namespace softraster {

const char* version();  // "major.minor.patch"

}  // namespace softraster
