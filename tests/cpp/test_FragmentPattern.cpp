// Tests of the fragment layouts replacing a crushed grain, Dubina & Elias section 2 and Fig. 1:
// fragments inside the parent, no overlap, largest radii the layout allows, and the kept volume.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "FragmentPattern.hpp"
#include "ArgumentMessage.hpp"
#include "InputCheck.hpp"

using namespace ballast;

namespace {

const double kGeom  = 1e-12;  // containment / overlap slack (unit parent)
const double kTight = 1e-9;   // a contact counts as touching within this gap
const double kRel   = 1e-12;  // relative tolerance of closed forms

const Layout kAll[] = {Layout::Tetra4, Layout::Planar4, Layout::Octa6, Layout::Fill14};

size_t expectedCount(Layout l)
{
	switch (l) {
		case Layout::Tetra4: return 4;
		case Layout::Planar4: return 4;
		case Layout::Octa6: return 6;
		case Layout::Fill14: return 14;
	}
	return 0;
}

// Fill14 independently of the implementation: octahedral spheres rho = 1/(1+sqrt2) at d = 1 - rho, corner
// spheres s on the cube diagonal touching the shell (centre at 1 - s) and the octahedral sphere on +x:
//   |(1-s) (1,1,1)/sqrt3 - d e_x| = rho + s, solved for s by bisection.
double fill14CornerRadius()
{
	const double rho = 1.0 / (1.0 + std::sqrt(2.0)), d = 1.0 - rho;
	const Vec3   u   = Vec3(1, 1, 1).normalized();
	auto         gap = [&](double s) { return ((1.0 - s) * u - d * Vec3::UnitX()).norm() - (rho + s); };
	double       lo = 0.0, hi = 0.5;  // gap(0) > 0 (room left), gap(0.5) < 0 (overlap)
	for (int i = 0; i < 200; ++i) {
		const double mid = 0.5 * (lo + hi);
		(gap(mid) > 0 ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}

double closedFormFraction(Layout l)
{
	const double k = std::sqrt(2.0 / 3.0), q = 1.0 / (1.0 + std::sqrt(2.0));
	switch (l) {
		case Layout::Tetra4: return 4.0 * std::pow(k / (1.0 + k), 3);  // edge 2 rho = (1 - rho) sqrt(8/3)
		case Layout::Planar4: return 4.0 * q * q * q;                   // edge 2 rho = (1 - rho) sqrt(2)
		case Layout::Octa6: return 6.0 * q * q * q;
		case Layout::Fill14: {
			const double s = fill14CornerRadius();
			return 6.0 * q * q * q + 8.0 * s * s * s;
		}
	}
	return 0;
}

using ballast_test::messageOf;

}  // namespace

TEST(FragmentPattern, Counts)
{
	for (Layout l : kAll)
		EXPECT_EQ(fragmentPattern(l).size(), expectedCount(l)) << layoutName(l);
}

TEST(FragmentPattern, InsideParentAndNoOverlap)
{
	// No protrusion from the parent (|c| + r <= 1) and no overlap (|ci - cj| >= ri + rj), section 2.
	for (Layout l : kAll) {
		const auto f = fragmentPattern(l);
		for (size_t i = 0; i < f.size(); ++i) {
			EXPECT_GT(f[i][3], 0.0);
			EXPECT_LE(f[i].head<3>().norm() + f[i][3], 1.0 + kGeom) << layoutName(l) << " fragment " << i;
			for (size_t j = i + 1; j < f.size(); ++j)
				EXPECT_GE((f[i].head<3>() - f[j].head<3>()).norm(), f[i][3] + f[j][3] - kGeom)
				        << layoutName(l) << " fragments " << i << ", " << j;
		}
	}
}

TEST(FragmentPattern, RadiiAreMaximal)
{
	// Every fragment is blocked by at least one tight constraint (touches the shell or a neighbour), so no
	// radius can grow; and the layout has both kinds of contact (otherwise a uniform scaling would fit).
	for (Layout l : kAll) {
		const auto f         = fragmentPattern(l);
		int        shellHits = 0, pairHits = 0;
		for (size_t i = 0; i < f.size(); ++i) {
			bool tight = std::abs(f[i].head<3>().norm() + f[i][3] - 1.0) < kTight;
			shellHits += tight;
			for (size_t j = 0; j < f.size(); ++j) {
				if (i == j) continue;
				const bool touch = std::abs((f[i].head<3>() - f[j].head<3>()).norm() - f[i][3] - f[j][3]) < kTight;
				tight            = tight || touch;
				pairHits += touch && j > i;
			}
			EXPECT_TRUE(tight) << layoutName(l) << " fragment " << i << " could grow";
		}
		EXPECT_EQ(shellHits, static_cast<int>(f.size())) << layoutName(l);  // all fragments touch the shell
		EXPECT_GT(pairHits, 0) << layoutName(l);
	}
	// Octahedral neighbours touch: 12 edges; fill14 adds 8 corners x 3 octahedral neighbours = 24 contacts.
	auto countPairs = [](Layout l) {
		const auto f = fragmentPattern(l);
		int        n = 0;
		for (size_t i = 0; i < f.size(); ++i)
			for (size_t j = i + 1; j < f.size(); ++j)
				n += std::abs((f[i].head<3>() - f[j].head<3>()).norm() - f[i][3] - f[j][3]) < kTight;
		return n;
	};
	EXPECT_EQ(countPairs(Layout::Tetra4), 6);
	EXPECT_EQ(countPairs(Layout::Planar4), 4);
	EXPECT_EQ(countPairs(Layout::Octa6), 12);
	EXPECT_EQ(countPairs(Layout::Fill14), 12 + 24);
}

TEST(FragmentPattern, KeptVolumeClosedForms)
{
	// Kept fraction = sum r^3 (unit parent) = closed form of each layout.
	for (Layout l : kAll) {
		double sum = 0;
		for (const Sphere4& s : fragmentPattern(l))
			sum += s[3] * s[3] * s[3];
		const double ref = closedFormFraction(l);
		EXPECT_NEAR(keptVolumeFraction(l), sum, kRel * sum) << layoutName(l);
		EXPECT_NEAR(keptVolumeFraction(l), ref, kRel * ref) << layoutName(l);
	}
	// the numbers quoted in the header and the paper's Fig. 1 (4 digits)
	EXPECT_NEAR(keptVolumeFraction(Layout::Tetra4), 0.3633, 5e-5);
	EXPECT_NEAR(keptVolumeFraction(Layout::Planar4), 0.2843, 5e-5);
	EXPECT_NEAR(keptVolumeFraction(Layout::Octa6), 0.4264, 5e-5);
	EXPECT_NEAR(keptVolumeFraction(Layout::Fill14), 0.5239, 5e-5);
	EXPECT_GT(keptVolumeFraction(Layout::Fill14), 0.52);
}

TEST(FragmentPattern, Fill14FromFragments)
{
	// Fill14 has 6 equal octahedral spheres rho and 8 equal corner spheres s: fraction = 6 rho^3 + 8 s^3.
	const auto   f   = fragmentPattern(Layout::Fill14);
	const double rho = 1.0 / (1.0 + std::sqrt(2.0)), s = fill14CornerRadius();
	int          nRho = 0, nS = 0;
	for (const Sphere4& x : f) {
		nRho += std::abs(x[3] - rho) < kRel;
		nS += std::abs(x[3] - s) < 1e-12;
	}
	EXPECT_EQ(nRho, 6);
	EXPECT_EQ(nS, 8);
	EXPECT_NEAR(keptVolumeFraction(Layout::Fill14), 6 * rho * rho * rho + 8 * s * s * s, kRel);
}

TEST(FragmentPattern, CentreOfMassAtOrigin)
{
	// Mass-weighted centre sum r^3 c / sum r^3 = 0: crushing does not move the grain's centre of mass.
	for (Layout l : kAll) {
		Vec3   m = Vec3::Zero();
		double v = 0;
		for (const Sphere4& s : fragmentPattern(l)) {
			m += s[3] * s[3] * s[3] * s.head<3>();
			v += s[3] * s[3] * s[3];
		}
		EXPECT_NEAR((m / v).norm(), 0.0, kGeom) << layoutName(l);
	}
}

TEST(FragmentPattern, LayoutNames)
{
	EXPECT_EQ(layoutFromCount(4), Layout::Tetra4);
	EXPECT_EQ(layoutFromCount(6), Layout::Octa6);
	EXPECT_EQ(layoutFromCount(14), Layout::Fill14);
	for (Layout l : kAll)
		EXPECT_EQ(layoutFromName(layoutName(l)), l);
	EXPECT_EQ(layoutFromName("4"), Layout::Tetra4);
	EXPECT_EQ(layoutFromName("6"), Layout::Octa6);
	EXPECT_EQ(layoutFromName("14"), Layout::Fill14);
	EXPECT_EQ(layoutName(Layout::Planar4), "planar4");
	for (long n : {0L, 1L, 5L, 8L, -4L, 15L}) {
		EXPECT_THROW(layoutFromCount(n), ArgumentError) << n;
		try {
			layoutFromCount(n);
		} catch (const ArgumentError& e) {
			EXPECT_EQ(std::string(e.what()).rfind("pattern", 0), 0u) << e.what();
		}
	}
	for (const char* s : {"", "Tetra4", "octa", "5", "fill 14"}) {
		EXPECT_THROW(layoutFromName(s), ArgumentError) << s;
		try {
			layoutFromName(s);
		} catch (const ArgumentError& e) {
			EXPECT_EQ(std::string(e.what()).rfind("pattern", 0), 0u) << e.what();
		}
	}
}

TEST(FragmentPattern, RandomRotationIsRotation)
{
	for (std::uint64_t c = 0; c < 200; ++c) {
		const Mat3 R = randomRotation(42, c);
		EXPECT_NEAR((R.transpose() * R - Mat3::Identity()).norm(), 0.0, 1e-12) << c;
		EXPECT_NEAR(R.determinant(), 1.0, 1e-12) << c;
	}
}

TEST(FragmentPattern, RandomRotationReproducible)
{
	// Same (seed, counter) -> identical matrix; another counter or seed -> another one.
	EXPECT_EQ(randomRotation(7, 3), randomRotation(7, 3));
	EXPECT_GT((randomRotation(7, 3) - randomRotation(7, 4)).norm(), 1e-3);
	EXPECT_GT((randomRotation(7, 3) - randomRotation(8, 3)).norm(), 1e-3);
	EXPECT_GT((randomRotation(0, 0) - randomRotation(0, 1)).norm(), 1e-3);
}

TEST(FragmentPattern, RandomRotationUniform)
{
	// For uniform rotations R e_z is uniform on the sphere: E[R e_z] = 0 and E[z^2] = 1/3.
	// N = 20000: standard errors 1/sqrt(3N) = 0.004 and sqrt(4/45/N) = 0.002; bounds are 5 sigma.
	const int N = 20000;
	Vec3      mean = Vec3::Zero();
	double    z2   = 0;
	for (int i = 0; i < N; ++i) {
		const Vec3 v = randomRotation(2024, i) * Vec3::UnitZ();
		mean += v;
		z2 += v.z() * v.z();
	}
	mean /= N;
	z2 /= N;
	EXPECT_LT(mean.norm(), 0.02);
	EXPECT_NEAR(z2, 1.0 / 3.0, 0.01);
}

TEST(FragmentPattern, PlaceFragments)
{
	// Scaled by r, rotated, shifted by the centre: c = centre + r R c_unit, radius r r_unit.
	const Vec3   centre(1.5, -2.0, 0.3);
	const double r   = 0.02;
	const Mat3   rot = randomRotation(11, 5);
	for (Layout l : kAll) {
		const auto unit = fragmentPattern(l);
		const auto f    = placeFragments(l, centre, r, rot);
		ASSERT_EQ(f.size(), unit.size());
		double vol = 0;
		for (size_t i = 0; i < f.size(); ++i) {
			const Vec3 c = centre + r * (rot * unit[i].head<3>());
			EXPECT_NEAR((f[i].head<3>() - c).norm(), 0.0, kGeom * r) << layoutName(l) << " " << i;
			EXPECT_NEAR(f[i][3], r * unit[i][3], kRel * r);
			// inside the parent of radius r at centre
			EXPECT_LE((f[i].head<3>() - centre).norm() + f[i][3], r * (1.0 + kGeom)) << layoutName(l) << " " << i;
			for (size_t j = i + 1; j < f.size(); ++j)
				EXPECT_GE((f[i].head<3>() - f[j].head<3>()).norm(), f[i][3] + f[j][3] - kGeom * r)
				        << layoutName(l) << " " << i << ", " << j;
			vol += std::pow(f[i][3], 3);
		}
		// volume kept scales with r^3
		EXPECT_NEAR(vol / (r * r * r), closedFormFraction(l), kRel * 10);
	}
}

TEST(FragmentPattern, PlaceFragmentsBadArguments)
{
	const std::string m1 = messageOf([] { placeFragments(Layout::Octa6, Vec3::Zero(), 0.0, Mat3::Identity()); });
	EXPECT_NE(m1.find("radius"), std::string::npos) << m1;
	const std::string m2 =
	        messageOf([] { placeFragments(Layout::Octa6, Vec3(0, std::nan(""), 0), 0.01, Mat3::Identity()); });
	EXPECT_NE(m2.find("centre[1]"), std::string::npos) << m2;
}
