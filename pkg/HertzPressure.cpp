#include "HertzPressure.hpp"

#include <cmath>

#include "InputCheck.hpp"

namespace ballast {

double effectiveRadius(double R1, double R2)
{
	requireNonNegative("R1", R1);
	requireNonNegative("R2", R2);
	if (R1 == 0 && R2 == 0) throw ArgumentError("R1, R2: expected at least one radius > 0 (0 means a wall), got 0 and 0");
	if (R1 == 0) return R2;
	if (R2 == 0) return R1;
	return R1 * R2 / (R1 + R2);
}

double hertzPressure(double Fn, double R1, double R2, double uN)
{
	requireFinite("Fn", Fn);
	requireFinite("uN", uN);
	const double R = effectiveRadius(R1, R2);
	if (Fn <= 0 || uN <= 0) return 0.0;
	return 3.0 * Fn / (2.0 * M_PI * R * uN);  // a^2 = R uN
}

}  // namespace ballast
