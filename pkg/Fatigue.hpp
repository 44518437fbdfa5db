// Fatigue of grains under repeated loading, beyond the paper (docs/fatigue.md): Basquin's S-N law
// N_f(s_p) = s_p^-b and a residual strength falling linearly with the cycles (Broutman & Sahu), counted
// on the peaks of each grain's stress ratio s = sigma_e / f_t (eqs. 1-4):
//   a peak s_p >= endurance adds  D += (1 - s_p) s_p^b   (the strength lost per cycle at s_p)
//   the strength falls with D:    crush  <=>  r >= rMin  and  s > 1 - D   (eq. 1 with f_t (1 - D))
// so a constant peak s_p crushes the grain after N_f peaks, as Miner's rule says, and a variable one
// sums the losses. Grains below rMin never degrade: they accumulate no damage.
// Peaks are load reversals: a peak is counted when s falls `hysteresis` below its running maximum,
// the next rise starts when s climbs `hysteresis` above its running minimum. Counting load cycles,
// not checks, keeps the law independent of T_c as long as the checks sample the peaks.
// No YADE here.
#pragma once

namespace ballast {

// The fatigue parameters, each within its range (InputCheck.hpp: fatigueExponent, fatigueEndurance,
// fatigueHysteresis, rMin): `checked` is the only way to build them, so the functions below take them as valid.
class FatigueParameters {
public:
	const double exponent;    // Basquin exponent b [-]
	const double endurance;   // peaks below this ratio do no damage [-]
	const double hysteresis;  // fall (and rise) of s that ends a peak (a valley) [-]
	const double rMin;        // grains with r < rMin never degrade [m] (the crushing rMin)

	// ArgumentError naming the first parameter out of its range, in the order of the arguments.
	static FatigueParameters checked(double exponent, double endurance, double hysteresis, double rMin);

private:
	FatigueParameters(double exponent_, double endurance_, double hysteresis_, double rMin_)
	        : exponent(exponent_), endurance(endurance_), hysteresis(hysteresis_), rMin(rMin_)
	{
	}
};

// Per-grain state, four doubles a grain (row-major (n,4) in the binding and the saved engine state).
struct GrainFatigue {
	double damage  = 0;  // Miner's sum D [-]
	double extreme = 0;  // running maximum of s while rising, minimum while falling [-]
	double rising  = 1;  // 1 while s climbs towards a peak, 0 while it falls towards a valley
	double peaks   = 0;  // peaks that did damage [-]
};
static_assert(sizeof(GrainFatigue) == 4 * sizeof(double), "GrainFatigue is read as an (n,4) array of doubles");

// One sample s of a grain: counts a peak if s ends one (D += (1 - peak) peak^b when peak >= endurance).
void sampleFatigue(const FatigueParameters& p, double s, GrainFatigue& g);

// Whether a grain of damage D crushes at ratio s: s > 1 - D.
inline bool crushesWithDamage(double s, double damage) { return s > 1.0 - damage; }

// For n grains: ratio [-] (finite, >= 0), radius [m] (> 0) and state of each (checked: ArgumentError names the
// grain); updates the state of the grains with r >= rMin with the sample, then writes crush (0/1):
// r >= rMin and s > 1 - D.
void evaluateFatigue(const FatigueParameters& p, long n, const double* ratio, const double* radii, GrainFatigue* state,
                     unsigned char* crush);

}  // namespace ballast
