// Density scaling (mass scaling) that survives crushing: every body gets the inertia that makes its own
// P-wave step (eq. 5 for that body) reach a target step, so the run steps at the target while each body
// is as far from its stability limit as the paper's smallest grain is at the paper's step.
//   ownStep = r sqrt(rho / E)  [s]   (eq. 5 for one sphere; YADE's PWaveTimeStep is its minimum)
//   YADE's State::densityScaling multiplies the body's accelerations: s = (ownStep / targetStep)^2, which
//   scales its density by 1/s; s = 1 when ownStep >= targetStep (a body is never made lighter).
#pragma once

namespace ballast {

// r sqrt(rho / E) [s]: radius r [m] > 0, density rho [kg/m^3] > 0, Young's modulus E [Pa] > 0.
double pWaveStep(double r, double density, double young);

// The factor of YADE's State::densityScaling, in (0, 1]: (ownStep / targetStep)^2, at most 1.
// ownStep [s] > 0; targetStep [s] >= 0, 0 meaning no scaling (1).
double densityScaling(double ownStep, double targetStep);

}  // namespace ballast
