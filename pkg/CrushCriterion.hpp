// The stress a crushing criterion compares with the grain's strength f_t (eq. 1), beyond the paper's
// choice (issue 13; docs/strength.md). With the fabric stress sigma of eq. 3 (compression negative):
//   vonMises        sigma_e of eq. 2, the paper's; the octahedral shear stress is sqrt(2)/3 sigma_e
//   maxContactForce F_max / d^2, the largest normal contact force over the squared diameter (the
//                   characteristic stress de Bono & McDowell 2016 found to reproduce oedometer tests)
//   majorPrincipal  the largest principal compressive stress of sigma, -lambda_min(sym sigma), 0 if none
// Units: Pa. No YADE here.
#pragma once
#include <string>
#include <vector>

#include "Types.hpp"

namespace ballast {

enum class Criterion { VonMises, MaxContactForce, MajorPrincipal };

// Every criterion, in the order of the enum.
const std::vector<Criterion>& criteria();
// "vonMises", "maxContactForce" or "majorPrincipal"; anything else raises ArgumentError naming `criterion`.
Criterion   parseCriterion(const std::string& name);
const char* criterionName(Criterion c);

// The criterion's stress [Pa] of a grain of radius r [m] with fabric stress s [Pa] and largest normal
// contact force fMax [N] (read only by maxContactForce); the caller checked r > 0 and fMax >= 0.
double criterionStress(Criterion c, const Mat3& s, double fMax, double r);

}  // namespace ballast
