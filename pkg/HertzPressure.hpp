// Maximum Hertz contact pressure, Dubina & Elias eq. 7:
//   p0 = 3 F_N / (2 pi a^2),   a^2 = R u_N,   R = R1 R2 / (R1 + R2),
// F_N the normal force [N], u_N the penetration depth (overlap) [m], R1, R2 the radii [m].
// A flat wall is given as radius 0: R2 = 0 gives R = R1 (the limit R2 -> infinity), and likewise R1 = 0.
#pragma once

namespace ballast {

// Effective radius [m]; R1, R2 >= 0 (0 = wall), not both 0.
double effectiveRadius(double R1, double R2);

// p0 [Pa]. A contact with no compression (F_N <= 0 or u_N <= 0) has no contact area and gives 0.
double hertzPressure(double Fn, double R1, double R2, double uN);

// Contact modulus E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa] of two elastic bodies (Hertz).
double contactModulus(double E1, double nu1, double E2, double nu2);

// Eq. 7 on a Hertzian contact, F_N = 4/3 E* sqrt(R) u_N^(3/2): eliminating u_N gives
//   p0 = (6 F_N E*^2 / (pi^3 R^2))^(1/3)   [Pa], from the force alone; 0 for F_N <= 0.
double hertzPressureFromForce(double Fn, double R, double Estar);

}  // namespace ballast
