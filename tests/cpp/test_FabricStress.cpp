// Tests of the fabric (Love-Weber) stress, Dubina & Elias eq. 3: sigma_ij = (1/V) sum_c l_i F_j.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "FabricStress.hpp"
#include "ArgumentMessage.hpp"
#include "InputCheck.hpp"
#include "VonMises.hpp"

using namespace ballast;

namespace {

const double kPi  = std::acos(-1.0);
const double kRel = 1e-12;  // relative tolerance: a few roundings of a short sum

using ballast_test::messageOf;

}  // namespace

TEST(FabricStress, SphereVolume)
{
	const double r = 0.0175;
	EXPECT_NEAR(sphereVolume(r), 4.0 / 3.0 * kPi * r * r * r, kRel * 4.0 / 3.0 * kPi * r * r * r);
	EXPECT_THROW(sphereVolume(0.0), ArgumentError);
	EXPECT_THROW(sphereVolume(-1.0), ArgumentError);
}

TEST(FabricStress, VolumeThatUnderOrOverflowsIsRefused)
{
	// 4/3 pi r^3 is a normal double for about 2e-103 < r < 3e102; beyond, it is 0, subnormal or inf.
	for (double r : {1e-102, 1e-50, 1e50, 1e102})
		EXPECT_NEAR(sphereVolume(r), 4.0 / 3.0 * kPi * std::pow(r, 3), kRel * 4.0 / 3.0 * kPi * std::pow(r, 3)) << r;
	for (double r : {1e-200, 1e-105, 1e103, 1e200}) {
		const std::string m = messageOf([r] { sphereVolume(r); });
		EXPECT_EQ(m.rfind("radius:", 0), 0u) << m;
		EXPECT_NE(m.find(formatValue(r)), std::string::npos) << m;
		EXPECT_NE(m.find("under- nor overflows"), std::string::npos) << m;
	}
	const std::string m = messageOf([] { sphereVolume("radii", 3, 1e-200); });
	EXPECT_EQ(m.rfind("radii[3]:", 0), 0u) << m;
	// without the check a grain of radius 1e-200 would get 0/0 = NaN from eq. 3
	const std::string m2 = messageOf([] {
		const double radii[] = {0.01, 1e-200};
		double       out[18];
		fabricStressMany(2, radii, 0, nullptr, nullptr, nullptr, out);
	});
	EXPECT_EQ(m2.rfind("radii[1]:", 0), 0u) << m2;
	EXPECT_EQ(messageOf([] { fabricStress(1e-200, {}, {}); }).rfind("radius:", 0), 0u);
}

TEST(FabricStress, DiametralCompression)
{
	// Grain squeezed by two opposite forces F along x: contact points +-r e_x, forces on the grain -+F e_x.
	// Eq. 3: sigma_xx = (r(-F) + (-r)F)/V = -2Fr/V = -3F/(2 pi r^2), all other components 0.
	const double r = 0.02, F = 1500.0;
	const Mat3   s = fabricStress(r, {Vec3(r, 0, 0), Vec3(-r, 0, 0)}, {Vec3(-F, 0, 0), Vec3(F, 0, 0)});
	const double sxx = -3.0 * F / (2.0 * kPi * r * r);
	EXPECT_NEAR(s(0, 0), sxx, kRel * std::abs(sxx));
	EXPECT_NEAR(s(0, 0), -2.0 * F * r / (4.0 / 3.0 * kPi * r * r * r), kRel * std::abs(sxx));
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			if (i || j) {
				EXPECT_NEAR(s(i, j), 0.0, kRel * std::abs(sxx));
			}
	// uniaxial: eq. 2 gives |sigma_xx| = 3F/(2 pi r^2)
	EXPECT_NEAR(vonMises(s), 3.0 * F / (2.0 * kPi * r * r), kRel * std::abs(sxx));
}

TEST(FabricStress, TangentialCouple)
{
	// Tangential forces +-T e_y at +-r e_x: only sigma_xy = 2 r T / V is non-zero (the tensor is not symmetric).
	const double r = 0.03, T = 200.0;
	const Mat3   s   = fabricStress(r, {Vec3(r, 0, 0), Vec3(-r, 0, 0)}, {Vec3(0, T, 0), Vec3(0, -T, 0)});
	const double sxy = 2.0 * r * T / (4.0 / 3.0 * kPi * r * r * r);
	EXPECT_NEAR(s(0, 1), sxy, kRel * sxy);
	EXPECT_NEAR(s(1, 0), 0.0, kRel * sxy);
	EXPECT_NEAR(s(0, 0), 0.0, kRel * sxy);
}

TEST(FabricStress, TraceOfNormalForces)
{
	// Purely normal compressive forces F = -Fn l/|l| give l.F = -|l| Fn, so trace = -(1/V) sum |l| Fn.
	std::mt19937                           gen(7);
	std::uniform_real_distribution<double> u(-1.0, 1.0), f(10.0, 1000.0);
	const double                           r = 0.015;
	std::vector<Vec3>                      l, F;
	double                                 sum = 0;
	for (int c = 0; c < 9; ++c) {
		Vec3 n(u(gen), u(gen), u(gen));
		n.normalize();
		const double len = r * (0.97 + 0.03 * std::abs(u(gen)));  // branch slightly shorter than r (overlap)
		const double fn  = f(gen);
		l.push_back(len * n);
		F.push_back(-fn * n);
		sum += len * fn;
	}
	const double V  = 4.0 / 3.0 * kPi * r * r * r;
	const double tr = -sum / V;
	EXPECT_NEAR(fabricStress(r, l, F).trace(), tr, kRel * std::abs(tr));
}

TEST(FabricStress, EmptyContactListGivesZero)
{
	const Mat3 s = fabricStress(0.01, {}, {});
	EXPECT_EQ(s.norm(), 0.0);
}

TEST(FabricStress, ManyEqualsPerGrain)
{
	// Flat-array eq. 3 for several grains, contacts interleaved between grains, equals per-grain eq. 3.
	std::mt19937                           gen(2024);
	std::uniform_real_distribution<double> u(-1.0, 1.0);
	const int                              nG = 4, nC = 15;
	const double                           radii[nG] = {0.011, 0.02, 0.0155, 0.022};
	std::vector<long>                      grainOf(nC);
	std::vector<double>                    br(3 * nC), fo(3 * nC);
	std::vector<std::vector<Vec3>>         L(nG), Fv(nG);
	for (int c = 0; c < nC; ++c) {
		grainOf[c] = (c * 2) % (nG - 1);  // grain 3 gets no contact: it must come out zero
		const Vec3 l = radii[grainOf[c]] * Vec3(u(gen), u(gen), u(gen)).normalized();
		const Vec3 f = 500.0 * Vec3(u(gen), u(gen), u(gen));
		for (int i = 0; i < 3; ++i) {
			br[3 * c + i] = l[i];
			fo[3 * c + i] = f[i];
		}
		L[grainOf[c]].push_back(l);
		Fv[grainOf[c]].push_back(f);
	}
	std::vector<double> out(9 * nG, -7.0);  // garbage must be overwritten
	fabricStressMany(nG, radii, nC, grainOf.data(), br.data(), fo.data(), out.data());
	for (int g = 0; g < nG; ++g) {
		const Mat3 ref   = fabricStress(radii[g], L[g], Fv[g]);
		// hand check of the (0,0) entry straight from eq. 3
		double     s00 = 0;
		for (size_t c = 0; c < L[g].size(); ++c)
			s00 += L[g][c][0] * Fv[g][c][0];
		s00 /= 4.0 / 3.0 * kPi * std::pow(radii[g], 3);
		const double scale = std::max(ref.norm(), 1.0);
		EXPECT_NEAR(out[9 * g], s00, kRel * scale);
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				EXPECT_NEAR(out[9 * g + 3 * i + j], ref(i, j), kRel * scale) << "grain " << g << " (" << i << "," << j << ")";
	}
	for (int k = 0; k < 9; ++k)
		EXPECT_EQ(out[9 * 3 + k], 0.0);
}

TEST(FabricStress, ManyRowMajor)
{
	// One contact with l = r e_x and F = F e_y: only sigma_xy, at flat index 3*0+1 (row-major), not 3.
	const double r = 0.02, F = 100.0;
	const long   g[]  = {0};
	const double br[] = {r, 0, 0}, fo[] = {0, F, 0};
	double       out[9];
	fabricStressMany(1, &r, 1, g, br, fo, out);
	const double sxy = r * F / (4.0 / 3.0 * kPi * r * r * r);
	EXPECT_NEAR(out[1], sxy, kRel * sxy);
	EXPECT_NEAR(out[3], 0.0, kRel * sxy);
}

TEST(FabricStress, BadArgumentsNameTheArgument)
{
	const std::string m1 = messageOf([] { fabricStress(0.01, {Vec3(0.01, 0, 0)}, {}); });
	EXPECT_NE(m1.find("forces"), std::string::npos) << m1;

	const std::string m2 = messageOf([] { fabricStress(-0.01, {}, {}); });
	EXPECT_NE(m2.find("radius"), std::string::npos) << m2;
	EXPECT_NE(m2.find("-0.01"), std::string::npos) << m2;

	const std::string m3 = messageOf([] {
		const double radii[] = {0.01, 0.02};
		const long   g[]     = {0, 2};
		const double v[6]    = {};
		double       out[18];
		fabricStressMany(2, radii, 2, g, v, v, out);
	});
	EXPECT_NE(m3.find("grainIndex[1]"), std::string::npos) << m3;

	const std::string m4 = messageOf([] {
		const double radii[] = {0.01};
		const long   g[]     = {-1};
		const double v[3]    = {};
		double       out[9];
		fabricStressMany(1, radii, 1, g, v, v, out);
	});
	EXPECT_NE(m4.find("grainIndex[0]"), std::string::npos) << m4;

	const std::string m5 = messageOf([] {
		const double radii[] = {0.01, 0.0};
		double       out[18];
		fabricStressMany(2, radii, 0, nullptr, nullptr, nullptr, out);
	});
	EXPECT_NE(m5.find("radii[1]"), std::string::npos) << m5;

	const std::string m6 = messageOf([] {
		const double radii[] = {std::nan("")};
		double       out[9];
		fabricStressMany(1, radii, 0, nullptr, nullptr, nullptr, out);
	});
	EXPECT_NE(m6.find("radii[0]"), std::string::npos) << m6;

	const std::string m7 = messageOf([] { fabricStressMany(-1, nullptr, 0, nullptr, nullptr, nullptr, nullptr); });
	EXPECT_NE(m7.find("nGrains"), std::string::npos) << m7;
}
