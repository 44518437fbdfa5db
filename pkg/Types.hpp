// Common Eigen types of the ballast core. The core has no YADE dependency.
#pragma once
#include <Eigen/Dense>

namespace ballast {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
// A sphere as [x, y, z, r] in metres.
using Sphere4 = Eigen::Vector4d;
}  // namespace ballast
