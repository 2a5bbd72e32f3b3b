#include <core/math.h>

#include <fmt/format.h>

namespace rayrad {

std::string toString(const Vec3& v) { return fmt::format("({:.9g}, {:.9g}, {:.9g})", v.x, v.y, v.z); }

}  // namespace rayrad
