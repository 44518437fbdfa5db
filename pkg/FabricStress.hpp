// Fabric (Love-Weber) stress of one spherical grain, Dubina & Elias eq. 3:
//   sigma_ij = (1/V) sum_c l_i^c F_j^c,   V = 4/3 pi r^3,
// l^c from the grain centre to contact point c [m], F^c the force acting on the grain there [N].
// Compression is negative. The tensor is not symmetrised here (see VonMises.hpp).
#pragma once
#include <vector>

#include "Types.hpp"

namespace ballast {

// Volume of a sphere of radius r [m^3]; r > 0, and the volume neither under- nor overflows
// (about 2e-103 < r < 3e102): stresses divided by it stay meaningful.
double sphereVolume(double r);
// The same for element index of an array of radii, named in the error ("radii[3]").
double sphereVolume(const char* array, long index, double r);

// Eq. 3 for one grain of radius r [m]; branches and forces have the same length.
Mat3 fabricStress(double r, const std::vector<Vec3>& branches, const std::vector<Vec3>& forces);

// Eq. 3 for many grains at once from flat contact arrays: contact c acts on grain grainOf[c]
// (0 <= grainOf[c] < nGrains) with branch branches[3c..3c+2] and force forces[3c..3c+2].
// Writes nGrains row-major 3x3 tensors to out (9*nGrains doubles). radii has nGrains entries > 0.
void fabricStressMany(int nGrains, const double* radii, int nContacts, const long* grainOf, const double* branches,
                      const double* forces, double* out);

}  // namespace ballast
