// Closed-form tests of the crushing criteria (CrushCriterion.hpp) on the fabric stress of eq. 3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ArgumentMessage.hpp"
#include "CrushCriterion.hpp"
#include "FabricStress.hpp"

using namespace ballast;

namespace {

const double kPi = std::acos(-1.0);

// Eq. 3 of a grain of radius r under three orthogonal pairs of opposite compressive forces F1, F2, F3
// applied on its surface: sigma_ii = -2 r F_i / V = -3 F_i / (2 pi r^2).
Mat3 pairs(double r, double F1, double F2, double F3)
{
	std::vector<Vec3> l, f;
	const double      F[3] = {F1, F2, F3};
	for (int i = 0; i < 3; ++i) {
		Vec3 e = Vec3::Zero();
		e[i]   = 1;
		l.push_back(r * e);
		f.push_back(-F[i] * e);
		l.push_back(-r * e);
		f.push_back(F[i] * e);
	}
	return fabricStress(r, l, f);
}

}  // namespace

TEST(CrushCriterion, GrainSqueezedAlongADiameter)
{
	// F along one diameter: sigma_xx = -3F / (2 pi r^2), the rest 0. Von Mises and the major principal
	// stress are both 3F / (2 pi r^2); de Bono & McDowell's F / d^2 = F / (4 r^2).
	const double r = 0.015, F = 2.0e4, s = 3 * F / (2 * kPi * r * r);
	const Mat3   S = pairs(r, F, 0, 0);
	EXPECT_NEAR(criterionStress(Criterion::VonMises, S, F, r), s, 1e-12 * s);
	EXPECT_NEAR(criterionStress(Criterion::MajorPrincipal, S, F, r), s, 1e-12 * s);
	EXPECT_NEAR(criterionStress(Criterion::MaxContactForce, S, F, r), F / (4 * r * r), 1e-12 * s);
}

TEST(CrushCriterion, GrainUnderThreeOrthogonalPairs)
{
	// F = (3, 2, 1) x 1e4 N: sigma_ii = -3 F_i / (2 pi r^2) = -k F_i. Von Mises:
	// k sqrt(((3-2)^2 + (2-1)^2 + (1-3)^2) / 2) 1e4 = k sqrt(3) 1e4; major principal k 3e4; F/d^2 3e4 / (4 r^2).
	const double r = 0.02, k = 3 / (2 * kPi * r * r);
	const Mat3   S = pairs(r, 3e4, 2e4, 1e4);
	EXPECT_NEAR(criterionStress(Criterion::VonMises, S, 3e4, r), k * std::sqrt(3.0) * 1e4, 1e-12 * k * 3e4);
	EXPECT_NEAR(criterionStress(Criterion::MajorPrincipal, S, 3e4, r), k * 3e4, 1e-12 * k * 3e4);
	EXPECT_NEAR(criterionStress(Criterion::MaxContactForce, S, 3e4, r), 3e4 / (4 * r * r), 1e-12 * k * 3e4);
	// equal pairs (isotropic compression): no deviatoric stress, von Mises 0; the others do not vanish
	const Mat3 H = pairs(r, 1e4, 1e4, 1e4);
	EXPECT_NEAR(criterionStress(Criterion::VonMises, H, 1e4, r), 0.0, 1e-9 * k * 1e4);
	EXPECT_NEAR(criterionStress(Criterion::MajorPrincipal, H, 1e4, r), k * 1e4, 1e-12 * k * 1e4);
	// all in tension: nothing compressive, major principal 0
	EXPECT_EQ(criterionStress(Criterion::MajorPrincipal, -H, 0.0, r), 0.0);
}

TEST(CrushCriterion, Names)
{
	// the paper's criterion first; every name reads back to its criterion
	ASSERT_EQ(criteria().size(), 3u);
	EXPECT_EQ(criteria()[0], Criterion::VonMises);
	const char* names[] = {"vonMises", "maxContactForce", "majorPrincipal"};
	for (size_t i = 0; i < criteria().size(); ++i) {
		EXPECT_EQ(std::string(criterionName(criteria()[i])), names[i]);
		EXPECT_EQ(parseCriterion(names[i]), criteria()[i]);
	}
	EXPECT_EQ(ballast_test::messageOf([] { parseCriterion("tresca"); }),
	          "criterion: expected 'vonMises', 'maxContactForce' or 'majorPrincipal', got 'tresca'");
}
