// Tests of the abrasion decision, Dubina & Elias section 3: abrade <=> r >= rMin and max_c p0 > strength,
// p0 = 3 Fn / (2 pi R uN) the maximum Hertz pressure of eq. 7.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <random>
#include <limits>
#include <string>
#include <vector>

#include "ArgumentMessage.hpp"
#include "BallastAbrasionEngine.hpp"
#include "HertzPressure.hpp"
#include "InputCheck.hpp"

using namespace ballast;

namespace {

using ballast_test::messageOf;

const double kPi  = std::acos(-1.0);
const double kRel = 1e-12;

// Eq. 7 by hand with R = R1 R2 / (R1 + R2), a wall (0) giving the other radius.
double p0Hand(double Fn, double R1, double R2, double uN)
{
	const double R = R1 == 0 ? R2 : R2 == 0 ? R1 : R1 * R2 / (R1 + R2);
	return 3.0 * Fn / (2.0 * kPi * R * uN);
}

// Normal force giving pressure p0 (eq. 7 inverted).
double forceFor(double p0, double R, double uN) { return p0 * 2.0 * kPi * R * uN / 3.0; }

// A list of contacts in the flat form evaluateAbrasion takes.
struct Contacts {
	std::vector<long>   g1, g2;
	std::vector<double> Fn, R1, R2, uN;
	void                add(long a, long b, double f, double r1, double r2, double u)
	{
		g1.push_back(a);
		g2.push_back(b);
		Fn.push_back(f);
		R1.push_back(r1);
		R2.push_back(r2);
		uN.push_back(u);
	}
	long n() const { return static_cast<long>(g1.size()); }
};

// The abrasion parameters before their check.
struct Unchecked {
	double strength, rMin;
};

// As the binding does: the parameters checked once (AbrasionParameters::checked), then the decision.
void run(const Unchecked& u, const std::vector<double>& radii, const Contacts& c, std::vector<double>& p0,
         std::vector<std::uint8_t>& ab)
{
	const AbrasionParameters p = AbrasionParameters::checked(u.strength, u.rMin);
	p0.assign(radii.size(), -1.0);
	ab.assign(radii.size(), 7);
	evaluateAbrasion(p, static_cast<long>(radii.size()), radii.data(), c.n(), c.g1.data(), c.g2.data(), c.Fn.data(),
	                 c.R1.data(), c.R2.data(), c.uN.data(), p0.data(), ab.data());
}

}  // namespace

TEST(BallastAbrasionEngine, MaxOverContactsOfOneGrain)
{
	// One grain, three contacts of different pressure: p0max is the largest of the three by eq. 7.
	const std::vector<double> radii = {0.02};
	Contacts                  c;
	c.add(0, -1, 1e3, 0.02, 0.015, 1e-5);
	c.add(-1, 0, 4e3, 0.01, 0.02, 2e-5);  // the grain on side 2
	c.add(0, -1, 2e3, 0.02, 0.0, 5e-6);   // wall
	const double p[3] = {p0Hand(1e3, 0.02, 0.015, 1e-5), p0Hand(4e3, 0.01, 0.02, 2e-5), p0Hand(2e3, 0.02, 0.0, 5e-6)};
	const double pmax = std::max(p[0], std::max(p[1], p[2]));
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	run({0.99 * pmax, 0.0}, radii, c, p0, ab);
	EXPECT_NEAR(p0[0], pmax, kRel * pmax);
	EXPECT_EQ(ab[0], 1);
	run({1.01 * pmax, 0.0}, radii, c, p0, ab);
	EXPECT_NEAR(p0[0], pmax, kRel * pmax);
	EXPECT_EQ(ab[0], 0);
}

TEST(BallastAbrasionEngine, WallContact)
{
	// Sphere on a wall, R2 = 0: R = R1, p0 = 3 Fn / (2 pi R1 uN).
	const double              r = 0.018, Fn = 3e3, uN = 8e-6;
	const double              ph = 3.0 * Fn / (2.0 * kPi * r * uN);
	Contacts                  c;
	c.add(0, -1, Fn, r, 0.0, uN);
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	run({1e3, 0.0}, {r}, c, p0, ab);
	EXPECT_NEAR(p0[0], ph, kRel * ph);
	EXPECT_EQ(ab[0], 1);
}

TEST(BallastAbrasionEngine, ContactCountsForBothSides)
{
	// A contact between grains 0 and 2 raises both; grain 1 has no contact and keeps p0max = 0.
	const std::vector<double> radii = {0.02, 0.02, 0.01};
	Contacts                  c;
	c.add(0, 2, 5e3, 0.02, 0.01, 1e-5);
	const double              ph = 3.0 * 5e3 / (2.0 * kPi * (0.02 * 0.01 / 0.03) * 1e-5);
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	run({0.99 * ph, 0.0}, radii, c, p0, ab);
	EXPECT_NEAR(p0[0], ph, kRel * ph);
	EXPECT_NEAR(p0[2], ph, kRel * ph);
	EXPECT_EQ(p0[1], 0.0);
	EXPECT_EQ(ab[0], 1);
	EXPECT_EQ(ab[1], 0);
	EXPECT_EQ(ab[2], 1);
}

TEST(BallastAbrasionEngine, UncheckedSidesSkipped)
{
	// A contact with both sides -1 is ignored entirely, even with data eq. 7 would reject (two walls).
	Contacts c;
	c.add(-1, -1, 1e9, 0.0, 0.0, 1e-3);
	c.add(-1, 0, 10.0, 0.01, 0.02, 1e-5);
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	EXPECT_NO_THROW(run({1e12, 0.0}, {0.02}, c, p0, ab));
	const double ph = p0Hand(10.0, 0.01, 0.02, 1e-5);
	EXPECT_NEAR(p0[0], ph, kRel * ph);
	EXPECT_EQ(ab[0], 0);
}

TEST(BallastAbrasionEngine, TensileOrSeparatedContactsGiveNoPressure)
{
	Contacts c;
	c.add(0, -1, -50.0, 0.02, 0.02, 1e-5);
	c.add(0, -1, 50.0, 0.02, 0.02, -1e-6);
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	run({1.0, 0.0}, {0.02}, c, p0, ab);
	EXPECT_EQ(p0[0], 0.0);
	EXPECT_EQ(ab[0], 0);
}

TEST(BallastAbrasionEngine, ThresholdAndMinimumRadius)
{
	// Pressures set to 1.01 and 0.99 times the strength; grains below rMin never abrade, r == rMin may.
	const double              S = 2e8, rMin = 0.015, uN = 1e-5;
	const std::vector<double> radii = {0.02, 0.02, 0.01, rMin, std::nextafter(rMin, 0.0)};
	const double              fac[5] = {1.01, 0.99, 5.0, 1.01, 1.01};
	Contacts                  c;
	for (long g = 0; g < 5; ++g)  // each grain on a wall: R = radius
		c.add(g, -1, forceFor(fac[g] * S, radii[g], uN), radii[g], 0.0, uN);
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	run({S, rMin}, radii, c, p0, ab);
	for (int g = 0; g < 5; ++g)
		EXPECT_NEAR(p0[g], fac[g] * S, kRel * S) << g;
	EXPECT_EQ(ab[0], 1);
	EXPECT_EQ(ab[1], 0);
	EXPECT_EQ(ab[2], 0);  // 5x the strength but r < rMin
	EXPECT_EQ(ab[3], 1);  // r == rMin is eligible
	EXPECT_EQ(ab[4], 0);
}

TEST(BallastAbrasionEngine, BadInputsThrow)
{
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	for (long bad : {1L, 5L, -2L}) {
		Contacts c;
		c.add(0, bad, 10.0, 0.01, 0.01, 1e-6);
		try {
			run({1e6, 0.0}, {0.01}, c, p0, ab);
			ADD_FAILURE() << "grain index " << bad << " accepted";
		} catch (const ArgumentError& e) {
			const std::string m = e.what();
			EXPECT_EQ(m.rfind("grain2[0]", 0), 0u) << m;  // the argument and the contact
			EXPECT_NE(m.find(std::to_string(bad)), std::string::npos) << m;
		}
	}
	Contacts c;
	EXPECT_EQ(messageOf([&] { run({0.0, 0.0}, {0.01}, c, p0, ab); }), "strength: expected a finite number > 0, got 0");
	EXPECT_EQ(messageOf([&] { run({-5.0, 0.0}, {0.01}, c, p0, ab); }), "strength: expected a finite number > 0, got -5");
	EXPECT_EQ(messageOf([&] { run({1e6, -1.0}, {0.01}, c, p0, ab); }), "rMin: expected a finite number >= 0, got -1");
	EXPECT_EQ(messageOf([&] { run({5.0, std::numeric_limits<double>::quiet_NaN()}, {0.01}, c, p0, ab); }),
	          "rMin: expected a finite number >= 0, got nan");
	EXPECT_EQ(messageOf([&] { run({1e6, 0.0}, {0.01, 0.0}, c, p0, ab); }), "radii[1]: expected a finite number > 0, got 0");
}

namespace {

// Hertz contact by hand: the overlap of force F on effective radius R with modulus Es.
double hertzOverlap(double F, double R, double Es) { return std::pow(3 * F / (4 * Es * std::sqrt(R)), 2.0 / 3.0); }

// tr(sigma) of eq. 3 for a grain of radius r whose contacts push with F[c] at overlap u[c]:
// the branch to the contact point is r - u/2 long and parallel to the force.
double traceOf(double r, const std::vector<double>& F, const std::vector<double>& u)
{
	double s = 0;
	for (size_t c = 0; c < F.size(); ++c) s += F[c] * (r - u[c] / 2);
	return -s / (4.0 / 3.0 * kPi * r * r * r);  // compression negative
}

}  // namespace

TEST(BallastAbrasionEngine, PressureBoundOfOneContactClosedForm)
{
	// One contact with the smallest sphere: the bound is eq. 7 at 2 l / r times the force, with
	// l = r - uN/2, so bound / p0 = (2 l / r)^(1/3) exactly (just below 2^(1/3)).
	const double r = 0.02, rs = 0.005, Es = 1.65e11, F = 4e4;
	const double R  = r * rs / (r + rs);
	const double uN = hertzOverlap(F, R, Es);
	const double tr = traceOf(r, {F}, {uN});
	double       bound;
	abrasionPressureBound(1, &tr, &r, rs, Es, &bound);
	const double p0 = hertzPressure(F, r, rs, uN);
	EXPECT_NEAR(bound / p0, std::cbrt(2 * (r - uN / 2) / r), 1e-12);
	EXPECT_GT(bound, p0);
}

TEST(BallastAbrasionEngine, PressureBoundHoldsForRandomGrains)
{
	// Random grains with 1-12 Hertz contacts against spheres (radius >= rSmall) or walls, moduli
	// up to EstarMax: the bound of each grain is at least the largest p0 of eq. 7 over its contacts.
	std::mt19937_64                        rng(12345);
	std::uniform_real_distribution<double> U(0.0, 1.0);
	const double                           rs = 0.004, EsMax = 2.6e11;
	double                                 worst = 0;  // smallest bound / p0 seen
	for (int g = 0; g < 2000; ++g) {
		const double        r = 0.005 + 0.02 * U(rng);
		const int           n = 1 + static_cast<int>(12 * U(rng));
		std::vector<double> F, u, p;
		for (int c = 0; c < n; ++c) {
			const double other = U(rng) < 0.2 ? 0.0 : rs + 0.03 * U(rng) * U(rng);  // 0: a wall
			const double R     = other == 0 ? r : r * other / (r + other);
			const double Es    = EsMax * (0.3 + 0.7 * U(rng));
			F.push_back(std::pow(10.0, 6 * U(rng)));  // 1 N ... 1 MN
			u.push_back(hertzOverlap(F.back(), R, Es));
			p.push_back(hertzPressure(F.back(), r, other, u.back()));
		}
		const double tr = traceOf(r, F, u);
		double       bound;
		abrasionPressureBound(1, &tr, &r, rs, EsMax, &bound);
		const double pmax = *std::max_element(p.begin(), p.end());
		EXPECT_GE(bound, pmax) << "grain " << g;
		worst = std::min(worst == 0 ? bound / pmax : worst, bound / pmax);
	}
	EXPECT_GE(worst, 1.0);
	EXPECT_LT(worst, 1.4);  // not vacuous: the tightest possible is 2^(1/3) = 1.26 (one contact, l = r)
}

TEST(BallastAbrasionEngine, PressureBoundBadInputs)
{
	const double tr = -1e6, r = 0.01, nan = std::numeric_limits<double>::quiet_NaN();
	double       b;
	EXPECT_THROW(abrasionPressureBound(1, &tr, &r, -0.01, 1e11, &b), ArgumentError);
	EXPECT_THROW(abrasionPressureBound(1, &tr, &r, 0.01, 0.0, &b), ArgumentError);
	const double r0 = 0.0;
	EXPECT_THROW(abrasionPressureBound(1, &tr, &r0, 0.01, 1e11, &b), ArgumentError);
	EXPECT_THROW(abrasionPressureBound(1, &nan, &r, 0.01, 1e11, &b), ArgumentError);
	const double zero = 0.0;
	abrasionPressureBound(1, &zero, &r, 0.01, 1e11, &b);
	EXPECT_EQ(b, 0.0);  // an unloaded grain cannot abrade
}

TEST(BallastAbrasionEngine, PressureBoundRefusesNonFiniteIntermediates)
{
	// A trace so large that the largest force 2 |tr| V / r overflows: refused, naming the arrays and the grain.
	const double r[] = {0.01, 1.0}, tr[] = {-1e6, -1e308};
	double       b[2];
	const std::string m = messageOf([&] { abrasionPressureBound(2, tr, r, 0.01, 1e11, b); });
	EXPECT_EQ(m.rfind("traces, radii:", 0), 0u) << m;
	EXPECT_NE(m.find("would be inf at index 1"), std::string::npos) << m;
	// A radius whose volume underflows (V = 0 would give a bound of 0 whatever the stress)
	const double tiny = 1e-200;
	const std::string m2 = messageOf([&] { abrasionPressureBound(1, tr, &tiny, 0.01, 1e11, b); });
	EXPECT_EQ(m2.rfind("radii[0]:", 0), 0u) << m2;
	EXPECT_NE(m2.find("1e-200"), std::string::npos) << m2;
}

TEST(BallastAbrasionEngine, BadGrain1IsNamed)
{
	std::vector<double>       p0;
	std::vector<std::uint8_t> ab;
	Contacts                  c;
	c.add(0, -1, 10.0, 0.01, 0.0, 1e-6);
	c.add(3, 0, 10.0, 0.01, 0.01, 1e-6);
	const std::string m = messageOf([&] { run({1e6, 0.0}, {0.01}, c, p0, ab); });
	EXPECT_EQ(m.rfind("grain1[1]: expected -1 or 0 <= index < 1, got 3", 0), 0u) << m;
}

TEST(BallastAbrasionEngine, WallContactBoundUsesTheGrainRadius)
{
	// rPartner = 0: the contacts are with walls, R = r. One wall contact: bound / p0 = (2 l / r)^(1/3).
	const double r = 0.015, Es = 3.2e11, F = 2e4;
	const double uN = hertzOverlap(F, r, Es);
	const double tr = traceOf(r, {F}, {uN});
	double       bound;
	abrasionPressureBound(1, &tr, &r, 0.0, Es, &bound);
	EXPECT_NEAR(bound / hertzPressure(F, r, 0.0, uN), std::cbrt(2 * (r - uN / 2) / r), 1e-12);
}

TEST(BallastAbrasionEngine, SphereContactBoundFromTheLargestOverlapRatio)
{
	// Hertz contacts between spheres: eq. 7 depends on u_N / R only, so the contact with the largest
	// u_N / (2 R) has the largest p0, and the bound equals it.
	const double Es = 1.65e11;
	double       worst = 0, rho = 0;
	for (double R1 : {0.012, 0.02})
		for (double R2 : {0.01, 0.022})
			for (double F : {1e3, 5e4}) {
				const double R  = R1 * R2 / (R1 + R2);
				const double uN = hertzOverlap(F, R, Es);
				if (uN / (2 * R) > rho) {
					rho   = uN / (2 * R);
					worst = hertzPressure(F, R1, R2, uN);
				}
			}
	EXPECT_NEAR(sphereContactBound(rho, Es), worst, 1e-12 * worst);
	EXPECT_EQ(sphereContactBound(-1.0, Es), 0.0);  // YADE's value when no spheres touch
	EXPECT_THROW(sphereContactBound(0.01, 0.0), ArgumentError);
	EXPECT_THROW(sphereContactBound(std::numeric_limits<double>::infinity(), Es), ArgumentError);
}
