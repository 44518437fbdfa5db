// Tests of density scaling: a body's own P-wave step r sqrt(rho/E) (eq. 5) and YADE's densityScaling
// factor (ownStep / targetStep)^2, never above 1.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "DensityScaling.hpp"
#include "InputCheck.hpp"

using namespace ballast;

TEST(DensityScaling, OwnStepOfTheSmallestPaperGrain)
{
	// d = 20.5 mm of granite, E = 3e11 Pa, rho = 2600 kg/m^3: 0.01025 sqrt(2600 / 3e11) = 9.542e-7 s
	const double step = 0.01025 * std::sqrt(2600.0 / 3e11);
	EXPECT_NEAR(pWaveStep(0.01025, 2600.0, 3e11), step, 1e-15 * step);
	EXPECT_NEAR(step, 9.5423e-7, 1e-10);
}

TEST(DensityScaling, ScaledBodyReachesTheTarget)
{
	// a body whose own step is 4e-7 s, target 2e-6 s: factor (0.2)^2 = 0.04, i.e. its density x 25, and
	// its scaled own step r sqrt(25 rho / E) = 5 x 4e-7 = the target
	const double s = densityScaling(4e-7, 2e-6);
	EXPECT_NEAR(s, 0.04, 1e-16);
	EXPECT_NEAR(4e-7 / std::sqrt(s), 2e-6, 1e-20);
}

TEST(DensityScaling, NeverLighterAndOffAtZero)
{
	EXPECT_EQ(densityScaling(3e-6, 2e-6), 1.0);  // already slower than the target: not scaled
	EXPECT_EQ(densityScaling(2e-6, 2e-6), 1.0);
	EXPECT_EQ(densityScaling(1e-7, 0.0), 1.0);   // 0 = no density scaling
}

TEST(DensityScaling, BadInputNamed)
{
	auto message = [](double own, double target) {
		try {
			densityScaling(own, target);
		} catch (const ArgumentError& e) {
			return std::string(e.what());
		}
		return std::string();
	};
	EXPECT_NE(message(0.0, 1e-6).find("ownStep"), std::string::npos);
	EXPECT_NE(message(1e-6, -1.0).find("targetStep"), std::string::npos);
	EXPECT_NE(message(1e-6, NAN).find("targetStep"), std::string::npos);
	EXPECT_THROW(pWaveStep(0.01, 2600.0, 0.0), ArgumentError);
	EXPECT_NE(message(1e-200, 1e200).find("underflows"), std::string::npos);  // a body that could never move
}
