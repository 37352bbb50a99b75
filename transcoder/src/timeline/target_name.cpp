#include "fapc/transcoder/target_name.hpp"

#include <ostream>

namespace fapc {

std::ostream& operator<<(std::ostream& out, const TargetName& name) { return out << name.str(); }

}  // namespace fapc
