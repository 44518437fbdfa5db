// Cycle jumping (docs/cycles.md): many load cycles of fatigue damage advanced at once, as fatigue analyses of
// structures do, where the directly simulated cycles show a steady damage rate. Over the last `window`
// directly simulated cycles each grain's damage D (Fatigue.hpp) grew at the rate r = (D_W - D_0) / W per
// cycle; the rates of the window's two halves, a and b, tell how steady it is. s_p is a grain's largest
// stress ratio s = sigma_e / f_t in the window and d the drift of its peaks per cycle (the mean peak of the
// second half less that of the first, over W / 2 cycles) less `driftNoise` standard errors of that difference
// (from the scatter of the peaks about their halves' means): peaks that only scatter do not drift. A grain below
// the endurance ratio e whose peaks drift (s_k = s_p + k d in the k-th jumped cycle) would collect, unseen, the
// damage of Fatigue.hpp's law: Dd(DN) = sum over k <= DN of (1 - s_k) s_k^b where s_k >= e, bounded above by
// (1/d) times the integral of that law (made nondecreasing past its top at b / (b + 1)) from max(e, s_1) to
// s_DN + d. The jump DN is the largest number of cycles for which
//   DN              <= growth N             the count N grows by at most that factor: cycles are simulated
//                                           again in every stretch of log N, where the bed may change
//   DN r            <= maxDamage            no grain's damage changes by more than maxDamage
//   DN |b - a|      <= steady maxDamage     the extrapolation of each grain is uncertain by at most that
//   Dd(DN)          <= driftDamage          no grain below the endurance ratio drifts up into more damage unseen
//                                           (driftDamage 0: none reaches e, s_p + DN d <= e)
//   s_p + (DN + margin) d <= 1 - D          nor drifts up to failure (eq. 1) inside the jump
//   D + (DN + margin) r <= 1 - s_p          no grain fails inside the jump (eq. 1 with f_t (1 - D) at its
//                                           largest ratio s_p of the window), and `margin` cycles before the
//                                           failing one are simulated again
//   DN              <= remaining            the run's cycles
// Crushes are never extrapolated: the cycle a grain fails in is always simulated. No YADE here.
#pragma once

namespace ballast {

// The parameters, each within its range (InputCheck.hpp: jumpWindow, jumpSteady, jumpMaxDamage, jumpMargin,
// jumpGrowth, fatigueEndurance, jumpDriftNoise, fatigueExponent, jumpDriftDamage): `checked` is the only way to
// build them.
class CycleJumpParameters {
public:
	const long   window;     // directly simulated cycles whose damage gives the rate [cycles]
	const double steady;     // allowed uncertainty of a jump's damage, as a fraction of maxDamage [-]
	const double maxDamage;  // largest change of any grain's damage in one jump [-]
	const long   margin;     // simulated cycles left before the first cycle a grain is predicted to fail in [cycles]
	const double growth;      // largest jump as a multiple of the cycles counted so far [-]
	const double endurance;   // the fatigue law's endurance ratio: peaks below it do no damage [-]
	const double driftNoise;  // a drift of the peaks counts beyond this many standard errors [-]
	const double exponent;    // the fatigue law's exponent b [-]
	const double driftDamage; // damage a grain below the endurance ratio may collect unseen in a jump as it drifts [-]

	// ArgumentError naming the first parameter out of its range, in the order of the arguments.
	static CycleJumpParameters checked(double window, double steady, double maxDamage, double margin, double growth,
	                                   double endurance, double driftNoise, double exponent, double driftDamage);

private:
	CycleJumpParameters(long window_, double steady_, double maxDamage_, long margin_, double growth_, double endurance_,
	                    double driftNoise_, double exponent_, double driftDamage_)
	        : window(window_), steady(steady_), maxDamage(maxDamage_), margin(margin_), growth(growth_),
	          endurance(endurance_), driftNoise(driftNoise_), exponent(exponent_), driftDamage(driftDamage_)
	{
	}
};

// What bounds a jump, in the order the bounds are tested (the first of equal bounds is named).
enum class JumpLimit { remaining = 0, growth = 1, maxDamage = 2, steady = 3, endurance = 4, failure = 5 };
const char* jumpLimitName(JumpLimit limit);

struct JumpPlan {
	long      cycles  = 0;   // DN >= 0 (0: simulate on)
	JumpLimit limit   = JumpLimit::remaining;
	long      grain   = -1;  // the grain that bounds it (-1 for remaining)
	double    maxRate = 0;   // the largest damage rate r [1/cycle]
	double    peak    = 0;   // the bounding grain's largest ratio s_p in the window [-] (0 for remaining, growth)
	double    drift   = 0;   // and the drift d of its peaks [1/cycle] (<= 0: none counted)
};

// n grains; damage: (window + 1) x n, row-major, row k the damage of every grain at the end of the k-th of
// the window's cycles (row 0 where the window starts: finite, >= 0, never falling along a column); peaks:
// window x n, each grain's largest s in each of the window's cycles (finite, >= 0; some > 0 where its damage
// grew); cycle (>= 1) the count N at the window's end; remaining (>= 0) cycles left. Writes each grain's rate r
// to rate (n).
// The upper bound on Dd(cycles) above for a grain of largest ratio sMax < e whose peaks drift by d > 0 a cycle.
double driftDamageBound(const CycleJumpParameters& p, double sMax, double d, double cycles);

JumpPlan planJump(const CycleJumpParameters& p, long n, const double* damage, const double* peaks, long cycle,
                  long remaining, double* rate);

}  // namespace ballast
