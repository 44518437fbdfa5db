// Tests of the clump stress reduction (ClumpStress.hpp) against the direct Love-Weber sum over contacts,
// sigma_clump = (1/V) sum_c f^c (x) (x^c - X), worked out here from the contacts themselves.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "ArgumentMessage.hpp"
#include "ClumpStress.hpp"

using namespace ballast;

namespace {
using V3 = std::array<double, 3>;
struct Contact {
	int m;  // member
	V3  x;  // contact point [m]
	V3  f;  // force on the member [N]
};
}  // namespace

TEST(ClumpStress, ReductionEqualsTheDirectSumOverContacts)
{
	// two members of one clump, a third member alone in a second clump
	const std::vector<V3>     pos = {{{0.0, 0.0, 0.0}}, {{0.02, 0.0, 0.0}}, {{1.0, 1.0, 1.0}}};
	const std::vector<double> Vm  = {4.0e-6, 3.0e-6, 1.0e-6};
	const std::vector<long>   of  = {0, 0, 1};
	const std::vector<V3>     X   = {{{0.009, 0.001, -0.002}}, {{1.0, 1.0, 1.0}}};
	const std::vector<double> V   = {6.5e-6, 1.0e-6};
	const std::vector<Contact> cs = {{0, {{-0.01, 0.0, 0.0}}, {{100.0, 5.0, -3.0}}},
	                                  {0, {{0.0, 0.0, 0.01}}, {{2.0, 0.0, -50.0}}},
	                                  {1, {{0.03, 0.0, 0.0}}, {{-80.0, 1.0, 0.0}}},
	                                  {1, {{0.02, -0.01, 0.0}}, {{0.0, 40.0, 7.0}}},
	                                  {2, {{1.0, 1.0, 1.01}}, {{0.0, 0.0, -9.0}}}};
	std::vector<double> s(9 * 3, 0.0), F(9, 0.0), x(9), direct(18, 0.0);
	for (const Contact& c : cs)
		for (int i = 0; i < 3; ++i) {
			F[3 * c.m + i] += c.f[i];
			for (int j = 0; j < 3; ++j) {
				s[9 * c.m + 3 * i + j] += c.f[i] * (c.x[j] - pos[c.m][j]) / Vm[c.m];   // YADE's f_i l_j / V_m
				direct[9 * of[c.m] + 3 * i + j] += c.f[i] * (c.x[j] - X[of[c.m]][j]) / V[of[c.m]];
			}
		}
	for (int m = 0; m < 3; ++m)
		for (int i = 0; i < 3; ++i)
			x[3 * m + i] = pos[m][i];
	std::vector<double> Xf = {X[0][0], X[0][1], X[0][2], X[1][0], X[1][1], X[1][2]};
	std::vector<double> out(18);
	clumpStress(3, s.data(), Vm.data(), F.data(), x.data(), of.data(), 2, Xf.data(), V.data(), out.data());
	double scale = 0;
	for (double d : direct)
		scale = std::max(scale, std::fabs(d));
	for (int i = 0; i < 18; ++i)
		EXPECT_NEAR(out[i], direct[i], 1e-12 * scale) << i;
	// one hand value: clump 1 (one member at X) is the member's own stress: sigma_zz = -9 * 0.01 / 1e-6
	EXPECT_NEAR(out[9 + 8], -9.0 * 0.01 / 1e-6, 1e-9);
}

TEST(ClumpStress, BadArgumentsAreNamed)
{
	const double s[9] = {0}, v = 1.0, f[3] = {0}, x[3] = {0}, X[3] = {0};
	double       out[9];
	const long   bad = 1, good = 0;
	const double zero = 0.0;
	EXPECT_EQ(ballast_test::messageOf([&] { clumpStress(1, s, &v, f, x, &bad, 1, X, &v, out); }).rfind("clumpIndex[0]:", 0), 0u);
	EXPECT_EQ(ballast_test::messageOf([&] { clumpStress(1, s, &zero, f, x, &good, 1, X, &v, out); }).rfind("memberVolumes[0]", 0), 0u);
	EXPECT_EQ(ballast_test::messageOf([&] { clumpStress(1, s, &v, f, x, &good, 1, X, &zero, out); }).rfind("clumpVolumes[0]", 0), 0u);
}
