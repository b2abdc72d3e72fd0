#include "softraster/version.h"

namespace softraster {

const char* version() { return SOFTRASTER_VERSION; }

}  // namespace softraster
