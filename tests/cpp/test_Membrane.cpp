// Tests of the membrane's stress boundary (Membrane.hpp): rays worked out by hand, the pressure's resultant equal to
// p times the membrane's area, a closed ring's resultant zero, the enclosed volume between hand bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "InputCheck.hpp"
#include "Membrane.hpp"

using namespace ballast;

namespace {
const double kNoBridge = 1.0;  // [m] a depth beyond any grain: every cell rests where its own ray hits

double radialSum(const MembraneLoad& m, const std::vector<double>& c)
{   // the inward radial components of the grains' forces, summed [N]
	double s = 0;
	for (size_t i = 0; i < c.size() / 3; ++i) {
		const double rc = std::hypot(c[3 * i], c[3 * i + 1]);
		s -= (m.force[3 * i] * c[3 * i] + m.force[3 * i + 1] * c[3 * i + 1]) / rc;
	}
	return s;
}
}  // namespace

TEST(Membrane, RaysByHand)
{
	// a sphere r = 0.02 on the centre ray of cell (theta 0.5 dtheta, z 0.305): the hit is at 0.15 + r; one cell up
	// (h = 0.01) at 0.15 + sqrt(r^2 - h^2); one cell around (b = 0.15 sin dtheta) at 0.15 cos dtheta + sqrt(r^2 - b^2)
	const long   nT = 360, nZ = 60;
	const double dth = 2 * M_PI / nT, R = 0.15, r = 0.02, t = 0.5 * dth;
	const auto   g   = MembraneGrid::checked(0, 0, 0, 0.6, nT, nZ, kNoBridge);
	const std::vector<double> c{R * std::cos(t), R * std::sin(t), 0.305}, rad{r};
	const MembraneLoad m = membraneLoad(g, 1, c.data(), rad.data(), 1e5);
	EXPECT_NEAR(m.radius[30 * nT + 0], R + r, 1e-14);
	EXPECT_NEAR(m.radius[31 * nT + 0], R + std::sqrt(r * r - 0.01 * 0.01), 1e-14);
	const double b = R * std::sin(dth);
	EXPECT_NEAR(m.radius[30 * nT + 1], R * std::cos(dth) + std::sqrt(r * r - b * b), 1e-14);
	EXPECT_EQ(m.owner[30 * nT + 0], 0);
	EXPECT_EQ(m.owner[0], -1);  // far below: no grain near
	EXPECT_EQ(m.bridged, 0);
	// the force: p times the area of the cells it carries, each towards the axis from its cell: within the
	// silhouette's half-angle asin(r / R) of the grain's direction, so the radial sum is at least cos of it
	EXPECT_LE(radialSum(m, c), 1e5 * m.area * (1 + 1e-12));
	EXPECT_GE(radialSum(m, c), 1e5 * m.area * std::cos(std::asin(r / R)));
	// the sphere's footprint seen from outside is about its disc, pi r^2 (cells 1/100 of it: within 5 %)
	EXPECT_NEAR(m.area, M_PI * r * r, 0.05 * M_PI * r * r);
}

TEST(Membrane, ClosedRingsOfSpheres)
{
	// rings of 24 spheres (r = 0.02) at 0.15 m from the axis, a ring every 2r from z = r, cells of about r / 2: the
	// membrane lies between R + r / 2 (it spans the gaps) and R + r, the radial force is p times its area, the
	// resultant of a closed ring is zero
	const double R = 0.15, r = 0.02, depth = 0.005, p = 6e4;
	const long   perRing = 24, rings = 10;
	std::vector<double> c, rad;
	for (long k = 0; k < rings; ++k)
		for (long j = 0; j < perRing; ++j) {
			const double t = 2 * M_PI * j / perRing;
			c.insert(c.end(), {R * std::cos(t), R * std::sin(t), r + 2 * r * k});
			rad.push_back(r);
		}
	const double H = 2 * r * rings;
	const auto   g = MembraneGrid::checked(0, 0, 0, H, 108, 80, depth);
	const MembraneLoad m = membraneLoad(g, static_cast<long>(rad.size()), c.data(), rad.data(), p);
	EXPECT_EQ(m.empty, 0);
	EXPECT_GT(m.bridged, 0);  // the gaps between the spheres
	EXPECT_GT(m.area, 2 * M_PI * (R + r / 2) * H);
	EXPECT_LE(m.area, 2 * M_PI * (R + r) * H * (1 + 1e-12));
	EXPECT_GT(m.volume, M_PI * std::pow(R + r / 2, 2) * H);
	EXPECT_LE(m.volume, M_PI * std::pow(R + r, 2) * H * (1 + 1e-12));
	EXPECT_LE(radialSum(m, c), p * m.area * (1 + 1e-12));
	EXPECT_GE(radialSum(m, c), p * m.area * std::cos(std::asin(r / R)));
	double fx = 0, fy = 0, fz = 0;
	for (size_t i = 0; i < rad.size(); ++i) {
		fx += m.force[3 * i];
		fy += m.force[3 * i + 1];
		fz += m.force[3 * i + 2];
	}
	EXPECT_NEAR(fx, 0, 1e-9 * p * m.area);
	EXPECT_NEAR(fy, 0, 1e-9 * p * m.area);
	EXPECT_EQ(fz, 0);  // the membrane carries no axial load
	// an inner grain behind the ring carries nothing
	c.insert(c.end(), {0, 0, H / 2});
	rad.push_back(r);
	const MembraneLoad m2 = membraneLoad(g, static_cast<long>(rad.size()), c.data(), rad.data(), p);
	EXPECT_EQ(m2.force[3 * (rad.size() - 1)], 0);
	EXPECT_EQ(m2.area, m.area);
}

TEST(Membrane, BridgesAGapAtTheDepth)
{
	// two spheres r = 0.02 at theta = +-0.3 rad: the cells between them see no grain within the neighbourhood's reach
	// (empty) except next to them, where the membrane spans at the outermost hit less depth, carried by that sphere
	const long   nT = 100, nZ = 20;
	const double R = 0.15, r = 0.02, depth = 0.004;
	const auto   g = MembraneGrid::checked(0, 0, 0.28, 0.32, nT, nZ, depth);
	const double t = 0.3;
	const std::vector<double> c{R * std::cos(t), R * std::sin(t), 0.3, R * std::cos(t), -R * std::sin(t), 0.3},
	        rad{r, r};
	const MembraneLoad m = membraneLoad(g, 2, c.data(), rad.data(), 1e5);
	EXPECT_GT(m.bridged, 0);
	EXPECT_GT(m.empty, 0);
	// midway (theta = 0, 45 mm from either sphere's centre, more than r and a cell away): nothing to rest on
	for (long kz = 0; kz < nZ; ++kz) {
		EXPECT_EQ(m.owner[kz * nT + 0], -1);
		EXPECT_EQ(m.owner[kz * nT + nT - 1], -1);
	}
	// the crowns' cells rest on their own sphere (theta = 0.3 rad is 4.77 cells: the nearest centre ray is k = 4, and
	// k = 95 for -0.3), and no cell lies outside the spheres
	EXPECT_EQ(m.owner[10 * nT + 4], 0);
	EXPECT_EQ(m.owner[10 * nT + 95], 1);
	for (long kz = 0; kz < nZ; ++kz)
		for (long k = 0; k < nT; ++k)
			if (m.owner[kz * nT + k] >= 0) {
				EXPECT_LE(m.radius[kz * nT + k], R + r + 1e-12);
			}
	EXPECT_LE(radialSum(m, c), 1e5 * m.area * (1 + 1e-12));
	EXPECT_GE(radialSum(m, c), 1e5 * m.area * std::cos(std::asin(r / R)));
}

TEST(Membrane, BadInput)
{
	EXPECT_THROW(MembraneGrid::checked(0, 0, 0.6, 0.6, 10, 10, 0.01), ArgumentError);
	EXPECT_THROW(MembraneGrid::checked(0, 0, 0, 0.6, 2, 10, 0.01), ArgumentError);
	EXPECT_THROW(MembraneGrid::checked(0, 0, 0, 0.6, 10, 0, 0.01), ArgumentError);
	EXPECT_THROW(MembraneGrid::checked(0, 0, 0, 0.6, 10, 10, -1), ArgumentError);
	EXPECT_THROW(MembraneGrid::checked(NAN, 0, 0, 0.6, 10, 10, 0.01), ArgumentError);
	const auto g = MembraneGrid::checked(0, 0, 0, 0.6, 10, 10, 0.01);
	const std::vector<double> c{0.1, 0, 0.3}, bad{0.0}, good{0.02};
	EXPECT_THROW(membraneLoad(g, 1, c.data(), bad.data(), 1e5), ArgumentError);
	EXPECT_THROW(membraneLoad(g, 1, c.data(), good.data(), -1), ArgumentError);
	try {
		MembraneGrid::checked(0, 0, 0.6, 0.5, 10, 10, 0.01);
	} catch (const ArgumentError& e) {
		EXPECT_NE(std::string(e.what()).find("z1: expected above z0 = 0.6, got 0.5"), std::string::npos) << e.what();
	}
}
