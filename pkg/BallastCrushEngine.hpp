// Bulk crushing decision for all grains of a snapshot, Dubina & Elias section 2:
//   crush  <=>  r >= rMin  and  sigma > f_t,
// sigma the criterion's stress (CrushCriterion.hpp; the paper's: sigma_e of eq. 2, VonMises.hpp) of the
// fabric stress of eq. 3 (FabricStress.hpp), f_t = w ft0 / r^m from eq. 4 (Strength.hpp) with w a
// grain's Weibull strength factor (Weibull.hpp; 1 in the paper). The fragments are in FragmentPattern.hpp.
// This is the per-grain physics of the YADE engine ballast.BallastCrushEngine; no YADE here.
#pragma once
#include <cstdint>

#include "CrushCriterion.hpp"

namespace ballast {

// The crushing parameters, each within its range (InputCheck.hpp): `checked` is the only way to
// build them, so evaluateCrushing takes them as valid and checks only the grains' values.
class CrushParameters {
public:
	const double    ft0;        // reference strength [Pa m^m]
	const double    m;          // size-effect exponent [-] (eq. 4: 1)
	const double    rMin;       // grains with r < rMin never crush [m]
	const Criterion criterion;  // the stress compared with f_t

	// ArgumentError naming the first parameter out of its range, in the order of the arguments.
	static CrushParameters checked(double ft0, double m, double rMin, Criterion criterion = Criterion::VonMises);

private:
	CrushParameters(double ft0_, double m_, double rMin_, Criterion criterion_)
	        : ft0(ft0_), m(m_), rMin(rMin_), criterion(criterion_)
	{
	}
};

// For n grains: stresses holds n row-major 3x3 fabric tensors [Pa], radii n radii [m] (> 0), fMax the
// largest normal contact force of each [N] (>= 0; read by maxContactForce only; may be null otherwise),
// factor each grain's strength factor w [-] (> 0; null: all 1). Writes the criterion's stress [Pa],
// the strength f_t [Pa] and crush (0/1) for every grain. ArgumentError names a bad grain value ("radii[3]").
void evaluateCrushing(const CrushParameters& p, long n, const double* stresses, const double* radii, const double* fMax,
                      const double* factor, double* stress, double* strength, std::uint8_t* crush);

}  // namespace ballast
