// The inertial number of a sheared or compressed granular sample (GDR MiDi, Eur. Phys. J. E 14, 2004;
// da Cruz et al., Phys. Rev. E 72, 2005): I = rate d sqrt(rho / p), the ratio of the time a grain takes
// to rearrange under the pressure p to the time of the deformation. I < 1e-3 is the quasi-static
// regime, where the response does not depend on the rate (nor on the grains' density: density scaling
// is sound while the scaled I stays there).
#pragma once

namespace ballast {

// I [-] from the strain rate [1/s] (its magnitude), the grain diameter d [m] > 0, the grain density
// rho [kg/m^3] > 0 (the scaled one under density scaling) and the pressure p [Pa] > 0.
double inertialNumber(double rate, double d, double density, double pressure);

}  // namespace ballast
