// Tests of the clump split (ClumpSplit.hpp) against pieces and planes worked out by hand: four members at
// (+-a, +-b, 0) about the centre X = 0 (a = 0.01 m, b = 0.02 m, radii 0.011 m, so only the pairs 2a apart overlap).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "ArgumentMessage.hpp"
#include "ClumpSplit.hpp"

using namespace ballast;

namespace {
const double a = 0.01, b = 0.02, r = 0.011;
const std::vector<double> kPos = {a, b, 0, a, -b, 0, -a, b, 0, -a, -b, 0};
const std::vector<double> kRad = {r, r, r, r};
const double kX[3] = {0, 0, 0};
const double kPi = std::acos(-1.0);

// sigma = sum_k l_k e_k e_k^T for the axes x, y, z turned by angle about z
std::vector<double> turned(double l1, double l2, double l3, double angle)
{
	const double c = std::cos(angle), s = std::sin(angle);
	const double e[3][3] = {{c, s, 0}, {-s, c, 0}, {0, 0, 1}};
	const double l[3] = {l1, l2, l3};
	std::vector<double> S(9, 0.0);
	for (int k = 0; k < 3; ++k)
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				S[3 * i + j] += l[k] * e[k][i] * e[k][j];
	return S;
}

void expectNormal(const ClumpSplit& c, int k, double x, double y, double z)
{
	EXPECT_NEAR(c.normals[3 * k], x, 1e-12);
	EXPECT_NEAR(c.normals[3 * k + 1], y, 1e-12);
	EXPECT_NEAR(c.normals[3 * k + 2], z, 1e-12);
}
}  // namespace

TEST(ClumpSplit, UniaxialTensionAlongXSplitsByThePlaneXEqualsX)
{
	// l = (T, 0, 0): s2 = -T/3 < 0, one plane normal to x; members with x > 0 first (piece 0), x < 0 second
	const auto S = turned(1e6, 0, 0, 0);
	const ClumpSplit c = clumpSplit(S.data(), kX, 4, kPos.data(), kRad.data());
	EXPECT_EQ(c.nPieces, 2);
	EXPECT_EQ(c.piece, (std::vector<long>{0, 0, 1, 1}));
	ASSERT_EQ(c.normals.size(), 3u);
	expectNormal(c, 0, 1, 0, 0);
	EXPECT_FALSE(c.median);
	// members 0-2 and 1-3 are 2a = 0.02 < 2r apart across the plane; the diagonals 2 sqrt(a^2 + b^2) are not
	EXPECT_EQ(c.pairs, (std::vector<long>{0, 2, 1, 3}));
}

TEST(ClumpSplit, TheAssignmentFollowsPrincipalDirectionsTurned30Degrees)
{
	// tension along n1 = (cos 30, sin 30, 0): d1 = x cos30 + y sin30 = +1.866a, -0.134a, +0.134a, -1.866a
	const double t = kPi / 6;
	const auto S = turned(1e6, 0, 0, t);
	const ClumpSplit c = clumpSplit(S.data(), kX, 4, kPos.data(), kRad.data());
	EXPECT_EQ(c.nPieces, 2);
	EXPECT_EQ(c.piece, (std::vector<long>{0, 1, 0, 1}));   // unturned it was {0, 0, 1, 1}
	expectNormal(c, 0, std::cos(t), std::sin(t), 0);
	EXPECT_TRUE(c.pairs.empty());   // pieces across y: members 2b = 0.04 or the diagonal apart, none overlap
	// l = (3, 1, -5) MPa on the turned axes: s2 = 1 + 5/3 - 1 > 0, two planes normal to e1 and e2 = (-sin, cos, 0);
	// (d1, d2) of the members: (+,+), (-,-), (+,+), (-,-), so two of the four quarters are empty and dropped
	const auto S3 = turned(3e6, 1e6, -5e6, t);
	const ClumpSplit c3 = clumpSplit(S3.data(), kX, 4, kPos.data(), kRad.data());
	EXPECT_EQ(c3.nPieces, 2);
	EXPECT_EQ(c3.piece, (std::vector<long>{0, 1, 0, 1}));
	ASSERT_EQ(c3.normals.size(), 6u);
	expectNormal(c3, 0, std::cos(t), std::sin(t), 0);
	expectNormal(c3, 1, -std::sin(t), std::cos(t), 0);
}

TEST(ClumpSplit, UniaxialCompressionGivesFourWedgesAcrossTheLongestSpreadFirst)
{
	// l = (0, 0, -P): s1 = s2 = P/3 > 0, two planes containing z; x and y share one principal value, so the first
	// plane is across the members' longest spread, y (b > a), the second across x
	const auto S = turned(0, 0, -1e6, 0);
	const ClumpSplit c = clumpSplit(S.data(), kX, 4, kPos.data(), kRad.data());
	EXPECT_EQ(c.nPieces, 4);
	EXPECT_EQ(c.piece, (std::vector<long>{0, 1, 2, 3}));
	expectNormal(c, 0, 0, 1, 0);
	expectNormal(c, 1, 1, 0, 0);
	EXPECT_EQ(c.pairs, (std::vector<long>{0, 2, 1, 3}));
}

TEST(ClumpSplit, AllMembersOnOneSideAreHalvedAtTheMedian)
{
	// centre off the members: both at x = a > 0 under tension along x; they differ along y only (n2 from spread)
	const std::vector<double> pos = {a, b, 0, a, -b, 0};
	const auto S = turned(1e6, 0, 0, 0);
	const ClumpSplit c = clumpSplit(S.data(), kX, 2, pos.data(), kRad.data());
	EXPECT_TRUE(c.median);
	EXPECT_EQ(c.nPieces, 2);
	EXPECT_EQ(c.piece, (std::vector<long>{0, 1}));
	// three members at one point: halves by index, the first ceil(3/2) = 2 in piece 0
	const std::vector<double> same(9, 0.0);
	const ClumpSplit d = clumpSplit(S.data(), kX, 3, same.data(), kRad.data());
	EXPECT_TRUE(d.median);
	EXPECT_EQ(d.piece, (std::vector<long>{0, 0, 1}));
	EXPECT_EQ(d.pairs, (std::vector<long>{0, 2, 1, 2}));
	// one member: one piece, nothing to split
	const ClumpSplit e = clumpSplit(S.data(), kX, 1, pos.data(), kRad.data());
	EXPECT_EQ(e.nPieces, 1);
	EXPECT_EQ(e.piece, (std::vector<long>{0}));
	EXPECT_FALSE(e.median);
}

TEST(ClumpSplit, EveryMemberInExactlyOnePieceOnItsSideOfEveryPlane)
{
	std::mt19937_64 rng(47);
	std::normal_distribution<double> g(0.0, 1.0);
	for (int trial = 0; trial < 500; ++trial) {
		const int n = 2 + trial % 30;
		std::vector<double> S(9), pos(3 * n), rad(n), X = {g(rng), g(rng), g(rng)};
		for (double& s : S) s = 1e6 * g(rng);
		for (int m = 0; m < n; ++m) {
			rad[m] = 0.5 + std::fabs(g(rng));
			for (int i = 0; i < 3; ++i) pos[3 * m + i] = X[i] + g(rng);
		}
		const ClumpSplit c = clumpSplit(S.data(), X.data(), n, pos.data(), rad.data());
		ASSERT_GE(c.nPieces, 2);
		ASSERT_LE(c.nPieces, 4);
		std::set<long> seen(c.piece.begin(), c.piece.end());
		ASSERT_EQ((int)seen.size(), c.nPieces);   // every piece 0 ... nPieces-1 holds a member
		ASSERT_EQ(*seen.rbegin(), c.nPieces - 1);
		if (c.median) continue;
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j)
				for (size_t k = 0; k < c.normals.size() / 3; ++k) {
					double di = 0, dj = 0;
					for (int q = 0; q < 3; ++q) {
						di += (pos[3 * i + q] - X[q]) * c.normals[3 * k + q];
						dj += (pos[3 * j + q] - X[q]) * c.normals[3 * k + q];
					}
					if (c.piece[i] == c.piece[j]) {
						ASSERT_EQ(di > 0, dj > 0) << trial;
					}
				}
	}
}

TEST(ClumpSplit, BadArgumentsAreNamed)
{
	const auto S = turned(1e6, 0, 0, 0);
	std::vector<double> bad = S, pos = kPos, rad = kRad;
	bad[4] = std::nan("");
	EXPECT_EQ(ballast_test::messageOf([&] { clumpSplit(S.data(), kX, 0, pos.data(), rad.data()); }).rfind("nMembers: expected >= 1", 0), 0u);
	EXPECT_EQ(ballast_test::messageOf([&] { clumpSplit(bad.data(), kX, 4, pos.data(), rad.data()); }), "stress[4]: expected a finite number, got nan");
	rad[2] = 0.0;
	EXPECT_EQ(ballast_test::messageOf([&] { clumpSplit(S.data(), kX, 4, pos.data(), rad.data()); }), "memberRadii[2]: expected a finite number > 0, got 0");
	pos[7] = INFINITY;
	EXPECT_EQ(ballast_test::messageOf([&] { clumpSplit(S.data(), kX, 4, pos.data(), kRad.data()); }), "memberPositions[2]: expected a finite number, got inf");
}
