#include "ClumpStress.hpp"

#include <string>

#include "InputCheck.hpp"

namespace ballast {

void clumpStress(int nMembers, const double* memberStress, const double* memberVolume, const double* memberForce,
                 const double* memberPos, const long* clumpOf, int nClumps, const double* clumpCentre,
                 const double* clumpVolume, double* out)
{
	if (nMembers < 0) throw ArgumentError("nMembers: expected >= 0, got " + std::to_string(nMembers));
	if (nClumps < 0) throw ArgumentError("nClumps: expected >= 0, got " + std::to_string(nClumps));
	for (int k = 0; k < nClumps; ++k)
		requirePositive("clumpVolumes", k, clumpVolume[k]);
	for (int m = 0; m < nMembers; ++m) {
		requirePositive("memberVolumes", m, memberVolume[m]);
		if (clumpOf[m] < 0 || clumpOf[m] >= nClumps)
			throw ArgumentError("clumpIndex[" + std::to_string(m) + "]: expected 0 <= index < " + std::to_string(nClumps)
			                    + ", got " + std::to_string(clumpOf[m]));
	}
	for (int i = 0; i < 9 * nClumps; ++i)
		out[i] = 0.0;
	for (int m = 0; m < nMembers; ++m) {
		const long    k = clumpOf[m];
		const double* s = memberStress + 9 * m;
		const double* F = memberForce + 3 * m;
		const double* x = memberPos + 3 * m;
		const double* X = clumpCentre + 3 * k;
		double*       o = out + 9 * k;
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				o[3 * i + j] += s[3 * i + j] * memberVolume[m] + F[i] * (x[j] - X[j]);  // sigma_m V_m + F_m (x) (x_m - X)
	}
	for (int k = 0; k < nClumps; ++k)
		for (int i = 0; i < 9; ++i)
			out[9 * k + i] /= clumpVolume[k];
}

}  // namespace ballast
