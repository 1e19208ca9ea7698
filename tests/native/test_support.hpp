// Helpers shared by the native test files: printing vectors with full precision in failure messages.
#pragma once

#include <sstream>
#include <string>

#include <glm/vec3.hpp>

namespace conecurl::testing {

inline std::string str(glm::dvec3 v) {
    std::ostringstream os;
    os.precision(17);
    os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return os.str();
}

}  // namespace conecurl::testing
