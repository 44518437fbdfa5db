// Size-dependent grain strength, Dubina & Elias eq. 4 generalised to a power m:
//   f_t = f_t0 / r^m      (the paper's eq. 4 is m = 1; m = 1 is also the Weibull size effect of modulus 3).
// Units: r [m], f_t [Pa], so f_t0 is in [Pa m^m] (Pa m for the paper's m = 1).
#pragma once

namespace ballast {

// f_t [Pa] of a grain of radius r [m], of ft0 [Pa m^m] and m [-]. Checks nothing: the caller checked
// ft0 and m against their ranges (InputCheck.hpp; CrushParameters::checked) and r > 0.
double sizeStrength(double ft0, double r, double m = 1.0);

}  // namespace ballast
