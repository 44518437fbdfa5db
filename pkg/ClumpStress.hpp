// Love-Weber stress of a clump as one grain (issue 47, item 2), from its members' stresses:
//   sigma_clump = (1/V) sum_c f^c (x) (x^c - X)
//               = (1/V) sum_m [ sigma_m V_m + F_m (x) (x_m - X) ],
// sigma_m = (1/V_m) sum_{c of m} f^c (x) (x^c - x_m) the member's stress as YADE's bodyStressTensors gives it
// (f_i l_j, force on the member first, V_m = 4/3 pi refR^3), F_m = sum_{c of m} f^c the member's contact force,
// x_m its centre, X the clump's centre of mass, V the clump's (union) volume. Compression is negative.
#pragma once

namespace ballast {

// nMembers members, member m of clump clumpOf[m] (0 <= clumpOf[m] < nClumps):
// memberStress 9 nMembers (row-major 3x3), memberVolume nMembers (> 0), memberForce 3 nMembers,
// memberPos 3 nMembers, clumpCentre 3 nClumps, clumpVolume nClumps (> 0). Writes 9 nClumps to out.
void clumpStress(int nMembers, const double* memberStress, const double* memberVolume, const double* memberForce,
                 const double* memberPos, const long* clumpOf, int nClumps, const double* clumpCentre,
                 const double* clumpVolume, double* out);

}  // namespace ballast
