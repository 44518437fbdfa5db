// Surface crushing (abrasion) decision for all grains of a snapshot, Dubina & Elias section 3:
//   abrade  <=>  r >= rMin  and  max over the grain's contacts of p0 > strength,
// p0 the maximum Hertz pressure of eq. 7 (HertzPressure.hpp). An abraded grain's radius becomes
// gamma r. Eq. 6 compares p0 with f_t0, but f_t0 of eq. 4 is in Pa m and p0 in Pa: the two are
// kept as separate parameters, `strength` [Pa] here and ft0 [Pa m] for crushing.
// This is the per-grain physics of the YADE engine ballast.BallastAbrasionEngine; no YADE here.
#pragma once
#include <cstdint>

namespace ballast {

// The abrasion parameters, each within its range (InputCheck.hpp): `checked` is the only way to
// build them, so evaluateAbrasion takes them as valid and checks only the grains' and contacts' values.
class AbrasionParameters {
public:
	const double strength;  // pressure that abrades a grain [Pa]
	const double rMin;      // grains with r < rMin never abrade [m]

	// ArgumentError naming the first parameter out of its range, in the order of the arguments.
	static AbrasionParameters checked(double strength, double rMin);

private:
	AbrasionParameters(double strength_, double rMin_) : strength(strength_), rMin(rMin_) {}
};

// n grains of radii [m]; nContacts contacts, contact c between side 1 and side 2 with
// grain1[c], grain2[c] the grain index of each side or -1 when that side is not a checked grain
// (a wall, or a body outside the selection), normal force Fn [N], radii R1, R2 [m] (0 = wall)
// and overlap uN [m]. Writes for every grain the largest p0 over its contacts [Pa] and abrade (0/1).
void evaluateAbrasion(const AbrasionParameters& p, long n, const double* radii, long nContacts, const long* grain1,
                      const long* grain2, const double* Fn, const double* R1, const double* R2, const double* uN,
                      double* p0max, std::uint8_t* abrade);

// Bounds on p0 (eq. 7) for Hertzian contacts that only push (F_N = 4/3 E* sqrt(R) u_N^(3/2) >= 0),
// so that a check can skip the contacts that provably cannot abrade a grain.
//
// Sphere-sphere contacts, from the largest overlap ratio rho = max u_N / (2 R) of the scene
// (YADE's utils.maxOverlapRatio(), computed in C++): eq. 7 with the Hertz law is
//   p0 = 3 F_N / (2 pi R u_N) = (2 E* / pi) sqrt(u_N / R)  <=  (2 EstarMax / pi) sqrt(2 rho).   [Pa]
double sphereContactBound(double maxOverlapRatio, double EstarMax);

// Contacts of each grain with bodies no smaller than rPartner (0: walls and facets, R = r), from the
// grain's fabric stress alone (no contact data):
//   eq. 3 traced, shear being normal to the branch l = r - u_N/2:  sum_c F_N,c l_c = |tr sigma| V,
//   l_c >= r/2 (facet, box: l = r - u_N/2, u_N <= r; Wall: l = r - u_N, u_N <= r/2)  =>  F_N,c <= 2 |tr sigma| V / r,
//   then eq. 7 with the Hertz law (hertzPressureFromForce), R >= r rPartner / (r + rPartner), E* <= EstarMax.
// n grains: traces tr(sigma) [Pa], radii r [m] (V = 4/3 pi r^3, see sphereVolume). Writes bound [Pa], which may be
// infinite for an EstarMax or a force beyond the range of doubles (the binding refuses it).
void abrasionPressureBound(long n, const double* traces, const double* radii, double rPartner, double EstarMax,
                           double* bound);

}  // namespace ballast
