// Equivalent (von Mises) stress of a grain, Dubina & Elias eq. 2:
//   sigma_e = sqrt( ((sI-sII)^2 + (sII-sIII)^2 + (sI-sIII)^2) / 2 ),
// with sI >= sII >= sIII the principal stresses of the symmetric part of the fabric tensor
// (eq. 3 is not symmetric for a grain out of rotational balance; its skew part carries no stress).
#pragma once
#include "Types.hpp"

namespace ballast {

// Principal stresses of (s + s^T)/2, sorted sI >= sII >= sIII [Pa].
Vec3 principalStresses(const Mat3& s);

// Eq. 2 [Pa]. Evaluated as sqrt(3 J2) of the symmetric part, which equals eq. 2 exactly
// and needs no eigen-decomposition (tested against the principal-stress form).
double vonMises(const Mat3& s);

}  // namespace ballast
