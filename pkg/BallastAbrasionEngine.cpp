#include "BallastAbrasionEngine.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "FabricStress.hpp"
#include "HertzPressure.hpp"
#include "InputCheck.hpp"

namespace ballast {

AbrasionParameters AbrasionParameters::checked(double strength, double rMin)
{
	// braces: checked in the order written
	return AbrasionParameters{requireInRange(ranges::strength, "strength", strength),
	                          requireInRange(ranges::rMin, "rMin", rMin)};
}

void evaluateAbrasion(const AbrasionParameters& p, long n, const double* radii, long nContacts, const long* grain1,
                      const long* grain2, const double* Fn, const double* R1, const double* R2, const double* uN,
                      double* p0max, std::uint8_t* abrade)
{
	for (long g = 0; g < n; ++g) {
		requirePositive("radii", g, radii[g]);
		p0max[g] = 0;
	}
	for (long c = 0; c < nContacts; ++c) {
		const long gi[2] = {grain1[c], grain2[c]};
		for (int side = 0; side < 2; ++side)
			if (gi[side] < -1 || gi[side] >= n)
				throw ArgumentError(std::string(side ? "grain2[" : "grain1[") + std::to_string(c) + "]: expected -1 or 0 <= index < "
				                    + std::to_string(n) + ", got " + std::to_string(gi[side]));
		if (grain1[c] < 0 && grain2[c] < 0) continue;
		const double p0 = hertzPressure(Fn[c], R1[c], R2[c], uN[c]);  // eq. 7
		if (grain1[c] >= 0) p0max[grain1[c]] = std::max(p0max[grain1[c]], p0);
		if (grain2[c] >= 0) p0max[grain2[c]] = std::max(p0max[grain2[c]], p0);
	}
	for (long g = 0; g < n; ++g)
		abrade[g] = radii[g] >= p.rMin && p0max[g] > p.strength;  // eq. 6
}

double sphereContactBound(double maxOverlapRatio, double EstarMax)
{
	requireFinite("maxOverlapRatio", maxOverlapRatio);
	requirePositive("EstarMax", EstarMax);
	if (maxOverlapRatio <= 0) return 0.0;  // no overlapping pair of spheres (YADE gives -1)
	return 2.0 * EstarMax / M_PI * std::sqrt(2.0 * maxOverlapRatio);
}

void abrasionPressureBound(long n, const double* traces, const double* radii, double rPartner, double EstarMax,
                           double* bound)
{
	requireNonNegative("rPartner", rPartner);
	requirePositive("EstarMax", EstarMax);
	for (long g = 0; g < n; ++g) {
		const double r = radii[g];
		const double V = sphereVolume("radii", g, r);
		requireFinite("traces", g, traces[g]);
		const double Fmax = 2.0 * std::fabs(traces[g]) * V / r;  // largest single normal force
		requireFiniteResult("traces, radii", "largest contact force 2 |tr sigma| V / r", g, Fmax);
		bound[g] = hertzPressureFromForce(Fmax, effectiveRadius(r, rPartner), EstarMax);  // smallest R (rPartner 0: R = r)
	}
}

}  // namespace ballast
