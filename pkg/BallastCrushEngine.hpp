// Bulk crushing decision for all grains of a snapshot, Dubina & Elias section 2:
//   crush  <=>  r >= rMin  and  sigma_e > f_t,
// sigma_e from eq. 2 (VonMises.hpp) of the fabric stress of eq. 3 (FabricStress.hpp),
// f_t = ft0 / r^m from eq. 4 (Strength.hpp). The fragments are in FragmentPattern.hpp.
// This is the per-grain physics of the YADE engine ballast.BallastCrushEngine; no YADE here.
#pragma once
#include <cstdint>

namespace ballast {

struct CrushParameters {
	double ft0;   // reference strength [Pa m^m], > 0
	double m;     // size-effect exponent [-], >= 0 (eq. 4: 1)
	double rMin;  // grains with r < rMin never crush [m], >= 0
	void   validate() const;
};

// For n grains: stresses holds n row-major 3x3 fabric tensors [Pa], radii n radii [m] (> 0).
// Writes sigmaE [Pa], strength f_t [Pa] and crush (0/1) for every grain.
void evaluateCrushing(const CrushParameters& p, long n, const double* stresses, const double* radii, double* sigmaE,
                      double* strength, std::uint8_t* crush);

}  // namespace ballast
