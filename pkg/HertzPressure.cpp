#include "HertzPressure.hpp"

#include <algorithm>
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
	// R1 R2 / (R1 + R2) written so that it neither overflows (R1 R2 > 1.8e308) nor underflows (R1 R2 < 5e-324)
	const double a = std::min(R1, R2), b = std::max(R1, R2);
	return a / (1.0 + a / b);
}

double hertzPressure(double Fn, double R1, double R2, double uN)
{
	requireFinite("Fn", Fn);
	requireFinite("uN", uN);
	const double R = effectiveRadius(R1, R2);
	if (Fn <= 0 || uN <= 0) return 0.0;
	return 3.0 * Fn / (2.0 * M_PI * R * uN);  // a^2 = R uN
}

double contactModulus(double E1, double nu1, double E2, double nu2)
{
	requirePositive("E1", E1);
	requirePositive("E2", E2);
	for (double nu : {nu1, nu2})
		if (!(nu >= -1 && nu < 0.5)) throw ArgumentError("nu1, nu2: expected Poisson ratios in [-1, 0.5), got " + formatValue(nu));
	return 1.0 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
}

double hertzPressureFromForce(double Fn, double R, double Estar)
{
	requireFinite("Fn", Fn);
	requirePositive("R", R);
	requirePositive("Estar", Estar);
	if (Fn <= 0) return 0.0;
	return std::cbrt(6.0 * Fn * Estar * Estar / (M_PI * M_PI * M_PI * R * R));
}

}  // namespace ballast
