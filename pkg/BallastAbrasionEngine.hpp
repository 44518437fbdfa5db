// Surface crushing (abrasion) decision for all grains of a snapshot, Dubina & Elias section 3:
//   abrade  <=>  r >= rMin  and  max over the grain's contacts of p0 > strength,
// p0 the maximum Hertz pressure of eq. 7 (HertzPressure.hpp). An abraded grain's radius becomes
// gamma r. Eq. 6 compares p0 with f_t0, but f_t0 of eq. 4 is in Pa m and p0 in Pa: the two are
// kept as separate parameters, `strength` [Pa] here and ft0 [Pa m] for crushing.
// This is the per-grain physics of the YADE engine ballast.BallastAbrasionEngine; no YADE here.
#pragma once
#include <cstdint>

namespace ballast {

struct AbrasionParameters {
	double strength;  // pressure that abrades a grain [Pa], > 0
	double rMin;      // grains with r < rMin never abrade [m], >= 0
	void   validate() const;
};

// n grains of radii [m]; nContacts contacts, contact c between side 1 and side 2 with
// grain1[c], grain2[c] the grain index of each side or -1 when that side is not a checked grain
// (a wall, or a body outside the selection), normal force Fn [N], radii R1, R2 [m] (0 = wall)
// and overlap uN [m]. Writes for every grain the largest p0 over its contacts [Pa] and abrade (0/1).
void evaluateAbrasion(const AbrasionParameters& p, long n, const double* radii, long nContacts, const long* grain1,
                      const long* grain2, const double* Fn, const double* R1, const double* R2, const double* uN,
                      double* p0max, std::uint8_t* abrade);

}  // namespace ballast
